#include "cli/commands.hpp"

int main(int argc, char** argv) {
    using namespace asos::cli;
    CLI::App app{"asos: ray tracing with adaptive supersampling in object space"};
    app.require_subcommand(1);
    CommandResult result;

    // Subcommands register here, one line each.
    addParseCommand(app, result);
    addRenderCommand(app, result);
    CLI::App* bench = addBenchCommand(app);
    // Benchmarks register under `bench`, one line each.
    addBenchParseCommand(*bench, result);
    addBenchBvhCommand(*bench, result);
    addBenchIntersectCommand(*bench, result);
    addBenchRenderCommand(*bench, result);
    addBenchLightsCommand(*bench, result);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    return result.exitCode;
}
