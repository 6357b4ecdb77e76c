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

}  // namespace asos::cli
