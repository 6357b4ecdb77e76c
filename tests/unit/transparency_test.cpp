#include <catch2/catch.hpp>

#include <cmath>

#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/render/interiors.hpp"
#include "asos/render/spectral.hpp"
#include "asos/render/shading.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }

// A pane on z = 0 of colour `c`, lit by ambient only (1 x ambient_light 1).
Texture pane(const Color& c) {
    Texture t;
    t.pigment.color1 = c;
    t.finish.ambient = Vec3(1.0);
    t.finish.diffuse = 0.0;
    return t;
}

SurfaceHit paneHit() {
    SurfaceHit h;
    h.t = 1.0;
    h.position = {0, 0, 0};
    h.normal = {0, 0, -1};
    return h;
}

// What a pane shades to when `behind` is seen through it; `rays` counts the
// times what is behind is asked for.
Vec3 shadePane(const Color& c, const Vec3& behind, int& rays, int depth = 1, const ShadingSettings& s = {}) {
    const Texture t = pane(c);
    const Ray ray{{0, 0, -1}, {0, 0, 1}};
    return shadeSurface(
        {paneHit(), t, ray, depth}, {}, s, [](const ShadingPoint&) { return std::span<const LightSample>(); },
        [](const Ray&, int, double) { return Vec3(0.0); },
        [&](const Vec3&, double) {
            ++rays;
            return Transmitted{behind, false};
        });
}
}  // namespace

TEST_CASE("A pane of filter 1 in front of white shows its own colour", "[transparency]") {
    int rays = 0;
    // rgbf <0.2, 0.5, 0.9, 1>: opacity 0, so no ambient of its own; white
    // behind, filtered by the colour.
    const Vec3 c = shadePane({{0.2, 0.5, 0.9}, 1.0, 0.0}, Vec3(1.0), rays);
    CHECK(near(c, {0.2, 0.5, 0.9}));
    CHECK(rays == 1);
}

TEST_CASE("transmit t gives t x behind + (1 - t) x the surface's shading", "[transparency]") {
    int rays = 0;
    const Vec3 surface{0.8, 0.4, 0.2};
    const Vec3 behind{0.1, 0.6, 1.0};
    const Vec3 c = shadePane({surface, 0.0, 0.3}, behind, rays);
    CHECK(near(c, 0.3 * behind + 0.7 * surface));
    // filter and transmit together: opacity 1 - f - t; behind x (f x colour + t).
    const Vec3 both = shadePane({surface, 0.25, 0.5}, behind, rays);
    CHECK(near(both, 0.25 * surface + behind * (0.25 * surface + Vec3(0.5))));
}

TEST_CASE("An opaque pane traces nothing behind it, and max_trace_level stops the ray", "[transparency]") {
    int rays = 0;
    CHECK(near(shadePane({Vec3(0.5), 0.0, 0.0}, Vec3(1.0), rays), Vec3(0.5)));
    CHECK(rays == 0);
    // At the last trace level, nothing behind (POV-Ray's TraceRay).
    ShadingSettings s;
    s.maxTraceLevel = 3;
    CHECK(near(shadePane({Vec3(0.5), 0.0, 1.0}, Vec3(1.0), rays, 3, s), Vec3(0.0)));
    CHECK(rays == 0);
    // Below adc_bailout: nothing traced.
    CHECK(near(shadePane({Vec3(0.5), 0.0, 0.001}, Vec3(1.0), rays), Vec3(0.999 * 0.5)));
    CHECK(rays == 0);
}

