// Known answers for distributed light sources (paper: "Distributed Light
// Sources"): the light an area light sends a point, by ASOS shadow beams and
// by the classic grid, against a dense numerical integration of the same
// light model computed here (docs/lights.md): a rectangle of intensity
// colour / area with the weighting cos theta, a segment of colour / length,
// a sphere's apparent disc of colour / (pi r^2); each point of the light
// weighted by the cosine of incidence (what a white diffuse surface
// receives), nothing falling off with distance.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "asos/geometry/concentric_disc.hpp"
#include "asos/render/area_light.hpp"
#include "asos/render/area_light_shadow.hpp"
#include "asos/render/grid_light.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

Light areaLight(const Vec3& position, const Vec3& axis1, const Vec3& axis2, int n1, int n2,
                bool orient = false) {
    Light l = pointLight(position, Vec3(1.0));
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
                    std::optional<int> samples = std::nullopt) {
        LightSetup setup;
        setup.method = method;
        setup.sceneSettings = settings;
        setup.samples = samples;
        const SceneLights lights(d, setup);
        AreaLightQuery q;
        q.point = point;
        q.normal = normal;
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
    // 5 x 5 points on POV-Ray's lattice from edge to edge; a box hides the
    // half x < 0 of the light from the point below it.
    Object wall = makeObject(BoxShape{{-50, 2, -50}, {0.0, 2.2, 50}}, litTexture(Vec3(1.0)));
    Light light = areaLight({0, 5, 0}, {2, 0, 0}, {0, 0, 2}, 5, 5);
    light.area->adaptive = 0;
    LightSetupScene s(light, {wall});
    const AsosSettings settings;
    RenderCounters counters;
    // Far on the lit side: the four corners agree: four rays.
    s.received(LightMethod::Grid, settings, {30, 0, 0}, {0, 1, 0}, counters);
    CHECK(counters.shadowRays == 4);
    // Straight below the wall's edge (through the light's middle column):
    // the corners disagree, every level splits along the edge; the middle
    // column is lit (x = 0 grazes the wall's face), the left one dark.
    counters = {};
    const double lit = s.received(LightMethod::Grid, settings, {0, 0, 0}, {0, 1, 0}, counters);
    CHECK(counters.shadowRays > 4);
    CHECK(counters.shadowRays <= 25);
    CHECK(lit > 0.3);
    CHECK(lit < 0.8);
    // Without adaptive, every point.
    s.d.lights[0].area->adaptive.reset();
    counters = {};
    s.received(LightMethod::Grid, settings, {30, 0, 0}, {0, 1, 0}, counters);
    CHECK(counters.shadowRays == 25);
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
