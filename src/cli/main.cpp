#include <csignal>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
    using namespace asos::cli;
    // Past a file size limit (ulimit -f) a write then fails with EFBIG and is
    // reported like a full disk, instead of the signal ending the process.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{"asos: ray tracing with adaptive supersampling in object space", "asos"};
    app.require_subcommand(1);
    CommandResult result;

    // Subcommands register here, one line each.
    addParseCommand(app, result);
    addRenderCommand(app, result);
    addReferenceCommand(app, result);

    return runProgram(app, argc, argv, result);
}
