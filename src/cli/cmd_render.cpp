// asos render SCENE -o OUT.png|.exr|.tif|… [-W 640 -H 480] [--method asos|single|grid|jitter|adaptive|am1]
//   [--eps E|A/B --max M --jitter on|off --highlights on|off --pattern-edges on|off
//    --pattern-filter on|off]
//   [--samples N] [--threshold T --depth D]
//   [--light-method asos|grid] [--light-samples N] [--shadow-apex surface|behind]
//   [--bit-depth 8|16|half|float] [--threads N]
//   [--seed S] [--region x0,y0,x1,y1] [--clock C] [-D NAME=VALUE]... [-L DIR]...
//   [--frames A-B [--subset C-D] [--clock-from F] [--clock-to T]]
//   [--stats] [--stats-json FILE] [--aov samples=FILE] [--max-memory SIZE] [--quiet]
// Parses the scene, renders it (asos/render/renderer.hpp) and writes the
// image through OpenImageIO, by extension, never leaving a half-written file.
// Every option and every output is checked before any work; the outputs are
// put in place all together, only once all are written. An animation
// (--frames) parses, renders and writes each frame in turn, and stops at the
// first that fails, leaving those written. Exit codes: 0, 1 a bad scene, 2 a
// bad command line, 3 a file that cannot be read or written (docs/cli.md has
// the details).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/image/aov.hpp"
#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/scene/asos_settings.hpp"
#include "cli/animation.hpp"
#include "cli/common/arguments.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt_deferral.hpp"
#include "cli/progress_report.hpp"

namespace asos::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    int width = 640, height = 480;
    std::string method = "asos";
    std::optional<std::string> eps;
    std::optional<int> maxLevel;
    std::optional<std::string> jitter;
    std::optional<std::string> highlights;
    std::string patternEdges = "off";
    std::optional<std::string> patternFilter;
    int samples = 4;
    double threshold = 0.3;
    int depth = 2;
    std::optional<std::string> lightMethod;
    std::optional<int> lightSamples;
    std::string shadowApex = "surface";
    std::optional<std::string> bitDepth;
    int threads = 0;
    std::string seed = "0";
    std::optional<std::string> region;
    SceneInputs inputs;
    AnimationArgs animation;
    bool stats = false;
    std::optional<std::string> statsJson;
    std::vector<std::string> aovs;
    bool quiet = false;
};

void fail(const std::string& message) { std::cerr << "asos render: error: " << message << '\n'; }

// What a render of the settings needs at its peak, roughly: the colour and
// samples images of the whole image (3 + 2 floats a pixel) while rendering,
// then, for the pixels written, the samples converted for the file and the
// encoded file in memory, a cropped copy, the heat map (36 bytes). The
// scene itself is not counted.
std::uint64_t estimateMemory(const RenderSettings& settings) {
    const PixelRegion region = settings.region.value_or(PixelRegion::whole(settings.width, settings.height));
    const auto pixels = std::uint64_t(settings.width) * std::uint64_t(settings.height);
    const auto written = std::uint64_t(region.x1 - region.x0) * std::uint64_t(region.y1 - region.y0);
    return 20 * pixels + 36 * written;
}

bool samePath(const std::string& a, const std::string& b) {
    std::error_code ec1, ec2;
    const auto ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ec1);
    const auto cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b), ec2);
    return ec1 || ec2 ? a == b : ca == cb;
}

// The files one render writes: the image, and the samples AOV and the
// statistics where asked for.
struct Outputs {
    std::string image;
    std::optional<std::string> samplesAov;
    std::optional<std::string> statsJson;
};

// What every frame shares, checked before the first.
struct Job {
    std::string scene;
    RenderSettings settings;
    SampleFormat sampleFormat = SampleFormat::Auto;
    PixelRegion written;
    bool stats = false;
};

