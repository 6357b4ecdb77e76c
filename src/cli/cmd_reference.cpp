// asos reference SCENE -o REF.exr [-W 320 -H 240] [--eye-samples 32] [--light-samples 8]
//   [--threads N] [--no-cache] [--clock C] [-D NAME=VALUE]... [-L DIR]... [--quiet]
// A converged image of the scene by brute force (cli/common/reference.hpp):
// what the accuracy of every method is measured against. Cached under a hash
// of the scene text and the settings, so that a second call is a copy.
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "cli/commands.hpp"
#include "cli/common/arguments.hpp"
#include "cli/common/reference.hpp"
#include "cli/progress_report.hpp"

namespace asos::cli {

namespace {

struct ReferenceArgs {
    std::string scene;
    std::string output;
    ReferenceSettings settings;
    bool noCache = false;
    std::optional<std::string> cache;
    bool quiet = false;
    SceneInputs inputs;
};

void fail(const std::string& message) { std::cerr << "asos reference: error: " << message << '\n'; }

int runReference(const ReferenceArgs& args) {
    std::vector<std::string> problems;
    const ReferenceSettings& s = args.settings;
    if (std::string e = checkRenderSettings(referenceRenderSettings(s)); !e.empty()) problems.push_back(e);
    if (s.eyeSamples < 1 || s.lightSamples < 1)
        problems.push_back("--eye-samples and --light-samples must be positive");
    if (IoStatus st = checkOutputPath(args.output, SampleFormat::Auto, std::max(s.width, 1), std::max(s.height, 1));
        !st.ok())
        problems.push_back("-o: " + st.error);
    CheckedSceneInputs inputs = checkSceneInputs(args.inputs, "asos reference");
    inputs.options.imageWidth = s.width;
    inputs.options.imageHeight = s.height;
    if (const int code = reportBeforeScene("asos reference", problems, inputs, args.scene); code != kExitSuccess)
        return code;
    std::ostringstream text;
    text << std::ifstream(args.scene, std::ios::binary).rdbuf();

    Diagnostics diagnostics;
    const std::optional<SceneDescription> scene = lang::interpretFile(args.scene, inputs.options, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) std::cerr << formatDiagnostic(d);
    if (!scene) return kExitBadScene;

    ProgressReport progress(ProgressReport::modeForStderr(args.quiet), false);
    progress.start({});
    std::function<void(const TileProgress&)> onTile;
    if (progress.wanted()) onTile = [&progress](const TileProgress& p) { progress.update(p); };
    const ReferenceImage ref = loadOrRenderReference(*scene, args.scene, text.str(), s, args.inputs.defines,
                                                     inputs.options.clock,
                                                     args.cache ? std::optional<std::filesystem::path>(*args.cache)
                                                                : referenceCacheFolder(),
                                                     !args.noCache, onTile);
    progress.interrupt();
    if (!ref.error.empty()) {
        std::cerr << ref.error;
        return kExitBadScene;
    }
    WriteOptions options;
    options.assumedGamma = scene->globals.assumedGamma;
    if (IoStatus st = writeImage(ref.image, args.output, options); !st.ok()) {
        fail(st.error);
        return kExitIoFailure;
    }
    if (!args.quiet) {
        if (ref.fromCache)
            std::fprintf(stderr, "asos reference: from the cache, %s\n", ref.cached.string().c_str());
        else
            std::fprintf(stderr, "asos reference: rendered in %.1f s%s%s\n", ref.seconds,
                         ref.cached.empty() ? " (no cache folder that takes files)" : ", cached as ",
                         ref.cached.string().c_str());
    }
    return kExitSuccess;
}

}  // namespace

void addReferenceCommand(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<ReferenceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "reference", "Render a converged reference image by brute force (cached; docs/performance.md)");
    cmd->add_option("scene", args->scene, "Scene file (.pov)")->required();
    addLimitOptions(*cmd, args->inputs);
    cmd->add_option("-o,--output", args->output, "Image file (.exr keeps the linear floats)")->required();
    cmd->add_option("-W,--width", args->settings.width, "Image width in pixels (default 320)");
    cmd->add_option("-H,--height", args->settings.height, "Image height in pixels (default 240)");
    cmd->add_option("--eye-samples", args->settings.eyeSamples,
                    "N x N jittered eye rays per pixel (default 32)");
    cmd->add_option("--light-samples", args->settings.lightSamples,
                    "M x M stratified points over every area light's area, per eye ray (default 4)");
    cmd->add_option("--threads", args->settings.threads, "Worker threads (default 0: all cores)");
    cmd->add_option("--cache", args->cache,
                    "Cache folder (default $ASOS_REFERENCE_CACHE, else $XDG_CACHE_HOME/asos/references, "
                    "else ~/.cache/asos/references)");
    cmd->add_flag("--no-cache", args->noCache, "Render even when the cache holds the reference (and store it)");
    cmd->add_option("--clock", args->inputs.clock, "Value of `clock` (and `clock_on` 1)");
    cmd->add_option("-D,--define", args->inputs.defines,
                    "NAME=VALUE declared before the scene runs: a number, a vector or a quoted string");
    cmd->add_option("-L,--library-path", args->inputs.includePaths,
                    "Folder searched by #include after the including file's and the scene's");
    cmd->add_flag("--quiet", args->quiet, "No progress, and nothing about the cache");
    cmd->callback([args, &result] { result.exitCode = runReference(*args); });
}

}  // namespace asos::cli