TEST_CASE("A shadow through a filtering pane is tinted by it", "[transparency]") {
    // A white floor y = 0 lit from straight above through a pane at y = 1 of
    // rgbf <1, 0.5, 0, 0.8>: the light's colour x (0.8 x colour + 0).
    SceneDescription d;
    d.camera = lookAtCamera({0, 5, -5}, {0, 0, 0}, 40);
    d.lights.push_back(pointLight({0, 10, 0}));
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0}, litTexture(Vec3(1.0), 0.0, 1.0)));
    Texture glass = pane({{1.0, 0.5, 0.0}, 0.8, 0.0});
    d.objects.push_back(makeObject(BoxShape{{-1, 1, -1}, {1, 1.01, 1}}, glass));
    Diagnostics diagnostics;
    const std::unique_ptr<Scene> scene = Scene::build(d, diagnostics);
    REQUIRE(scene);
    const RayTracer tracer(*scene);
    RenderCounters counters;
    // The box's two faces filter alike: (0.8 x colour)^2.
    const Vec3 f = tracer.shadowRayFilter({0, 0, 0}, {0, 10, 0}, counters);
    CHECK(near(f, {0.64, 0.16, 0.0}));
    // Outside the pane's shadow: unfiltered.
    CHECK(near(tracer.shadowRayFilter({3, 0, 0}, {3, 10, 0}, counters), Vec3(1.0)));
    // An opaque occluder blocks, whatever else is on the ray.
    d.objects.push_back(makeObject(SphereShape{{0, 5, 0}, 0.5}, litTexture(Vec3(1.0))));
    const std::unique_ptr<Scene> blocked = Scene::build(d, diagnostics);
    REQUIRE(blocked);
    CHECK(RayTracer(*blocked).shadowRayFilter({0, 0, 0}, {0, 10, 0}, counters) == Vec3(0.0));
    // no_shadow: the pane casts none.
    d.objects.pop_back();
    d.objects.back().noShadow = true;
    const std::unique_ptr<Scene> free = Scene::build(d, diagnostics);
    REQUIRE(free);
    CHECK(near(RayTracer(*free).shadowRayFilter({0, 0, 0}, {0, 10, 0}, counters), Vec3(1.0)));
}

namespace {
// An 8 x 6 orthographic image of a white disc's edge (coverage shading)
// across its pixels, with or without a pane in front covering everything.
std::optional<RenderOutput> edgeBehindPane(std::optional<Color> paneColour, RenderMethod method) {
    SceneDescription d;
    d.camera = orthoCamera(8, 6);
    d.objects.push_back(makeObject(DiscShape{{1.3, -2.7, 0}, {0, 0, -1}, 3.1, 0.0}, coverageTexture()));
    if (paneColour) {
        Texture t = pane(*paneColour);
        t.finish.ambient = Vec3(0.0);
        d.objects.push_back(makeObject(BoxShape{{-1, -7, -5}, {9, 1, -4}}, t));
    }
    RenderSettings s;
    s.width = 8;
    s.height = 6;
    s.method = method;
    Diagnostics diagnostics;
    return render(d, s, diagnostics);
}
}  // namespace

TEST_CASE("ASOS sees the edges behind a transparent object", "[transparency][asos]") {
    // A clear pane (transmit 1) changes nothing, pixel for pixel: its two
    // faces hide nothing, so the disc's edge is subdivided as without it.
    const auto bare = edgeBehindPane(std::nullopt, RenderMethod::Asos);
    const auto clear = edgeBehindPane(Color{Vec3(1.0), 0.0, 1.0}, RenderMethod::Asos);
    REQUIRE(bare);
    REQUIRE(clear);
    int edgePixels = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const double v = bare->color.at(x, y, 0);
            if (v > 0.02 && v < 0.98) ++edgePixels;
            CHECK(clear->color.at(x, y, 0) == Approx(v).margin(1e-9));
            CHECK(clear->samples.at(x, y, 0) >= 1.0);
        }
    CHECK(edgePixels >= 4);
    // A filtering pane (filter 1, colour c) gives c^2 x the image behind it
    // (two faces), the edges' coverage included.
    const auto tinted = edgeBehindPane(Color{{0.5, 0.8, 1.0}, 1.0, 0.0}, RenderMethod::Asos);
    REQUIRE(tinted);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const double v = bare->color.at(x, y, 0);
            CHECK(tinted->color.at(x, y, 0) == Approx(0.25 * v).margin(1e-9));
            CHECK(tinted->color.at(x, y, 1) == Approx(0.64 * v).margin(1e-9));
        }
}

