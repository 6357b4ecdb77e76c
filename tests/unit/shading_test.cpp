#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "asos/lights/light_model.hpp"
#include "asos/render/shading.hpp"

using namespace asos;

namespace {
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }

Texture flat(const Vec3& rgb) {
    Texture t;
    t.pigment.color1.rgb = rgb;
    return t;
}

// A hit on the plane y = 0 at the origin, seen from above along `dir`.
SurfaceHit planeHit() {
    SurfaceHit h;
    h.position = {0, 0, 0};
    h.normal = {0, 1, 0};
    return h;
}

struct NoReflection {
    int calls = 0;
    Vec3 operator()(const Ray&, int, double) {
        ++calls;
        return Vec3(0.0);
    }
};
}  // namespace

TEST_CASE("Ambient is pigment times ambient times ambient_light", "[shading]") {
    Texture t = flat({0.5, 0.25, 1.0});
    t.finish.ambient = {0.2, 0.4, 0.1};
    t.finish.diffuse = 0.0;
    const SurfaceHit hit = planeHit();
    const Ray ray{{0, 1, 0}, {0, -1, 0}};
    ShadingSettings s;
    s.ambientLight = {1.0, 0.5, 2.0};
    int lightCalls = 0;
    NoReflection refl;
    const Vec3 c = shadeSurface({hit, t, ray}, {}, s,
                                [&](const ShadingPoint&) {
                                    ++lightCalls;
                                    return std::span<const LightSample>();
                                },
                                refl);
    CHECK(near(c, {0.5 * 0.2 * 1.0, 0.25 * 0.4 * 0.5, 1.0 * 0.1 * 2.0}));
    CHECK(lightCalls == 0);
    CHECK(refl.calls == 0);
}

// Measured with `povray` (no alpha output): rgbt <0.2, 0.3, 0.4, 0.7> gives
// codes 69, 85, 97 seen directly and in a mirror, rgbf the codes of rgb, and a
// transmit of 1.5 or -0.5 scales by -0.5 or 1.5 (reflected, unclipped).
TEST_CASE("The background's transmit darkens it, its filter does nothing", "[shading]") {
    SceneDescription scene;
    scene.background = {{0.2, 0.3, 0.4}, 0.0, 0.0};
    CHECK(near(backgroundColor(scene), {0.2, 0.3, 0.4}));
    scene.background.filter = 0.7;
    CHECK(near(backgroundColor(scene), {0.2, 0.3, 0.4}));
    scene.background = {{0.2, 0.3, 0.4}, 0.5, 0.25};
    CHECK(near(backgroundColor(scene), {0.15, 0.225, 0.3}));
    scene.background.transmit = 1.5;
    CHECK(near(backgroundColor(scene), {-0.1, -0.15, -0.2}));
}

