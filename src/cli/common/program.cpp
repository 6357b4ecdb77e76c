#include "cli/common/program.hpp"

#include "asos/version.hpp"

namespace asos::cli {

int runProgram(CLI::App& app, int argc, char** argv, const CommandResult& result) {
    app.set_version_flag("--version", app.get_name() + " " + kVersion);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    return result.exitCode;
}

void addLimitOptions(CLI::App& cmd, lang::InterpreterOptions& options) {
    cmd.add_option("--max-objects", options.maxObjects, "Most shapes and lights a scene may make (default 50000000)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-string-length", options.maxStringLength,
                   "Most characters in one string of a scene (default 16777216)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-array-elements", options.maxArrayElements,
                   "Most elements in one array of a scene (default 10000000)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-memory", options.maxMemoryMiB,
                   "MiB that a scene's objects, arrays and strings may take, estimated before they are made (default 8192)")
        ->check(CLI::PositiveNumber);
}

}  // namespace asos::cli
