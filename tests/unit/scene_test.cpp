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