TEST_CASE("crand takes a random share of crand off each light's diffuse intensity", "[shading]") {
    const Vec3 pigment{0.8, 0.6, 0.4};
    Finish f;
    f.diffuse = 0.6;
    f.crand = 0.2;
    Light light;
    const LightSample s{glm::normalize(Vec3(std::sqrt(3.0), 1.0, 0.0)), 10.0, {1.0, 1.0, 0.5}};
    const Vec3 n{0, 1, 0}, eye{0, -1, 0};
    // The caller passes crand times its number; the diffuse intensity loses it.
    CHECK(near(directLight(f, pigment, n, eye, light, s, 0.2 * 0.75), (0.6 * 0.5 - 0.15) * pigment * s.color, 1e-12));

    // Its numbers: in [0, 1), the same for the same pixel, seed and sample,
    // apart for each light, sample, layer and shaded sample.
    const GrainSource a{PixelRandom(7, 3, 4), 11};
    CHECK(a.draw(0, 0, 0) == GrainSource{PixelRandom(7, 3, 4), 11}.draw(0, 0, 0));
    CHECK(a.draw(0, 0, 0) != a.draw(1, 0, 0));
    CHECK(a.draw(0, 0, 0) != a.draw(0, 1, 0));
    CHECK(a.draw(0, 0, 0) != a.draw(0, 0, 1));
    CHECK(a.draw(0, 0, 0) != GrainSource{PixelRandom(7, 3, 4), 12}.draw(0, 0, 0));
    CHECK(a.draw(0, 0, 0) != GrainSource{PixelRandom(8, 3, 4), 11}.draw(0, 0, 0));

    // Over many pixels the grain takes crand / 2 off on average, as
    // POV-Ray's uniform numbers do.
    Texture t = flat(Vec3(1.0));
    t.finish.ambient = Vec3(0.0);
    t.finish.diffuse = 1.0;
    t.finish.crand = 0.2;
    const SurfaceHit hit = planeHit();
    const Ray ray{Vec3(0, 1, 0), Vec3(0, -1, 0)};
    const std::vector<Light> lights(1);
    const LightSample above{{0, 1, 0}, 10.0, {1, 1, 1}};
    double sum = 0.0, lowest = 1.0, highest = 0.0;
    const int count = 20000;
    for (int i = 0; i < count; ++i) {
        const Vec3 c = shadeSurface({hit, t, ray, 1, 1.0, std::nullopt, {PixelRandom(1, i, 0), 0}}, lights,
                                    ShadingSettings{},
                                    [&](const ShadingPoint&) { return std::span<const LightSample>(&above, 1); },
                                    NoReflection{});
        sum += c.x;
        lowest = std::min(lowest, c.x);
        highest = std::max(highest, c.x);
    }
    CHECK(sum / count == Approx(0.9).margin(0.002));
    CHECK(lowest >= 0.8);
    CHECK(highest <= 1.0);
    CHECK(highest - lowest > 0.19);
}

TEST_CASE("Diffuse follows Lambert's cosine raised to brilliance", "[shading]") {
    const Vec3 pigment{0.8, 0.6, 0.4};
    Finish f;
    f.diffuse = 0.6;
    Light light;
    // Light at 60 degrees from the normal: cos = 0.5.
    const LightSample s{glm::normalize(Vec3(std::sqrt(3.0), 1.0, 0.0)), 10.0, {1.0, 1.0, 0.5}};
    const Vec3 n{0, 1, 0}, eye{0, -1, 0};
    CHECK(near(directLight(f, pigment, n, eye, light, s), 0.6 * 0.5 * pigment * s.color, 1e-12));
    f.brilliance = 2.0;
    CHECK(near(directLight(f, pigment, n, eye, light, s), 0.6 * 0.25 * pigment * s.color, 1e-12));
    // From below the surface: nothing, whatever the finish.
    f.phong = 1.0;
    f.specular = 1.0;
    const LightSample below{{0, -1, 0}, 1.0, {1, 1, 1}};
    CHECK(directLight(f, pigment, n, eye, light, below) == Vec3(0.0));
}

TEST_CASE("Phong peaks along the mirror direction with phong_size as exponent", "[shading]") {
    Finish f;
    f.diffuse = 0.0;
    f.phong = 0.7;
    f.phongSize = 40.0;
    Light light;
    const Vec3 n{0, 1, 0};
    const Vec3 eye = glm::normalize(Vec3(1, -1, 0));  // 45 degrees in
    const Vec3 mirror = glm::normalize(Vec3(1, 1, 0));
    const LightSample onMirror{mirror, 5.0, {1, 1, 1}};
    CHECK(near(directLight(f, Vec3(1.0), n, eye, light, onMirror), Vec3(0.7)));
    // 10 degrees off the mirror direction: cos(10)^40.
    const double a = (45.0 - 10.0) * kPi / 180.0;
    const LightSample off{{std::cos(a), std::sin(a), 0.0}, 5.0, {1, 1, 1}};
    CHECK(near(directLight(f, Vec3(1.0), n, eye, light, off),
               Vec3(0.7 * std::pow(std::cos(10.0 * kPi / 180.0), 40.0)), 1e-12));
    // POV-Ray's cut-off: phong_size >= 60 ignores cosines below 0.0008.
    f.phongSize = 80.0;
    const double b = std::acos(0.0005);  // angle from the mirror direction
    const Vec3 farOff = glm::normalize(std::cos(b) * mirror + std::sin(b) * Vec3(0, 0, 1));
    CHECK(directLight(f, Vec3(1.0), n, eye, light, {farOff, 5.0, {1, 1, 1}}) == Vec3(0.0));
    // Highlights are light colour, not pigment; shadowless lights have none.
    light.shadowless = true;
    CHECK(directLight(f, Vec3(1.0), n, eye, light, onMirror) == Vec3(0.0));
}

