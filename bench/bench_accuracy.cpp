// `asos-bench accuracy [SCENES...] -o DIR [-W 160 -H 120] [--quick]`: speed
// against accuracy. For each scene, a brute-force reference (cached;
// cli/common/reference.hpp), then every method over a ladder of its
// settings, one thread each: render time (CPU time, steadier than wall time
// on a shared machine), rays, and the errors against the
// reference (asos/testing/image_error.hpp); with `povray` on the PATH,
// POV-Ray's +AM1/+AM2 ladder too, on the scene with its asos {} blocks
// blanked (asos/testing/povray_text.hpp). Writes DIR/accuracy.csv (every render),
// DIR/SCENE.dat and SCENE.gp (gnuplot's data and script) and, with `gnuplot`
// on the PATH, DIR/SCENE.png and SCENE.svg: RMSE against time on log-log
// axes, one curve per method, the Pareto front over all of them drawn
// thick; and DIR/summary.md, per scene the fastest setting of each method
// within --target RMSE, and the Pareto front. docs/performance.md shows them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/testing/csv_table.hpp"
#include "asos/testing/image_error.hpp"
#include "asos/testing/pareto_front.hpp"
#include "asos/testing/povray_text.hpp"
#include "bench_tools.hpp"
#include "benchmarks.hpp"
#include "cli/common/reference.hpp"

namespace asos::bench {

namespace {

namespace fs = std::filesystem;

struct AccuracyArgs {
    std::vector<std::string> scenes;  // empty: the benchmark scenes of examples/bench/
    std::string out;
    int width = 160, height = 120;
    bool quick = false;
    int eyeSamples = 32, lightSamples = 4;
    std::optional<std::string> cache;
    bool noCache = false;
    std::string povray = "auto";
    bool gnuplot = true;
    int repeat = 1;
    double target = 0.01;
};

// One setting of one method.
struct Rung {
    std::string method;   // the curve: "asos", "grid", ..., "povray"
    std::string setting;  // as the command line spells it
    RenderSettings settings;
    std::vector<std::string> povrayOptions;  // the POV-Ray rungs' options
};

struct Measured {
    std::string method, setting;
    double seconds = 0.0;
    std::uint64_t rays = 0;
    ImageError error;
    bool pareto = false;
};

Rung rung(std::string method, std::string setting, const RenderSettings& base,
          std::vector<std::string> povrayOptions = {}) {
    Rung r;
    r.method = std::move(method);
    r.setting = std::move(setting);
    r.settings = base;
    r.povrayOptions = std::move(povrayOptions);
    return r;
}

std::string fraction(int denominator) { return "1/" + std::to_string(denominator); }

std::vector<Rung> asosLadder(bool quick, const RenderSettings& base) {
    const std::vector<int> eps = quick ? std::vector<int>{4, 64} : std::vector<int>{4, 16, 64, 256, 1024};
    const std::vector<int> levels = quick ? std::vector<int>{2, 4} : std::vector<int>{2, 3, 4, 5, 6};
    std::vector<Rung> out;
    for (int e : eps)
        for (int m : levels) {
            Rung r = rung("asos", "--eps " + fraction(e) + " --max " + std::to_string(m), base);
            r.settings.method = RenderMethod::Asos;
            r.settings.asos.eps = 1.0 / e;
            r.settings.asos.maxLevel = m;
            out.push_back(r);
        }
    return out;
}

std::vector<Rung> classicLadder(bool quick, bool areaLights, const RenderSettings& base) {
    std::vector<Rung> out;
    const std::vector<int> ns = quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 3, 4, 6, 8, 12, 16};
    for (RenderMethod m : {RenderMethod::Grid, RenderMethod::Jitter})
        for (int n : ns) {
            Rung r = rung(methodName(m), "--samples " + std::to_string(n), base);
            r.settings.method = m;
            r.settings.samples = n;
            out.push_back(r);
        }
    const std::vector<double> thresholds = quick ? std::vector<double>{0.3, 0.1} : std::vector<double>{0.3, 0.1, 0.03};
    const std::vector<int> depths = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 3, 4};
    for (RenderMethod m : {RenderMethod::Adaptive, RenderMethod::Am1})
        for (double t : thresholds)
            for (int d : depths) {
                if (m == RenderMethod::Am1 && d > 3) continue;  // am1's (D+1)^2 sub-samples grow fast
                char setting[64];
                std::snprintf(setting, sizeof setting, "--threshold %g --depth %d", t, d);
                Rung r = rung(methodName(m), setting, base);
                r.settings.method = m;
                r.settings.adaptive.threshold = t;
                r.settings.adaptive.depth = d;
                out.push_back(r);
            }
    // Area lights: the grid light method's points per side, under a jittered eye.
    if (areaLights) {
        const std::vector<int> eye = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4};
        const std::vector<int> light = quick ? std::vector<int>{2, 4} : std::vector<int>{2, 4, 8, 16};
        for (int n : eye)
            for (int l : light) {
                Rung r = rung("jitter+grid light",
                              "--samples " + std::to_string(n) + " --light-samples " + std::to_string(l), base);
                r.settings.method = RenderMethod::Jitter;
                r.settings.samples = n;
                r.settings.lightSamples = l;
                out.push_back(r);
            }
    }
    return out;
}

