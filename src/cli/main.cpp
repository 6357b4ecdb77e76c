#include "cli/commands.hpp"

int main(int argc, char** argv) {
    using namespace asos::cli;
    CLI::App app{"asos: ray tracing with adaptive supersampling in object space", "asos"};
    app.require_subcommand(1);
    CommandResult result;

    // Subcommands register here, one line each.
    addParseCommand(app, result);
    addRenderCommand(app, result);

    return runProgram(app, argc, argv, result);
}
