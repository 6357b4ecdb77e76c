// `asos-bench stability [SCENE] -o DIR [-W 160 -H 120] [--frames 48] [--quick]`:
// flicker. The scene (default examples/bench/flicker.pov) holds one small
// object in the image's top half and one in its bottom half, moving slowly
// over the animation (`clock` 0 to 1 over the frames). For each method and
// setting, one thread, every frame is rendered and each half's sum of
// linear values taken: the object's total intensity in that frame. Its
// flicker is the standard deviation of the sums over their mean, across the
// frames; the cost is the mean CPU time and rays of a frame. Writes
// DIR/stability.csv (one row per setting), DIR/summary.md (the table, and
// ASOS at EPS 1/256 against image-space adaptive at the nearest cost) and
// DIR/stability.dat and .gp, and with `gnuplot` on the PATH
// DIR/stability.png and .svg: flicker against time per frame, log-log, one
// curve per method, a chart per object. docs/performance.md shows them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/testing/csv_table.hpp"
#include "bench_tools.hpp"
#include "benchmarks.hpp"

namespace asos::bench {

namespace {

namespace fs = std::filesystem;

struct StabilityArgs {
    std::string scene;  // empty: examples/bench/flicker.pov
    std::string out;
    int width = 160, height = 120;
    int frames = 48;
    bool quick = false;
    bool gnuplot = true;
};

// One setting of one method, and what its frames gave.
struct Setting {
    std::string method, setting;
    RenderSettings settings;
    double seconds = 0.0;      // all frames
    std::uint64_t rays = 0;    // all frames
    std::vector<double> top, bottom;  // per frame, each half's sum of linear values
};

// The sums' standard deviation over their mean (0 for sums all 0).
double flicker(const std::vector<double>& sums) {
    double mean = 0.0;
    for (double s : sums) mean += s;
    mean /= double(sums.size());
    double variance = 0.0;
    for (double s : sums) variance += (s - mean) * (s - mean);
    variance /= double(sums.size());
    return mean > 0.0 ? std::sqrt(variance) / mean : 0.0;
}

double mean(const std::vector<double>& sums) {
    double total = 0.0;
    for (double s : sums) total += s;
    return total / double(sums.size());
}

std::vector<Setting> ladder(bool quick, const RenderSettings& base) {
    std::vector<Setting> out;
    const auto add = [&](RenderMethod method, std::string setting, auto change) {
        Setting s;
        s.method = methodName(method);
        s.setting = std::move(setting);
        s.settings = base;
        s.settings.method = method;
        change(s.settings);
        out.push_back(std::move(s));
    };
    for (int e : quick ? std::vector<int>{16, 256} : std::vector<int>{16, 64, 256})
        for (int m : quick ? std::vector<int>{3} : std::vector<int>{3, 4, 5})
            add(RenderMethod::Asos, "--eps 1/" + std::to_string(e) + " --max " + std::to_string(m),
                [&](RenderSettings& s) {
                    s.asos.eps = 1.0 / e;
                    s.asos.maxLevel = m;
                });
    for (RenderMethod method : {RenderMethod::Grid, RenderMethod::Jitter})
        for (int n : quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4, 8, 16})
            add(method, "--samples " + std::to_string(n), [&](RenderSettings& s) { s.samples = n; });
    for (RenderMethod method : {RenderMethod::Adaptive, RenderMethod::Am1})
        for (double t : quick ? std::vector<double>{0.1} : std::vector<double>{0.3, 0.1, 0.03})
            for (int d : quick ? std::vector<int>{2} : std::vector<int>{2, 3, 4}) {
                if (method == RenderMethod::Am1 && d > 3) continue;  // am1's (D+1)^2 sub-samples grow fast
                add(method, "--threshold " + number(t, "%g") + " --depth " + std::to_string(d),
                    [&](RenderSettings& s) {
                        s.adaptive.threshold = t;
                        s.adaptive.depth = d;
                    });
            }
    return out;
}

// The gnuplot data (per method one block of seconds per frame, top flicker,
// bottom flicker, sorted by time) and its script: two charts side by side.
void writePlot(const fs::path& dir, const std::string& title, const std::vector<Setting>& rows, int frames) {
    std::vector<std::string> methods;
    for (const Setting& s : rows)
        if (std::find(methods.begin(), methods.end(), s.method) == methods.end()) methods.push_back(s.method);
    std::ofstream data(dir / "stability.dat");
    for (const std::string& method : methods) {
        std::vector<const Setting*> own;
        for (const Setting& s : rows)
            if (s.method == method) own.push_back(&s);
        std::sort(own.begin(), own.end(), [](auto* a, auto* b) { return a->seconds < b->seconds; });
        data << "# " << method << ": seconds per frame, flicker top, flicker bottom\n";
        // A flicker of 0 has no place on a log axis: 1e-5 stands for it.
        for (const Setting* s : own)
            data << s->seconds / frames << ' ' << std::max(flicker(s->top), 1e-5) << ' '
                 << std::max(flicker(s->bottom), 1e-5) << '\n';
        data << "\n\n";
    }
    std::ofstream gp(dir / "stability.gp");
    gp << "# gnuplot stability.gp (written by asos-bench stability): stability.png and stability.svg\n";
    gp << "set logscale xy\nset grid\nset key bottom left box\n";
    gp << "set xlabel 'render time per frame, CPU s (one thread)'\nset ylabel 'flicker: std / mean of the total "
          "intensity over the frames'\n";
    const auto plot = [&](int column) {
        std::string p = "plot";
        for (std::size_t k = 0; k < methods.size(); ++k)
            p += (k ? ", \\\n     " : " ") + std::string(k ? "''" : "'stability.dat'") + " index " +
                 std::to_string(k) + " using 1:" + std::to_string(column) + " with linespoints pt " +
                 std::to_string(k + 5) + " lc " + std::to_string(k + 1) + " title '" + methods[k] + "'";
        return p + "\n";
    };
    for (const char* terminal : {"pngcairo size 900,380 font ',8'", "svg size 1200,520 font ',10'"}) {
        const bool png = std::string(terminal).starts_with("png");
        gp << "set terminal " << terminal << "\nset output 'stability" << (png ? ".png" : ".svg") << "'\n";
        gp << "set multiplot layout 1,2 title '" << title << "' noenhanced\n";
        gp << "set title 'the wire (top half)'\n" << plot(2);
        gp << "set title 'the sphere (bottom half)'\n" << plot(3);
        gp << "unset multiplot\n";
    }
}

int runStability(const StabilityArgs& args) {
    if (args.width < 2 || args.height < 2 || args.frames < 2) {
        std::fprintf(stderr, "asos-bench stability: error: the size must be at least 2 x 2 and --frames at least 2\n");
        return 2;
    }
    const std::string scenePath =
        args.scene.empty() ? exampleScene(fs::path("bench") / "flicker.pov").string() : args.scene;
    const fs::path dir = args.out;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "asos-bench stability: error: cannot make %s: %s\n", dir.c_str(), ec.message().c_str());
        return 3;
    }
    RenderSettings base;
    base.width = args.width;
    base.height = args.height;
    base.threads = 1;
    std::vector<Setting> rows = ladder(args.quick, base);

    const auto started = std::chrono::steady_clock::now();
    for (int frame = 0; frame < args.frames; ++frame) {
        lang::InterpreterOptions options;
        options.imageWidth = args.width;
        options.imageHeight = args.height;
        options.clock = double(frame) / double(args.frames - 1);
        options.clockOn = true;
        const std::optional<LoadedScene> loaded = loadScene(scenePath, options);
        if (!loaded) return 1;
        const std::unique_ptr<Scene>& scene = loaded->scene;
        for (Setting& s : rows) {
            const double start = processCpuSeconds();
            const RenderOutput out = render(*scene, s.settings);
            s.seconds += processCpuSeconds() - start;
            s.rays += out.stats.counters.allRays();
            double top = 0.0, bottom = 0.0;
            for (int y = 0; y < args.height; ++y)
                for (int x = 0; x < args.width; ++x) {
                    const double v = double(out.color.at(x, y, 0)) + out.color.at(x, y, 1) + out.color.at(x, y, 2);
                    (2 * y < args.height ? top : bottom) += v / 3.0;
                }
            s.top.push_back(top);
            s.bottom.push_back(bottom);
        }
        std::fprintf(stderr, "\rframe %d of %d", frame + 1, args.frames);
    }
    std::fprintf(stderr, "\n");

    CsvTable csv({"method", "setting", "width", "height", "frames", "seconds_per_frame", "rays_per_pixel",
                  "top_mean", "top_flicker", "bottom_mean", "bottom_flicker"});
    const double pixels = double(args.width) * args.height * args.frames;
    std::string summary =
        "| method | setting | s / frame | rays/px | wire: mean | wire: flicker | sphere: mean | sphere: flicker |\n"
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const Setting& s : rows) {
        csv.addRow({s.method, s.setting, std::to_string(args.width), std::to_string(args.height),
                    std::to_string(args.frames), number(s.seconds / args.frames), number(double(s.rays) / pixels),
                    number(mean(s.top)), number(flicker(s.top)), number(mean(s.bottom)), number(flicker(s.bottom))});
        summary += "| " + s.method + " | `" + s.setting + "` | " + number(s.seconds / args.frames, "%.4f") + " | " +
                   number(double(s.rays) / pixels, "%.2f") + " | " + number(mean(s.top), "%.3f") + " | " +
                   number(flicker(s.top), "%.4f") + " | " + number(mean(s.bottom), "%.4f") + " | " +
                   number(flicker(s.bottom), "%.4f") + " |\n";
    }
    // The goal: ASOS at EPS 1/256 against the adaptive setting of nearest cost.
    summary += "\nASOS at EPS 1/256 against `adaptive` at the nearest time per frame (flicker ratios, asos / adaptive):\n\n"
               "| asos | adaptive | time ratio | wire | sphere |\n| --- | --- | ---: | ---: | ---: |\n";
    for (const Setting& a : rows) {
        if (a.method != "asos" || !a.setting.starts_with("--eps 1/256")) continue;
        const Setting* nearest = nullptr;
        for (const Setting& b : rows)
            if (b.method == "adaptive" &&
                (!nearest || std::abs(std::log(b.seconds / a.seconds)) < std::abs(std::log(nearest->seconds / a.seconds))))
                nearest = &b;
        if (!nearest) continue;
        const auto ratio = [](double x, double y) { return y > 0.0 ? number(x / y, "%.3f") : std::string("-"); };
        summary += "| `" + a.setting + "` | `" + nearest->setting + "` | " + number(a.seconds / nearest->seconds, "%.2f") +
                   " | " + ratio(flicker(a.top), flicker(nearest->top)) + " | " +
                   ratio(flicker(a.bottom), flicker(nearest->bottom)) + " |\n";
    }
    {
        std::ofstream out(dir / "stability.csv");
        out << csv.text();
        std::ofstream md(dir / "summary.md");
        md << summary;
        if (!out || !md) {
            std::fprintf(stderr, "asos-bench stability: error: cannot write into %s\n", dir.c_str());
            return 3;
        }
    }
    const std::string title = fs::path(scenePath).stem().string() + ", " + std::to_string(args.width) + " x " +
                              std::to_string(args.height) + ", " + std::to_string(args.frames) + " frames";
    writePlot(dir, title, rows, args.frames);
    if (args.gnuplot && onPath("gnuplot") &&
        std::system(("cd " + shellQuoted(dir.string()) + " && gnuplot stability.gp").c_str()) != 0)
        std::fprintf(stderr, "asos-bench stability: gnuplot failed on %s\n", (dir / "stability.gp").c_str());
    std::printf("%s", summary.c_str());
    std::printf("%zu settings x %d frames in %.0f s; CSV, data, chart and summary.md in %s\n", rows.size(),
                args.frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
                dir.c_str());
    return 0;
}

}  // namespace

void addStabilityBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<StabilityArgs>();
    CLI::App* cmd = app.add_subcommand(
        "stability", "Flicker: each small object's total intensity across an animation's frames, per method");
    cmd->add_option("scene", args->scene,
                    "Scene with one small object in each half of the image (default: examples/bench/flicker.pov)");
    cmd->add_option("-o,--output", args->out, "Folder for stability.csv, the chart and summary.md")->required();
    cmd->add_option("-W,--width", args->width, "Image width (default 160)");
    cmd->add_option("-H,--height", args->height, "Image height (default 120)");
    cmd->add_option("--frames", args->frames, "Frames, the clock from 0 to 1 (default 48)");
    cmd->add_flag("--quick", args->quick, "A short ladder of each method, to check the command (CI)");
    cmd->add_flag("!--no-gnuplot", args->gnuplot, "Write the gnuplot script but do not run gnuplot");
    cmd->callback([args, &result] { result.exitCode = runStability(*args); });
}

}  // namespace asos::bench
