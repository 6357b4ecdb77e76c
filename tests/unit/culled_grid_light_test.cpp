// The benchmarks' reference sampler (asos_testing's culled_grid_light.hpp):
// with the paper's emitter, the classic grid's samples, bit for bit, with
// fewer shadow rays; with POV-Ray's, the visible fraction of the converged
// model (ASOS at a fine EPS agrees), without rays where one cone test
// decides. Lit, blocked and partly shadowed points under each area light
// form.
#include <catch2/catch.hpp>

#include <vector>

#include "asos/render/area_light.hpp"
#include "asos/render/grid_light.hpp"
#include "asos/testing/culled_grid_light.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// A floor, a sphere of radius 0.8 at height 3 and an area light at height 6
// with first axis (2, 0, 0), `axis2` and counts n1 x n2, circular orient or
// not.
SceneDescription sphereOverFloor(const Vec3& axis2, int n1, int n2, bool orient) {
    SceneDescription d;
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, litTexture(Vec3(1.0))));
    d.objects.push_back(makeObject(SphereShape{{0, 3, 0}, 0.8}, litTexture(Vec3(1.0))));
    Light light = pointLight({0, 6, 0});
    AreaLight area;
    area.axis1 = {2, 0, 0};
    area.axis2 = axis2;
    area.size1 = n1;
    area.size2 = n2;
    area.circular = area.orient = orient;
    light.area = area;
    d.lights.push_back(light);
    return d;
}

// The floor's point at x (under the sphere, across its penumbra, far out),
// facing up.
AreaLightQuery floorQuery(double x) {
    AreaLightQuery q;
    q.point = Vec3(x, 0, 0.2 * x);
    q.normal = Vec3(0, 1, 0);
    q.key = 7;
    return q;
}

}  // namespace

TEST_CASE("The culled grid: the grid's samples, without the rays one cone test decides", "[lights]") {
    // Axes for a rectangle, a segment (second axis of zero length) and a sphere (orient).
    struct Form {
        Vec3 axis2;
        bool orient;
    };
    const Form forms[] = {{{0, 0, 2}, false}, {{0, 0, 0}, false}, {{0, 0, 2}, true}};
    for (const Form& form : forms) {
        SceneDescription d = sphereOverFloor(form.axis2, 6, 6, form.orient);
        Light& light = d.lights[0];
        light.area->jitter = true;
        light.asos.emitter = LightEmitter::Panel;
        const std::unique_ptr<Scene> scene = buildScene(d);
        const LightModel model = makeLightModel(light, AsosSettings{});
        REQUIRE(model.isArea());
        AreaLightScratch scratch;
        std::uint64_t gridRays = 0, culledRays = 0;
        // Under the occluder (umbra), across its penumbra, far out (lit).
        for (double x : {0.0, 0.6, 1.0, 1.5, 2.0, 3.0, 8.0, 30.0}) {
            const AreaLightQuery q = floorQuery(x);
            RenderCounters counters;
            const std::span<const LightSample> g = gridAreaLightSamples(*scene, model, q, scratch, counters);
            const std::vector<LightSample> grid(g.begin(), g.end());
            gridRays += counters.shadowRays;
            counters = RenderCounters{};
            const std::span<const LightSample> c = culledGridAreaLightSamples(*scene, model, q, scratch, counters);
            culledRays += counters.shadowRays;
            INFO(lightFormName(model.form) << " at x = " << x);
            REQUIRE(c.size() == grid.size());
            for (std::size_t i = 0; i < grid.size(); ++i) {
                CHECK(c[i].direction == grid[i].direction);
                CHECK(c[i].distance == grid[i].distance);
                CHECK(c[i].color == grid[i].color);
            }
        }
        CHECK(culledRays < gridRays);
    }
}

TEST_CASE("The culled reference of POV-Ray's emitter: its converged model, without the rays one cone test decides",
          "[lights]") {
    const Vec3 up(0, 1, 0);
    struct Form {
        Vec3 axis2;
        int n2;
        bool orient;
    };
    const Form forms[] = {{{0, 0, 2}, 64, false}, {{0, 0, 0}, 1, false}, {{0, 0, 2}, 64, true}};
    for (const Form& form : forms) {
        const SceneDescription d = sphereOverFloor(form.axis2, form.n2 == 1 ? 1024 : 64, form.n2, form.orient);
        const std::unique_ptr<Scene> scene = buildScene(d);
        const AsosSettings fine{1.0 / 256.0, 8, false};
        LightSetup setup;
        setup.method = LightMethod::Asos;
        setup.sceneSettings = fine;
        const SceneLights lights(d, setup);
        const LightModel& model = lights[0];
        AreaLightScratch scratch;
        for (double x : {0.0, 0.6, 1.0, 1.5, 2.0, 3.0, 8.0, 30.0}) {
            const AreaLightQuery q = floorQuery(x);
            RenderCounters counters;
            const double reference = diffuseIrradiance(culledGridAreaLightSamples(*scene, model, q, scratch, counters), up).x;
            const bool decided = counters.shadowRays == 0;
            const double asos = diffuseIrradiance(areaLightSamples(*scene, lights, q, scratch, counters), up).x;
            INFO(lightFormName(model.form) << " at x = " << x << ": reference " << reference << ", asos " << asos);
            CHECK(std::abs(reference - asos) <= fine.eps + 0.01);
            // Umbra and far out: one cone test decides, no ray.
            if (x == 0.0 || x >= 8.0) CHECK(decided);
        }
    }
}