TEST_CASE("Specular uses the halfway vector and 1/roughness", "[shading]") {
    Finish f;
    f.diffuse = 0.0;
    f.specular = 0.5;
    f.roughness = 0.05;  // exponent 20
    Light light;
    const Vec3 n{0, 1, 0};
    const Vec3 eye{0, -1, 0};  // looking straight down
    // Light 30 degrees from the normal: halfway 15 degrees from it.
    const double a = 30.0 * kPi / 180.0;
    const LightSample s{{std::sin(a), std::cos(a), 0.0}, 3.0, {1, 0.5, 0.25}};
    const double expected = 0.5 * std::pow(std::cos(a / 2.0), 20.0);
    CHECK(near(directLight(f, Vec3(1.0), n, eye, light, s), expected * s.color, 1e-12));
    f.roughness = 0.0;  // POV-Ray: exponent 0
    CHECK(near(directLight(f, Vec3(1.0), n, eye, light, s), 0.5 * s.color, 1e-12));
}

TEST_CASE("Light fade follows POV-Ray's formula", "[shading]") {
    Light l;
    CHECK(lightFade(l.fadeDistance, l.fadePower, 123.0) == 1.0);
    l.fadeDistance = 10.0;
    l.fadePower = 2.0;
    CHECK(lightFade(l.fadeDistance, l.fadePower, 10.0) == Approx(1.0));
    CHECK(lightFade(l.fadeDistance, l.fadePower, 20.0) == Approx(2.0 / 5.0));
    CHECK(lightFade(l.fadeDistance, l.fadePower, 0.0) == Approx(2.0));  // brighter than nominal up close
    l.fadeDistance = 0.0;
    CHECK(lightFade(l.fadeDistance, l.fadePower, 4.0) == Approx(1.0 / 16.0));
    l.fadePower = 0.0;
    l.fadeDistance = 5.0;
    CHECK(lightFade(l.fadeDistance, l.fadePower, 50.0) == 1.0);
    // Fade scales the sample's colour in directLight.
    l.fadePower = 1.0;
    Finish f;
    const LightSample s{{0, 1, 0}, 15.0, {1, 1, 1}};
    CHECK(near(directLight(f, Vec3(1.0), {0, 1, 0}, {0, -1, 0}, l, s), Vec3(0.6 * 2.0 / (1.0 + 3.0))));
}

TEST_CASE("evaluatePigment gives a checker's colours in its pattern space", "[shading]") {
    Pigment p;
    p.kind = Pigment::Kind::Checker;
    p.color1.rgb = {1, 0, 0};
    p.color2.rgb = {0, 0, 1};
    p.worldFromPattern = Transform::scale({2, 2, 2});
    CHECK(evaluatePigment(p, {1.5, 0.5, 0.5}).rgb == Vec3(1, 0, 0));  // pattern point 0.75
    CHECK(evaluatePigment(p, {2.5, 0.5, 0.5}).rgb == Vec3(0, 0, 1));  // pattern point 1.25
}