// Parses the scene with `options`, renders it and writes `outputs`: one
// still, or one frame of an animation. Returns the exit code.
int renderOnce(const Job& job, const lang::InterpreterOptions& options, const Outputs& outputs,
               ProgressReport& progress) {
    // The scene.
    Diagnostics diagnostics;
    const auto parseStart = std::chrono::steady_clock::now();
    std::optional<SceneDescription> scene = lang::interpretFile(job.scene, options, diagnostics);
    const double parseSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - parseStart).count();
    for (const Diagnostic& d : diagnostics.all()) std::cerr << formatDiagnostic(d);
    if (!scene) return kExitBadScene;
    diagnostics.clear();

    // The render.
    RenderSettings settings = job.settings;
    if (progress.wanted()) settings.progress = [&progress](const TileProgress& p) { progress.update(p); };
    std::optional<RenderOutput> out;
    try {
        out = render(*scene, settings, diagnostics);
    } catch (const std::bad_alloc&) {
        throw;  // runProgram's message
    } catch (const std::exception& e) {
        progress.interrupt();
        fail(e.what());
        return kExitBadScene;
    }
    progress.interrupt();
    for (const Diagnostic& d : diagnostics.all()) std::cerr << formatDiagnostic(d);
    if (!out) return kExitBadScene;
    out->stats.times.parseSeconds = parseSeconds;

    // The files: each written whole beside its target first; all put in
    // place only when all are written, so a failed run leaves every old file
    // as it was.
    InterruptDeferral interrupts;
    const PixelRegion& written = job.written;
    const bool cropped = written != PixelRegion::whole(settings.width, settings.height);
    std::vector<StagedFile> staged;
    auto stage = [&](StagedResult r) {
        if (r.file) staged.push_back(std::move(*r.file));
        else fail(r.error);
        return r.file.has_value();
    };
    WriteOptions writeOptions;
    writeOptions.format = job.sampleFormat;
    writeOptions.assumedGamma = scene->globals.assumedGamma;
    if (!stage(stageImage(cropped ? out->color.cropped(written.x0, written.y0, written.x1, written.y1) : out->color,
                          outputs.image, writeOptions)))
        return kExitIoFailure;
    if (outputs.samplesAov &&
        !stage(stageSamplesAov(
            cropped ? out->samples.cropped(written.x0, written.y0, written.x1, written.y1) : out->samples,
            *outputs.samplesAov)))
        return kExitIoFailure;
    if (outputs.statsJson) {
        const std::string json = statsToJson(out->stats);
        const auto* bytes = reinterpret_cast<const unsigned char*>(json.data());
        if (!stage(StagedFile::fromBytes(*outputs.statsJson, {bytes, json.size()}))) return kExitIoFailure;
    }
    if (interrupts.caught()) {
        staged.clear();
        fail("interrupted while writing: no file written");
        interrupts.endByCaughtSignal();
    }
    for (std::size_t i = 0; i < staged.size(); ++i)
        if (std::string e = staged[i].commit(); !e.empty()) {
            std::string done;
            for (std::size_t k = 0; k < i; ++k) done += (done.empty() ? "" : ", ") + staged[k].target().string();
            fail(e + (done.empty() ? "" : " (already written: " + done + ")"));
            return kExitIoFailure;
        }
    if (job.stats) std::cout << formatStatsTable(out->stats);
    return kExitSuccess;
}

Outputs frameOutputs(const Outputs& patterns, const Animation& animation, int frame) {
    auto name = [&](const std::optional<std::string>& p) {
        return p ? std::optional(animation.fileName(*p, frame)) : std::nullopt;
    };
    return {animation.fileName(patterns.image, frame), name(patterns.samplesAov), name(patterns.statsJson)};
}

// The frames one after another, each parsed anew with its clock; the first
// that fails ends the run, naming it and the frames already written.
int renderFrames(const Job& job, const Animation& animation, const lang::InterpreterOptions& options,
                 const Outputs& patterns, ProgressReport& progress) {
    const int count = animation.frameCount();
    for (int frame = animation.firstFrame(); frame <= animation.lastFrame(); ++frame) {
        const int index = frame - animation.firstFrame() + 1;
        const Outputs outputs = frameOutputs(patterns, animation, frame);
        char clock[32];
        std::snprintf(clock, sizeof clock, "%.6g", animation.clockAt(frame));
        progress.start("frame " + std::to_string(frame) + " (" + std::to_string(index) + " of " +
                       std::to_string(count) + ") ");
        if (job.stats) std::cout << "Frame " << frame << " (clock " << clock << ")\n";
        const int code = renderOnce(job, animation.frameOptions(options, frame), outputs, progress);
        if (code != kExitSuccess) {
            fail("frame " + std::to_string(frame) + " (clock " + clock + ") failed; " +
                 (index == 1 ? std::string("no frame written")
                             : "frames " + std::to_string(animation.firstFrame()) + "-" + std::to_string(frame - 1) +
                                   " are written"));
            return code;
        }
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.2f", progress.seconds());
        progress.frameWritten("Rendered frame " + std::to_string(frame) + " (" + std::to_string(index) + " of " +
                              std::to_string(count) + ", clock " + clock + ") to " + outputs.image + " in " +
                              seconds + " s");
    }
    return kExitSuccess;
}

