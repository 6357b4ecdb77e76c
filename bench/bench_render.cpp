// `asos-bench render [SCENE] [-W 640 -H 480] [--threads 1,2] [--repeat 3] [--samples 4]`:
// renders a scene by every method (asos, asos with pattern edges, single,
// grid, jitter, adaptive, am1) with
// each thread count and prints a table of render time (best of --repeat),
// rays (eye and reflected, shadow, all), pyrays, rays per second, and each method's rays
// and time relative to ASOS. Without SCENE it renders examples/default.pov,
// the six primitives on a checkered plane under one point light;
// examples/bench/spheres.pov (1600 small spheres) is the hardest case.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "benchmarks.hpp"

namespace asos::bench {

namespace {

struct BenchArgs {
    std::string scene;  // empty: examples/default.pov
    int width = 640, height = 480;
    std::vector<int> threads{1, 2};
    int repeat = 3;
    int samples = 4;
};

std::string count(std::uint64_t v) {
    // Thousands separated, for reading large counts at a glance.
    const std::string digits = std::to_string(v);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

int runBench(const BenchArgs& args) {
    if (args.repeat < 1 || args.samples < 1 || args.width < 1 || args.height < 1 ||
        std::any_of(args.threads.begin(), args.threads.end(), [](int t) { return t < 1; })) {
        std::fprintf(stderr, "asos-bench render: error: sizes, --repeat, --samples and --threads must be positive\n");
        return 1;
    }
    lang::InterpreterOptions options;
    options.imageWidth = args.width;
    options.imageHeight = args.height;
    Diagnostics diagnostics;
    const std::string scenePath = args.scene.empty() ? exampleScene("default.pov").string() : args.scene;
    const std::optional<SceneDescription> description = lang::interpretFile(scenePath, options, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
    if (!description) return 1;
    diagnostics.clear();
    if (!checkRenderable(*description, diagnostics)) {
        for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
        return 1;
    }
    const std::unique_ptr<Scene> scene = Scene::build(*description, diagnostics);
    if (!scene) {
        for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
        return 1;
    }

    struct Row {
        std::string method;
        int threads;
        double seconds;
        RenderCounters counters;
    };
    std::vector<Row> rows;
    const std::string samples = std::to_string(args.samples);
    struct Method {
        RenderMethod method;
        std::string label;
        bool patternEdges;
    };
    const Method methods[] = {{RenderMethod::Asos, "asos", false},
                              {RenderMethod::Asos, "asos+patterns", true},
                              {RenderMethod::Single, "single", false},
                              {RenderMethod::Grid, "grid " + samples + "x" + samples, false},
                              {RenderMethod::Jitter, "jitter " + samples + "x" + samples, false},
                              {RenderMethod::Adaptive, "adaptive", false},
                              {RenderMethod::Am1, "am1", false}};
    for (int threads : args.threads)
        for (const auto& [method, label, patternEdges] : methods) {
            RenderSettings s;
            s.method = method;
            s.patternEdges = patternEdges;
            s.width = args.width;
            s.height = args.height;
            s.samples = args.samples;
            s.threads = threads;
            Row row{label, threads, 0.0, {}};
            for (int i = 0; i < args.repeat; ++i) {
                const RenderOutput out = render(*scene, s);
                if (i == 0 || out.stats.times.renderSeconds < row.seconds)
                    row.seconds = out.stats.times.renderSeconds;
                row.counters = out.stats.counters;
            }
            rows.push_back(row);
        }

    std::printf("%s, %d x %d, best of %d; ratios against asos at the same thread count\n", scenePath.c_str(),
                args.width, args.height, args.repeat);
    std::printf("%-14s %7s %9s %12s %12s %12s %12s %12s %8s %8s\n", "method", "threads", "time s",
                "eye+refl", "shadow rays", "all rays", "pyrays", "rays/s", "x rays", "x time");
    for (const Row& r : rows) {
        const Row& asos = *std::find_if(rows.begin(), rows.end(), [&](const Row& a) {
            return a.threads == r.threads && a.method == "asos";
        });
        std::uint64_t pyrays = 0;
        for (std::uint64_t n : r.counters.pyraysByLevel) pyrays += n;
        const double all = static_cast<double>(r.counters.allRays());
        std::printf("%-14s %7d %9.3f %12s %12s %12s %12s %12.0f %8.2f %8.2f\n", r.method.c_str(), r.threads,
                    r.seconds, count(r.counters.eyeRays + r.counters.reflectedRays).c_str(),
                    count(r.counters.shadowRays).c_str(), count(r.counters.allRays()).c_str(),
                    pyrays ? count(pyrays).c_str() : "-", r.seconds > 0 ? all / r.seconds : 0.0,
                    all / static_cast<double>(std::max<std::uint64_t>(asos.counters.allRays(), 1)),
                    r.seconds / std::max(asos.seconds, 1e-9));
    }
    return 0;
}

}  // namespace

void addRenderBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Time and rays of every method on a scene (default: the six primitives)");
    cmd->add_option("scene", args->scene,
                    "Scene file (default: examples/default.pov, the six primitives; "
                    "examples/bench/spheres.pov has outlines everywhere)");
    cmd->add_option("-W,--width", args->width, "Image width (default 640)");
    cmd->add_option("-H,--height", args->height, "Image height (default 480)");
    cmd->add_option("--threads", args->threads, "Thread counts to run, e.g. 1,2 (default 1,2)")
        ->delimiter(',');
    cmd->add_option("--repeat", args->repeat, "Renders per entry; the best time counts (default 3)");
    cmd->add_option("--samples", args->samples, "N of the N x N grid and jitter methods (default 4)");
    cmd->callback([args, &result] { result.exitCode = runBench(*args); });
}

}  // namespace asos::bench