TEST_CASE("Lights are summed over their samples and turned toward the viewer", "[shading]") {
    Texture t = flat(Vec3(1.0));
    t.finish.ambient = Vec3(0.0);
    t.finish.diffuse = 1.0;
    std::vector<Light> lights(2);
    SurfaceHit hit = planeHit();
    hit.normal = {0, -1, 0};  // the geometric normal points away from the eye: it gets flipped
    const Ray ray{{0, 1, 0}, {0, -1, 0}};
    const LightSample a[] = {{{0, 1, 0}, 1.0, {0.25, 0, 0}}, {{0, 1, 0}, 1.0, {0.25, 0, 0}}};
    const LightSample b[] = {{{0, 1, 0}, 1.0, {0, 0.5, 0}}};
    std::vector<int> asked;
    NoReflection refl;
    const Vec3 c = shadeSurface({hit, t, ray}, lights, ShadingSettings{},
                                [&](const ShadingPoint& p) -> std::span<const LightSample> {
                                    asked.push_back(p.lightIndex);
                                    CHECK(p.normal == Vec3(0, 1, 0));
                                    CHECK(p.light == &lights[p.lightIndex]);
                                    if (p.lightIndex == 0) return a;
                                    return b;
                                },
                                refl);
    CHECK(near(c, {0.5, 0.5, 0.0}));
    CHECK(asked == std::vector<int>{0, 1});
}

TEST_CASE("Reflection recurses with POV-Ray's trace level and ADC bailout", "[shading]") {
    Texture t = flat(Vec3(0.0));
    t.finish.ambient = Vec3(0.0);
    t.finish.diffuse = 0.0;
    t.finish.reflection = {0.5, 0.25, 0.0};
    const SurfaceHit hit = planeHit();
    const Ray ray{{-1, 1, 0}, glm::normalize(Vec3(1, -1, 0))};
    auto noLights = [](const ShadingPoint&) { return std::span<const LightSample>(); };

    struct Recorder {
        Ray ray;
        int depth = 0;
        double weight = 0.0;
        int calls = 0;
        Vec3 operator()(const Ray& r, int d, double w) {
            ray = r;
            depth = d;
            weight = w;
            ++calls;
            return {1.0, 1.0, 1.0};
        }
    } rec;
    ShadingSettings s;
    const Vec3 c = shadeSurface({hit, t, ray, 2, 0.8}, {}, s, noLights, rec);
    CHECK(near(c, {0.5, 0.25, 0.0}));
    REQUIRE(rec.calls == 1);
    CHECK(near(rec.ray.dir, glm::normalize(Vec3(1, 1, 0))));
    CHECK(near(rec.ray.origin, hit.position));
    CHECK(rec.depth == 3);
    CHECK(rec.weight == Approx(0.8 * 0.5));

    // At max_trace_level the reflection is black and not traced.
    s.maxTraceLevel = 2;
    rec.calls = 0;
    CHECK(shadeSurface({hit, t, ray, 2, 1.0}, {}, s, noLights, rec) == Vec3(0.0));
    CHECK(rec.calls == 0);
    // A weight below adc_bailout (1/255) is not traced either.
    s.maxTraceLevel = 5;
    t.finish.reflection = Vec3(0.003);
    CHECK(shadeSurface({hit, t, ray, 1, 1.0}, {}, s, noLights, rec) == Vec3(0.0));
    CHECK(rec.calls == 0);
}

TEST_CASE("A point light sample points at the light and scales by the lit fraction", "[shading]") {
    const LightSample s = pointLightSample({3, 4, 0}, {1, 0.5, 0.25}, {0, 0, 0}, 0.5);
    CHECK(near(s.direction, {0.6, 0.8, 0}));
    CHECK(s.distance == Approx(5.0));
    CHECK(near(s.color, {0.5, 0.25, 0.125}));
    // A light at the point itself lights nothing (no direction).
    const Light light;
    CHECK(directLight(Finish{}, Vec3(1.0), {0, 1, 0}, {0, -1, 0}, light,
                      pointLightSample({1, 1, 1}, Vec3(1.0), {1, 1, 1})) == Vec3(0.0));
}

