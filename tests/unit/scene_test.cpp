#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "asos/scene/scene.hpp"

using namespace asos;

namespace {
Object sphereObject(const Vec3& center, double radius, bool noShadow = false) {
    Object o;
    o.shape = SphereShape{center, radius};
    o.noShadow = noShadow;
    return o;
}
}  // namespace

TEST_CASE("Scene queries agree with brute force over its primitives", "[scene]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    SceneDescription d;
    for (int i = 0; i < 200; ++i)
        d.objects.push_back(sphereObject({u(rng), u(rng), u(rng)}, 0.2 + 0.01 * (i % 50), i % 3 == 0));
    Object ground;
    ground.shape = PlaneShape{{0, 1, 0}, -12};
    d.objects.push_back(ground);

    Diagnostics diag;
    const auto scene = Scene::build(d, diag);
    REQUIRE(scene);
    REQUIRE(scene->objectCount() == d.objects.size());
    for (int i = 0; i < 2000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, glm::normalize(Vec3(u(rng), u(rng), u(rng)))};
        std::optional<SurfaceHit> brute;
        bool blocked = false;
        for (std::uint32_t o = 0; o < scene->objectCount(); ++o) {
            if (auto h = scene->primitive(o).intersect(ray, 0.0, kInfinity))
                if (!brute || h->t < brute->t) { brute = h; brute->objectIndex = int(o); }
            blocked = blocked || (!d.objects[o].noShadow &&
                                  scene->primitive(o).intersectAny(ray, 0.0, kInfinity));
        }
        const auto hit = scene->intersect(ray, 0.0, kInfinity);
        REQUIRE(hit.has_value() == brute.has_value());
        if (hit) {
            CHECK(hit->objectIndex == brute->objectIndex);
            CHECK(hit->t == Approx(brute->t));
        }
        CHECK(scene->occluded(ray, 0.0, kInfinity) == blocked);

        // Every object that the cone truly meets is a candidate.
        const Cone cone{ray.origin, ray.dir, 0.05, 0.0, kInfinity};
        std::vector<std::uint32_t> candidates;
        scene->coneCandidates(cone, [&](std::uint32_t o) { candidates.push_back(o); });
        for (std::uint32_t o = 0; o < scene->objectCount(); ++o)
            if (scene->primitive(o).classify(cone).coverage != Coverage::Miss)
                CHECK(std::count(candidates.begin(), candidates.end(), o) == 1);
    }
}

TEST_CASE("Scene build reports every meaningless object with its location", "[scene]") {
    SceneDescription d;
    d.objects.push_back(sphereObject({0, 0, 0}, -1));
    d.objects.push_back(sphereObject({0, 0, 0}, 1));
    d.objects.push_back(sphereObject({0, 0, 0}, -2));
    d.objects[0].loc.line = 3;
    d.objects[2].loc.line = 9;
    Diagnostics diag;
    CHECK_FALSE(Scene::build(d, diag));
    REQUIRE(diag.all().size() == 2);
    CHECK(diag.all()[0].loc.line == 3);
    CHECK(diag.all()[1].loc.line == 9);
}

TEST_CASE("Scene build names what is wrong with an object too large to bound, at its location", "[scene]") {
    SceneDescription d;
    d.objects.push_back(sphereObject({1e308, 0, 0}, 1e308));  // finite numbers, infinite bounds
    d.objects.push_back(sphereObject({0, 0, 0}, 1));
    d.objects.back().worldFromObject = Transform::scale(Vec3(1e300));  // a volume of 1e900
    d.objects[0].loc.line = 4;
    d.objects[1].loc.line = 6;
    Diagnostics diag;
    CHECK_FALSE(Scene::build(d, diag));
    REQUIRE(diag.all().size() == 2);
    CHECK(diag.all()[0].loc.line == 4);
    CHECK_THAT(diag.all()[0].message, Catch::Contains("too large: its bounding box is not finite"));
    CHECK(diag.all()[1].loc.line == 6);
    CHECK_THAT(diag.all()[1].message, Catch::Contains("scales it too much"));
}

