// `asos-bench lights`: ASOS shadows from distributed lights against the
// classic grid of point lights (issue 5's benchmark). The paper's Figure 6
// arrangement (examples/figure6.pov) is rendered under each area light kind
// with the ASOS eye method throughout, so that images differ only by how
// the light is sampled:
//   - a converged reference: the grid at R x R points (R = --reference, 64;
//     R^2, at most 1024, along a linear light), jittered (stratified,
//     unbiased), with the rays that a whole-light cone test decides skipped
//     (same image, less time);
//   - ASOS shadow beams at each --eps (the light's EPS, MAX = --max, twice
//     that for a linear light, which is halved where the others are
//     quartered), and with --behind also with the beams' apex behind the
//     surface;
//   - the grid at N x N points for each N of --grids (4, 8, 16; N^2 points
//     along a linear light, the same number of rays), as POV-Ray traces
//     them: a shadow ray to every point.
// For each: render time, shadow rays, and the error against the reference
// (RMS and largest, over every channel of every pixel, linear values). With
// --behind, also against a reference converged in the image as well (N x N
// jittered eye rays per pixel, --eye-samples), which the shadow apex behind
// the surface (antialiasing shadows across the eye pyray's footprint) aims
// at, over the pixels that one surface covers (the ASOS eye resolved them
// at level 0), where no edge of an object confounds the shadow's error.
// References are kept in --cache (when given) and reused; each row shows the
// best time of --passes renders.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/testing/culled_grid_light.hpp"
#include "cli/common/arguments.hpp"
#include "benchmarks.hpp"