std::vector<Rung> povrayLadder(bool quick, bool areaLights) {
    std::vector<Rung> out;
    const RenderSettings none;
    const std::vector<int> ams = quick ? std::vector<int>{2} : std::vector<int>{1, 2};
    const std::vector<std::string> thresholds =
        quick ? std::vector<std::string>{"0.3"} : std::vector<std::string>{"0.3", "0.1", "0.03"};
    const std::vector<int> depths = quick ? std::vector<int>{2} : std::vector<int>{2, 3, 4};
    out.push_back(rung("povray", "-A", none, {"-A"}));
    for (int am : ams)
        for (const std::string& a : thresholds)
            for (int r : depths)
                out.push_back(rung("povray", "+AM" + std::to_string(am) + " +A" + a + " +R" + std::to_string(r), none,
                                   {"+AM" + std::to_string(am), "+A" + a, "+R" + std::to_string(r), "-J"}));
    // Its light points: the scenes' LightN, under +AM2 +A0.1 +R3.
    if (areaLights)
        for (int n : quick ? std::vector<int>{3} : std::vector<int>{3, 5, 9, 17})
            out.push_back(rung("povray light", "+AM2 +A0.1 +R3 LightN=" + std::to_string(n), none,
                               {"+AM2", "+A0.1", "+R3", "-J", "Declare=LightN=" + std::to_string(n)}));
    return out;
}

// POV-Ray's render of `scene` with `options`, one thread: its image (read
// from a linear EXR), the CPU time of its trace and its camera and shadow
// rays, from its statistics. Nothing when it fails. `library`: the folder
// its #includes are found in (the original scene's, when `scene` is a copy).
struct PovrayRun {
    Image image;
    double seconds = 0.0;
    std::uint64_t rays = 0;
};
std::optional<PovrayRun> runPovray(const fs::path& scene, const fs::path& library, const fs::path& work, int width,
                                   int height, const std::vector<std::string>& options) {
    const fs::path image = work / "povray.exr", log = work / "povray.log";
    std::string command = "povray -D +WT1 +FE +I" + shellQuoted(scene.string()) + " +O" + shellQuoted(image.string()) +
                          " +L" + shellQuoted(library.string()) + " +W" + std::to_string(width) + " +H" +
                          std::to_string(height);
    for (const std::string& o : options) command += " " + shellQuoted(o);
    command += " >" + shellQuoted(log.string()) + " 2>&1";
    if (std::system(command.c_str()) != 0) return std::nullopt;
    ReadResult r = readImage(image);
    if (!r.ok()) return std::nullopt;
    PovrayRun run;
    run.image = std::move(r.image);
    std::ifstream in(log);
    // "Trace Time: ... (0.138 seconds)", then "using 1 thread(s) with 0.044 CPU-seconds total".
    const std::regex trace(R"(Trace Time:)"), cpu(R"(with ([0-9.]+) CPU-seconds)");
    const std::regex rays(R"(^Rays:\s+([0-9]+))"), shadow(R"(^Shadow Ray Tests:\s+([0-9]+))");
    std::string line;
    std::smatch m;
    bool afterTrace = false;
    while (std::getline(in, line)) {
        if (std::regex_search(line, trace)) afterTrace = true;
        else if (afterTrace && std::regex_search(line, m, cpu)) {
            run.seconds = std::stod(m[1]);
            afterTrace = false;
        }
        if (std::regex_search(line, m, rays)) run.rays += std::stoull(m[1]);
        if (std::regex_search(line, m, shadow)) run.rays += std::stoull(m[1]);
    }
    return run;
}

