// asos bench parse [--max-exponent 6] [--povray] [--dir DIR]
// Writes scenes of 10^3 … 10^N spheres, written out one by one ("explicit")
// and made by a #while loop ("loop"), then times scene text → description for
// each. Each case runs in a forked child so that its peak memory (the child's
// getrusage maxrss) is its own. With --povray, POV-Ray 3.7 parses the same
// files (`povray +W1 +H1 -D -GA +GS`) and its reported parse time is shown.
#include <sys/resource.h>
#include <sys/wait.h>
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
#include "cli/commands.hpp"

namespace asos::cli {

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
    double peakMiB = 0.0;
    std::size_t objects = 0;
};

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
                                      x, y, z, 100 + i % 300, (i % 7) / 7.0, (i % 11) / 11.0);
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

// Runs `work` in a forked child; returns its report and the child's peak RSS.
Measure measureInChild(const fs::path& scene) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid < 0) return {};
    if (pid == 0) {
        close(fds[0]);
        Diagnostics diagnostics;
        const auto start = std::chrono::steady_clock::now();
        auto description = lang::interpretFile(scene, lang::InterpreterOptions{}, diagnostics);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double report[2] = {description ? seconds : -1.0,
                                  description ? static_cast<double>(description->objects.size()) : 0.0};
        const ssize_t written = write(fds[1], report, sizeof report);
        _exit(written == sizeof report ? 0 : 1);
    }
    close(fds[1]);
    double report[2] = {-1.0, 0.0};
    const ssize_t got = read(fds[0], report, sizeof report);
    close(fds[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Measure m;
    m.ok = got == sizeof report && report[0] >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    m.seconds = report[0];
    m.objects = static_cast<std::size_t>(report[1]);
    m.peakMiB = usage.ru_maxrss / 1024.0;
    return m;
}

// POV-Ray's own "Parse Time" for the file, and its peak RSS.
std::optional<Measure> measurePovray(const fs::path& scene) {
    const fs::path log = scene.string() + ".povray.log";
    const pid_t pid = fork();
    if (pid < 0) return std::nullopt;
    if (pid == 0) {
        std::FILE* f = std::freopen(log.c_str(), "w", stderr);
        if (!f || !std::freopen("/dev/null", "w", stdout)) _exit(127);
        const std::string input = "+I" + scene.string();
        execlp("povray", "povray", "+W1", "+H1", "-D", "-GA", "+GS", "-F", input.c_str(),
               static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    std::string text;
    {
        std::ifstream in(log);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::error_code ec;
    fs::remove(log, ec);
    std::smatch match;
    if (!std::regex_search(text, match, std::regex(R"(Parse Time:[^(]*\(([0-9.]+) seconds\))")))
        return std::nullopt;
    Measure m;
    m.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    m.seconds = std::stod(match[1]);
    m.peakMiB = usage.ru_maxrss / 1024.0;
    return m;
}

int runBench(const BenchArgs& args) {
    if (args.maxExponent < 3 || args.maxExponent > 7) {
        std::cerr << "asos bench parse: error: --max-exponent must be from 3 to 7\n";
        return 1;
    }
    std::error_code ec;
    const fs::path dir = args.dir.empty() ? fs::temp_directory_path() / ("asos-bench-parse-" + std::to_string(getpid()))
                                          : fs::path(args.dir);
    fs::create_directories(dir, ec);
    if (ec) {
        std::cerr << "asos bench parse: error: cannot create " << dir << ": " << ec.message() << '\n';
        return 1;
    }
    std::cout << "scene text -> scene description (asos parse), one child process per case\n"
              << "files in " << dir.string() << "\n\n"
              << std::left << std::setw(10) << "case" << std::right << std::setw(10) << "spheres"
              << std::setw(10) << "MiB file" << std::setw(10) << "seconds" << std::setw(12) << "peak MiB";
    if (args.povray) std::cout << std::setw(16) << "povray seconds" << std::setw(14) << "povray MiB";
    std::cout << '\n';
    int failures = 0;
    for (int e = 3; e <= args.maxExponent; ++e) {
        const long n = std::lround(std::pow(10.0, e));
        for (const bool loop : {false, true}) {
            const fs::path file = dir / ((loop ? "loop-1e" : "explicit-1e") + std::to_string(e) + ".pov");
            if (loop)
                writeLoop(file, n);
            else
                writeExplicit(file, n);
            const Measure m = measureInChild(file);
            const bool ok = m.ok && m.objects == static_cast<std::size_t>(n);
            if (!ok) ++failures;
            std::cout << std::left << std::setw(10) << (loop ? "loop" : "explicit") << std::right
                      << std::setw(10) << n << std::setw(10) << std::fixed << std::setprecision(1)
                      << fs::file_size(file, ec) / 1048576.0 << std::setw(10) << std::setprecision(3)
                      << m.seconds << std::setw(12) << std::setprecision(1) << m.peakMiB;
            if (args.povray) {
                if (auto p = measurePovray(file))
                    std::cout << std::setw(16) << std::setprecision(3) << p->seconds << std::setw(14)
                              << std::setprecision(1) << p->peakMiB;
                else
                    std::cout << std::setw(16) << "failed" << std::setw(14) << "-";
            }
            std::cout << (ok ? "" : "   FAILED") << std::endl;
            if (args.dir.empty()) fs::remove(file, ec);
        }
    }
    if (args.dir.empty()) fs::remove_all(dir, ec);
    return failures ? 1 : 0;
}

}  // namespace

void addBenchParseCommand(CLI::App& bench, CommandResult& result) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = bench.add_subcommand("parse", "Parse time and peak memory, 10^3 to 10^6 spheres");
    cmd->add_option("--max-exponent", args->maxExponent, "Largest case is 10^N spheres (3 to 7)");
    cmd->add_flag("--povray", args->povray, "Also time POV-Ray 3.7 on the same files");
    cmd->add_option("--dir", args->dir, "Keep the generated scenes in this folder");
    cmd->callback([args, &result] { result.exitCode = runBench(*args); });
}

}  // namespace asos::cli
