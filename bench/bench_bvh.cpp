// `asos-bench bvh`: BVH build time and single-thread nearest-hit rays per
// second on random spheres and random triangles, for camera rays (a pinhole
// looking at the scene) and random rays (origins inside the scene's bounds,
// directions uniform on the sphere), and the camera rays again in 8x8 pixel
// tiles traced as packets (Scene::intersect over a span of rays; the same
// hits, checked). Issue 3's goal: >= 10 M camera rays/s per core on 10^4
// spheres, cost growing about logarithmically with item count.
//
// The items are asos::Primitive objects (sphere, and polygon of three points
// for a triangle) in an asos::Scene, traced by Scene::intersect: the figures
// are the product's own, dispatch and full hit record included.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <memory>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <time.h>

#include <tbb/info.h>

#include "asos/accel/bvh.hpp"
#include "asos/diag/diagnostics.hpp"
#include "asos/scene/scene.hpp"
#include "benchmarks.hpp"

namespace asos::bench {
namespace {

// Unit density: n items in a cube of side n^(1/3), each about 0.4 across.
// Items keep their size and spacing as n grows, so a ray that hits something
// hits it after a similar distance at every size, and the growth of its cost
// shows the hierarchy's depth. (Rays that cross the whole cube without a hit
// cost in proportion to its side, n^(1/3): see docs/accel.md.)
double sideFor(std::size_t n) { return std::cbrt(static_cast<double>(n)); }

// Spheres of radius 0.1 to 0.3 at random centres.
std::vector<Object> makeSpheres(std::size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double side = sideFor(n);
    std::vector<Object> objects(n);
    for (auto& o : objects) {
        SphereShape s;
        s.center = Vec3(u01(rng), u01(rng), u01(rng)) * side;
        s.radius = 0.1 + 0.2 * u01(rng);
        o.shape = s;
    }
    return objects;
}

// Triangles (polygons of three points) with corners in a cube of side 0.8
// about a random centre.
std::vector<Object> makeTriangles(std::size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double side = sideFor(n);
    std::vector<Object> objects(n);
    for (auto& o : objects) {
        const Vec3 c = Vec3(u01(rng), u01(rng), u01(rng)) * side;
        const auto corner = [&] { return c + (Vec3(u01(rng), u01(rng), u01(rng)) - 0.5) * 0.8; };
        const Vec3 a = corner(), b = corner(), d = corner();
        o.shape = PolygonShape{{a, b, d}};
    }
    return objects;
}

// Camera rays: a pinhole outside the scene looking at its centre, the image
// (width x width) covering the scene.
std::vector<Ray> cameraRays(const Bounds3& scene, int width) {
    const Vec3 centre = scene.center();
    const double radius = 0.5 * glm::length(scene.diagonal());
    const Vec3 eye = centre + glm::normalize(Vec3(0.3, 0.4, -1.0)) * (2.2 * radius);
    const Vec3 forward = glm::normalize(centre - eye);
    const Vec3 right = glm::normalize(glm::cross(forward, Vec3(0, 1, 0)));
    const Vec3 up = glm::cross(right, forward);
    const double halfWidth = 0.35;  // about 39 degrees across: the scene fills the image
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(width) * width);
    for (int y = 0; y < width; ++y) {
        for (int x = 0; x < width; ++x) {
            const double u = ((x + 0.5) / width * 2.0 - 1.0) * halfWidth;
            const double v = ((y + 0.5) / width * 2.0 - 1.0) * halfWidth;
            rays.push_back({eye, glm::normalize(forward + u * right + v * up)});
        }
    }
    return rays;
}

std::vector<Ray> randomRays(const Bounds3& scene, std::size_t count, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::normal_distribution<double> normal;
    std::vector<Ray> rays(count);
    for (auto& r : rays) {
        r.origin = scene.lo + Vec3(u01(rng), u01(rng), u01(rng)) * scene.diagonal();
        Vec3 d;
        do d = Vec3(normal(rng), normal(rng), normal(rng));
        while (glm::length(d) < 1e-9);
        r.dir = glm::normalize(d);
    }
    return rays;
}

struct TraceResult {
    double seconds = 0.0;
    std::size_t hits = 0;
    double checksum = 0.0;  // keeps the work observable
};

// The CPU time of the calling thread: rays per second per core, whatever else
// the machine is running (wall time would count the time slices given to
// other processes).
double threadSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The best of `passes` passes over the rays (the fastest pass is the one
// least disturbed: caches shared with other processes).
TraceResult trace(const Scene& scene, const std::vector<Ray>& rays, int passes) {
    TraceResult best;
    for (int pass = 0; pass < passes; ++pass) {
        TraceResult result;
        const double start = threadSeconds();
        for (const Ray& ray : rays) {
            const auto hit = scene.intersect(ray, 0.0, kInfinity);
            if (hit) {
                ++result.hits;
                result.checksum += hit->t;
            }
        }
        result.seconds = threadSeconds() - start;
        if (pass == 0 || result.seconds < best.seconds) best = result;
    }
    return best;
}

// The camera rays again, in tiles of 8x8 pixels, each tile traced as one
// packet (Scene::intersect over a span of rays: Bvh::traversePacket). The
// rays are put in tile order before the clock starts, as a renderer would
// make them tile by tile. The hits and the checksum (the sum of t in pixel
// order, as trace adds them) must equal the single-ray pass's: every ray's
// answer is the same by construction, and a difference is an error.
constexpr int kTile = 8;

TraceResult tracePackets(const Scene& scene, const std::vector<Ray>& camera, int width, int passes) {
    std::vector<Ray> tiled;
    std::vector<std::size_t> pixelOf;  // tiled index -> pixel index
    std::vector<std::size_t> tileStart;
    tiled.reserve(camera.size());
    pixelOf.reserve(camera.size());
    for (int ty = 0; ty < width; ty += kTile) {
        for (int tx = 0; tx < width; tx += kTile) {
            tileStart.push_back(tiled.size());
            for (int y = ty; y < std::min(width, ty + kTile); ++y) {
                for (int x = tx; x < std::min(width, tx + kTile); ++x) {
                    const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
                    tiled.push_back(camera[pixel]);
                    pixelOf.push_back(pixel);
                }
            }
        }
    }
    tileStart.push_back(tiled.size());
    std::vector<std::optional<SurfaceHit>> hits(kTile * kTile);
    std::vector<double> tOf(camera.size());
    TraceResult best;
    for (int pass = 0; pass < passes; ++pass) {
        TraceResult result;
        const double start = threadSeconds();
        for (std::size_t tile = 0; tile + 1 < tileStart.size(); ++tile) {
            const std::size_t begin = tileStart[tile], n = tileStart[tile + 1] - begin;
            scene.intersect(std::span<const Ray>(tiled).subspan(begin, n), 0.0, kInfinity,
                            std::span(hits).first(n));
            for (std::size_t i = 0; i < n; ++i) {
                const auto& hit = hits[i];
                tOf[pixelOf[begin + i]] = hit ? hit->t : -1.0;
                if (hit) ++result.hits;
            }
        }
        result.seconds = threadSeconds() - start;
        for (const double t : tOf)
            if (t >= 0.0) result.checksum += t;
        if (pass == 0 || result.seconds < best.seconds) best = result;
    }
    return best;
}

// Pixel cones, as the ASOS detection phase asks (paper: "Detection Phase"):
// about each camera ray, with a half-angle of 0.75 of the angle between
// neighbouring camera rays, to infinity; every item visited. Microseconds
// per cone (best pass) and items visited per cone.
struct ConeResult {
    double microseconds = 0.0;
    double visits = 0.0;
};

ConeResult traceCones(const Scene& scene, const std::vector<Ray>& camera, std::size_t count, int passes) {
    const double halfAngle = 0.75 * std::acos(std::min(1.0, glm::dot(camera[0].dir, camera[1].dir)));
    const std::size_t step = std::max<std::size_t>(1, camera.size() / count);
    ConeResult best;
    for (int pass = 0; pass < passes; ++pass) {
        std::size_t visits = 0, cones = 0;
        const double start = threadSeconds();
        for (std::size_t i = 0; i < camera.size(); i += step) {
            scene.coneCandidates(Cone{camera[i].origin, camera[i].dir, halfAngle, 0.0, kInfinity},
                                 [&](std::uint32_t) { ++visits; });
            ++cones;
        }
        const double us = (threadSeconds() - start) * 1e6 / static_cast<double>(cones);
        if (pass == 0 || us < best.microseconds) best = {us, static_cast<double>(visits) / static_cast<double>(cones)};
    }
    return best;
}

struct Settings {
    std::vector<std::size_t> sizes{1000, 10000, 100000, 1000000};
    int imageWidth = 1024;
    std::size_t randomRayCount = 1u << 20;
    std::size_t coneCount = 1u << 16;
    std::uint64_t seed = 1;
    std::string scenes = "both";
    int passes = 3;
};

double perSecond(std::size_t count, double seconds) { return static_cast<double>(count) / seconds; }
double percent(std::size_t part, std::size_t whole) {
    return 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

// Build time is Scene::build's: the primitives and the BVH over them.
void benchScene(const char* name, std::vector<Object> objects, const Settings& settings,
                std::mt19937_64& rng) {
    const std::size_t count = objects.size();
    SceneDescription description;
    description.objects = std::move(objects);
    Diagnostics diagnostics;
    const auto buildStart = std::chrono::steady_clock::now();
    const std::unique_ptr<Scene> scene = Scene::build(std::move(description), diagnostics);
    const double buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    if (!scene) throw std::runtime_error("asos-bench bvh: a generated object was rejected");
    const Bvh& bvh = scene->bvh();

    const auto camera = cameraRays(bvh.bounds(), settings.imageWidth);
    const auto random = randomRays(bvh.bounds(), settings.randomRayCount, rng);
    const TraceResult c = trace(*scene, camera, settings.passes);
    const TraceResult p = tracePackets(*scene, camera, settings.imageWidth, settings.passes);
    if (p.hits != c.hits || p.checksum != c.checksum)
        throw std::runtime_error("asos-bench bvh: the packet pass's hits differ from the single-ray pass's (" +
                                 std::to_string(p.hits) + " hits, checksum " +
                                 std::to_string(p.checksum) + " against " + std::to_string(c.hits) +
                                 ", " + std::to_string(c.checksum) + ")");
    const TraceResult r = trace(*scene, random, settings.passes);
    const ConeResult cones = traceCones(*scene, camera, settings.coneCount, settings.passes);
    std::printf("%-10s %9zu %9.3f %9zu %6d %11.2f %7.1f%% %11.2f %11.2f %7.1f%% %9.2f %7.1f   %.6g\n",
                name, count, buildSeconds, bvh.nodeCount(), bvh.depth(),
                perSecond(camera.size(), c.seconds) * 1e-6, percent(c.hits, camera.size()),
                perSecond(camera.size(), p.seconds) * 1e-6,
                perSecond(random.size(), r.seconds) * 1e-6, percent(r.hits, random.size()),
                cones.microseconds, cones.visits, c.checksum + r.checksum);
}

int run(const Settings& settings) {
    std::printf("asos-bench bvh: nearest hit, one thread tracing (rays/s from its CPU time); "
                "build on %d threads (wall time)\n",
                tbb::info::default_concurrency());
    std::printf("camera: %dx%d pinhole rays; random: %zu rays from inside the bounds; "
                "best of %d passes\n",
                settings.imageWidth, settings.imageWidth, settings.randomRayCount, settings.passes);
    std::printf("packet: the camera rays in %dx%d pixel tiles, one packet each (same hits)\n",
                kTile, kTile);
    std::printf("pixel cones: %zu, about camera rays, 0.75 x the angle between neighbours\n",
                settings.coneCount);
    std::printf("%-10s %9s %9s %9s %6s %11s %8s %11s %11s %8s %9s %7s   %s\n", "scene", "items",
                "build_s", "nodes", "depth", "camera_Mr/s", "cam_hit", "packet_Mr/s", "random_Mr/s",
                "rnd_hit",
                "cone_us", "visits", "checksum");
    std::fflush(stdout);
    for (const std::size_t n : settings.sizes) {
        std::mt19937_64 rng(settings.seed + n);
        if (settings.scenes != "triangles") {
            benchScene("spheres", makeSpheres(n, rng), settings, rng);
            std::fflush(stdout);
        }
        if (settings.scenes != "spheres") {
            benchScene("triangles", makeTriangles(n, rng), settings, rng);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace

void addBvhBenchmark(CLI::App& app, CommandResult& result) {
    auto settings = std::make_shared<Settings>();
    CLI::App* cmd = app.add_subcommand("bvh", "BVH build time and nearest-hit rays per second");
    cmd->add_option("--sizes", settings->sizes, "item counts")->delimiter(',');
    cmd->add_option("--width", settings->imageWidth, "camera image width and height (rays = width^2)")
        ->check(CLI::Range(1, 8192));
    cmd->add_option("--random-rays", settings->randomRayCount, "random rays per scene");
    cmd->add_option("--cones", settings->coneCount, "pixel cones per scene")->check(CLI::PositiveNumber);
    cmd->add_option("--seed", settings->seed, "random seed");
    cmd->add_option("--passes", settings->passes, "passes over the rays (the best is reported)")
        ->check(CLI::Range(1, 100));
    cmd->add_option("--scenes", settings->scenes, "spheres, triangles or both")
        ->check(CLI::IsMember({"spheres", "triangles", "both"}));
    cmd->callback([settings, &result] { result.exitCode = run(*settings); });
}

}  // namespace asos::bench
