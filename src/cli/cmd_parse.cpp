// asos parse SCENE [-L dir]... [-D NAME=VALUE]... [--clock C] [--stats]
// Prints the canonical dump of the scene description to stdout; diagnostics
// (errors, warnings, #debug) go to stderr; exit status 1 after an error.
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
    lang::InterpreterOptions limits;  // --max-*: the limits of what the scene may ask for
    std::vector<std::string> includePaths;
    std::vector<std::string> defines;
    double clock = 0.0;
    bool clockGiven = false;  // `clock_on` is 1 when --clock is given, as with POV-Ray's +K
    bool stats = false;
    bool noLocations = false;
};

int runParse(const ParseArgs& args) {
    lang::InterpreterOptions options = args.limits;
    for (const auto& dir : args.includePaths) options.includePaths.emplace_back(dir);
    for (const auto& text : args.defines) {
        std::optional<lang::Define> define = parseDefine(text);
        if (!define) {
            std::cerr << "asos parse: error: -D wants NAME=VALUE with NAME an identifier that is not a "
                         "keyword, not '"
                      << text << "'\n";
            return 1;
        }
        options.defines.push_back(std::move(*define));
    }
    options.libraryPaths = lang::povrayLibraryPaths();
    options.clock = args.clock;
    options.clockOn = args.clockGiven;

    Diagnostics diagnostics;
    const auto start = std::chrono::steady_clock::now();
    auto scene = lang::interpretFile(args.scene, options, diagnostics);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const Diagnostic& d : diagnostics.all()) std::cerr << formatDiagnostic(d);
    if (!scene) return 1;

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
    return std::cout ? 0 : 1;
}

}  // namespace

void addParseCommand(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<ParseArgs>();
    CLI::App* cmd = app.add_subcommand("parse", "Parse a scene and print its canonical description");
    cmd->add_option("scene", args->scene, "Scene file (.pov)")->required();
    addLimitOptions(*cmd, args->limits);
    cmd->add_option("-L,--library-path", args->includePaths,
                    "Folder searched by #include after the including file's and the scene's, before POV-Ray's own");
    cmd->add_option("-D,--define", args->defines, "NAME=VALUE declared before the scene runs");
    cmd->add_option("--clock", args->clock, "Value of `clock`")->each([args](const std::string&) {
        args->clockGiven = true;
    });
    cmd->add_flag("--stats", args->stats, "Print object count, time and peak memory instead of the dump");
    cmd->add_flag("--no-locations", args->noLocations, "Leave the source-location comments out of the dump");
    cmd->callback([args, &result] { result.exitCode = runParse(*args); });
}

}  // namespace asos::cli
