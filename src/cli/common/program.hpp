#pragma once
// What the two programs, asos and asos-bench, share around their
// subcommands. Each subcommand lives in its own file and is registered by the
// program's main.cpp with one line; it sets `result.exitCode` from its
// callback, and only the program prints and decides the exit code.
#include <CLI/CLI.hpp>

#include "asos/lang/interpreter.hpp"
#include "cli/common/arguments.hpp"

namespace asos::cli {

// The exit codes (docs/cli.md, "Exit codes").
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitBadScene = 1;        // the scene: an error in it, or more memory than there is
inline constexpr int kExitBadCommandLine = 2;  // the options, found before anything is read
inline constexpr int kExitIoFailure = 3;       // a file that cannot be read or written

// Printed after every command-line error.
inline constexpr const char* kUsageHint = "Run with --help for more information.";

struct CommandResult {
    int exitCode = kExitSuccess;
};

// Adds --version ("NAME VERSION", the app's name and the project's
// version), parses the command line and runs the chosen subcommand. Returns
// 0 for --help and --version; for a mistake CLI11 finds in the options
// (its codes 104-114) prints "NAME: error: MESSAGE" and the usage hint and
// returns kExitBadCommandLine; for memory running out anywhere (a
// std::bad_alloc, from any thread) prints a message and returns
// kExitBadScene; else the command's code.
int runProgram(CLI::App& app, int argc, char** argv, const CommandResult& result);

// What a command checks before it reads its scene, reported: each of
// `problems` as "COMMAND: error: ...", then the scene inputs' problems, and
// the usage hint (kExitBadCommandLine); else a scene file that cannot be read
// (kExitIoFailure). kExitSuccess when there is nothing to report.
int reportBeforeScene(const std::string& command, const std::vector<std::string>& problems,
                      const CheckedSceneInputs& inputs, const std::string& scene);

// --max-objects, --max-string-length, --max-array-elements and --max-memory:
// the limits of what a scene (and a render) may ask for, set in `inputs`.
void addLimitOptions(CLI::App& cmd, SceneInputs& inputs);

}  // namespace asos::cli
