// `asos bench lights`: ASOS shadows from distributed lights against the
// classic grid of point lights (issue 5's benchmark). The paper's Figure 6
// arrangement (examples/figure6.pov) is rendered under each area light kind
// with the ASOS eye method throughout, so that images differ only by how
// the light is sampled:
//   - a converged reference: the grid at R x R points (R = --reference, 64),
//     jittered (stratified, unbiased), with the rays a whole-light cone test
//     decides skipped (same image, less time);
//   - ASOS shadow beams at each --eps (the light's EPS, MAX = --max), and with
//     --behind also with the beams' apex behind the surface;
//   - the grid at N x N points for each N of --grids (4, 8, 16), as POV-Ray
//     traces them: a shadow ray to every point.
// For each: render time, shadow rays, and the error against the reference
// (RMS and largest, over every channel of every pixel, linear values).
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
#include "cli/commands.hpp"

namespace asos::cli {
namespace {

namespace fs = std::filesystem;

struct BenchLightsArgs {
    std::string scene = "examples/figure6.pov";
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

std::optional<double> parseFraction(const std::string& text) {
    try {
        std::size_t used = 0;
        const auto slash = text.find('/');
        if (slash == std::string::npos) {
            const double v = std::stod(text, &used);
            return used == text.size() ? std::optional<double>(v) : std::nullopt;
        }
        const double a = std::stod(text.substr(0, slash));
        const double b = std::stod(text.substr(slash + 1));
        return b != 0.0 ? std::optional<double>(a / b) : std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

struct Run {
    Image image;
    double seconds = 0.0;
    std::uint64_t shadowRays = 0;
    std::uint64_t coneTests = 0;
};

struct Errors {
    double rms = 0.0, max = 0.0;
};

Errors compare(const Image& a, const Image& b) {
    Errors e;
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.at(x, y, c)) - double(b.at(x, y, c));
                sum += d * d;
                e.max = std::max(e.max, std::abs(d));
                ++n;
            }
    e.rms = std::sqrt(sum / double(n));
    return e;
}

std::string count(std::uint64_t n) {
    char text[32];
    if (n >= 10'000'000) std::snprintf(text, sizeof text, "%.0fM", n / 1e6);
    else if (n >= 1'000'000) std::snprintf(text, sizeof text, "%.1fM", n / 1e6);
    else if (n >= 10'000) std::snprintf(text, sizeof text, "%.0fk", n / 1e3);
    else std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(n));
    return text;
}

int runBenchLights(const BenchLightsArgs& args) {
    std::vector<Kind> kinds;
    for (const std::string& name : splitList(args.lights)) {
        const auto k = std::find_if(std::begin(kKinds), std::end(kKinds),
                                    [&](const Kind& kind) { return name == kind.name; });
        if (k == std::end(kKinds)) {
            std::cerr << "asos bench lights: error: --lights takes point, spherical, linear and "
                         "rectangular, not '" << name << "'\n";
            return 1;
        }
        kinds.push_back(*k);
    }
    std::vector<int> grids;
    for (const std::string& g : splitList(args.grids)) {
        const std::optional<double> n = parseFraction(g);
        if (!n || *n < 1 || *n > kMaxLightSamplesPerSide || *n != std::floor(*n)) {
            std::cerr << "asos bench lights: error: --grids takes whole numbers, not '" << g << "'\n";
            return 1;
        }
        grids.push_back(static_cast<int>(*n));
    }
    std::vector<std::pair<std::string, double>> epsList;
    for (const std::string& e : splitList(args.eps)) {
        const std::optional<double> v = parseFraction(e);
        if (!v || !(*v >= 0.0)) {
            std::cerr << "asos bench lights: error: --eps takes numbers or fractions, not '" << e << "'\n";
            return 1;
        }
        epsList.emplace_back(e, *v);
    }
    if (!fs::exists(args.scene)) {
        std::cerr << "asos bench lights: error: no scene '" << args.scene
                  << "' (run from the repository root, or give --scene)\n";
        return 1;
    }
    if (!args.cache.empty()) fs::create_directories(args.cache);

    auto load = [&](const Kind& kind, bool jitter) -> std::optional<SceneDescription> {
        lang::InterpreterOptions options;
        options.imageWidth = args.width;
        options.imageHeight = args.height;
        options.defines.push_back({"Light", std::to_string(kind.light)});
        Diagnostics diagnostics;
        std::optional<SceneDescription> d = lang::interpretFile(args.scene, options, diagnostics);
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
            std::optional<RenderOutput> out = asos::render(d, s, diagnostics);
            for (const Diagnostic& diag : diagnostics.all()) std::cerr << formatDiagnostic(diag);
            if (!out) return std::nullopt;
            if (best && best->seconds <= out->stats.times.renderSeconds) continue;
            best = Run{std::move(out->color), out->stats.times.renderSeconds, out->stats.counters.shadowRays,
                       out->stats.counters.coneTests};
        }
        return best;
    };