TEST_CASE("Shadows through a filtering pane under every light method", "[transparency]") {
    // A white floor lit from above through a pane of rgbf <1, 0.5, 0, 0.8>
    // (two faces: (0.8 x colour)^2), by a point light and by a small area
    // light, under ASOS and one ray per pixel: the floor below the pane's
    // middle is tinted, the floor outside its shadow is not.
    for (bool area : {false, true})
        for (RenderMethod method : {RenderMethod::Asos, RenderMethod::Single}) {
            INFO((area ? "area light, " : "point light, ") << methodName(method));
            SceneDescription d;
            // Looking down from below the pane (y = 10) at the floor:
            // pixel (u, v) sees (u - 4, 0, 3 - v).
            d.camera.projection = Camera::Projection::Orthographic;
            d.camera.location = {0, 5, 0};
            d.camera.direction = {0, -1, 0};
            d.camera.right = {8, 0, 0};
            d.camera.up = {0, 0, 6};
            Light light = pointLight({0, 20, 0});
            if (area) light.area = AreaLight{{0.2, 0, 0}, {0, 0, 0.2}, 3, 3, std::nullopt, false, false, false};
            d.lights.push_back(light);
            d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0}, litTexture(Vec3(1.0), 0.0, 1.0)));
            Texture glass = pane({{1.0, 0.5, 0.0}, 0.8, 0.0});
            glass.finish.ambient = Vec3(0.0);
            d.objects.push_back(makeObject(BoxShape{{-1.5, 10, -1.5}, {1.5, 10.01, 1.5}}, glass));
            RenderSettings s;
            s.width = 8;
            s.height = 6;
            s.method = method;
            Diagnostics diagnostics;
            const std::optional<RenderOutput> out = render(d, s, diagnostics);
            REQUIRE(out);
            // The shadow of the pane reaches x, z = +-3 on the floor. The
            // light has no fall-off: a point is lit by cos(incidence).
            const auto cosine = [](double x, double z) { return 20.0 / std::sqrt(x * x + z * z + 400.0); };
            CHECK(out->color.at(7, 0, 0) == Approx(cosine(3.5, 2.5)).margin(1e-3));  // (3.5, 0, 2.5): open
            CHECK(out->color.at(4, 3, 0) == Approx(0.64 * cosine(0.5, -0.5)).margin(1e-3));  // (0.5, 0, -0.5)
            CHECK(out->color.at(4, 3, 1) == Approx(0.16 * cosine(0.5, -0.5)).margin(1e-3));
            CHECK(out->color.at(4, 3, 2) == Approx(0.0).margin(1e-9));
        }
}

TEST_CASE("A merge of transparent objects renders as a union, with a warning", "[transparency]") {
    Diagnostics diagnostics;
    const std::optional<SceneDescription> d = lang::interpretText(
        "#version 3.7; global_settings { assumed_gamma 1 } camera { location <0, 0, -5> look_at 0 }\n"
        "light_source { <0, 10, -10> rgb 1 }\n"
        "merge { sphere { 0, 1 } sphere { x, 1 } pigment { rgbf <1, 1, 1, 0.5> } }\n",
        "merge.pov", {}, diagnostics);
    REQUIRE(d);
    diagnostics.clear();
    RenderSettings s;
    s.width = 8;
    s.height = 6;
    s.method = RenderMethod::Single;
    REQUIRE(render(*d, s, diagnostics));
    REQUIRE(diagnostics.all().size() == 1);
    CHECK(diagnostics.all()[0].severity == Severity::Warning);
    CHECK_THAT(diagnostics.all()[0].message, Catch::Contains("inner surfaces"));
    CHECK(diagnostics.all()[0].loc.line == 3);
}

TEST_CASE("Refraction follows Snell's law, with total internal reflection", "[transparency][refraction]") {
    // Into glass (ratio 1/1.5) at 30 degrees from the normal.
    const Vec3 n{0, 0, -1};
    const double a = 30.0 * kPi / 180.0;
    const Vec3 d{std::sin(a), 0, std::cos(a)};
    const std::optional<Vec3> r = refractedDirection(d, n, 1.0 / 1.5);
    REQUIRE(r);
    CHECK(glm::length(*r) == Approx(1.0).epsilon(1e-12));
    CHECK(r->x == Approx(std::sin(a) / 1.5).epsilon(1e-12));  // sin(t) = sin(i) / 1.5
    CHECK(r->z > 0.0);
    // At normal incidence nothing bends.
    CHECK(near(*refractedDirection({0, 0, 1}, n, 1.0 / 1.5), {0, 0, 1}));
    // Out of glass past the critical angle asin(1/1.5) = 41.8 degrees: none.
    const double b = 45.0 * kPi / 180.0;
    CHECK_FALSE(refractedDirection({std::sin(b), 0, std::cos(b)}, n, 1.5));
    CHECK(refractedDirection({std::sin(0.7), 0, std::cos(0.7)}, n, 1.5));  // 40.1 degrees: out
}