namespace asos::bench {
namespace {

namespace fs = std::filesystem;

struct BenchLightsArgs {
    std::string scene;  // empty: examples/figure6.pov
    int width = 640, height = 480;
    int threads = 2;
    std::string lights = "spherical,linear,rectangular";
    std::string grids = "4,8,16";
    std::string eps = "1/16,1/64";
    int maxLevel = 4;
    int reference = 64;
    bool behind = false;
    std::string cache;
    int passes = 1;
    int eyeSamples = 4;
};

struct Kind {
    const char* name;
    int light;  // the scene's Light switch
};
constexpr Kind kKinds[] = {{"point", 0}, {"spherical", 1}, {"linear", 2}, {"rectangular", 3}};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

struct Run {
    Image image;
    Image samples;  // channels "rays" and "level" per pixel
    double seconds = 0.0;
    std::uint64_t shadowRays = 0;
    std::uint64_t coneTests = 0;
};

struct Errors {
    double rms = 0.0, max = 0.0;
};

// Over every pixel, or with `levels` (a samples AOV) only over the pixels
// whose eye pyray was resolved at level 0 (one surface covers the pixel: its
// error is the shading's, not an edge's).
Errors compare(const Image& a, const Image& b, const Image* levels = nullptr) {
    Errors e;
    double sum = 0.0;
    std::size_t n = 0;
    const int level = levels ? levels->channelIndex("level") : -1;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                if (levels && (level < 0 || levels->at(x, y, level) != 0.0f)) continue;
                const double d = double(a.at(x, y, c)) - double(b.at(x, y, c));
                sum += d * d;
                e.max = std::max(e.max, std::abs(d));
                ++n;
            }
    e.rms = n > 0 ? std::sqrt(sum / double(n)) : 0.0;
    return e;
}

std::string count(std::uint64_t n) {
    char text[32];
    const double v = static_cast<double>(n);
    if (n >= 10'000'000) std::snprintf(text, sizeof text, "%.0fM", v / 1e6);
    else if (n >= 1'000'000) std::snprintf(text, sizeof text, "%.1fM", v / 1e6);
    else if (n >= 10'000) std::snprintf(text, sizeof text, "%.0fk", v / 1e3);
    else std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(n));
    return text;
}

int runBenchLights(const BenchLightsArgs& args) {
    std::vector<Kind> kinds;
    for (const std::string& name : splitList(args.lights)) {
        const auto k = std::find_if(std::begin(kKinds), std::end(kKinds),
                                    [&](const Kind& kind) { return name == kind.name; });
        if (k == std::end(kKinds)) {
            std::cerr << "asos-bench lights: error: --lights takes point, spherical, linear and "
                         "rectangular, not '" << name << "'\n";
            return 1;
        }
        kinds.push_back(*k);
    }
    std::vector<int> grids;
    for (const std::string& g : splitList(args.grids)) {
        const std::optional<double> n = cli::parseNumber(g);
        if (!n || *n < 1 || *n > kMaxLightSamplesPerSide || *n != std::floor(*n)) {
            std::cerr << "asos-bench lights: error: --grids takes whole numbers, not '" << g << "'\n";
            return 1;
        }
        grids.push_back(static_cast<int>(*n));
    }
    std::vector<std::pair<std::string, double>> epsList;
    for (const std::string& e : splitList(args.eps)) {
        const std::optional<double> v = cli::parseFraction(e);
        if (!v || !(*v >= 0.0)) {
            std::cerr << "asos-bench lights: error: --eps takes numbers or fractions, not '" << e << "'\n";
            return 1;
        }
        epsList.emplace_back(e, *v);
    }
    const std::string scenePath = args.scene.empty() ? exampleScene("figure6.pov").string() : args.scene;
    if (!fs::exists(scenePath)) {
        std::cerr << "asos-bench lights: error: no scene '" << scenePath << "'\n";
        return 1;
    }
    if (!args.cache.empty()) fs::create_directories(args.cache);

    auto load = [&](const Kind& kind, bool jitter) -> std::optional<SceneDescription> {
        lang::InterpreterOptions options;
        options.imageWidth = args.width;
        options.imageHeight = args.height;
        options.defines.push_back({"Light", std::to_string(kind.light)});
        Diagnostics diagnostics;
        std::optional<SceneDescription> d = lang::interpretFile(scenePath, options, diagnostics);
        for (const Diagnostic& diag : diagnostics.all()) std::cerr << formatDiagnostic(diag);
        if (d && jitter)
            for (Light& l : d->lights)
                if (l.area) l.area->jitter = true;
        return d;
    };
    // The best time of --passes renders (the machine may be shared).
    auto render = [&](const SceneDescription& d, RenderSettings s, int passes) -> std::optional<Run> {
        s.width = args.width;
        s.height = args.height;
        s.threads = args.threads;
        std::optional<Run> best;
        for (int pass = 0; pass < passes; ++pass) {
            Diagnostics diagnostics;
            std::optional<RenderOutput> out;
            try {
                out = asos::render(d, s, diagnostics);
            } catch (const std::exception& e) {
                std::cerr << "asos-bench lights: error: " << e.what() << '\n';
                return std::nullopt;
            }
            for (const Diagnostic& diag : diagnostics.all()) std::cerr << formatDiagnostic(diag);
            if (!out) return std::nullopt;
            if (best && best->seconds <= out->stats.times.renderSeconds) continue;
            best = Run{std::move(out->color), std::move(out->samples), out->stats.times.renderSeconds,
                       out->stats.counters.shadowRays, out->stats.counters.coneTests};
        }
        return best;
    };

    // A reference image, from the cache when it is there: the grid at R x R
    // jittered points (R^2, at most 1024, along a linear light), seen by the ASOS eye
    // method (eyeSamples 0) or by eyeSamples x eyeSamples jittered eye rays
    // per pixel (converged in the image as well).
    // Along a linear light, as many points as the others' R x R, up to the
    // largest count.
    const int linearReference = std::min(args.reference * args.reference, kMaxLightSamplesPerSide);
    auto referenceFor = [&](const Kind& kind, int eyeSamples) -> std::optional<Image> {
        const bool linear = kind.light == 2;
        const std::string name = std::string("reference_") + kind.name + "_" + std::to_string(args.width) + "x" +
                                 std::to_string(args.height) + "_" + std::to_string(args.reference) +
                                 (eyeSamples > 0 ? "_eye" + std::to_string(eyeSamples) : "") + ".exr";
        const fs::path cached = args.cache.empty() ? fs::path() : fs::path(args.cache) / name;
        if (!cached.empty() && fs::exists(cached)) {
            ReadResult r = readImage(cached);
            if (r.ok()) return std::move(r.image);
        }
        const std::optional<SceneDescription> d = load(kind, true);
        if (!d) return std::nullopt;
        RenderSettings s;
        s.lightMethod = LightMethod::Grid;
        s.lightSamples = linear ? linearReference : args.reference;
        s.areaLightSampler = culledGridAreaLightSamples;
        if (eyeSamples > 0) {
            s.method = RenderMethod::Jitter;
            s.samples = eyeSamples;
        }
        const std::optional<Run> run = render(*d, s, 1);
        if (!run) return std::nullopt;
        const std::string what = "reference " + std::to_string(args.reference) + "x" +
                                 std::to_string(args.reference) + " jittered" +
                                 (eyeSamples > 0 ? ", eye " + std::to_string(eyeSamples) + "x" +
                                                       std::to_string(eyeSamples)
                                                 : "");
        std::printf("%-12s %-34s %9.2f %12s %11s\n", kind.name, what.c_str(), run->seconds,
                    count(run->shadowRays).c_str(), count(run->coneTests).c_str());
        if (!cached.empty()) (void)writeImage(run->image, cached);
        return run->image;
    };

    std::printf("asos-bench lights: %s at %dx%d, %d threads, ASOS eye method; error against the grid at "
                "%dx%d jittered points (%d along a linear light), linear RGB",
                scenePath.c_str(), args.width, args.height, args.threads, args.reference, args.reference,
                linearReference);
    if (args.behind)
        std::printf("; '*': against the same seen by %dx%d jittered eye rays per pixel, over the pixels "
                    "one surface covers (eye pyray resolved at level 0)",
                    args.eyeSamples, args.eyeSamples);
    std::printf("\n\n%-12s %-34s %9s %12s %11s %10s %10s", "light", "shadows", "time (s)", "shadow rays",
                "cone tests", "RMS error", "max error");
    if (args.behind) std::printf(" %10s %10s", "RMS*", "max*");
    std::printf("\n");
    for (const Kind& kind : kinds) {
        const bool linear = kind.light == 2;
        const std::optional<Image> reference = referenceFor(kind, 0);
        if (!reference) return 1;
        std::optional<Image> converged;
        if (args.behind) {
            converged = referenceFor(kind, args.eyeSamples);
            if (!converged) return 1;
        }
        const std::optional<SceneDescription> d = load(kind, false);
        if (!d) return 1;
        auto row = [&](const std::string& what, const SceneDescription& scene, const RenderSettings& s) {
            const std::optional<Run> run = render(scene, s, std::max(args.passes, 1));
            if (!run) return false;
            const Errors e = compare(run->image, *reference);
            std::printf("%-12s %-34s %9.2f %12s %11s %10.6f %10.4f", kind.name, what.c_str(), run->seconds,
                        count(run->shadowRays).c_str(), count(run->coneTests).c_str(), e.rms, e.max);
            if (converged) {
                const Errors c = compare(run->image, *converged, &run->samples);
                std::printf(" %10.6f %10.4f", c.rms, c.max);
            }
            std::printf("\n");
            std::fflush(stdout);
            return true;
        };
        // A linear light is halved at each level where the others are
        // quartered: twice the levels reach the same resolution.
        const int maxLevel = linear ? 2 * args.maxLevel : args.maxLevel;
        for (const auto& [text, eps] : epsList) {
            // The light's own settings, as its asos block would give them.
            SceneDescription tuned = *d;
            for (Light& l : tuned.lights) {
                l.asos.eps = eps;
                l.asos.maxLevel = maxLevel;
            }
            for (int apex = 0; apex < (args.behind ? 2 : 1); ++apex) {
                RenderSettings s;
                s.lightMethod = LightMethod::Asos;
                s.shadowApex = apex ? ShadowApex::Behind : ShadowApex::Surface;
                if (!row("asos eps " + text + " max " + std::to_string(maxLevel) + (apex ? " behind" : ""),
                         tuned, s))
                    return 1;
            }
        }
        for (int n : grids) {
            RenderSettings s;
            s.lightMethod = LightMethod::Grid;
            s.lightSamples = linear ? std::min(n * n, kMaxLightSamplesPerSide) : n;
            const std::string what = linear ? "grid " + std::to_string(*s.lightSamples) + " points"
                                            : "grid " + std::to_string(n) + "x" + std::to_string(n);
            if (!row(what, *d, s)) return 1;
        }
    }
    return 0;
}

}  // namespace

void addLightsBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<BenchLightsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "lights", "Area light shadows: ASOS beams against the grid of point lights (time, rays, error)");
    cmd->add_option("--scene", args->scene, "Scene with a Light switch (default examples/figure6.pov)");
    cmd->add_option("-W,--width", args->width, "Image width (default 640)");
    cmd->add_option("-H,--height", args->height, "Image height (default 480)");
    cmd->add_option("--threads", args->threads, "Worker threads (default 2)");
    cmd->add_option("--lights", args->lights, "Light kinds: point, spherical, linear, rectangular");
    cmd->add_option("--grids", args->grids, "Grid sizes N for N x N points (default 4,8,16)");
    cmd->add_option("--eps", args->eps, "The lights' EPS for ASOS rows (default 1/16,1/64)");
    cmd->add_option("--max", args->maxLevel, "The lights' MAX for ASOS rows (default 4)");
    cmd->add_option("--reference", args->reference, "Reference grid size, jittered (default 64)");
    cmd->add_flag("--behind", args->behind, "Also ASOS with the shadow apex behind the surface");
    cmd->add_option("--cache", args->cache, "Folder keeping the reference images between runs");
    cmd->add_option("--passes", args->passes, "Renders per row; the best time is shown (default 1)");
    cmd->add_option("--eye-samples", args->eyeSamples,
                    "With --behind: N x N jittered eye rays per pixel for the second reference (default 4)");
    cmd->callback([args, &result] { result.exitCode = runBenchLights(*args); });
}

}  // namespace asos::bench