int runRender(const RenderArgs& args) {
    // Options first: nothing is parsed or rendered before they all make sense.
    RenderSettings settings;
    std::vector<std::string> problems;
    const std::optional<RenderMethod> method = parseMethod(args.method);
    if (!method)
        problems.push_back("--method must be asos, single, grid, jitter, adaptive or am1, not '" +
                           args.method + "'");
    else
        settings.method = *method;
    settings.width = args.width;
    settings.height = args.height;
    if (args.eps) {
        const std::optional<double> eps = parseFraction(*args.eps);
        if (!eps) problems.push_back("--eps wants a number or a fraction A/B, not '" + *args.eps + "'");
        else if (std::string e = epsProblem(*eps); !e.empty()) problems.push_back("--eps: " + e);
        else settings.asos.eps = *eps;
    }
    settings.asos.maxLevel = args.maxLevel;
    if (args.jitter) {
        if (*args.jitter == "on") settings.asos.jitter = true;
        else if (*args.jitter == "off") settings.asos.jitter = false;
        else problems.push_back("--jitter wants on or off, not '" + *args.jitter + "'");
        settings.adaptive.jitter = settings.asos.jitter.value_or(false);
    }
    if (args.highlights) {
        if (*args.highlights == "on" || *args.highlights == "off")
            settings.asos.highlights = *args.highlights == "on";
        else
            problems.push_back("--highlights wants on or off, not '" + *args.highlights + "'");
    }
    if (args.patternEdges == "on" || args.patternEdges == "off")
        settings.patternEdges = args.patternEdges == "on";
    else
        problems.push_back("--pattern-edges wants on or off, not '" + args.patternEdges + "'");
    if (args.patternFilter) {
        if (*args.patternFilter == "on" || *args.patternFilter == "off")
            settings.patternFilter = *args.patternFilter == "on";
        else
            problems.push_back("--pattern-filter wants on or off, not '" + *args.patternFilter + "'");
    }
    settings.samples = args.samples;
    settings.adaptive.threshold = args.threshold;
    settings.adaptive.depth = args.depth;
    if (args.lightMethod) {
        settings.lightMethod = parseLightMethod(*args.lightMethod);
        if (!settings.lightMethod)
            problems.push_back("--light-method must be asos or grid, not '" + *args.lightMethod + "'");
    }
    settings.lightSamples = args.lightSamples;
    if (const std::optional<ShadowApex> apex = parseShadowApex(args.shadowApex))
        settings.shadowApex = *apex;
    else
        problems.push_back("--shadow-apex must be surface or behind, not '" + args.shadowApex + "'");
    settings.threads = args.threads;
    if (const std::optional<std::uint64_t> seed = parseUnsigned(args.seed))
        settings.seed = *seed;
    else
        problems.push_back("--seed wants a whole number from 0 to 18446744073709551615, not '" + args.seed + "'");
    if (std::string e = checkRenderSettings(settings); !e.empty()) problems.push_back(e);
    const bool sized = settings.width >= 1 && settings.height >= 1;
    if (args.region && sized) {
        const RegionParse r = parseRegion(*args.region, settings.width, settings.height);
        if (!r.region) problems.push_back("--region: " + r.error);
        else settings.region = r.region;
    }
    // A --max-memory that is no size is reported with the scene's inputs.
    const std::optional<std::uint64_t> maxMemory = parseByteSize(args.inputs.maxMemory);
    if (maxMemory && sized && settings.width <= 65536 && settings.height <= 65536) {
        const std::uint64_t needed = estimateMemory(settings);
        if (needed > *maxMemory)
            problems.push_back("a " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                               " render needs about " + formatByteSize(needed) + ", more than --max-memory (" +
                               formatByteSize(*maxMemory) + "); give a larger --max-memory to render it");
    }
    SampleFormat sampleFormat = SampleFormat::Auto;
    if (args.bitDepth) {
        if (*args.bitDepth == "8") sampleFormat = SampleFormat::UInt8;
        else if (*args.bitDepth == "16") sampleFormat = SampleFormat::UInt16;
        else if (*args.bitDepth == "half") sampleFormat = SampleFormat::Half;
        else if (*args.bitDepth == "float") sampleFormat = SampleFormat::Float;
        else problems.push_back("--bit-depth must be 8, 16, half or float, not '" + *args.bitDepth + "'");
    }
    // The animation: its frames, and the names its outputs take for each.
    Animation::Parse animation = Animation::parse(args.animation);
    problems.insert(problems.end(), animation.problems.begin(), animation.problems.end());
    if (args.animation.frames && args.inputs.clock)
        problems.push_back("--clock and --frames together: --frames gives each frame its clock "
                           "(--clock-from, --clock-to)");
    // The outputs: each folder takes files, each format has a writer that
    // can hold the samples of an image of this size. An animation's are
    // checked by its first frame's names.
    Outputs patterns{args.output, std::nullopt, args.statsJson};
    for (const std::string& aov : args.aovs) {
        const auto eq = aov.find('=');
        if (eq == std::string::npos || aov.substr(0, eq) != "samples" || eq + 1 == aov.size())
            problems.push_back("--aov wants samples=FILE, not '" + aov + "'");
        else
            patterns.samplesAov = aov.substr(eq + 1);
    }
    Outputs first = patterns;
    if (animation.animation) {
        const Animation& a = *animation.animation;
        for (const auto& [option, pattern] : {std::pair{"-o", std::optional(patterns.image)},
                                              std::pair{"--aov", patterns.samplesAov},
                                              std::pair{"--stats-json", patterns.statsJson}})
            if (pattern)
                if (std::string e = frameNameProblem(option, *pattern, a); !e.empty()) problems.push_back(e);
        first = frameOutputs(patterns, a, a.firstFrame());
    }
    const PixelRegion written = settings.region.value_or(
        PixelRegion::whole(std::max(settings.width, 1), std::max(settings.height, 1)));
    const int writtenWidth = written.x1 - written.x0, writtenHeight = written.y1 - written.y0;
    if (IoStatus s = checkOutputPath(first.image, sampleFormat, writtenWidth, writtenHeight); !s.ok())
        problems.push_back("-o: " + s.error);
    if (first.samplesAov)
        if (IoStatus s = checkOutputPath(*first.samplesAov, SampleFormat::Auto, writtenWidth, writtenHeight); !s.ok())
            problems.push_back("--aov: " + s.error);
    if (first.statsJson)
        if (std::string e = checkWritable(*first.statsJson); !e.empty()) problems.push_back("--stats-json: " + e);
    {
        std::vector<std::string> outputs{first.image};
        if (first.samplesAov) outputs.push_back(*first.samplesAov);
        if (first.statsJson) outputs.push_back(*first.statsJson);
        for (std::size_t i = 0; i < outputs.size(); ++i)
            for (std::size_t k = i + 1; k < outputs.size(); ++k)
                if (samePath(outputs[i], outputs[k]))
                    problems.push_back("'" + outputs[k] + "' is named for two outputs (-o, --aov, --stats-json)");
    }
    CheckedSceneInputs inputs = checkSceneInputs(args.inputs, "asos render");
    lang::InterpreterOptions& options = inputs.options;
    options.imageWidth = settings.width;
    options.imageHeight = settings.height;
    if (const int code = reportBeforeScene("asos render", problems, inputs, args.scene); code != kExitSuccess)
        return code;

    const Job job{args.scene, settings, sampleFormat, written, args.stats};
    ProgressReport progress(ProgressReport::modeForStderr(args.quiet), animation.animation.has_value());
    if (animation.animation) return renderFrames(job, *animation.animation, options, patterns, progress);
    progress.start({});
    return renderOnce(job, options, patterns, progress);
}

}  // namespace

