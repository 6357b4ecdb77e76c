#pragma once
// Each subcommand of the `asos` program lives in its own file and registers
// itself here. A command sets `exitCode` from its callback; only the command
// line prints and decides the exit code.
#include <CLI/CLI.hpp>

namespace asos::cli {

struct CommandResult {
    int exitCode = 0;
};

}  // namespace asos::cli
