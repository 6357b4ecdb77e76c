#include "cli/common/program.hpp"

#include <iostream>
#include <new>

#include "asos/version.hpp"

namespace asos::cli {

int runProgram(CLI::App& app, int argc, char** argv, const CommandResult& result) {
    app.set_version_flag("--version", app.get_name() + " " + kVersion);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
        std::cerr << app.get_name() << ": error: " << e.what() << '\n' << kUsageHint << '\n';
        return kExitBadCommandLine;
    } catch (const std::bad_alloc&) {
        // Anywhere: the interpreter, the renderer's worker threads (TBB passes
        // their exception on), the encoders. Nothing has been written.
        std::cerr << app.get_name() << ": error: out of memory (the scene or the image needs more than there is)\n";
        return kExitBadScene;
    }
    return result.exitCode;
}

}  // namespace asos::cli