void addRenderCommand(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image file");
    cmd->add_option("scene", args->scene, "Scene file (.pov)")->required();
    addLimitOptions(*cmd, args->inputs);
    cmd->add_option("-o,--output", args->output,
                    "Image file; the format follows the extension (.png, .exr, .tif, ...)")
        ->required();
    cmd->add_option("-W,--width", args->width, "Image width in pixels (default 640)");
    cmd->add_option("-H,--height", args->height, "Image height in pixels (default 480)");
    cmd->add_option("--method", args->method,
                    "asos (default), single, grid, jitter, adaptive (POV-Ray's +AM2) or am1 (+AM1)");
    cmd->add_option("--eps", args->eps, "ASOS: EPS, a number or a fraction such as 1/64 (default 1/64)");
    cmd->add_option("--max", args->maxLevel, "ASOS: MAX, the deepest subdivision level (default 4)");
    cmd->add_option("--jitter", args->jitter,
                    "on|off: ASOS jitters its MAX-rays, adaptive and am1 their sub-samples (default off)");
    cmd->add_option("--highlights", args->highlights,
                    "on|off: ASOS subdivides pixels one object covers where its phong or specular "
                    "highlight may vary by more than EPS (default on)");
    cmd->add_option("--pattern-edges", args->patternEdges,
                    "on|off: ASOS also subdivides where a pigment pattern's edge crosses a pixel (default off)");
    cmd->add_option("--pattern-filter", args->patternFilter,
                    "on|off: ASOS shades a pattern averaged over each ray's footprint (default on "
                    "under --method asos unless --pattern-edges is on)");
    cmd->add_option("--samples", args->samples, "grid and jitter: N x N rays per pixel (default 4)");
    cmd->add_option("--threshold", args->threshold,
                    "adaptive and am1: colour difference that subdivides or supersamples (default 0.3)");
    cmd->add_option("--depth", args->depth,
                    "adaptive: subdivision levels; am1: (D+1) x (D+1) sub-samples "
                    "(default 2, POV-Ray's +R3)");
    cmd->add_option("--light-method", args->lightMethod,
                    "Area lights: asos (shadow beams) or grid (point lights); default asos with "
                    "--method asos, grid with the classic methods");
    cmd->add_option("--light-samples", args->lightSamples,
                    "Area lights: N x N grid points for every light (N along a linear light)");
    cmd->add_option("--shadow-apex", args->shadowApex,
                    "ASOS area light shadows start at the surface (default) or behind it");
    cmd->add_option("--bit-depth", args->bitDepth,
                    "8, 16 (sRGB-encoded integers, as POV-Ray's +FN8/+FN16), half or float (linear); "
                    "default 8 for integer formats, float for .exr");
    cmd->add_option("--threads", args->threads, "Worker threads, at most 1024 (default 0: all cores)");
    cmd->add_option("--seed", args->seed, "Seed of the random numbers, 0 to 2^64-1 (default 0)");
    cmd->add_option("--region", args->region,
                    "x0,y0,x1,y1: render columns x0..x1-1 and rows y0..y1-1 only, and write that part");
    cmd->add_option("--clock", args->inputs.clock, "Value of `clock` (and `clock_on` 1)");
    cmd->add_option("--frames", args->animation.frames,
                    "A-B: render frames A to B, an animation (POV-Ray's +KFI A +KFF B); the outputs' "
                    "run of '#' takes the frame number");
    cmd->add_option("--subset", args->animation.subset,
                    "C-D or N: render only these frames of --frames, with the whole range's clock "
                    "(POV-Ray's +SF/+EF)");
    cmd->add_option("--clock-from", args->animation.clockFrom,
                    "The clock of the first frame of --frames (default 0, POV-Ray's +KI)");
    cmd->add_option("--clock-to", args->animation.clockTo,
                    "The clock of the last frame of --frames (default 1, POV-Ray's +KF)");
    cmd->add_option("-D,--define", args->inputs.defines,
                    "NAME=VALUE declared before the scene runs: a number, a vector or a quoted string");
    cmd->add_option("-L,--library-path", args->inputs.includePaths,
                    "Folder searched by #include after the including file's and the scene's, before POV-Ray's own");
    cmd->add_flag("--stats", args->stats, "Print the render statistics");
    cmd->add_option("--stats-json", args->statsJson, "Write the render statistics as JSON");
    cmd->add_option("--aov", args->aovs,
                    "samples=FILE: rays per pixel and deepest level (.exr channels, else a heat map)");
    cmd->add_flag("--quiet", args->quiet,
                  "No progress (a bar on a terminal, else a line per tenth of a still or per frame)");
    cmd->callback([args, &result] { result.exitCode = runRender(*args); });
}

}  // namespace asos::cli
