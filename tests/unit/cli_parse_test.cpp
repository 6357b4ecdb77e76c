// `asos parse` as a user runs it: the dump on stdout, diagnostics on stderr
// as file:line:col: error: message, the source line and a caret, exit 1.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

struct Result {
    int exitCode = -1;
    std::string out;
    std::string err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

Result asos(std::vector<std::string> args) {
    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli";
    fs::create_directories(dir);
    // ctest runs the test cases side by side: files of our own.
    const std::string tag = std::to_string(getpid());
    const fs::path out = dir / ("stdout-" + tag + ".txt");
    const fs::path err = dir / ("stderr-" + tag + ".txt");
    const pid_t pid = fork();
    if (pid == 0) {
        const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || chdir(dir.c_str()) != 0) _exit(126);
        dup2(o, STDOUT_FILENO);
        dup2(e, STDERR_FILENO);
        std::vector<char*> argv{const_cast<char*>(ASOS_EXE)};
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(ASOS_EXE, argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    Result r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

fs::path scene(const std::string& name, const std::string& text) {
    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli";
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

}  // namespace

TEST_CASE("asos parse prints the dump and exits 0", "[cli]") {
    scene("good.pov", "sphere { <0, 1, 0>, 0.5 }\n");
    const Result r = asos({"parse", "good.pov"});
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.rfind("// asos scene description", 0) == 0);
    CHECK(r.out.find("// good.pov:1:1\nsphere {\n  <0, 1, 0>, 0.5\n") != std::string::npos);
}

TEST_CASE("asos parse reports errors with the source line and a caret, exit 1", "[cli]") {
    scene("bad.pov", "sphere { 0, 1 }\nsphere { <0, 1, 0>, -2 }\nbox { 0, 1 scale 0 }\n");
    const Result r = asos({"parse", "bad.pov"});
    CHECK(r.exitCode == 1);
    CHECK(r.out.empty());
    CHECK(r.err ==
          "bad.pov:2:21: error: the radius of a sphere must be positive, not -2\n"
          "sphere { <0, 1, 0>, -2 }\n"
          "                    ^\n"
          "bad.pov:3:18: error: scale by zero (<0, 0, 0>) flattens everything\n"
          "box { 0, 1 scale 0 }\n"
          "                 ^\n");
}

TEST_CASE("asos parse takes -L, -D and --clock", "[cli]") {
    const fs::path lib = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli" / "lib";
    fs::create_directories(lib);
    std::ofstream(lib / "size.inc") << "#declare Size = 2;\n";
    scene("opts.pov", "#include \"size.inc\"\nsphere { Where, Size * Scale + clock }\n");
    const Result r = asos({"parse", "opts.pov", "-L", lib.string(), "-D", "Scale=3", "-D", "Where=<1,2,3>",
                           "--clock", "0.5", "--no-locations"});
    INFO(r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("sphere {\n  <1, 2, 3>, 6.5\n") != std::string::npos);

    const Result bad = asos({"parse", "opts.pov", "-D", "sphere=1"});
    CHECK(bad.exitCode == 1);
    CHECK(bad.err.find("-D wants NAME=VALUE") != std::string::npos);
}

TEST_CASE("asos parse on a missing file fails cleanly", "[cli]") {
    const Result r = asos({"parse", "no-such-file.pov"});
    CHECK(r.exitCode == 1);
    CHECK(r.err == "no-such-file.pov: error: cannot read the scene file\n");
}
