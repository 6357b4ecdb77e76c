// Plain rays through a scene: shadow rays (no_shadow, shadowless), and
// reflections up to max_trace_level, as POV-Ray 3.7 traces them.
#include <catch2/catch.hpp>

#include <optional>
#include <vector>

#include "asos/render/ray_tracer.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// A white floor (diffuse only) under a light straight above the origin, a
// sphere between them.
SceneDescription shadowScene() {
    SceneDescription d;
    d.lights.push_back(pointLight({0, 10, 0}));
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0}, litTexture(Vec3(1.0), 0.0, 1.0)));
    d.objects.push_back(makeObject(SphereShape{{0, 5, 0}, 1.0}, litTexture(Vec3(1.0), 0.0, 1.0)));
    return d;
}

// Looking straight down at floor point (x, 0, z).
Ray downAt(double x, double z) { return {{x, 3.0, z}, {0, -1, 0}}; }

}  // namespace

TEST_CASE("Plain shadow rays: blocked, no_shadow and shadowless", "[tracer]") {
    SceneDescription d = shadowScene();
    {
        const auto scene = buildScene(d);
        const RayTracer tracer(*scene);
        RenderCounters c;
        CHECK(tracer.radiance(downAt(0, 0), 1, 1.0, c).x == 0.0);  // under the sphere
        CHECK(tracer.radiance(downAt(5, 0), 1, 1.0, c).x > 0.5);   // beside it
        CHECK(c.shadowRays == 2);
        CHECK(tracer.shadowRayBlocked({0, 0, 0}, {0, 10, 0}, c));
        CHECK_FALSE(tracer.shadowRayBlocked({5, 0, 0}, {0, 10, 0}, c));
    }
    {
        d.objects[1].noShadow = true;
        const auto scene = buildScene(d);
        const RayTracer tracer(*scene);
        RenderCounters c;
        CHECK(tracer.radiance(downAt(0, 0), 1, 1.0, c).x == Approx(1.0));
    }
    {
        d.objects[1].noShadow = false;
        d.lights[0].shadowless = true;
        Texture shiny = *d.objects[0].texture;
        shiny.finish.phong = 1.0;
        d.objects[0].texture = std::make_shared<const Texture>(shiny);
        const auto scene = buildScene(d);
        const RayTracer tracer(*scene);
        RenderCounters c;
        // Lit through the sphere, diffuse only: no highlight from a shadowless light.
        CHECK(tracer.radiance(downAt(0, 0), 1, 1.0, c).x == Approx(1.0));
        CHECK(c.shadowRays == 0);
    }
}

TEST_CASE("A light behind the surface costs no shadow ray", "[tracer]") {
    SceneDescription d = shadowScene();
    d.lights[0].position = {0, -10, 0};
    const auto scene = buildScene(d);
    const RayTracer tracer(*scene);
    RenderCounters c;
    CHECK(tracer.radiance(downAt(5, 0), 1, 1.0, c).x == 0.0);
    CHECK(c.shadowRays == 0);
}

TEST_CASE("Reflections are traced up to max_trace_level", "[tracer]") {
    // Two parallel mirrors facing each other, seen along their normal: each
    // bounce adds the ambient of the next mirror times the reflection.
    SceneDescription d;
    Texture mirror = litTexture(Vec3(1.0), 0.1, 0.0);
    mirror.finish.reflection = Vec3(0.5);
    d.objects.push_back(makeObject(PlaneShape{{0, 0, 1}, 1.0}, mirror));
    d.objects.push_back(makeObject(PlaneShape{{0, 0, 1}, -1.0}, mirror));
    for (int level : {1, 2, 3, 5}) {
        d.globals.maxTraceLevel = level;
        const auto scene = buildScene(d);
        const RayTracer tracer(*scene);
        RenderCounters c;
        const Vec3 v = tracer.radiance({{0, 0, 0}, {0, 0, 1}}, 1, 1.0, c);
        // 0.1 (1 + 0.5 + 0.25 + ...) over `level` surfaces.
        double expected = 0.0;
        for (int k = 0; k < level; ++k) expected += 0.1 * std::pow(0.5, k);
        INFO("max_trace_level " << level);
        CHECK(v.x == Approx(expected));
        CHECK(c.reflectedRays == std::uint64_t(level - 1));
    }
}

// The classic grid and jitter methods find their eye rays' hits as packets
// (nearestHits) and shade each with radiance(hit, ...): the colour must be
// radiance(ray)'s, bit for bit, so that the images do not change.
TEST_CASE("Eye rays' colours are the same from packet hits as one by one", "[tracer][packet]") {
    SceneDescription d = shadowScene();
    d.camera = lookAtCamera({0.5, 6, -9}, {0, 1, 0}, 60);
    Texture shiny = litTexture({0.3, 0.5, 0.9});
    shiny.finish.reflection = Vec3(0.3);
    for (int i = 0; i < 30; ++i)
        d.objects.push_back(makeObject(SphereShape{{-3 + 0.2 * i, 0.3 + 0.05 * i, (i % 5) - 2.0}, 0.35},
                                       i % 2 ? shiny : litTexture({0.9, 0.3, 0.2})));
    const auto scene = buildScene(d);
    const RayTracer tracer(*scene);
    const CameraModel camera(d.camera, 40, 30);
    int hits = 0;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            std::vector<Ray> rays;
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) rays.push_back(camera.ray(x + (i + 0.5) / 3, y + (j + 0.5) / 3));
            std::vector<std::optional<SurfaceHit>> found(rays.size());
            tracer.nearestHits(rays, found);
            for (std::size_t k = 0; k < rays.size(); ++k) {
                RenderCounters one, packet;
                const Vec3 expected = tracer.radiance(rays[k], 1, 1.0, one);
                const Vec3 got = tracer.radiance(found[k], rays[k], 1, 1.0, packet);
                REQUIRE(got == expected);
                CHECK(packet.shadowRays == one.shadowRays);
                CHECK(packet.reflectedRays == one.reflectedRays);
                hits += found[k].has_value();
            }
        }
    }
    CHECK(hits > 1000);
}