    std::printf("asos bench lights: %s at %dx%d, %d threads, ASOS eye method; error against the grid "
                "at %dx%d jittered points (linear RGB)\n\n",
                args.scene.c_str(), args.width, args.height, args.threads, args.reference, args.reference);
    std::printf("%-12s %-30s %9s %12s %11s %10s %10s\n", "light", "shadows", "time (s)", "shadow rays",
                "cone tests", "RMS error", "max error");
    for (const Kind& kind : kinds) {
        // The reference, from the cache when it is there.
        Image reference;
        const fs::path cached = args.cache.empty()
                                    ? fs::path()
                                    : fs::path(args.cache) / (std::string("reference_") + kind.name + "_" +
                                                             std::to_string(args.width) + "x" +
                                                             std::to_string(args.height) + "_" +
                                                             std::to_string(args.reference) + ".exr");
        if (!cached.empty() && fs::exists(cached)) {
            ReadResult r = readImage(cached);
            if (r.ok()) reference = std::move(r.image);
        }
        if (reference.width() == 0) {
            const std::optional<SceneDescription> d = load(kind, true);
            if (!d) return 1;
            RenderSettings s;
            s.lightMethod = LightMethod::Grid;
            s.lightSamples = args.reference;
            s.gridLightCulling = true;
            const std::optional<Run> run = render(*d, s, 1);
            if (!run) return 1;
            reference = run->image;
            std::printf("%-12s %-30s %9.2f %12s %11s %10s %10s\n", kind.name,
                        ("reference " + std::to_string(args.reference) + "x" + std::to_string(args.reference) +
                         " jittered")
                            .c_str(),
                        run->seconds, count(run->shadowRays).c_str(), count(run->coneTests).c_str(), "-", "-");
            if (!cached.empty()) (void)writeImage(reference, cached);
        }
        const std::optional<SceneDescription> d = load(kind, false);
        if (!d) return 1;
        auto row = [&](const std::string& what, const SceneDescription& scene, const RenderSettings& s) {
            const std::optional<Run> run = render(scene, s, std::max(args.passes, 1));
            if (!run) return false;
            const Errors e = compare(run->image, reference);
            std::printf("%-12s %-30s %9.2f %12s %11s %10.5f %10.4f\n", kind.name, what.c_str(), run->seconds,
                        count(run->shadowRays).c_str(), count(run->coneTests).c_str(), e.rms, e.max);
            std::fflush(stdout);
            return true;
        };
        for (const auto& [text, eps] : epsList) {
            // The light's own settings, as its asos block would give them.
            SceneDescription tuned = *d;
            for (Light& l : tuned.lights) {
                l.asos.eps = eps;
                l.asos.maxLevel = args.maxLevel;
            }
            for (int apex = 0; apex < (args.behind ? 2 : 1); ++apex) {
                RenderSettings s;
                s.lightMethod = LightMethod::Asos;
                s.shadowApex = apex ? ShadowApex::Behind : ShadowApex::Surface;
                if (!row("asos eps " + text + " max " + std::to_string(args.maxLevel) + (apex ? " behind" : ""),
                         tuned, s))
                    return 1;
            }
        }
        for (int n : grids) {
            RenderSettings s;
            s.lightMethod = LightMethod::Grid;
            s.lightSamples = n;
            if (!row("grid " + std::to_string(n) + "x" + std::to_string(n), *d, s)) return 1;
        }
    }
    return 0;
}

}  // namespace

void addBenchLightsCommand(CLI::App& bench, CommandResult& result) {
    auto args = std::make_shared<BenchLightsArgs>();
    CLI::App* cmd = bench.add_subcommand(
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
    cmd->callback([args, &result] { result.exitCode = runBenchLights(*args); });
}

}  // namespace asos::cli
