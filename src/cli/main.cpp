#include <cstdio>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"asos: ray tracing with adaptive supersampling in object space"};
    app.require_subcommand(1);
    asos::cli::CommandResult result;
    // Subcommands register here, one line each.
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    return result.exitCode;
}
