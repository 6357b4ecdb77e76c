#pragma once
// Runs a program of the build (asos, asos-bench) as a user does, for the
// command-line tests: in a given folder, its stdout and stderr kept in files of this process's own
// (ctest runs test cases side by side), and read back whole.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace asos::test {

struct ProgramResult {
    int exitCode = -1;  // -1: killed by a signal
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// `inChild`, when given, runs in the child before the program starts (to set
// a resource limit, say).
inline ProgramResult runProgram(const char* program, const std::filesystem::path& dir,
                                std::vector<std::string> args, void (*inChild)() = nullptr) {
    std::filesystem::create_directories(dir);
    const std::string tag = std::to_string(getpid());
    const std::filesystem::path out = dir / ("stdout-" + tag + ".txt");
    const std::filesystem::path err = dir / ("stderr-" + tag + ".txt");
    const pid_t pid = fork();
    if (pid == 0) {
        const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || chdir(dir.c_str()) != 0) _exit(126);
        if (inChild) inChild();
        dup2(o, STDOUT_FILENO);
        dup2(e, STDERR_FILENO);
        std::vector<char*> argv{const_cast<char*>(program)};
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(program, argv.data());
        _exit(127);
    }
    ProgramResult r;
    if (pid < 0) return r;
    int status = 0;
    waitpid(pid, &status, 0);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

// A scratch folder of this test case's own, under test-output/<suite>/: ctest
// runs the test cases of a file side by side, so two must never share a scene
// file that each rewrites.
inline std::filesystem::path testCaseDir(const std::string& suite, const std::string& testCase) {
    std::string folder;
    for (const char c : testCase) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (plain) folder += c;
        else if (!folder.empty() && folder.back() != '-') folder += '-';
    }
    const std::filesystem::path dir = std::filesystem::path(ASOS_BINARY_DIR) / "test-output" / suite / folder;
    std::filesystem::create_directories(dir);
    return dir;
}

inline ProgramResult runAsos(const std::filesystem::path& dir, std::vector<std::string> args) {
    return runProgram(ASOS_EXE, dir, std::move(args));
}

// The files of `dir` other than the stdout/stderr captures runAsos leaves
// there: what a command wrote.
inline std::set<std::string> filesIn(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (!name.starts_with("stdout-") && !name.starts_with("stderr-")) names.insert(name);
    }
    return names;
}

}  // namespace asos::test
