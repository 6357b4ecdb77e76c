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

int reportBeforeScene(const std::string& command, const std::vector<std::string>& problems,
                      const CheckedSceneInputs& inputs, const std::string& scene) {
    if (!problems.empty() || !inputs.problems.empty()) {
        for (const std::string& p : problems) std::cerr << command << ": error: " << p << '\n';
        for (const std::string& p : inputs.problems) std::cerr << p;
        std::cerr << kUsageHint << '\n';
        return kExitBadCommandLine;
    }
    if (std::string e = unreadableScene(scene); !e.empty()) {
        std::cerr << command << ": error: " << e << '\n';
        return kExitIoFailure;
    }
    return kExitSuccess;
}

void addLimitOptions(CLI::App& cmd, SceneInputs& inputs) {
    cmd.add_option("--write-folder", inputs.writeFolder,
                   "Folder for the files the scene writes (#fopen … write or append; default: the current folder)");
    lang::InterpreterOptions& limits = inputs.limits;
    cmd.add_option("--max-objects", limits.maxObjects, "Most shapes and lights a scene may make (default 50000000)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-string-length", limits.maxStringLength,
                   "Most characters in one string of a scene (default 16777216)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-array-elements", limits.maxArrayElements,
                   "Most elements in one array of a scene (default 10000000)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--max-memory", inputs.maxMemory,
                   "Memory a scene's objects, arrays and strings and a render's images may take, estimated "
                   "before they are made: 8G (default), 512M, a number of bytes");
}

}  // namespace asos::cli
