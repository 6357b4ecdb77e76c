// `asos-bench scale -o DIR [-W 160 -H 120] [--quick]`: time and memory
// against scene size and against resolution, per method, one thread.
//  - objects: n spheres (10^2 … 10^6) at unit density in a cube of side
//    n^(1/3), as `asos-bench bvh` makes them, seen from a pinhole at the
//    cube's centre (67° wide). Past a few thousand spheres the view is full
//    and looks alike at every size (a ray meets a sphere within about 8
//    units), so what grows is the hierarchy the rays and cones descend.
//  - mesh: one sphere tessellated into n flat triangles (10^2 … 10^6), one
//    mesh, filling half the image: more and smaller faces in the same view.
//    Past about one face per pixel the faces' shared edges cross every
//    pixel, which ASOS sees as edges (adjacent faces are separate objects).
//  - pixels: the 10^4-sphere cube at 80 x 60 … 640 x 480 (--quick: at half
//    the size and at the size).
// Each run is a child process (fork), so that its peak memory is its own
// (getrusage's maximum resident set of the child, parse-free: the scene is
// made in memory), and its CPU time is measured around the render. Writes
// DIR/scale.csv, DIR/summary.md (the table and, per method, the growth of
// render time per tenfold objects or faces and the exponent of time against
// pixels), DIR/scale.dat and .gp, and with `gnuplot` DIR/scale.png and .svg:
// log-log charts, one curve per method. docs/performance.md shows them.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/render/renderer.hpp"
#include "asos/scene/scene.hpp"
#include "asos/testing/csv_table.hpp"
#include "bench_tools.hpp"
#include "benchmarks.hpp"