// The gnuplot data: per method two blocks (its points, then its own front by
// time), and last the front over all methods. Blocks are separated by two
// blank lines, so that `index` picks them.
void writePlot(const fs::path& dir, const std::string& name, const std::string& title,
               const std::vector<Measured>& rows) {
    std::vector<std::string> methods;
    for (const Measured& m : rows)
        if (std::find(methods.begin(), methods.end(), m.method) == methods.end()) methods.push_back(m.method);
    std::ofstream data(dir / (name + ".dat"));
    auto block = [&](std::vector<const Measured*> points) {
        std::sort(points.begin(), points.end(), [](auto* a, auto* b) { return a->seconds < b->seconds; });
        data << "# seconds rmse\n";
        // An error of 0 has no place on a log axis: 1e-6 is far below any measured.
        for (const Measured* p : points) data << p->seconds << ' ' << std::max(p->error.rmse, 1e-6) << '\n';
        data << "\n\n";
    };
    for (const std::string& method : methods) {
        std::vector<const Measured*> all;
        std::vector<double> t, e;
        for (const Measured& m : rows)
            if (m.method == method) {
                all.push_back(&m);
                t.push_back(m.seconds);
                e.push_back(m.error.rmse);
            }
        block(all);
        const std::vector<bool> front = paretoFront(t, e);
        std::vector<const Measured*> own;
        for (std::size_t i = 0; i < all.size(); ++i)
            if (front[i]) own.push_back(all[i]);
        block(own);
    }
    std::vector<const Measured*> front;
    for (const Measured& m : rows)
        if (m.pareto) front.push_back(&m);
    block(front);

    std::ofstream gp(dir / (name + ".gp"));
    gp << "# gnuplot " << name << ".gp (written by asos-bench accuracy): " << name << ".png and " << name
       << ".svg\n";
    gp << "set logscale xy\nset grid\nset key outside right top box\n";
    gp << "set xlabel 'render time, CPU s (one thread)'\nset ylabel 'RMSE against the reference (display values)'\n";
    gp << "set title '" << title << "' noenhanced\n";
    std::string plot = "plot";
    for (std::size_t k = 0; k < methods.size(); ++k) {
        plot += (k ? ", \\\n     " : " ") + std::string("'") + name + ".dat' index " + std::to_string(2 * k) +
                " using 1:2 with points pt " + std::to_string(k + 5) + " lc " + std::to_string(k + 1) +
                " title '" + methods[k] + "', '' index " + std::to_string(2 * k + 1) +
                " using 1:2 with lines lc " + std::to_string(k + 1) + " notitle";
    }
    plot += ", \\\n     '' index " + std::to_string(2 * methods.size()) +
            " using 1:2 with lines lw 4 lc rgb '#80000000' title 'Pareto front'\n";
    // The PNG small enough to sit in the docs' text, the SVG to zoom into.
    for (const char* terminal : {"pngcairo size 560,360 font ',8'", "svg size 800,520 font ',10'"}) {
        const bool png = std::string(terminal).starts_with("png");
        gp << "set terminal " << terminal << "\nset output '" << name << (png ? ".png" : ".svg") << "'\n" << plot;
    }
}

