// Known answers for distributed light sources (paper: "Distributed Light
// Sources"): the light an area light sends a point, by ASOS shadow beams and
// by the classic grid, against a dense numerical integration of the same
// light model computed here (docs/lights.md), what a white diffuse surface
// receives, nothing falling off with distance:
//   - POV-Ray's emitter (the default): the fraction of the light that
//     reaches the point (uniformly over a rectangle or a segment, over the
//     square of POV-Ray's disc map), times the cosine of incidence along the
//     direction of the light's centre;
//   - the paper's (`emitter panel`, the tests without "POV-Ray" in their
//     names): a rectangle of intensity colour / area with the weighting
//     cos theta, a segment of colour / length, a sphere's apparent disc of
//     colour / (pi r^2); each point of the light weighted by its own cosine
//     of incidence.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/render/area_light.hpp"
#include "asos/render/area_light_shadow.hpp"
#include "asos/render/grid_light.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

Light areaLight(const Vec3& position, const Vec3& axis1, const Vec3& axis2, int n1, int n2,
                bool orient = false, LightEmitter emitter = LightEmitter::Panel) {
    Light l = pointLight(position, Vec3(1.0));
    l.asos.emitter = emitter;
    AreaLight a;
    a.axis1 = axis1;
    a.axis2 = axis2;
    a.size1 = n1;
    a.size2 = n2;
    a.circular = orient;
    a.orient = orient;
    l.area = a;
    return l;
}

// A scene of a ground plane (object 0), the given occluders and one light.
struct LightSetupScene {
    SceneDescription d;
    std::unique_ptr<Scene> scene;
    AreaLightScratch scratch;

    LightSetupScene(const Light& light, std::vector<Object> occluders) {
        d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, litTexture(Vec3(1.0))));
        for (Object& o : occluders) d.objects.push_back(std::move(o));
        d.lights.push_back(light);
        scene = buildScene(d);
    }

    // The diffuse light a point receives (per unit of the light's colour):
    // the sum over the samples of colour x cos(incidence).
    double received(LightMethod method, const AsosSettings& settings, const Vec3& point,
                    const Vec3& normal, RenderCounters& counters, std::uint32_t shaded = 0,
                    std::optional<int> samples = std::nullopt, std::optional<Vec3> outward = std::nullopt) {
        LightSetup setup;
        setup.method = method;
        setup.sceneSettings = settings;
        setup.samples = samples;
        const SceneLights lights(d, setup);
        AreaLightQuery q;
        q.point = point;
        q.normal = normal;
        q.outward = outward.value_or(normal);
        q.shadedObject = shaded;
        return diffuseIrradiance(areaLightSamples(*scene, lights, q, scratch, counters), normal).x;
    }
    double received(LightMethod method, const AsosSettings& settings, const Vec3& point,
                    const Vec3& normal) {
        RenderCounters counters;
        return received(method, settings, point, normal, counters);
    }
};

// Dense midpoint integration over [0, 1]^2 (or [0, 1] when `m2` is 1).
double integrate(int m1, int m2, const std::function<double(double, double)>& f) {
    double sum = 0.0;
    for (int j = 0; j < m2; ++j)
        for (int i = 0; i < m1; ++i) sum += f((i + 0.5) / m1, (j + 0.5) / m2);
    return sum / (double(m1) * double(m2));
}

// The model's rectangle: (1 / A) integral of cos theta x max(0, N . L) dA
// (the 1 / A of I = colour / A cancels the area element's A).
double exactRectangle(const LightModel& m, const Vec3& p, const Vec3& n,
                      const std::function<bool(const Vec3&, const Vec3&)>& visible = {}) {
    const RectangleLight& r = std::get<RectangleLight>(m.form);
    const Vec3 normal = glm::normalize(glm::cross(r.edgeA, r.edgeB));
    return integrate(400, 400, [&](double s, double t) {
        const Vec3 y = r.corner + s * r.edgeA + t * r.edgeB;
        const Vec3 d = glm::normalize(y - p);
        if (visible && !visible(p, y)) return 0.0;
        return std::abs(glm::dot(normal, d)) * std::max(0.0, glm::dot(n, d));
    });
}

// Whether the segment from p to y passes through a sphere.
bool segmentMeetsSphere(const Vec3& p, const Vec3& y, const Vec3& centre, double radius) {
    const Vec3 d = y - p;
    const double t = std::clamp(glm::dot(centre - p, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p + t * d - centre) < radius;
}

}  // namespace