// POV-Ray's ComputeLightedTexture for layers: each layer's own light times
// its opacity (1 - (filter + transmit) in 3.7, measured with `povray`;
// 1 - (filter x the largest component + transmit) before), seen through the filter colour of
// the layers above (rgb x filter + transmit); reflections traced with the
// weight the layers above leave (the greyscale of that filter colour).
TEST_CASE("Layered textures: each layer lit and seen through those above", "[shading]") {
    Texture t = flat({1, 0, 0});
    t.finish.ambient = Vec3(1.0);
    t.finish.diffuse = 0.0;
    TextureLayer top;
    top.pigment.color1 = Color{{0, 0, 1}, 0.0, 0.5};
    top.finish.ambient = Vec3(1.0);
    top.finish.diffuse = 0.0;
    top.finish.reflection = Vec3(0.5);
    t.above.push_back(top);
    const SurfaceHit hit = planeHit();
    const Ray ray{{0, 1, 0}, {0, -1, 0}};
    auto noLights = [](const ShadingPoint&) { return std::span<const LightSample>(); };
    double reflectedWeight = 0.0;
    auto reflect = [&](const Ray&, int, double w) {
        reflectedWeight = w;
        return Vec3(0.0);
    };
    // Transmit 0.5: half of the top's blue, half of the red under it.
    CHECK(near(shadeSurface({hit, t, ray}, {}, ShadingSettings{}, noLights, reflect), {0.5, 0.0, 0.5}));
    CHECK(reflectedWeight == Approx(0.5));  // the top layer's: the ray's whole weight x 0.5
    // Filter 0.5 of half blue: the top keeps half of its light and lets
    // (0, 0, 0.25) through, which the red under it does not pass.
    t.above[0].pigment.color1 = Color{{0, 0, 0.5}, 0.5, 0.0};
    CHECK(near(shadeSurface({hit, t, ray}, {}, ShadingSettings{}, noLights, reflect), {0.0, 0.0, 0.25}));
    // Before 3.7: 1 - 0.5 x max(0, 0, 0.5) of it.
    ShadingSettings legacy;
    legacy.legacyLayerOpacity = true;
    CHECK(near(shadeSurface({hit, t, ray}, {}, legacy, noLights, reflect), {0.0, 0.0, 0.375}));
    // The bottom's reflection is traced with the weight left to it: the
    // greyscale of (0, 0, 0.5), 0.057, times its reflection.
    t.finish.reflection = Vec3(0.2);
    t.above[0].finish.reflection = Vec3(0.0);
    t.above[0].pigment.color1 = Color{{0, 0, 1}, 0.5, 0.0};
    shadeSurface({hit, t, ray}, {}, ShadingSettings{}, noLights, reflect);
    CHECK(reflectedWeight == Approx(0.057 * 0.2));
}

TEST_CASE("Reflectivity by angle: falloff, Fresnel and metallic, as POV-Ray computes it", "[shading][reflection]") {
    Finish f;
    f.reflection = Vec3(0.9);
    f.reflectionMin = Vec3(0.1);
    // Head-on the minimum, at grazing angles the maximum, between them by
    // (1 - cos)^falloff; the weight is the larger one's.
    CHECK(near(reflectivity(f, 1.0, 1.0, Vec3(1.0)).colour, Vec3(0.1)));
    CHECK(near(reflectivity(f, 0.0, 1.0, Vec3(1.0)).colour, Vec3(0.9)));
    CHECK(near(reflectivity(f, 0.5, 1.0, Vec3(1.0)).colour, Vec3(0.1 + 0.8 * 0.5)));
    f.reflectionFalloff = 2.0;
    CHECK(near(reflectivity(f, 0.5, 1.0, Vec3(1.0)).colour, Vec3(0.1 + 0.8 * 0.25)));
    CHECK(reflectivity(f, 0.5, 1.0, Vec3(1.0)).weight == Approx(0.9));
    // Fresnel: head-on ((n - 1) / (n + 1))^2 of the way for glass, 4 %; the
    // whole maximum past the critical angle from inside; nothing at ior 1.
    Finish g;
    g.reflection = Vec3(1.0);
    g.reflectionMin = Vec3(0.0);
    g.fresnel = true;
    CHECK(reflectivity(g, 1.0, 1.5, Vec3(1.0)).colour.x == Approx(0.04));
    CHECK(reflectivity(g, 1.0, 1.5, Vec3(1.0)).weight == Approx(0.04));
    CHECK(reflectivity(g, 0.3, 1.0 / 1.5, Vec3(1.0)).colour.x == Approx(1.0));
    CHECK(reflectivity(g, 0.7, 1.0, Vec3(1.0)).colour.x == Approx(0.0).margin(1e-12));
    // At 60 degrees, s and p polarisations averaged: 0.0892 for ior 1.5.
    const double c = 0.5, n = 1.5, t = std::sqrt(1.0 - (1.0 - c * c) / (n * n));
    const double rs = std::pow((c - n * t) / (c + n * t), 2.0), rp = std::pow((t - n * c) / (t + n * c), 2.0);
    CHECK(reflectivity(g, c, n, Vec3(1.0)).colour.x == Approx(0.5 * (rs + rp)));
    // reflection's metallic tints head-on by the pigment, not at grazing.
    Finish m;
    m.reflection = Vec3(0.5);
    m.reflectionMetallic = 1.0;
    CHECK(near(reflectivity(m, 1.0, 1.0, {0.8, 0.6, 0.2}).colour, Vec3(0.5) * Vec3(0.8, 0.6, 0.2), 1e-6));
    CHECK(near(reflectivity(m, 0.0, 1.0, {0.8, 0.6, 0.2}).colour, Vec3(0.5), 1e-6));
    CHECK(metallicFresnel(1.0) == Approx(0.0).margin(1e-6));
    CHECK(metallicFresnel(0.0) == Approx(1.0).margin(1e-6));
}

