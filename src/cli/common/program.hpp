#pragma once
// What the two programs, asos and asos-bench, share around their
// subcommands. Each subcommand lives in its own file and is registered by the
// program's main.cpp with one line; it sets `result.exitCode` from its
// callback, and only the program prints and decides the exit code.
#include <CLI/CLI.hpp>

#include "asos/lang/interpreter.hpp"

namespace asos::cli {

struct CommandResult {
    int exitCode = 0;
};

// Adds --version ("NAME VERSION", the app's name and the project's
// version), parses the command line and runs the chosen subcommand. Returns
// CLI11's exit code for --help, --version and a mistake in the options, else
// the command's.
int runProgram(CLI::App& app, int argc, char** argv, const CommandResult& result);

// --max-objects, --max-string-length, --max-array-elements and --max-memory:
// the limits of what a scene may ask for, set in `options`.
void addLimitOptions(CLI::App& cmd, lang::InterpreterOptions& options);

}  // namespace asos::cli
