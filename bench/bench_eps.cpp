// `asos-bench eps [SCENES...] [-W 160 -H 120] [--max 8] [--eps 16,64,256]`:
// EPS as a promise. For each flat scene (default examples/bench/coverage.pov),
// its exact image (asos/testing/exact_coverage.hpp) and ASOS's at each EPS
// with a MAX large enough, one thread: the share of pixels whose every
// channel is within EPS of the exact one (linear values, the units of
// ASOS's bound), the share within 2 EPS, the worst error in units of EPS,
// the share of pixels whose subdivision reached MAX (the samples AOV's
// "level"), time and rays. Prints a Markdown table (docs/performance.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/testing/exact_coverage.hpp"
#include "bench_tools.hpp"
#include "benchmarks.hpp"

namespace asos::bench {

namespace {

namespace fs = std::filesystem;

struct EpsArgs {
    std::vector<std::string> scenes;  // empty: examples/bench/coverage.pov
    int width = 160, height = 120;
    int maxLevel = 8;
    std::vector<int> eps{16, 64, 256};  // denominators
};

int runEps(const EpsArgs& args) {
    if (args.width < 1 || args.height < 1 || args.maxLevel < 1 || args.eps.empty() ||
        std::any_of(args.eps.begin(), args.eps.end(), [](int e) { return e < 1; })) {
        std::fprintf(stderr, "asos-bench eps: error: sizes, --max and --eps must be positive\n");
        return 2;
    }
    std::vector<std::string> scenes = args.scenes;
    if (scenes.empty()) scenes.push_back(exampleScene(fs::path("bench") / "coverage.pov").string());
    std::printf("| scene | EPS | MAX | within EPS | within 2 EPS | worst / EPS | reached MAX | time s | rays/px |\n"
                "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const std::string& scenePath : scenes) {
        lang::InterpreterOptions options;
        options.imageWidth = args.width;
        options.imageHeight = args.height;
        const std::optional<LoadedScene> loaded = loadScene(scenePath, options);
        if (!loaded) return 1;
        const SceneDescription* description = &loaded->description;
        const std::unique_ptr<Scene>& scene = loaded->scene;
        Image exact;
        try {
            exact = exactCoverageImage(*description, args.width, args.height);
        } catch (const std::invalid_argument& e) {
            std::fprintf(stderr, "asos-bench eps: error: %s is not flat: %s\n", scenePath.c_str(), e.what());
            return 1;
        }
        for (int e : args.eps) {
            RenderSettings settings;
            settings.width = args.width;
            settings.height = args.height;
            settings.threads = 1;
            settings.asos.eps = 1.0 / e;
            settings.asos.maxLevel = args.maxLevel;
            const double start = processCpuSeconds();
            const RenderOutput out = render(*scene, settings);
            const double seconds = processCpuSeconds() - start;
            const int level = out.samples.channelIndex("level");
            std::size_t within = 0, within2 = 0, atMax = 0;
            double worst = 0.0;
            for (int y = 0; y < args.height; ++y)
                for (int x = 0; x < args.width; ++x) {
                    double d = 0.0;
                    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(out.color.at(x, y, c)) - exact.at(x, y, c)));
                    within += d <= 1.0 / e;
                    within2 += d <= 2.0 / e;
                    worst = std::max(worst, d * e);
                    atMax += level >= 0 && out.samples.at(x, y, level) >= float(args.maxLevel);
                }
            const double pixels = double(args.width) * args.height;
            std::printf("| %s | 1/%d | %d | %.3f %% | %.3f %% | %.2f | %.2f %% | %.2f | %.1f |\n",
                        fs::path(scenePath).stem().c_str(), e, args.maxLevel, 100.0 * double(within) / pixels,
                        100.0 * double(within2) / pixels, worst, 100.0 * double(atMax) / pixels, seconds,
                        double(out.stats.counters.allRays()) / pixels);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace

void addEpsBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<EpsArgs>();
    CLI::App* cmd =
        app.add_subcommand("eps", "EPS as a promise: the share of pixels within EPS of the exact image, flat scenes");
    cmd->add_option("scenes", args->scenes, "Flat scene files (default: examples/bench/coverage.pov)");
    cmd->add_option("-W,--width", args->width, "Image width (default 160)");
    cmd->add_option("-H,--height", args->height, "Image height (default 120)");
    cmd->add_option("--max", args->maxLevel, "ASOS's MAX (default 8)");
    cmd->add_option("--eps", args->eps, "EPS denominators (default 16,64,256)")->delimiter(',');
    cmd->callback([args, &result] { result.exitCode = runEps(*args); });
}

}  // namespace asos::bench