int runAccuracy(const AccuracyArgs& args) {
    if (args.width < 1 || args.height < 1 || args.eyeSamples < 1 || args.lightSamples < 1 || args.repeat < 1 ||
        !(args.target > 0.0)) {
        std::fprintf(stderr, "asos-bench accuracy: error: sizes, sample counts, --repeat and --target must be positive\n");
        return 2;
    }
    if (args.povray != "auto" && args.povray != "off") {
        std::fprintf(stderr, "asos-bench accuracy: error: --povray must be auto or off, not '%s'\n", args.povray.c_str());
        return 2;
    }
    std::vector<std::string> scenes = args.scenes;
    if (scenes.empty())
        for (const char* s : {"edges", "thin", "penumbra", "checker", "room", "textured"})
            scenes.push_back(exampleScene(fs::path("bench") / (std::string(s) + ".pov")).string());
    const fs::path dir = args.out;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "asos-bench accuracy: error: cannot make %s: %s\n", dir.c_str(), ec.message().c_str());
        return 3;
    }
    const bool povray = args.povray == "auto" && onPath("povray");
    const bool gnuplot = args.gnuplot && onPath("gnuplot");
    const std::optional<fs::path> cacheFolder =
        args.cache ? std::optional<fs::path>(*args.cache) : cli::referenceCacheFolder();

    CsvTable csv({"scene", "method", "setting", "width", "height", "seconds", "rays", "rmse", "max_error",
                  "off_share", "pareto"});
    std::string summary;
    const auto started = std::chrono::steady_clock::now();
    for (const std::string& scenePath : scenes) {
        const std::string name = fs::path(scenePath).stem().string();
        std::ostringstream text;
        {
            std::ifstream in(scenePath, std::ios::binary);
            if (!in) {
                std::fprintf(stderr, "asos-bench accuracy: error: cannot read %s\n", scenePath.c_str());
                return 3;
            }
            text << in.rdbuf();
        }
        lang::InterpreterOptions options;
        options.imageWidth = args.width;
        options.imageHeight = args.height;
        const std::optional<LoadedScene> loaded = loadScene(scenePath, options);
        if (!loaded) return 1;
        const SceneDescription* description = &loaded->description;
        const std::unique_ptr<Scene>& scene = loaded->scene;

        cli::ReferenceSettings refSettings;
        refSettings.width = args.width;
        refSettings.height = args.height;
        refSettings.eyeSamples = args.eyeSamples;
        refSettings.lightSamples = args.lightSamples;
        std::fprintf(stderr, "== %s: the reference\n", name.c_str());
        const cli::ReferenceImage ref = cli::loadOrRenderReference(*description, scenePath, text.str(), refSettings,
                                                                   {}, 0.0, cacheFolder, !args.noCache, {});
        if (!ref.error.empty()) {
            std::fprintf(stderr, "%s", ref.error.c_str());
            return 1;
        }
        std::fprintf(stderr, "   %s\n", ref.fromCache ? ("from " + ref.cached.string()).c_str()
                                                      : ("rendered in " + number(ref.seconds, "%.1f") + " s").c_str());
        writeImage(ref.image, dir / (name + "-reference.png"), WriteOptions{.assumedGamma = description->globals.assumedGamma});

        const bool areaLights = std::any_of(description->lights.begin(), description->lights.end(),
                                            [](const Light& l) { return l.area.has_value(); });
        RenderSettings base;
        base.width = args.width;
        base.height = args.height;
        base.threads = 1;
        std::vector<Rung> ladder = asosLadder(args.quick, base);
        for (Rung& r : classicLadder(args.quick, areaLights, base)) ladder.push_back(std::move(r));
        // POV-Ray reads a copy without our asos {} blocks, its includes from the scene's folder.
        const fs::path povrayScene = dir / (name + "-povray.pov");
        if (povray) {
            std::ofstream(povrayScene, std::ios::binary) << withoutAsosBlocks(text.str());
            for (Rung& r : povrayLadder(args.quick, areaLights)) ladder.push_back(std::move(r));
        }
        const fs::path sceneFolder = fs::absolute(scenePath).parent_path();

        std::vector<Measured> rows;
        for (const Rung& rung : ladder) {
            Measured m{rung.method, rung.setting, 0.0, 0, {}, false};
            if (rung.method.starts_with("povray")) {
                std::optional<PovrayRun> best;
                for (int i = 0; i < args.repeat; ++i) {
                    std::optional<PovrayRun> run = runPovray(povrayScene, sceneFolder, dir, args.width, args.height,
                                                                 rung.povrayOptions);
                    if (run && (!best || run->seconds < best->seconds)) best = std::move(run);
                }
                if (!best) {
                    std::fprintf(stderr, "   povray %s failed (%s)\n", rung.setting.c_str(), (dir / "povray.log").c_str());
                    continue;
                }
                m.seconds = best->seconds;
                m.rays = best->rays;
                m.error = imageError(best->image, ref.image, description->globals.assumedGamma);
            } else {
                std::optional<RenderOutput> best;
                for (int i = 0; i < args.repeat; ++i) {
                    const double start = processCpuSeconds();
                    RenderOutput out = render(*scene, rung.settings);
                    const double seconds = processCpuSeconds() - start;
                    if (!best || seconds < m.seconds) {
                        best = std::move(out);
                        m.seconds = seconds;
                    }
                }
                m.rays = best->stats.counters.allRays();
                m.error = imageError(best->color, ref.image, description->globals.assumedGamma);
            }
            std::fprintf(stderr, "   %-18s %-36s %8.3f s  RMSE %.5f\n", m.method.c_str(), m.setting.c_str(), m.seconds,
                         m.error.rmse);
            rows.push_back(m);
        }
        std::vector<double> t, e;
        for (const Measured& m : rows) {
            t.push_back(m.seconds);
            e.push_back(m.error.rmse);
        }
        const std::vector<bool> front = paretoFront(t, e);
        for (std::size_t i = 0; i < rows.size(); ++i) rows[i].pareto = front[i];
        for (const Measured& m : rows)
            csv.addRow({name, m.method, m.setting, std::to_string(args.width), std::to_string(args.height),
                        number(m.seconds), std::to_string(m.rays), number(m.error.rmse), number(m.error.maxError),
                        number(m.error.offShare), m.pareto ? "1" : "0"});

        const std::string title = name + ", " + std::to_string(args.width) + " x " + std::to_string(args.height);
        writePlot(dir, name, title, rows);
        if (gnuplot &&
            std::system(("cd " + shellQuoted(dir.string()) + " && gnuplot " + shellQuoted(name + ".gp")).c_str()) != 0)
            std::fprintf(stderr, "asos-bench accuracy: gnuplot failed on %s\n", (dir / (name + ".gp")).c_str());

        // The summary: each method's fastest setting within the target, then the front.
        summary += "### " + name + "\n\n| method | fastest setting with RMSE <= " + number(args.target) +
                   " | time s | rays/px | RMSE | max | > 1/64 | time / asos |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
        std::vector<std::string> methods;
        for (const Measured& m : rows)
            if (std::find(methods.begin(), methods.end(), m.method) == methods.end()) methods.push_back(m.method);
        std::map<std::string, const Measured*> fastest;
        for (const Measured& m : rows)
            if (m.error.rmse <= args.target && (!fastest[m.method] || m.seconds < fastest[m.method]->seconds))
                fastest[m.method] = &m;
        const double pixels = double(args.width) * args.height;
        auto line = [&](const Measured& m, const std::string& first, const Measured* asos) {
            return "| " + first + " | `" + m.setting + "` | " + number(m.seconds, "%.3f") + " | " +
                   number(double(m.rays) / pixels, "%.1f") + " | " + number(m.error.rmse, "%.4f") + " | " +
                   number(m.error.maxError, "%.3f") + " | " + number(100.0 * m.error.offShare, "%.2f") + " % | " +
                   (asos ? number(m.seconds / asos->seconds, "%.2f") : std::string("")) + " |\n";
        };
        for (const std::string& method : methods)
            summary += fastest[method] ? line(*fastest[method], method, fastest["asos"])
                                       : "| " + method + " | none of its ladder | | | | | | |\n";
        summary += "\nThe Pareto front (fastest first):\n\n| method | setting | time s | rays/px | RMSE | max | > 1/64 | |\n"
                   "| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |\n";
        std::vector<const Measured*> onFront;
        for (const Measured& m : rows)
            if (m.pareto) onFront.push_back(&m);
        std::sort(onFront.begin(), onFront.end(), [](auto* a, auto* b) { return a->seconds < b->seconds; });
        for (const Measured* m : onFront) summary += line(*m, m->method, nullptr);
        summary += "\n";
    }
    {
        std::ofstream out(dir / "accuracy.csv");
        out << csv.text();
        std::ofstream md(dir / "summary.md");
        md << summary;
        if (!out || !md) {
            std::fprintf(stderr, "asos-bench accuracy: error: cannot write into %s\n", dir.c_str());
            return 3;
        }
    }
    std::printf("%s", summary.c_str());
    std::printf("%zu renders in %.0f s; CSV, data, charts and summary.md in %s\n", csv.rows(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), dir.c_str());
    return 0;
}

}  // namespace

void addAccuracyBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<AccuracyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "accuracy", "Speed against accuracy: every method's ladder against a brute-force reference, charted");
    cmd->add_option("scenes", args->scenes,
                    "Scene files (default: examples/bench/ edges, thin, penumbra, checker, room, textured)");
    cmd->add_option("-o,--output", args->out, "Folder for accuracy.csv, the charts and summary.md")->required();
    cmd->add_option("-W,--width", args->width, "Image width (default 160)");
    cmd->add_option("-H,--height", args->height, "Image height (default 120)");
    cmd->add_flag("--quick", args->quick, "A short ladder of each method, to check the command (CI)");
    cmd->add_option("--eye-samples", args->eyeSamples, "The reference's N x N eye rays per pixel (default 32)");
    cmd->add_option("--light-samples", args->lightSamples, "The reference's M x M points per area light (default 4)");
    cmd->add_option("--cache", args->cache, "The references' cache folder (default as asos reference's)");
    cmd->add_flag("--no-cache", args->noCache, "Render the references even when cached");
    cmd->add_option("--povray", args->povray, "auto (POV-Ray's ladder when povray is on the PATH) or off");
    cmd->add_flag("!--no-gnuplot", args->gnuplot, "Write the gnuplot scripts but do not run gnuplot");
    cmd->add_option("--repeat", args->repeat, "Renders per setting; the fastest counts (default 1)");
    cmd->add_option("--target", args->target, "The summary's RMSE to reach (default 0.01)");
    cmd->callback([args, &result] { result.exitCode = runAccuracy(*args); });
}

}  // namespace asos::bench