// The scene's ray searches test translated spheres from a compact array and
// every other object through its Primitive: both paths must give exactly the
// primitive's own answers, hit record included.
TEST_CASE("Scene ray searches give each primitive's exact answer, whatever its placement",
          "[scene]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-8.0, 8.0), size(0.2, 1.0), angle(-180.0, 180.0);
    SceneDescription d;
    for (int i = 0; i < 240; ++i) {
        Object o;
        const Vec3 at(u(rng), u(rng), u(rng));
        switch (i % 4) {
        case 0: o.shape = SphereShape{at, size(rng)}; break;
        case 1: o.shape = BoxShape{at, at + Vec3(size(rng), size(rng), size(rng))}; break;
        case 2: o.shape = CylinderShape{at, at + Vec3(0, size(rng), 0), 0.5 * size(rng), false}; break;
        default: o.shape = PolygonShape{{at, at + Vec3(size(rng), 0, 0), at + Vec3(0, size(rng), 0.3)}}; break;
        }
        // Spheres too: translated (the compact path), rotated, scaled.
        if (i % 3 == 1) o.worldFromObject = Transform::rotateDegrees({angle(rng), angle(rng), angle(rng)});
        if (i % 3 == 2) o.worldFromObject = Transform::scale({size(rng) + 0.5, 1.0, size(rng) + 0.5});
        o.noShadow = i % 5 == 0;
        d.objects.push_back(o);
    }
    Diagnostics diag;
    const auto scene = Scene::build(d, diag);
    REQUIRE(scene);
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, glm::normalize(Vec3(u(rng), u(rng), u(rng)))};
        const double tMin = i % 2 ? 0.0 : 0.5, tMax = i % 3 ? kInfinity : 6.0;
        std::optional<SurfaceHit> brute;
        bool blocked = false;
        for (std::uint32_t o = 0; o < scene->objectCount(); ++o) {
            if (auto h = scene->primitive(o).intersect(ray, tMin, tMax))
                if (!brute || h->t < brute->t) { brute = h; brute->objectIndex = int(o); }
            blocked = blocked || (!d.objects[o].noShadow &&
                                  scene->primitive(o).intersectAny(ray, tMin, tMax));
        }
        const auto hit = scene->intersect(ray, tMin, tMax);
        REQUIRE(hit.has_value() == brute.has_value());
        if (hit) {
            CHECK(hit->objectIndex == brute->objectIndex);
            CHECK(hit->t == brute->t);
            CHECK(hit->position == brute->position);
            CHECK(hit->normal == brute->normal);
            CHECK(hit->objectPoint == brute->objectPoint);
        }
        CHECK(scene->occluded(ray, tMin, tMax) == blocked);
    }
}

namespace {

bool sameHit(const std::optional<SurfaceHit>& a, const std::optional<SurfaceHit>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->t == b->t && a->position == b->position && a->normal == b->normal &&
                  a->objectPoint == b->objectPoint && a->objectIndex == b->objectIndex);
}

// Random objects in a cube of side 16: spheres, triangles (three-point
// polygons), or a mix of every bounded shape (translated, rotated, scaled)
// with two planes. Some objects come in exact copies, several of them, so
// that rays meet hits at equal distances in different leaves.
SceneDescription randomScene(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<double> u(-8.0, 8.0), size(0.2, 1.0), angle(-180.0, 180.0);
    SceneDescription d;
    for (int i = 0; i < 400; ++i) {
        Object o;
        const Vec3 at(u(rng), u(rng), u(rng));
        const int shape = kind == 0 ? 0 : kind == 1 ? 3 : i % 4;
        switch (shape) {
        case 0: o.shape = SphereShape{at, size(rng)}; break;
        case 1: o.shape = BoxShape{at, at + Vec3(size(rng), size(rng), size(rng))}; break;
        case 2: o.shape = CylinderShape{at, at + Vec3(0, size(rng), 0), 0.5 * size(rng), false}; break;
        default: o.shape = PolygonShape{{at, at + Vec3(size(rng), 0, 0), at + Vec3(0, size(rng), 0.3)}}; break;
        }
        if (kind == 2 && i % 3 == 1) o.worldFromObject = Transform::rotateDegrees({angle(rng), angle(rng), angle(rng)});
        if (kind == 2 && i % 3 == 2) o.worldFromObject = Transform::scale({size(rng) + 0.5, 1.0, size(rng) + 0.5});
        d.objects.push_back(o);
        if (i % 40 == 0)
            for (int copy = 0; copy < 9; ++copy) d.objects.push_back(o);
    }
    if (kind == 2) {
        Object ground;
        ground.shape = PlaneShape{{0, 1, 0}, -9};
        d.objects.push_back(ground);
        d.objects.push_back(ground);
        Object wall;
        wall.shape = PlaneShape{{0.3, 0, 1}, 10};
        d.objects.push_back(wall);
    }
    return d;
}

}  // namespace