TEST_CASE("The insides a ray is in, as POV-Ray keeps them", "[transparency][refraction]") {
    Object glass, water, plain;
    glass.interior = std::make_shared<const Interior>(Interior{1.5});
    water.interior = std::make_shared<const Interior>(Interior{1.33});
    Crossing c = cross({}, glass);  // entering glass from the air
    CHECK(c.iorRatio == Approx(1.0 / 1.5));
    const InteriorList inGlass = c.beyond;
    c = cross(inGlass, water);  // entering water inside glass
    CHECK(c.iorRatio == Approx(1.5 / 1.33));
    c = cross(c.beyond, water);  // leaving the water, back into glass
    CHECK(c.iorRatio == Approx(1.33 / 1.5));
    c = cross(c.beyond, glass);  // leaving the glass into the air
    CHECK(c.iorRatio == Approx(1.5));
    CHECK(c.beyond.empty());
    // Overlapping: (A (B A) B): leaving A while in B is a ratio of 1.
    c = cross(cross(inGlass, water).beyond, glass);
    CHECK(c.iorRatio == 1.0);
    // An object without an interior: ior 1 both ways.
    CHECK(cross({}, plain).iorRatio == 1.0);
}

TEST_CASE("An interior's fade at a known depth", "[transparency][refraction]") {
    Interior in;
    in.fadeDistance = 2.0;
    in.fadePower = 2.0;
    in.fadeColor = Vec3(0.5, 0.2, 0.0);
    // 1 + (4 / 2)^2 = 5: colour + (1 - colour) / 5.
    CHECK(near(fadeThrough(in, 4.0, true), Vec3(0.5 + 0.5 / 5, 0.2 + 0.8 / 5, 0.2), 1e-12));
    in.fadePower = 1000.0;  // exponential
    CHECK(near(fadeThrough(in, 4.0, true), Vec3(std::exp(-1.0), std::exp(-1.6), std::exp(-2.0)), 1e-12));
    // Power 0: eye rays still fade (POV-Ray's ComputeLightedTexture), shadows do not.
    in.fadePower = 0.0;
    CHECK(near(fadeThrough(in, 4.0, true), Vec3(0.75, 0.6, 0.5), 1e-12));
    CHECK(near(fadeThrough(in, 4.0, false), Vec3(1.0), 1e-12));
    CHECK(near(fadeThrough(Interior{}, 4.0, true), Vec3(1.0), 1e-12));
}

TEST_CASE("Dispersion's bands: their iors and hues, as POV-Ray's", "[transparency][dispersion]") {
    // Seven bands of 50 nm from 380 nm; the middle one is at 555 nm, the
    // centre, where the ior is the nominal one.
    const SpectralBand middle = SpectralBand::of(3, 7);
    CHECK(middle.wavelength == Approx(555.0));
    CHECK(middle.bandwidth == Approx(50.0));
    CHECK(middle.ior(1.5, 1.2) == Approx(1.5));
    // The violet end's ior over the red end's is the dispersion.
    const SpectralBand violet{380.0f, 1.0f}, red{730.0f, 1.0f};
    CHECK(violet.ior(1.5, 1.2) / red.ior(1.5, 1.2) == Approx(1.2));
    // The bands' hues average to (nearly) white, whatever their number, so
    // that white seen through glass stays white: the hue integral from 380
    // to 730 nm, (0.9947, 1, 1) - (0.0009, 0, 0.0038).
    for (unsigned n : {2u, 4u, 7u, 20u}) {
        Vec3 sum(0.0);
        for (unsigned i = 0; i < n; ++i) sum += SpectralBand::of(i, n).hue();
        sum /= double(n);
        CHECK(sum.x == Approx(0.9947 - 0.0009).margin(1e-5));
        CHECK(sum.y == Approx(1.0).margin(1e-5));
        CHECK(sum.z == Approx(1.0 - 0.0038).margin(1e-5));
    }
    // Violet bands are blue, red ones red.
    const Vec3 first = SpectralBand::of(0, 7).hue(), last = SpectralBand::of(6, 7).hue();
    CHECK(first.z > first.x);
    CHECK(last.x > last.z);
}
