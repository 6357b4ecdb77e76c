// asos parse SCENE [-L dir]... [-D NAME=VALUE]... [--clock C] [--stats]
// Prints the canonical dump of the scene description to stdout; diagnostics
// (errors, warnings, #debug) go to stderr; exit status 1 after an error in
// the scene, 2 for a bad option, 3 when the scene cannot be read.
#include <sys/resource.h>

#include <chrono>
#include <iostream>
#include <memory>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/scene/dump.hpp"
#include "cli/common/arguments.hpp"
#include "cli/commands.hpp"

namespace asos::cli {

namespace {

struct ParseArgs {
    std::string scene;
    SceneInputs inputs;
    bool stats = false;
    bool noLocations = false;
};

int runParse(const ParseArgs& args) {
    CheckedSceneInputs checked = checkSceneInputs(args.inputs, "asos parse");
    if (const int code = reportBeforeScene("asos parse", {}, checked, args.scene); code != kExitSuccess)
        return code;
    const lang::InterpreterOptions& options = checked.options;

    Diagnostics diagnostics;
    const auto start = std::chrono::steady_clock::now();
    auto scene = lang::interpretFile(args.scene, options, diagnostics);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const Diagnostic& d : diagnostics.all()) std::cerr << formatDiagnostic(d);
    if (!scene) return kExitBadScene;

    if (args.stats) {
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::cout << "objects " << scene->objects.size() << "\nlights " << scene->lights.size()
                  << "\nseconds " << seconds << "\npeak_rss_mib " << static_cast<double>(usage.ru_maxrss) / 1024.0 << '\n';
        return 0;
    }
    std::ios::sync_with_stdio(false);
    DumpOptions dumpOptions;
    dumpOptions.locations = !args.noLocations;
    writeDump(std::cout, *scene, dumpOptions);
    std::cout.flush();
    return std::cout ? kExitSuccess : kExitIoFailure;
}

}  // namespace

void addParseCommand(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<ParseArgs>();
    CLI::App* cmd = app.add_subcommand("parse", "Parse a scene and print its canonical description");
    cmd->add_option("scene", args->scene, "Scene file (.pov)")->required();
    addLimitOptions(*cmd, args->inputs);
    cmd->add_option("-L,--library-path", args->inputs.includePaths,
                    "Folder searched by #include after the including file's and the scene's, before POV-Ray's own");
    cmd->add_option("-D,--define", args->inputs.defines,
                    "NAME=VALUE declared before the scene runs: a number, a vector or a quoted string");
    cmd->add_option("--clock", args->inputs.clock, "Value of `clock` (and `clock_on` 1)");
    cmd->add_flag("--stats", args->stats, "Print object count, time and peak memory instead of the dump");
    cmd->add_flag("--no-locations", args->noLocations, "Leave the source-location comments out of the dump");
    cmd->callback([args, &result] { result.exitCode = runParse(*args); });
}

}  // namespace asos::cli