// The packet search must give every ray exactly Scene::intersect's answer:
// hit record and object, ties between copies included, for coherent camera
// tiles and for packets whose rays go every way (mixed octants, directions
// with zero or tiny components, which are traversed alone).
TEST_CASE("Scene packet search gives every ray intersect's answer bit for bit", "[scene][packet]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u01(0.0, 1.0), u(-8.0, 8.0);
    int rays = 0, hits = 0;
    for (int kind = 0; kind < 3; ++kind) {
        Diagnostics diag;
        const auto scene = Scene::build(randomScene(rng, kind), diag);
        REQUIRE(scene);
        for (int trial = 0; trial < 120; ++trial) {
            std::vector<Ray> packet;
            const int size = trial % 4 == 3 ? 1 + static_cast<int>(rng() % 150) : 64;
            const Vec3 eye = glm::normalize(Vec3(u(rng), u(rng), u(rng))) * (10.0 + 20.0 * u01(rng));
            switch (trial % 4) {
            case 0:
            case 1: {
                // An 8x8 tile of a pinhole; case 1 looks along an axis, so
                // that tiles straddle the planes where direction signs change.
                Vec3 forward = glm::normalize(Vec3(u(rng), u(rng), u(rng)) - eye);
                if (trial % 4 == 1) {
                    forward = Vec3(0.0);
                    forward[static_cast<int>(rng() % 3)] = rng() % 2 ? 1.0 : -1.0;
                }
                const Vec3 right = glm::normalize(glm::cross(forward, glm::normalize(Vec3(u(rng), u(rng), u(rng)))));
                const Vec3 up = glm::cross(right, forward);
                const double step = std::pow(10.0, -3.5 + 2.5 * u01(rng));
                for (int y = 0; y < 8; ++y)
                    for (int x = 0; x < 8; ++x)
                        packet.push_back({eye, glm::normalize(forward + (x - 3.5) * step * right + (y - 3.5) * step * up)});
                break;
            }
            case 2:
                // One origin, every direction; some with zero or tiny components.
                for (int i = 0; i < size; ++i) {
                    Vec3 d(u(rng), u(rng), u(rng));
                    if (i % 5 == 0) d[static_cast<int>(rng() % 3)] = 0.0;
                    if (i % 7 == 0) d[static_cast<int>(rng() % 3)] = 1e-35;
                    if (i % 11 == 0) d = Vec3(0.0), d[static_cast<int>(rng() % 3)] = rng() % 2 ? 1.0 : -1.0;
                    packet.push_back({eye, glm::normalize(d)});
                }
                break;
            default:
                // Different origins inside the scene.
                for (int i = 0; i < size; ++i)
                    packet.push_back({Vec3(u(rng), u(rng), u(rng)), glm::normalize(Vec3(u(rng), u(rng), u(rng)))});
                break;
            }
            const double tMin = trial % 3 == 0 ? 0.5 : 0.0;
            const double tMax = trial % 5 == 0 ? 15.0 : kInfinity;
            std::vector<std::optional<SurfaceHit>> got(packet.size());
            scene->intersect(packet, tMin, tMax, got);
            for (std::size_t i = 0; i < packet.size(); ++i) {
                const auto expected = scene->intersect(packet[i], tMin, tMax);
                ++rays;
                hits += expected.has_value();
                REQUIRE(sameHit(got[i], expected));
            }
        }
    }
    CHECK(hits > rays / 4);
    CHECK_THROWS_AS(
        [] {
            SceneDescription d;
            d.objects.push_back(sphereObject({0, 0, 0}, 1));
            Diagnostics diag;
            const auto scene = Scene::build(d, diag);
            std::vector<Ray> packet(3);
            std::vector<std::optional<SurfaceHit>> got(2);
            scene->intersect(packet, 0.0, kInfinity, got);
        }(),
        std::invalid_argument);
}
