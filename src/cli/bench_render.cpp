// `asos bench render [SCENE | --builtin primitives|spheres] [-W 640 -H 480] [--threads 1,2]
//                    [--repeat 3] [--samples 4]`:
// renders a scene by every method (asos, asos with pattern edges, single,
// grid, jitter, adaptive) with
// each thread count and prints a table of render time (best of --repeat),
// rays (eye and reflected, shadow, all), pyrays, rays per second, and each method's rays
// and time relative to ASOS. Without SCENE it renders a built-in scene: the
// issue's six primitives on a checkered plane under one point light (the same
// scene as examples/default.pov), or 1600 small spheres.
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
#include "cli/commands.hpp"

namespace asos::cli {

namespace {

constexpr const char* kBuiltInScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 4.5, -10> look_at <0, 0.9, 1> angle 48 }
light_source { <-8, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
#declare Shiny = finish { phong 0.6 phong_size 60 }
sphere { <-3, 1, 0>, 1 pigment { color rgb <0.85, 0.15, 0.12> } finish { Shiny } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate <0, 30, 0> pigment { color rgb <0.2, 0.45, 0.85> } finish { Shiny } }
cone { <3, 0, 0>, 1, <3, 2.2, 0>, 0 pigment { color rgb <0.95, 0.7, 0.1> } finish { Shiny } }
cylinder { <-3, 0, 3.5>, <-3, 1.6, 3.5>, 0.8 pigment { color rgb <0.2, 0.7, 0.3> } finish { Shiny } }
disc { <0, 1.3, 3.5>, <0, 0.5, -1>, 1.2, 0.45 pigment { color rgb <0.65, 0.3, 0.8> } }
polygon {
  7, <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  scale 1.1 rotate <-20, -15, 0> translate <3, 1.3, 3.5>
  pigment { color rgb <0.1, 0.75, 0.75> }
}
)";

// Many small spheres on a plane: nearly every pixel holds an outline, the
// hardest case for ASOS. Positions and colours come from a fixed sequence.
constexpr const char* kSpheresScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.8> }
camera { location <0, 6, -14> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -10>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.8 } }
#declare N = 40;
#for (I, 0, N - 1)
  #for (J, 0, N - 1)
    #declare U = mod(I * 0.618034 + J * 0.754878, 1);
    #declare V = mod(I * 0.569840 + J * 0.414214, 1);
    #declare R = 0.08 + 0.17 * mod(I * 0.381966 + J * 0.267949, 1);
    sphere {
      <-10 + 20 * (I + U) / N, R + 1.5 * mod(I * 0.2 + J * 0.7, 1), -8 + 20 * (J + V) / N>, R
      pigment { color rgb <0.3 + 0.7 * U, 0.3 + 0.7 * V, 0.3 + 0.7 * mod(U + V, 1)> }
    }
  #end
#end
)";

struct BenchArgs {
    std::string scene;
    std::string builtIn = "primitives";
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
        std::fprintf(stderr, "asos bench render: error: sizes, --repeat, --samples and --threads must be positive\n");
        return 1;
    }
    lang::InterpreterOptions options;
    options.imageWidth = args.width;
    options.imageHeight = args.height;
    Diagnostics diagnostics;
    if (args.builtIn != "primitives" && args.builtIn != "spheres") {
        std::fprintf(stderr, "asos bench render: error: --builtin wants primitives or spheres, not '%s'\n",
                     args.builtIn.c_str());
        return 1;
    }
    const char* builtInText = args.builtIn == "spheres" ? kSpheresScene : kBuiltInScene;
    const std::optional<SceneDescription> description =
        args.scene.empty()
            ? lang::interpretText(builtInText, "<built-in " + args.builtIn + ">", options, diagnostics)
            : lang::interpretFile(args.scene, options, diagnostics);
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
                              {RenderMethod::Adaptive, "adaptive", false}};
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

    const std::string what = !args.scene.empty()          ? args.scene
                             : args.builtIn == "spheres" ? "1600 spheres on a plane (built in)"
                                                         : "six primitives and a point light (built in)";
    std::printf("%s, %d x %d, best of %d; ratios against asos at the same thread count\n", what.c_str(),
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

void addBenchRenderCommand(CLI::App& bench, CommandResult& result) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "render", "Time and rays of every method on a scene (default: the six primitives)");
    cmd->add_option("scene", args->scene, "Scene file (default: a built-in scene, --builtin)");
    cmd->add_option("--builtin", args->builtIn,
                    "primitives (default: the six primitives, as examples/default.pov) or spheres "
                    "(1600 small spheres: outlines everywhere)");
    cmd->add_option("-W,--width", args->width, "Image width (default 640)");
    cmd->add_option("-H,--height", args->height, "Image height (default 480)");
    cmd->add_option("--threads", args->threads, "Thread counts to run, e.g. 1,2 (default 1,2)")
        ->delimiter(',');
    cmd->add_option("--repeat", args->repeat, "Renders per entry; the best time counts (default 3)");
    cmd->add_option("--samples", args->samples, "N of the N x N grid and jitter methods (default 4)");
    cmd->callback([args, &result] { result.exitCode = runBench(*args); });
}

}  // namespace asos::cli