TEST_CASE("A reflection exponent, metallic highlights and conserve_energy", "[shading][reflection]") {
    Texture t;
    t.pigment.color1 = Color{{0.8, 0.6, 0.2}, 0.0, 0.0};
    t.finish.diffuse = 0.0;
    t.finish.ambient = Vec3(0.0);
    t.finish.reflection = Vec3(0.5);
    const SurfaceHit hit = planeHit();
    const Ray ray{{0, 1, 0}, {0, -1, 0}};
    auto noLights = [](const ShadingPoint&) { return std::span<const LightSample>(); };
    auto grey = [](const Ray&, int, double) { return Vec3(0.25); };
    CHECK(near(shadeSurface({hit, t, ray}, {}, ShadingSettings{}, noLights, grey), Vec3(0.125)));
    // exponent 2 (POV-Ray keeps 1/2): 0.5 x 0.25^(1/2).
    t.finish.reflectionExponent = 0.5;
    CHECK(near(shadeSurface({hit, t, ray}, {}, ShadingSettings{}, noLights, grey), Vec3(0.25)));
    // metallic 1: a highlight head-on takes the pigment's colour.
    Finish f;
    f.diffuse = 0.0;
    f.phong = 1.0;
    f.metallic = 1.0;
    const Light light{};
    const LightSample s{{0, 1, 0}, 5.0, {1, 1, 1}};
    const Vec3 colour(0.8, 0.6, 0.2);
    CHECK(near(directLight(f, colour, {0, 1, 0}, {0, -1, 0}, light, s, 0.0, &colour), colour, 1e-6));
    f.metallic = 0.0;
    CHECK(near(directLight(f, colour, {0, 1, 0}, {0, -1, 0}, light, s, 0.0, &colour), Vec3(1.0), 1e-6));
    // conserve_energy: a transparent layer that reflects 0.5 lets through
    // half as much.
    Texture glass;
    glass.pigment.color1 = Color{{1, 1, 1}, 0.0, 1.0};
    glass.finish.reflection = Vec3(0.5);
    glass.finish.conserveEnergy = true;
    double through = 0.0;
    auto transmit = [&](const Vec3&, double w) {
        through = w;
        return Transmitted{Vec3(1.0), false};
    };
    auto none = [](const Ray&, int, double) { return Vec3(0.0); };
    CHECK(near(shadeSurface({hit, glass, ray}, {}, ShadingSettings{}, noLights, none, transmit), Vec3(0.5)));
    CHECK(through == Approx(0.5));
    glass.finish.conserveEnergy = false;
    CHECK(near(shadeSurface({hit, glass, ray}, {}, ShadingSettings{}, noLights, none, transmit), Vec3(1.0)));
}
