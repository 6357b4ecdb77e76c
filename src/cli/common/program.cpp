#include "cli/common/program.hpp"

namespace asos::cli {

int runProgram(CLI::App& app, int argc, char** argv, const CommandResult& result) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    return result.exitCode;
}

}  // namespace asos::cli