namespace asos::bench {

namespace {

namespace fs = std::filesystem;

struct ScaleArgs {
    std::string out;
    int width = 160, height = 120;
    bool quick = false;
    bool gnuplot = true;
    std::string ladder;  // only this ladder (objects, mesh, pixels); empty: all
};

// One method's settings: the defaults of each, one thread.
struct Method {
    std::string name, setting;
    RenderSettings settings;
};

std::vector<Method> methods(bool quick) {
    std::vector<Method> out;
    const auto add = [&](RenderMethod m, std::string setting, auto change) {
        Method method{methodName(m), std::move(setting), {}};
        method.settings.method = m;
        method.settings.threads = 1;
        change(method.settings);
        out.push_back(std::move(method));
    };
    add(RenderMethod::Asos, "defaults (EPS 1/64, MAX 4)", [](RenderSettings&) {});
    add(RenderMethod::Single, "one ray a pixel", [](RenderSettings&) {});
    if (!quick) {
        add(RenderMethod::Grid, "4 x 4", [](RenderSettings& s) { s.samples = 4; });
        add(RenderMethod::Jitter, "4 x 4", [](RenderSettings& s) { s.samples = 4; });
        add(RenderMethod::Adaptive, "defaults", [](RenderSettings&) {});
    }
    return out;
}

Light pointLight(const Vec3& at) {
    Light l;
    l.position = at;
    l.color = Vec3(1.0);
    return l;
}

std::shared_ptr<const Texture> matte(const Vec3& colour) {
    auto t = std::make_shared<Texture>();
    t->pigment.color1.rgb = colour;
    return t;
}

// n spheres of radius 0.1 to 0.3 at unit density; the camera at the centre.
SceneDescription sphereCube(std::size_t n) {
    std::mt19937_64 rng(1993 + n);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double side = std::cbrt(double(n));
    SceneDescription d;
    const auto texture = matte(Vec3(0.9, 0.75, 0.5));
    d.objects.resize(n);
    for (Object& o : d.objects) {
        o.shape = SphereShape{Vec3(u01(rng), u01(rng), u01(rng)) * side, 0.1 + 0.2 * u01(rng)};
        o.texture = texture;
    }
    d.camera.location = Vec3(side / 2.0);
    d.camera.direction = Vec3(0.0, 0.0, 1.0);
    d.camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
    d.camera.up = Vec3(0.0, 1.0, 0.0);
    d.lights.push_back(pointLight(Vec3(side / 2.0) + Vec3(-0.3, 0.4, -0.2)));
    d.background = Color{Vec3(0.3, 0.4, 0.6)};
    return d;
}

// A unit sphere of about n flat triangles (a latitude-longitude grid: u
// segments around, v bands, u = 2v, 2u(v - 1) faces), 3 units in front of
// the camera.
SceneDescription meshSphere(std::size_t n) {
    const int v = std::max(3, int(std::lround(std::sqrt(double(n) / 4.0))));
    const int u = 2 * v;
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices.push_back(Vec3(0.0, 1.0, 0.0));  // the north pole
    for (int i = 1; i < v; ++i) {
        const double theta = std::numbers::pi * i / v;
        for (int j = 0; j < u; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / u;
            mesh->vertices.push_back(Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    }
    mesh->vertices.push_back(Vec3(0.0, -1.0, 0.0));  // the south pole
    const auto at = [&](int band, int j) { return std::uint32_t(1 + (band - 1) * u + (j % u)); };
    const std::uint32_t south = std::uint32_t(mesh->vertices.size() - 1);
    for (int j = 0; j < u; ++j) {
        mesh->faces.push_back({{0, at(1, j + 1), at(1, j)}, {}, false});
        for (int i = 1; i + 1 < v; ++i) {
            mesh->faces.push_back({{at(i, j), at(i, j + 1), at(i + 1, j + 1)}, {}, false});
            mesh->faces.push_back({{at(i, j), at(i + 1, j + 1), at(i + 1, j)}, {}, false});
        }
        mesh->faces.push_back({{at(v - 1, j), at(v - 1, j + 1), south}, {}, false});
    }
    SceneDescription d;
    const auto texture = matte(Vec3(0.9, 0.75, 0.5));
    d.objects.resize(mesh->faces.size());
    for (std::size_t f = 0; f < mesh->faces.size(); ++f) {
        d.objects[f].shape = TriangleShape{mesh, std::uint32_t(f)};
        d.objects[f].texture = texture;
    }
    d.camera.location = Vec3(0.0, 0.0, -3.0);
    d.camera.direction = Vec3(0.0, 0.0, 1.0);
    d.camera.right = Vec3(4.0 / 3.0, 0.0, 0.0);
    d.camera.up = Vec3(0.0, 1.0, 0.0);
    d.lights.push_back(pointLight(Vec3(-3.0, 4.0, -5.0)));
    d.background = Color{Vec3(0.3, 0.4, 0.6)};
    return d;
}

// What one run measured.
struct Run {
    std::string ladder;  // objects, mesh, pixels
    std::size_t size = 0;  // objects or faces
    int width = 0, height = 0;
    std::string method, setting;
    bool ok = false;
    double buildSeconds = 0.0, renderSeconds = 0.0;  // CPU
    double raysPerPixel = 0.0;
    double peakMiB = 0.0;
};

// Builds and renders in a child process; its CPU times and rays come back
// through a pipe, its peak memory from wait4.
Run runChild(const std::string& ladder, std::size_t size, int width, int height, const Method& method) {
    Run run{ladder, size, width, height, method.name, method.setting};
    int fds[2];
    if (pipe(fds) != 0) return run;
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return run;
    }
    if (pid == 0) {
        close(fds[0]);
        double values[3] = {-1.0, -1.0, -1.0};
        try {
            SceneDescription d = ladder == "mesh" ? meshSphere(size) : sphereCube(size);
            Diagnostics diagnostics;
            double start = processCpuSeconds();
            const std::unique_ptr<Scene> scene = Scene::build(std::move(d), diagnostics);
            values[0] = processCpuSeconds() - start;
            if (scene) {
                RenderSettings s = method.settings;
                s.width = width;
                s.height = height;
                start = processCpuSeconds();
                const RenderOutput out = render(*scene, s);
                values[1] = processCpuSeconds() - start;
                values[2] = double(out.stats.counters.allRays()) / (double(width) * height);
            }
        } catch (...) {
        }
        const ssize_t written = write(fds[1], values, sizeof values);
        _exit(written == ssize_t(sizeof values) && values[1] >= 0.0 ? 0 : 1);
    }
    close(fds[1]);
    double values[3] = {-1.0, -1.0, -1.0};
    const ssize_t got = read(fds[0], values, sizeof values);
    close(fds[0]);
    int status = 0;
    struct rusage usage {};
    wait4(pid, &status, 0, &usage);
    run.ok = got == ssize_t(sizeof values) && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    run.buildSeconds = values[0];
    run.renderSeconds = values[1];
    run.raysPerPixel = values[2];
    run.peakMiB = double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
    return run;
}

// Per method, the slope of log(render time) against log(x) over the
// ladder's points, by least squares.
double logSlope(const std::vector<std::pair<double, double>>& points) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(points.size());
    for (auto [x, y] : points) {
        const double lx = std::log(x), ly = std::log(y);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double d = n * sxx - sx * sx;
    return d > 0.0 ? (n * sxy - sx * sy) / d : 0.0;
}

void writePlot(const fs::path& dir, const std::vector<Run>& runs, const std::vector<Method>& ms) {
    std::ofstream data(dir / "scale.dat");
    for (const char* ladder : {"objects", "mesh", "pixels"})
        for (const Method& m : ms) {
            data << "# " << ladder << ", " << m.name << ": size or pixels, render CPU s, peak MiB\n";
            for (const Run& r : runs)
                if (r.ok && r.ladder == ladder && r.method == m.name)
                    data << (r.ladder == std::string("pixels") ? double(r.width) * r.height : double(r.size)) << ' '
                         << std::max(r.renderSeconds, 1e-4) << ' ' << r.peakMiB << '\n';
            data << "\n\n";
        }
    std::ofstream gp(dir / "scale.gp");
    gp << "# gnuplot scale.gp (written by asos-bench scale): scale.png and scale.svg\n";
    gp << "set logscale xy\nset grid\nset key top left box\n";
    const auto plot = [&](int block, int column) {
        std::string p = "plot";
        for (std::size_t k = 0; k < ms.size(); ++k)
            p += (k ? ", \\\n     " : " ") + std::string(k ? "''" : "'scale.dat'") + " index " +
                 std::to_string(block * int(ms.size()) + int(k)) + " using 1:" + std::to_string(column) +
                 " with linespoints pt " + std::to_string(k + 5) + " lc " + std::to_string(k + 1) + " title '" +
                 ms[k].name + "'";
        return p + "\n";
    };
    for (const char* terminal : {"pngcairo size 1200,360 font ',8'", "svg size 1500,450 font ',10'"}) {
        const bool png = std::string(terminal).starts_with("png");
        gp << "set terminal " << terminal << "\nset output 'scale" << (png ? ".png" : ".svg") << "'\n";
        gp << "set multiplot layout 1,4 title 'asos-bench scale: one thread, render CPU time and peak memory' "
              "noenhanced\n";
        gp << "set xlabel 'spheres'\nset ylabel 'render CPU s'\nset title 'spheres at unit density'\n" << plot(0, 2);
        gp << "set ylabel 'peak MiB'\nset title 'peak memory, spheres'\n" << plot(0, 3);
        gp << "set xlabel 'faces'\nset ylabel 'render CPU s'\nset title 'a sphere of n faces'\n" << plot(1, 2);
        gp << "set xlabel 'pixels'\nset title '10^4 spheres, resolution'\n" << plot(2, 2);
        gp << "unset multiplot\n";
    }
}

int runScale(const ScaleArgs& args) {
    if (args.width < 8 || args.height < 6) {
        std::fprintf(stderr, "asos-bench scale: error: the size must be at least 8 x 6\n");
        return 2;
    }
    const fs::path dir = args.out;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        std::fprintf(stderr, "asos-bench scale: error: cannot make %s: %s\n", dir.c_str(), ec.message().c_str());
        return 3;
    }
    const std::vector<Method> ms = methods(args.quick);
    const std::vector<std::size_t> sizes = args.quick ? std::vector<std::size_t>{100, 1000}
                                                      : std::vector<std::size_t>{100, 1000, 10000, 100000, 1000000};
    const std::vector<std::pair<int, int>> resolutions =
        args.quick ? std::vector<std::pair<int, int>>{{args.width / 2, args.height / 2}, {args.width, args.height}}
                   : std::vector<std::pair<int, int>>{{80, 60}, {160, 120}, {320, 240}, {640, 480}};

    std::vector<Run> runs;
    const auto report = [](const Run& r) {
        std::fprintf(stderr, "%-8s %8zu %4d x %-4d %-9s %s\n", r.ladder.c_str(), r.size, r.width, r.height,
                     r.method.c_str(),
                     r.ok ? (number(r.renderSeconds, "%.3f") + " s, " + number(r.peakMiB, "%.0f") + " MiB").c_str()
                          : "failed");
    };
    const auto wanted = [&](const std::string& ladder) { return args.ladder.empty() || args.ladder == ladder; };
    for (const char* ladder : {"objects", "mesh"})
        for (std::size_t n : wanted(ladder) ? sizes : std::vector<std::size_t>{})
            for (const Method& m : ms) {
                runs.push_back(runChild(ladder, n, args.width, args.height, m));
                report(runs.back());
            }
    for (auto [w, h] : wanted("pixels") ? resolutions : std::vector<std::pair<int, int>>{})
        for (const Method& m : ms) {
            runs.push_back(runChild("pixels", 10000, w, h, m));
            report(runs.back());
        }

    CsvTable csv({"ladder", "size", "width", "height", "method", "setting", "ok", "build_cpu_s", "render_cpu_s",
                  "rays_per_pixel", "peak_mib"});
    std::string summary = "| ladder | objects | image | method | build CPU s | render CPU s | rays/px | peak MiB |\n"
                          "| --- | ---: | --- | --- | ---: | ---: | ---: | ---: |\n";
    bool allOk = true;
    for (const Run& r : runs) {
        allOk = allOk && r.ok;
        csv.addRow({r.ladder, std::to_string(r.size), std::to_string(r.width), std::to_string(r.height), r.method,
                    r.setting, r.ok ? "1" : "0", number(r.buildSeconds), number(r.renderSeconds),
                    number(r.raysPerPixel), number(r.peakMiB)});
        summary += "| " + r.ladder + " | " + std::to_string(r.size) + " | " + std::to_string(r.width) + " x " +
                   std::to_string(r.height) + " | " + r.method + " | " +
                   (r.ok ? number(r.buildSeconds, "%.3f") + " | " + number(r.renderSeconds, "%.3f") + " | " +
                               number(r.raysPerPixel, "%.2f") + " | " + number(r.peakMiB, "%.0f")
                         : std::string("failed | | |")) +
                   " |\n";
    }
    // Growth: render time's slope against log10 of the size (seconds per
    // tenfold, relative to the smallest size's time) and the exponent of
    // time against pixels (1: linear).
    summary += "\nGrowth of render CPU time, per method: the factor per tenfold objects (or faces) from the "
               "smallest to the largest size, and the exponent of time against pixels (1 is linear):\n\n"
               "| method | spheres: factor per 10x | mesh faces: factor per 10x | pixels: exponent |\n"
               "| --- | ---: | ---: | ---: |\n";
    for (const Method& m : ms) {
        std::string row = "| " + m.name;
        for (const char* ladder : {"objects", "mesh", "pixels"}) {
            std::vector<std::pair<double, double>> points;
            for (const Run& r : runs)
                if (r.ok && r.ladder == ladder && r.method == m.name && r.renderSeconds > 0.0)
                    points.push_back({ladder == std::string("pixels") ? double(r.width) * r.height : double(r.size),
                                      r.renderSeconds});
            const double slope = points.size() >= 2 ? logSlope(points) : 0.0;
            row += " | " + (points.size() < 2 ? std::string("-")
                                              : ladder == std::string("pixels") ? number(slope, "%.2f")
                                                                                : number(std::pow(10.0, slope), "%.2f"));
        }
        summary += row + " |\n";
    }
    {
        std::ofstream out(dir / "scale.csv");
        out << csv.text();
        std::ofstream md(dir / "summary.md");
        md << summary;
        if (!out || !md) {
            std::fprintf(stderr, "asos-bench scale: error: cannot write into %s\n", dir.c_str());
            return 3;
        }
    }
    writePlot(dir, runs, ms);
    if (args.gnuplot && onPath("gnuplot") &&
        std::system(("cd " + shellQuoted(dir.string()) + " && gnuplot scale.gp").c_str()) != 0)
        std::fprintf(stderr, "asos-bench scale: gnuplot failed on %s\n", (dir / "scale.gp").c_str());
    std::printf("%s", summary.c_str());
    std::printf("%zu runs; CSV, data, chart and summary.md in %s\n", runs.size(), dir.c_str());
    if (!allOk) std::fprintf(stderr, "asos-bench scale: error: some runs failed (see the table)\n");
    return allOk ? 0 : 1;
}

}  // namespace

void addScaleBenchmark(CLI::App& app, CommandResult& result) {
    auto args = std::make_shared<ScaleArgs>();
    CLI::App* cmd = app.add_subcommand(
        "scale", "Time and memory against objects (10^2 to 10^6 spheres, a mesh) and pixels, per method");
    cmd->add_option("-o,--output", args->out, "Folder for scale.csv, the chart and summary.md")->required();
    cmd->add_option("-W,--width", args->width, "Image width of the object ladders (default 160)");
    cmd->add_option("-H,--height", args->height, "Image height of the object ladders (default 120)");
    cmd->add_flag("--quick", args->quick, "Two sizes, two methods, two resolutions: to check the command (CI)");
    cmd->add_option("--ladder", args->ladder, "Only this ladder: objects, mesh or pixels")
        ->check(CLI::IsMember({"objects", "mesh", "pixels"}));
    cmd->add_flag("!--no-gnuplot", args->gnuplot, "Write the gnuplot script but do not run gnuplot");
    cmd->callback([args, &result] { result.exitCode = runScale(*args); });
}

}  // namespace asos::bench
