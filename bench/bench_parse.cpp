// asos-bench parse [--max-exponent 6] [--povray] [--dir DIR]
// Writes scenes of 10^3 … 10^N spheres, written out one by one ("explicit"),
// made by a #while loop ("loop") and by a macro called from a #for loop for
// each sphere ("macro"), then times scene text → description for
// each: wall time, CPU time (user + system: steadier when the machine is
// shared) and peak memory. Each case runs in a forked child so that its peak
// memory (the child's getrusage maxrss) is its own. With --povray, POV-Ray 3.7
// parses the same files (`povray +W1 +H1 -D -F -GA +GS<file>`) and the parse
// time it reports (wall and CPU) is shown with its peak memory.
// The scenes are generated rather than kept in examples/: their size is the
// workload (up to 10^7 spheres, hundreds of MiB), and both cases come from
// the same formula, so the loop makes the spheres written out.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "benchmarks.hpp"

namespace asos::bench {

namespace {

namespace fs = std::filesystem;

struct BenchArgs {
    int maxExponent = 6;
    bool povray = false;
    std::string dir;
};

struct Measure {
    bool ok = false;
    double seconds = 0.0;
    double cpuSeconds = 0.0;
    double peakMiB = 0.0;
    std::size_t objects = 0;
};

double cpuNow() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Explicit spheres on a 100 x 100 x 100 grid with varied radii and colours.
void writeExplicit(const fs::path& path, long n) {
    std::ofstream out(path);
    out << "// " << n << " spheres written out one by one\n"
        << "camera { location <50, 50, -150> look_at <50, 50, 50> }\n"
        << "light_source { <0, 200, -100>, rgb 1 }\n";
    char line[160];
    for (long i = 0; i < n; ++i) {
        const long x = i % 100, y = (i / 100) % 100, z = i / 10000;
        const int len = std::snprintf(line, sizeof line,
                                      "sphere { <%ld.25, %ld.5, %ld.75>, 0.%03ld pigment { rgb <%.3f, 0.5, %.3f> } }\n",
                                      x, y, z, 100 + i % 300, static_cast<double>(i % 7) / 7.0, static_cast<double>(i % 11) / 11.0);
        out.write(line, len);
    }
}

void writeLoop(const fs::path& path, long n) {
    std::ofstream out(path);
    out << "// " << n << " spheres made by a #while loop\n"
        << "camera { location <50, 50, -150> look_at <50, 50, 50> }\n"
        << "light_source { <0, 200, -100>, rgb 1 }\n"
        << "#declare I = 0;\n"
        << "#while (I < " << n << ")\n"
        << "  sphere { <mod(I, 100) + 0.25, mod(div(I, 100), 100) + 0.5, div(I, 10000) + 0.75>,\n"
        << "           0.1 + mod(I, 300) / 1000\n"
        << "           pigment { rgb <mod(I, 7) / 7, 0.5, mod(I, 11) / 11> } }\n"
        << "  #declare I = I + 1;\n"
        << "#end\n";
}

void writeMacro(const fs::path& path, long n) {
    std::ofstream out(path);
    out << "// " << n << " spheres made by a macro, called from a #for loop\n"
        << "camera { location <50, 50, -150> look_at <50, 50, 50> }\n"
        << "light_source { <0, 200, -100>, rgb 1 }\n"
        << "#macro Ball(I)\n"
        << "  sphere { <mod(I, 100) + 0.25, mod(div(I, 100), 100) + 0.5, div(I, 10000) + 0.75>,\n"
        << "           0.1 + mod(I, 300) / 1000\n"
        << "           pigment { rgb <mod(I, 7) / 7, 0.5, mod(I, 11) / 11> } }\n"
        << "#end\n"
        << "#for (I, 0, " << n - 1 << ")\n"
        << "  Ball(I)\n"
        << "#end\n";
}

// Runs `work` in a forked child; returns its report and the child's peak RSS.
Measure measureInChild(const fs::path& scene) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    std::cout.flush();  // the child must not inherit (and print again) pending output
    const pid_t pid = fork();
    if (pid < 0) return {};
    if (pid == 0) {
        close(fds[0]);
        Diagnostics diagnostics;
        const double cpuStart = cpuNow();
        const auto start = std::chrono::steady_clock::now();
        auto description = lang::interpretFile(scene, lang::InterpreterOptions{}, diagnostics);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double report[3] = {description ? seconds : -1.0,
                                  description ? static_cast<double>(description->objects.size()) : 0.0,
                                  cpuNow() - cpuStart};
        const ssize_t written = write(fds[1], report, sizeof report);
        _exit(written == sizeof report ? 0 : 1);
    }
    close(fds[1]);
    double report[3] = {-1.0, 0.0, 0.0};
    const ssize_t got = read(fds[0], report, sizeof report);
    close(fds[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Measure m;
    m.ok = got == sizeof report && report[0] >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    m.seconds = report[0];
    m.objects = static_cast<std::size_t>(report[1]);
    m.cpuSeconds = report[2];
    m.peakMiB = static_cast<double>(usage.ru_maxrss) / 1024.0;
    return m;
}

// POV-Ray's own "Parse Time" for the file (wall and CPU), and its peak RSS.
std::optional<Measure> measurePovray(const fs::path& scene) {
    const fs::path stats = scene.string() + ".povray-stats.txt";
    std::cout.flush();
    const pid_t pid = fork();
    if (pid < 0) return std::nullopt;
    if (pid == 0) {
        const int devNull = open("/dev/null", O_WRONLY);
        if (devNull < 0) _exit(126);
        dup2(devNull, STDOUT_FILENO);
        dup2(devNull, STDERR_FILENO);
        // POV-Ray writes stream files only beside its image: run in the scene's folder.
        if (chdir(scene.parent_path().c_str()) != 0) _exit(126);
        const std::string input = "+I" + scene.filename().string();
        const std::string statsOption = "+GS" + stats.filename().string();
        execlp("povray", "povray", "+W1", "+H1", "-D", "-F", "-GA", statsOption.c_str(), input.c_str(),
               static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    std::string text;
    {
        std::ifstream in(stats);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::error_code ec;
    fs::remove(stats, ec);
    std::smatch match;
    if (!std::regex_search(text, match,
                           std::regex(R"(Parse Time:[^(]*\(([0-9.]+) seconds\)\s*using \d+ thread\(s\) with ([0-9.]+) CPU-seconds)")))
        return std::nullopt;
    Measure m;
    m.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    m.seconds = std::stod(match[1]);
    m.cpuSeconds = std::stod(match[2]);
    m.peakMiB = static_cast<double>(usage.ru_maxrss) / 1024.0;
    return m;
}

int runBench(const BenchArgs& args) {
    if (args.maxExponent < 3 || args.maxExponent > 7) {
        std::cerr << "asos-bench parse: error: --max-exponent must be from 3 to 7\n";
        return 1;
    }
    std::error_code ec;
    const fs::path dir = args.dir.empty() ? fs::temp_directory_path() / ("asos-bench-parse-" + std::to_string(getpid()))
                                          : fs::path(args.dir);
    fs::create_directories(dir, ec);
    if (ec) {
        std::cerr << "asos-bench parse: error: cannot create " << dir << ": " << ec.message() << '\n';
        return 1;
    }
    std::cout << "scene text -> scene description (asos parse), one child process per case\n"
              << "files in " << dir.string() << "\n\n"
              << std::left << std::setw(10) << "case" << std::right << std::setw(10) << "spheres"
              << std::setw(10) << "file MiB" << std::setw(10) << "wall s" << std::setw(10) << "CPU s"
              << std::setw(10) << "peak MiB";
    if (args.povray)
        std::cout << "  |" << std::setw(10) << "povray" << std::setw(10) << "povray" << std::setw(10) << "povray";
    std::cout << '\n';
    if (args.povray)
        std::cout << std::setw(60) << "" << "  |" << std::setw(10) << "wall s" << std::setw(10) << "CPU s"
                  << std::setw(10) << "peak MiB" << '\n';
    int failures = 0;
    for (int e = 3; e <= args.maxExponent; ++e) {
        const long n = std::lround(std::pow(10.0, e));
        for (const std::string kind : {"explicit", "loop", "macro"}) {
            const fs::path file = dir / (kind + "-1e" + std::to_string(e) + ".pov");
            if (kind == "loop")
                writeLoop(file, n);
            else if (kind == "macro")
                writeMacro(file, n);
            else
                writeExplicit(file, n);
            const Measure m = measureInChild(file);
            const bool ok = m.ok && m.objects == static_cast<std::size_t>(n);
            if (!ok) ++failures;
            std::cout << std::left << std::setw(10) << kind << std::right
                      << std::setw(10) << n << std::setw(10) << std::fixed << std::setprecision(1)
                      << static_cast<double>(fs::file_size(file, ec)) / 1048576.0 << std::setw(10) << std::setprecision(3)
                      << m.seconds << std::setw(10) << m.cpuSeconds << std::setw(10) << std::setprecision(1)
                      << m.peakMiB;
            if (args.povray) {
                std::cout << "  |";
                if (auto p = measurePovray(file))
                    std::cout << std::setw(10) << std::setprecision(3) << p->seconds << std::setw(10)
                              << p->cpuSeconds << std::setw(10) << std::setprecision(1) << p->peakMiB;
                else
                    std::cout << std::setw(30) << "failed";
            }
            std::cout << (ok ? "" : "   FAILED") << std::endl;
            if (args.dir.empty()) fs::remove(file, ec);
        }
    }
    if (args.dir.empty()) fs::remove_all(dir, ec);
    return failures ? 1 : 0;
}

}  // namespace

void addParseBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("parse", "Parse time and peak memory, 10^3 to 10^6 spheres, written out, "
                                                "by #while, by a macro");
    cmd->add_option("--max-exponent", args->maxExponent, "Largest case is 10^N spheres (3 to 7)");
    cmd->add_flag("--povray", args->povray, "Also time POV-Ray 3.7 on the same files");
    cmd->add_option("--dir", args->dir, "Keep the generated scenes in this folder");
    cmd->callback([args, &result] { result.exitCode = runBench(*args); });
}

}  // namespace asos::bench