TEST_CASE("An unoccluded rectangular light is integrated to EPS, near and far, head-on and grazing",
          "[lights]") {
    const AsosSettings settings{1.0 / 64.0, 4, false};
    struct Case {
        const char* what;
        Vec3 position, axis1, axis2, point, normal;
    };
    const Vec3 up(0, 1, 0);
    const Vec3 tilted = glm::normalize(Vec3(0.0, 1.0, 1.0));
    const Case cases[] = {
        {"near, straight below", {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, {0, 0, 0}, up},
        {"near, off centre", {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, {0.8, 0, -0.5}, up},
        {"near, beyond the edge", {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, {1.7, 0, 0.3}, up},
        {"far, straight below", {0, 20, 0}, {2, 0, 0}, {0, 0, 2}, {0.3, 0, 0}, up},
        {"far, to the side", {0, 6, 0}, {3, 0, 0}, {0, 0, 1}, {9, 0, 4}, up},
        {"grazing", {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, {12, 0, 0}, up},
        {"head-on, tilted surface", {0, 3, 0}, {2, 0, 0}, {0, 0, 2}, {0, 0, -3}, tilted},
        {"light turned, near", {0, 1.5, 0}, {1.5, 0, 0}, {0, 1.2, 1.2}, {0.4, 0, 0.6}, up},
        {"the light's far side", {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, {0.5, 2, 0.2}, -up},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        LightSetupScene s(areaLight(c.position, c.axis1, c.axis2, 4, 4), {});
        const LightModel model = makeLightModel(s.d.lights[0], settings);
        REQUIRE(std::holds_alternative<RectangleLight>(model.form));
        const double exact = exactRectangle(model, c.point, c.normal);
        RenderCounters counters;
        const double asos = s.received(LightMethod::Asos, settings, c.point, c.normal, counters);
        CHECK(std::abs(asos - exact) <= settings.eps);
        // Unoccluded: no shadow ray at all.
        CHECK(counters.shadowRays == 0);
        // The grid converges to the same light.
        const double grid = s.received(LightMethod::Grid, settings, c.point, c.normal, counters, 0, 64);
        CHECK(std::abs(grid - exact) <= 2e-3);
    }
    // A far point straight below a light facing it receives the light's
    // colour, as from a point light: the normalisation.
    LightSetupScene far(areaLight({0, 1000, 0}, {1, 0, 0}, {0, 0, 1}, 2, 2), {});
    CHECK(far.received(LightMethod::Asos, settings, {0, 0, 0}, up) == Approx(1.0).epsilon(1e-6));
    CHECK(far.received(LightMethod::Grid, settings, {0, 0, 0}, up) == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("Lights across the surface's horizon: the clamped cosine's kink refined, not smoothed over",
          "[lights]") {
    // Unoccluded lights that the shaded point's tangent plane cuts (a
    // terminator): the cosine of incidence is clamped at the plane, a kink
    // that second differences do not bound. ASOS refines the pieces it
    // crosses to MAX, where the central rays alone carry them, so its error
    // is that of MAX's pieces along the kink: checked here at EPS / 8 (the
    // errors are 0.02-0.04 EPS). The five-point rule accepted across the kink
    // missed the segment's by 1.2 EPS at the last normal.
    const AsosSettings settings{1.0 / 64.0, 4, false};
    const Vec3 origin(0.0);
    int checked = 0;
    for (double tilt : {-0.6, -0.25, 0.0, 0.3, 0.55}) {
        // The normal leans toward +x: the plane x cos + y sin = 0 passes
        // through every light below, centred straight above.
        const Vec3 n = glm::normalize(Vec3(1.0, tilt, 0.0));
        INFO("normal " << n.x << " " << n.y);
        {
            LightSetupScene s(areaLight({0, 2, 0}, {3, 0, 0}, {0, 0, 3}, 4, 4), {});
            const LightModel model = makeLightModel(s.d.lights[0], settings);
            const double exact = exactRectangle(model, origin, n);
            const double asos = s.received(LightMethod::Asos, settings, origin, n);
            INFO("rectangle: exact " << exact << ", asos " << asos);
            CHECK(std::abs(asos - exact) <= settings.eps / 8.0);
        }
        {
            LightSetupScene s(areaLight({0, 2, 0}, {3, 0, 0}, {0, 0, 0}, 16, 1), {});
            const double exact = integrate(20000, 1, [&](double f, double) {
                return std::max(0.0, glm::dot(n, glm::normalize(Vec3(-1.5 + 3.0 * f, 2.0, 0.0))));
            });
            const double asos = s.received(LightMethod::Asos, settings, origin, n);
            INFO("segment: exact " << exact << ", asos " << asos);
            CHECK(std::abs(asos - exact) <= settings.eps / 8.0);
        }
        {
            LightSetupScene s(areaLight({0, 2, 0}, {3, 0, 0}, {0, 0, 3}, 8, 8, true), {});
            const Vec3 toCentre(0, 2, 0);
            const double tanAlpha = std::tan(std::asin(1.5 / 2.0));
            const Frame frame = Frame::around(toCentre / 2.0);
            // Uniform over the apparent disc by the concentric map (equal areas).
            const double exact = integrate(500, 500, [&](double s1, double s2) {
                const Vec2 d = concentricDisc(s1, s2);
                return std::max(0.0, glm::dot(n, glm::normalize(frame.toWorld(tanAlpha * d.x, tanAlpha * d.y, 1.0))));
            });
            const double asos = s.received(LightMethod::Asos, settings, origin, n);
            INFO("sphere: exact " << exact << ", asos " << asos);
            CHECK(std::abs(asos - exact) <= settings.eps / 8.0);
        }
        ++checked;
    }
    CHECK(checked == 5);
}

TEST_CASE("A spherical light partly hidden by a sphere: across the penumbra within EPS",
          "[lights]") {
    // EPS 1/32 and a MAX deep enough that the paper's bound, not MAX, stops.
    const AsosSettings settings{1.0 / 32.0, 8, false};
    const Vec3 lightCentre(0, 6, 0), occluderCentre(0, 3, 0);
    const double lightRadius = 1.0, occluderRadius = 0.8;
    Object occluder = makeObject(SphereShape{occluderCentre, occluderRadius}, litTexture(Vec3(1.0)));
    LightSetupScene s(areaLight(lightCentre, {2, 0, 0}, {0, 0, 2}, 8, 8, true), {occluder});
    const LightModel model = makeLightModel(s.d.lights[0], settings);
    REQUIRE(std::holds_alternative<SphereLight>(model.form));
    REQUIRE(std::get<SphereLight>(model.form).radius == 1.0);
    const Vec3 up(0, 1, 0);
    int partial = 0;
    // The umbra ends near x = 0.6 and the penumbra near x = 3.
    for (double x = 0.0; x <= 3.4; x += 0.2) {
        const Vec3 p(x, 0, 0.3 * x);
        // The apparent disc, uniformly in its unit-disc coordinates: the
        // directions of the tangent cone (a disc facing the point).
        const Vec3 toCentre = lightCentre - p;
        const double distance = glm::length(toCentre);
        const double tanAlpha = std::tan(std::asin(lightRadius / distance));
        const Frame frame = Frame::around(toCentre / distance);
        const double inDisc = integrate(500, 500, [&](double s1, double s2) {
            const double u = 2 * s1 - 1, v = 2 * s2 - 1;
            return u * u + v * v <= 1.0 ? 1.0 : 0.0;
        });
        const double exact = integrate(500, 500, [&](double s1, double s2) {
                                 const double u = 2 * s1 - 1, v = 2 * s2 - 1;
                                 if (u * u + v * v > 1.0) return 0.0;
                                 const Vec3 d = glm::normalize(frame.toWorld(tanAlpha * u, tanAlpha * v, 1.0));
                                 if (segmentMeetsSphere(p, p + 10.0 * d, occluderCentre, occluderRadius))
                                     return 0.0;
                                 return std::max(0.0, glm::dot(up, d));
                             }) /
                             inDisc;
        RenderCounters counters;
        const double asos = s.received(LightMethod::Asos, settings, p, up, counters);
        INFO("x = " << x << ": exact " << exact << ", asos " << asos);
        CHECK(std::abs(asos - exact) <= settings.eps);
        const double grid = s.received(LightMethod::Grid, settings, p, up, counters, 0, 48);
        CHECK(std::abs(grid - exact) <= 0.01);
        if (exact > 0.05 && exact < 0.9 * std::max(0.0, glm::dot(up, glm::normalize(toCentre)))) ++partial;
    }
    CHECK(partial >= 6);
}

TEST_CASE("A linear light over a long box edge: the penumbra profile within EPS", "[lights]") {
    const AsosSettings settings{1.0 / 64.0, 7, false};
    // A box standing on the ground, its top edge along x at z = 0, y = 1; a
    // linear light across it at height 5 from z = -1 to z = 1 (axis2 of zero
    // length). A ground point at z0 sees the light point at z through the
    // edge's plane when z0 + (z - z0) / 5 >= 0.
    Object box = makeObject(BoxShape{{-50, 0, -50}, {50, 1, 0}}, litTexture(Vec3(1.0)));
    LightSetupScene s(areaLight({0, 5, 0}, {0, 0, 2}, {0, 0, 0}, 16, 1), {box});
    const LightModel model = makeLightModel(s.d.lights[0], settings);
    REQUIRE(std::holds_alternative<SegmentLight>(model.form));
    const Vec3 up(0, 1, 0);
    for (double z0 = 0.01; z0 < 0.3; z0 += 0.02) {
        const Vec3 p(0.3, 0, z0);
        const double exact = integrate(20000, 1, [&](double f, double) {
            const double z = -1.0 + 2.0 * f;
            if (z0 + (z - z0) / 5.0 < 0.0) return 0.0;
            return std::max(0.0, glm::dot(up, glm::normalize(Vec3(-0.3, 5.0, z - z0))));
        });
        const double asos = s.received(LightMethod::Asos, settings, p, up);
        INFO("z0 = " << z0 << ": exact " << exact << ", asos " << asos);
        CHECK(std::abs(asos - exact) <= settings.eps);
        RenderCounters counters;
        const double grid = s.received(LightMethod::Grid, settings, p, up, counters, 0, 256);
        CHECK(std::abs(grid - exact) <= 1.0 / 256.0 + 1e-3);
    }
    // The profile falls from the lit side to the edge: half the light at
    // z0 = 0 (exactly above z = 0 ... 1 of the segment seen).
    const double atEdge = s.received(LightMethod::Asos, settings, {0.3, 0, 1e-6}, up);
    CHECK(atEdge == Approx(0.5).margin(settings.eps));
}

TEST_CASE("Jittered MAX-beams and grids are deterministic and stay within the light", "[lights]") {
    const AsosSettings settings{1.0 / 64.0, 3, true};
    Object occluder = makeObject(SphereShape{{0.2, 2, 0}, 0.5}, litTexture(Vec3(1.0)));
    LightSetupScene s(areaLight({0, 5, 0}, {2, 0, 0}, {0, 0, 2}, 8, 8), {occluder});
    s.d.lights[0].area->jitter = true;
    const Vec3 up(0, 1, 0), p(0.9, 0, 0.1);
    LightSetup setup;
    setup.method = LightMethod::Asos;
    setup.sceneSettings = settings;
    const SceneLights lights(s.d, setup);
    auto samplesOf = [&](std::uint64_t key) {
        AreaLightQuery q;
        q.point = p;
        q.normal = up;
        q.rng = PixelRandom(7, 3, 4);
        q.key = key;
        RenderCounters counters;
        const auto span = areaLightSamples(*s.scene, lights, q, s.scratch, counters);
        return std::vector<LightSample>(span.begin(), span.end());
    };
    const std::vector<LightSample> a = samplesOf(1), b = samplesOf(1), c = samplesOf(2);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) CHECK(a[i].direction == b[i].direction);
    bool differs = a.size() != c.size();
    for (std::size_t i = 0; i < std::min(a.size(), c.size()); ++i) differs = differs || a[i].direction != c[i].direction;
    CHECK(differs);
    // Every sample points at the light's rectangle.
    for (const LightSample& sample : a) {
        const Vec3 y = p + sample.distance * sample.direction;
        CHECK(y.y == Approx(5.0));
        CHECK(std::abs(y.x) <= 1.0 + 1e-9);
        CHECK(std::abs(y.z) <= 1.0 + 1e-9);
    }
}

TEST_CASE("POV-Ray's adaptive corner scheme: corners first, splits where they disagree", "[lights]") {
    // 5 x 5 points on POV-Ray's lattice from edge to edge, columns at x =
    // -1, -0.5, 0, 0.5, 1; a box hides the columns x <= 0 from the point
    // below it.
    Object wall = makeObject(BoxShape{{-50, 2, -50}, {0.02, 2.2, 50}}, litTexture(Vec3(1.0)));
    Light light = areaLight({0, 5, 0}, {2, 0, 0}, {0, 0, 2}, 5, 5, false, LightEmitter::Povray);
    light.area->adaptive = 0;
    LightSetupScene s(light, {wall});
    const AsosSettings settings;
    const Vec3 up(0, 1, 0);
    RenderCounters counters;
    // Far on the lit side: the four corners agree: four rays.
    s.received(LightMethod::Grid, settings, {30, 0, 0}, up, counters);
    CHECK(counters.shadowRays == 4);
    // Straight below the wall's edge: the corners disagree, and the
    // rectangles across the edge split: the right half's rectangles are
    // (1/2 + 1) / 2 of the light, the left's nothing: 3/8 (the trapezoid
    // weights 1, 2, 2, 2, 1 over 8 of the lit columns, here).
    counters = {};
    const double lit = s.received(LightMethod::Grid, settings, {0, 0, 0}, up, counters);
    CHECK(counters.shadowRays > 4);
    CHECK(counters.shadowRays < 25);
    CHECK(lit == Approx(0.375).epsilon(1e-12));  // cos 1 straight below the centre
    // Without adaptive, POV-Ray's default level 100: every point, every rectangle split.
    s.d.lights[0].area->adaptive.reset();
    counters = {};
    s.received(LightMethod::Grid, settings, {30, 0, 0}, up, counters);
    CHECK(counters.shadowRays == 25);
    // A faded light's colour is compared faded: at fade 2 / (1 + 10^2) the
    // corners' colours differ by less than 0.1, and adaptive 0 stops at them
    // whatever they say; with area_illumination the colour is unfaded.
    s.d.lights[0].area->adaptive = 0;
    s.d.lights[0].fadeDistance = 0.5;
    s.d.lights[0].fadePower = 2.0;
    counters = {};
    s.received(LightMethod::Grid, settings, {0, 0, 0}, up, counters);
    CHECK(counters.shadowRays == 4);
    s.d.lights[0].areaIllumination = true;
    counters = {};
    s.received(LightMethod::Grid, settings, {0, 0, 0}, up, counters);
    CHECK(counters.shadowRays > 4);
}

TEST_CASE("POV-Ray's corner recursion weighs its lattice from edge to edge", "[lights]") {
    // A linear light from x = -2 to 2 at height 5, a box just below it
    // hiding x < 0.3 from the point straight below: the visible fraction is
    // the weights of the lit lattice points, POV-Ray's recursion's (level
    // 100, every rectangle split): the trapezoid rule for 2^k + 1 points,
    // equal weights for 2^k, uneven ones otherwise.
    Object box = makeObject(BoxShape{{-50, 4.9, -50}, {0.3, 4.95, 50}}, litTexture(Vec3(1.0)));
    struct Case {
        int n;
        double visible;
    };
    // Lattice x_i = -2 + 4 i / (n - 1); lit where x_i > 0.3 / 0.98.
    const Case cases[] = {{3, 1.0 / 4.0},  {4, 2.0 / 4.0},  {5, 3.0 / 8.0},
                          {6, 4.0 / 8.0},  {7, 3.0 / 8.0},  {9, 7.0 / 16.0}};
    for (const Case& c : cases) {
        INFO(c.n << " points");
        LightSetupScene s(areaLight({0, 5, 0}, {4, 0, 0}, {0, 0, 0}, c.n, 1, false, LightEmitter::Povray), {box});
        RenderCounters counters;
        CHECK(s.received(LightMethod::Grid, AsosSettings{}, {0, 0, 0}, {0, 1, 0}, counters) ==
              Approx(c.visible).epsilon(1e-12));
        CHECK(counters.shadowRays == std::uint64_t(c.n));
        // --light-samples N: N points on the same lattice.
        CHECK(s.received(LightMethod::Grid, AsosSettings{}, {0, 0, 0}, {0, 1, 0}, counters, 0, c.n) ==
              Approx(c.visible).epsilon(1e-12));
    }
}

TEST_CASE("POV-Ray's emitter, unoccluded: the light's colour along its centre, no shadow ray", "[lights]") {
    const AsosSettings settings{1.0 / 64.0, 4, false};
    const Vec3 up(0, 1, 0);
    struct Case {
        const char* what;
        Light light;
        Vec3 point, normal;
    };
    const Vec3 tilted = glm::normalize(Vec3(0.0, 1.0, 1.0));
    const Case cases[] = {
        {"rectangle, near", areaLight({0, 1, 0}, {2, 0, 0}, {0, 0, 2}, 4, 4, false, LightEmitter::Povray),
         {0.8, 0, -0.5}, up},
        {"rectangle, grazing", areaLight({0, 1, 0}, {2, 0, 0}, {0, 0, 2}, 4, 4, false, LightEmitter::Povray),
         {12, 0, 0}, up},
        {"rectangle, tilted surface", areaLight({0, 3, 0}, {2, 0, 0}, {0, 0, 2}, 4, 4, false, LightEmitter::Povray),
         {0, 0, -3}, tilted},
        {"segment", areaLight({0, 2, 0}, {3, 0, 0}, {0, 0, 0}, 8, 1, false, LightEmitter::Povray), {1, 0, 0.5},
         up},
        {"disc", areaLight({0, 2, 0}, {3, 0, 0}, {0, 0, 3}, 8, 8, true, LightEmitter::Povray), {0.7, 0, 0.2},
         up},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        LightSetupScene s(c.light, {});
        const Vec3 toCentre = glm::normalize(c.light.position - c.point);
        const double expected = std::max(0.0, glm::dot(c.normal, toCentre));
        RenderCounters counters;
        CHECK(s.received(LightMethod::Asos, settings, c.point, c.normal, counters) == Approx(expected).epsilon(1e-12));
        CHECK(counters.shadowRays == 0);
        CHECK(s.received(LightMethod::Grid, settings, c.point, c.normal) == Approx(expected).epsilon(1e-12));
    }
    // The light's centre below the horizon: nothing, though part of the
    // light is above it (POV-Ray tests the centre before any shadow ray).
    LightSetupScene s(areaLight({0, 1, 0}, {4, 0, 0}, {0, 0, 4}, 4, 4, false, LightEmitter::Povray), {});
    const Vec3 leaning = glm::normalize(Vec3(1.0, -0.1, 0.0));
    RenderCounters counters;
    CHECK(s.received(LightMethod::Asos, settings, {0, 0, 0}, leaning, counters) == 0.0);
    CHECK(s.received(LightMethod::Grid, settings, {0, 0, 0}, leaning, counters) == 0.0);
    CHECK(counters.shadowRays == 0);
    // With area_illumination each of POV-Ray's lattice points lights the
    // point along its own direction (1/16 of the light each), those above
    // the horizon only: no centre test.
    s.d.lights[0].areaIllumination = true;
    double expected = 0.0;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const Vec3 y(-2.0 + 4.0 * i / 3.0, 1.0, -2.0 + 4.0 * j / 3.0);
            expected += std::max(0.0, glm::dot(leaning, glm::normalize(y))) / 16.0;
        }
    REQUIRE(expected > 0.05);
    CHECK(s.received(LightMethod::Asos, settings, {0, 0, 0}, leaning) == Approx(expected).epsilon(1e-12));
    CHECK(s.received(LightMethod::Grid, settings, {0, 0, 0}, leaning) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("POV-Ray's isotropic emitter and the paper's panel against dense integration, across a penumbra",
          "[lights]") {
    // A sphere between the point and each light. POV-Ray's emitter: the
    // visible fraction V of the light (uniform over the rectangle and the
    // segment, POV-Ray's density over its disc) times the cosine along the
    // centre; the panel: each element's cos theta and own cosine. ASOS
    // within EPS of each; POV-Ray's grid at 33 points a side (the trapezoid
    // rule) within the lattice's resolution.
    const AsosSettings settings{1.0 / 64.0, 6, false};
    const Vec3 lightCentre(0, 6, 0), occluderCentre(0, 3, 0);
    const double occluderRadius = 0.8;
    const Vec3 up(0, 1, 0);
    const auto visibleFrom = [&](const Vec3& p) {
        return [&, p](const Vec3& y) { return !segmentMeetsSphere(p, y, occluderCentre, occluderRadius); };
    };
    struct Form {
        const char* what;
        Vec3 axis2;
        int n2;
        bool orient;
    };
    const Form forms[] = {{"rectangle", {0, 0, 2}, 33, false}, {"segment", {0, 0, 0}, 1, false},
                          {"disc", {0, 0, 2}, 33, true}};
    for (const Form& f : forms) {
        Object occluder = makeObject(SphereShape{occluderCentre, occluderRadius}, litTexture(Vec3(1.0)));
        LightSetupScene pov(areaLight(lightCentre, {2, 0, 0}, f.axis2, 33, f.n2, f.orient, LightEmitter::Povray),
                            {occluder});
        LightSetupScene panel(areaLight(lightCentre, {2, 0, 0}, f.axis2, 33, f.n2, f.orient, LightEmitter::Panel),
                              {occluder});
        int partial = 0;
        double largestGap = 0.0;
        for (double x = 0.0; x <= 3.0; x += 0.25) {
            const Vec3 p(x, 0, 0.3 * x);
            const auto visible = visibleFrom(p);
            // The light's points, over the unit square (s, t).
            std::function<Vec3(double, double)> pointAt;
            if (f.orient) {
                const Frame frame = povrayOrientFrame(glm::normalize(lightCentre - p));
                pointAt = [&, frame](double s1, double s2) {
                    const Vec2 d = povrayDisc(s1, s2);
                    return lightCentre + 1.0 * (d.x * frame.u + d.y * frame.v);
                };
            } else {
                pointAt = [&](double s1, double s2) {
                    return lightCentre + (s1 - 0.5) * Vec3(2, 0, 0) + (s2 - 0.5) * f.axis2;
                };
            }
            const int m = f.n2 == 1 ? 1 : 400;
            const double V = integrate(f.n2 == 1 ? 20000 : 400, m, [&](double s1, double s2) {
                return visible(pointAt(s1, s2)) ? 1.0 : 0.0;
            });
            const double exact = V * glm::dot(up, glm::normalize(lightCentre - p));
            const double asos = pov.received(LightMethod::Asos, settings, p, up);
            const double grid = pov.received(LightMethod::Grid, settings, p, up);
            INFO(f.what << " x = " << x << ": V " << V << ", exact " << exact << ", asos " << asos << ", grid "
                        << grid);
            CHECK(std::abs(asos - exact) <= settings.eps);
            CHECK(std::abs(grid - exact) <= 0.02);
            if (V > 0.05 && V < 0.95) ++partial;
            // The paper's panel: ASOS within EPS of its own integral.
            if (!f.orient) {
                double panelExact;
                if (f.n2 == 1) {
                    panelExact = integrate(20000, 1, [&](double s1, double) {
                        const Vec3 y = pointAt(s1, 0.5);
                        return visible(y) ? std::max(0.0, glm::dot(up, glm::normalize(y - p))) : 0.0;
                    });
                } else {
                    const LightModel model = makeLightModel(panel.d.lights[0], settings);
                    panelExact = exactRectangle(model, p, up, [&](const Vec3&, const Vec3& y) { return visible(y); });
                }
                const double panelAsos = panel.received(LightMethod::Asos, settings, p, up);
                INFO("panel: exact " << panelExact << ", asos " << panelAsos);
                CHECK(std::abs(panelAsos - panelExact) <= settings.eps);
                largestGap = std::max(largestGap, std::abs(panelExact - exact));
            }
        }
        CHECK(partial >= 3);
        // The two emitters are different lights.
        if (f.n2 > 1 && !f.orient) CHECK(largestGap > 0.02);
    }
}

TEST_CASE("POV-Ray's emitter below the horizon: a solid shaded object hides it, a flat one does not",
          "[lights]") {
    const AsosSettings settings{1.0 / 64.0, 6, false};
    // A point on a unit sphere (object 1) whose tangent plane cuts a large
    // light above it: POV-Ray's rays toward the light's points below the
    // plane enter the sphere and are blocked, those above pass: V is the
    // share of the light above the plane, x > -1 / (2 sin 60 deg) here.
    const double theta = kPi / 3.0;
    const Vec3 p(std::sin(theta), std::cos(theta), 0.0), n = p;
    Object ball = makeObject(SphereShape{{0, 0, 0}, 1.0}, litTexture(Vec3(1.0)));
    LightSetupScene s(areaLight({0, 3, 0}, {6, 0, 0}, {0, 0, 6}, 33, 33, false, LightEmitter::Povray), {ball});
    const double cut = (1.0 - 3.0 * std::cos(theta)) / std::sin(theta);
    const double V = (3.0 - cut) / 6.0;
    const double cosCentre = glm::dot(n, glm::normalize(Vec3(0, 3, 0) - p));
    REQUIRE(cosCentre > 0.1);
    RenderCounters counters;
    const double asos = s.received(LightMethod::Asos, settings, p, n, counters, 1);
    const double grid = s.received(LightMethod::Grid, settings, p, n, counters, 1);
    INFO("V " << V << ", asos " << asos / cosCentre << ", grid " << grid / cosCentre);
    CHECK(std::abs(asos / cosCentre - V) <= settings.eps);
    CHECK(std::abs(grid / cosCentre - V) <= 1.0 / 32.0);
    // The shaded sphere is the one occluder and is known in closed form
    // (rays below the tangent plane enter it): the beams subdivide along
    // the plane's line across the light only, not down to MAX over all of
    // it (64 x 64 MAX-beams).
    CHECK(counters.shadowRays < 64 * 64);
    // Seen from inside (the shading normal turned inward), the sphere's far
    // side hides a light beyond it from the lowest point, whose rays toward
    // it all enter the sphere.
    LightSetupScene above(areaLight({0, 3, 0}, {1, 0, 0}, {0, 0, 1}, 5, 5, false, LightEmitter::Povray), {ball});
    for (LightMethod method : {LightMethod::Asos, LightMethod::Grid}) {
        RenderCounters inside;
        CHECK(above.received(method, settings, {0, -1, 0}, {0, 1, 0}, inside, 1, std::nullopt, Vec3(0, -1, 0)) ==
              0.0);
    }
    // A vertical light standing across the ground plane: a point of the
    // plane sees all of it (its rays below the plane leave the plane).
    LightSetupScene flat(areaLight({0, 0.5, 3}, {2, 0, 0}, {0, 2, 0}, 9, 9, false, LightEmitter::Povray), {});
    const Vec3 up(0, 1, 0);
    const double cosFlat = glm::dot(up, glm::normalize(Vec3(0, 0.5, 3)));
    CHECK(flat.received(LightMethod::Asos, settings, {0, 0, 0}, up) == Approx(cosFlat).epsilon(1e-12));
    CHECK(flat.received(LightMethod::Grid, settings, {0, 0, 0}, up) == Approx(cosFlat).epsilon(1e-12));
}

TEST_CASE("POV-Ray's map: square rings to circles, angles kept, denser toward the diagonals", "[lights]") {
    // The image of (s, t) lies at the radius max(|a|, |b|) of (a, b) = (2s -
    // 1, 2t - 1), in its direction.
    for (double s1 : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0})
        for (double s2 : {0.0, 0.25, 0.5, 0.9}) {
            const double a = 2 * s1 - 1, b = 2 * s2 - 1;
            const Vec2 d = povrayDisc(s1, s2);
            CHECK(glm::length(d) == Approx(std::max(std::abs(a), std::abs(b))).margin(1e-15));
            if (a != 0.0 || b != 0.0) CHECK(std::atan2(d.y, d.x) == Approx(std::atan2(b, a)).margin(1e-12));
        }
    // Not equal-area: the cell on the diagonal of a 4 x 4 grid's ring holds
    // less of the disc than the cell on the axis (the density grows as
    // 1 / cos^2 of the angle from the axis).
    const auto area = [](double s0, double t0, double size) {
        double sum = 0.0;
        const int steps = 400;
        Vec2 previous = povrayDisc(s0, t0);
        for (int k = 1; k <= 4 * steps; ++k) {
            const int side = (k - 1) / steps;
            const double f = double(k - side * steps) / steps * size;
            double s1 = s0, s2 = t0;
            if (side == 0) s1 += f;
            else if (side == 1) s1 += size, s2 += f;
            else if (side == 2) s1 += size - f, s2 += size;
            else s2 += size - f;
            const Vec2 q = povrayDisc(s1, s2);
            sum += previous.x * q.y - q.x * previous.y;
            previous = q;
        }
        return std::abs(sum) / 2.0;
    };
    const double diagonal = area(0.75, 0.75, 0.25), axis = area(0.75, 0.5, 0.25);
    CHECK(diagonal < 0.85 * axis);
    CHECK(area(0.0, 0.0, 1.0) == Approx(kPi).epsilon(1e-4));
}

TEST_CASE("The concentric map takes equal areas of the square to equal areas of the disc", "[lights]") {
    // The image of each of the 16 cells of a 4 x 4 grid, by the shoelace
    // formula over its mapped boundary, is 1/16 of the disc.
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            double area = 0.0;
            const int steps = 400;
            Vec2 previous = concentricDisc(i / 4.0, j / 4.0);
            for (int k = 1; k <= 4 * steps; ++k) {
                const int side = (k - 1) / steps;
                const double f = double(k - side * steps) / steps;
                double s = i / 4.0, t = j / 4.0;
                if (side == 0) s += f / 4.0;
                else if (side == 1) s += 0.25, t += f / 4.0;
                else if (side == 2) s += 0.25 - f / 4.0, t += 0.25;
                else t += 0.25 - f / 4.0;
                const Vec2 p = concentricDisc(s, t);
                area += previous.x * p.y - p.x * previous.y;
                previous = p;
            }
            CHECK(std::abs(area) / 2.0 == Approx(kPi / 16.0).epsilon(2e-3));
        }
    CHECK(glm::length(concentricDisc(1.0, 0.5)) == Approx(1.0));
    CHECK(glm::length(concentricDisc(0.5, 0.5)) == 0.0);
}

TEST_CASE("The apex behind the surface averages a sharp shadow over the eye pyray's footprint",
          "[lights]") {
    // A thin slab just above the floor, its edge along z at x = 1: its
    // shadow on the floor is sharp (the penumbra is 0.005 wide) under a
    // 2 x 2 light five units up. A pixel's footprint 0.1 wide reaches from
    // x = 0.98 to 1.08: a fifth of it lies in the shadow.
    Camera camera;
    camera.projection = Camera::Projection::Orthographic;
    const double pixel = 0.1;
    camera.location = {0.5 * 64 * pixel, 10.0, -0.5 * 64 * pixel};
    camera.direction = {0.0, -1.0, 0.0};
    camera.right = {64 * pixel, 0.0, 0.0};
    camera.up = {0.0, 0.0, 64 * pixel};
    const CameraModel cameraModel(camera, 64, 64);
    Object slab = makeObject(BoxShape{{-50, 0.001, -50}, {1.0, 0.011, 50}}, litTexture(Vec3(1.0)));
    LightSetupScene s(areaLight({1.0, 5, -1.6}, {2, 0, 0}, {0, 0, 2}, 8, 8), {slab});
    s.d.camera = camera;
    const ImageSquare square{9.8, 16.0, 10.8, 17.0};
    const Vec3 up(0, 1, 0);
    const Vec3 centre = cameraModel.ray(square.uMid(), square.vMid()).at(10.0);
    REQUIRE(centre.x == Approx(1.03));
    const Footprint footprint(cameraModel, square, centre, up, 10.0);
    const AsosSettings settings{1.0 / 256.0, 6, false};
    auto receivedAt = [&](const Vec3& p, ShadowApex apex) {
        LightSetup setup;
        setup.method = LightMethod::Asos;
        setup.sceneSettings = settings;
        setup.apex = apex;
        const SceneLights lights(s.d, setup);
        AreaLightQuery q;
        q.point = p;
        q.normal = up;
        q.footprint = &footprint;
        RenderCounters counters;
        return diffuseIrradiance(areaLightSamples(*s.scene, lights, q, s.scratch, counters), up).x;
    };
    // The footprint's average, point by point from the surface.
    double average = 0.0;
    const int m = 40;
    for (int i = 0; i < m; ++i) {
        const double u = square.u0 + (i + 0.5) / m * (square.u1 - square.u0);
        average += receivedAt(cameraModel.ray(u, square.vMid()).at(10.0), ShadowApex::Surface) / m;
    }
    const double atCentre = receivedAt(centre, ShadowApex::Surface);
    const double behind = receivedAt(centre, ShadowApex::Behind);
    INFO("average " << average << ", from the centre " << atCentre << ", from behind " << behind);
    CHECK(atCentre - average > 0.1);               // the centre is lit: the paper's beam aliases
    CHECK(std::abs(behind - average) < 0.02);      // the beam from behind sees the footprint
    CHECK(behindApex(makeLightModel(s.d.lights[0], settings), centre, up, footprint).has_value());
}

TEST_CASE("The ASOS beams' weighted diffuse sum makes mergeDiffuse's sample", "[lights]") {
    const Vec3 colour(0.8, 0.5, 0.25);
    const Vec3 dirs[3] = {glm::normalize(Vec3(0.1, 1.0, 0.2)), glm::normalize(Vec3(-0.3, 1.0, 0.0)),
                          glm::normalize(Vec3(0.0, 1.0, -0.4))};
    const double distances[3] = {5.0, 5.5, 6.0}, weights[3] = {0.25, 0.125, 0.5};
    WeightedDiffuseSum sum;
    std::vector<LightSample> samples;
    for (int i = 0; i < 3; ++i) {
        sum.add(dirs[i], distances[i], weights[i]);
        samples.push_back({dirs[i], distances[i], colour * weights[i]});
        LightSample storage;
        const std::span<const LightSample> merged = mergeDiffuse(samples, storage);
        REQUIRE(merged.size() == 1);
        const std::optional<LightSample> made = sum.merged(colour);
        REQUIRE(made);
        CHECK(glm::length(made->direction - merged[0].direction) <= 1e-14);
        CHECK(made->distance == Approx(merged[0].distance).epsilon(1e-14));
        CHECK(glm::length(made->color - merged[0].color) <= 1e-14);
    }
    // No light: no sample.
    WeightedDiffuseSum none;
    none.add(dirs[0], 5.0, 0.5);
    none.add(dirs[0], 5.0, -0.5);
    CHECK_FALSE(none.merged(colour));
}

TEST_CASE("A convex occluder's shadow on the point samples: every ray's answer, from fewer rays", "[lights]") {
    // The same tilted square as a polygon of one convex loop, and as a loop
    // that runs back along one edge (the same region, not known to be
    // convex). ASOS sends every point the same light from both, bit for bit;
    // with the convex one the point samples' shadow is found by
    // ConvexLattice, with fewer shadow rays.
    const AsosSettings settings{1.0 / 64.0, 4, false};
    const Vec3 o(-0.4, 1.2, 0.3), u(1.6, 0.3, 0.2), v(-0.2, 0.4, 1.5);
    const auto at = [&](double a, double b) { return o + a * u + b * v; };
    const std::vector<Vec3> convex = {at(0, 0), at(1, 0), at(1, 1), at(0, 1), at(0, 0)};
    const std::vector<Vec3> twin = {at(0, 0), at(1, 0), at(1, 1), at(0, 1), at(0, 0.25), at(0, 0.5), at(0, 0)};
    const Light lights[] = {areaLight({0.5, 5, 0.5}, {3, 0, 0}, {0, 0, 2.5}, 8, 8),
                            areaLight({0.5, 5, 0.5}, {3, 0, 0.5}, {0, 0, 0}, 16, 1)};
    for (const Light& light : lights) {
        LightSetupScene a(light, {makeObject(PolygonShape{convex}, litTexture(Vec3(1.0)))});
        LightSetupScene b(light, {makeObject(PolygonShape{twin}, litTexture(Vec3(1.0)))});
        REQUIRE(a.scene->primitive(1).convex());
        REQUIRE_FALSE(b.scene->primitive(1).convex());
        RenderCounters fromConvex, fromTwin;
        const Vec3 up(0, 1, 0);
        int compared = 0;
        for (double x = -2.5; x <= 3.5; x += 0.125)
            for (double z = -2.0; z <= 4.0; z += 0.125) {
                const Vec3 p(x, 0.0, z);
                const double la = a.received(LightMethod::Asos, settings, p, up, fromConvex);
                const double lb = b.received(LightMethod::Asos, settings, p, up, fromTwin);
                INFO("point " << x << ", " << z);
                REQUIRE(la == lb);
                ++compared;
            }
        CHECK(compared > 2000);
        INFO("shadow rays: convex " << fromConvex.shadowRays << ", twin " << fromTwin.shadowRays);
        CHECK(fromConvex.shadowRays < fromTwin.shadowRays);
    }
}
