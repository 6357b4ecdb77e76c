// Highlights inside covered pixels (render/highlight_bound.hpp). Property:
// over random pyrays that a sphere, a cylinder's or cone's side or a plane
// covers without a crease, under random transforms, with random phong and
// specular finishes and lights near the mirror direction, the interval
// highlightRange gives holds the highlight of every ray of a dense set
// inside the pyray. Known answers: a sphere whose highlight is narrower than
// the pixel that it covers is subdivided, and then comes within EPS of the
// pixel's dense mean; a matte sphere, or the switch off, costs one ray.
#include <catch2/catch.hpp>

#include <cmath>

#include "asos/render/asos_tracer.hpp"
#include "asos/render/highlight_bound.hpp"
#include "asos/render/shading.hpp"
#include "render_scenes.hpp"
#include "shape_property.hpp"

using namespace asos;
using namespace asos::testing;
using shapetest::fmt;

namespace {

Shape randomSmoothShape(Rng& rng) {
    const double a = rng.uniform(0.3, 2.0), h = rng.uniform(0.3, 2.0);
    switch (rng.index(4)) {
        case 0: return SphereShape{{0, 0, 0}, a};
        case 1: return CylinderShape{{0, 0, 0}, {0, h, 0}, a, rng.chance(0.5)};
        case 2: return ConeShape{{0, 0, 0}, a, {0, h, 0}, rng.chance(0.5) ? 0.0 : rng.uniform(0.1, 1.5), false};
        default: return PlaneShape{glm::normalize(rng.unitVector()), rng.uniform(-1.0, 1.0)};
    }
}

Finish randomShinyFinish(Rng& rng) {
    Finish f;
    f.diffuse = 0.0;
    if (rng.chance(0.7)) {
        f.phong = rng.uniform(0.1, 1.0);
        f.phongSize = rng.logUniform(0.0, 3.5);
    }
    if (rng.chance(0.7) || f.phong == 0.0) {
        f.specular = rng.uniform(0.1, 1.0);
        f.roughness = rng.logUniform(-3.5, -0.5);
    }
    return f;
}

// The highlight of one ray on the primitive (directLight without the
// diffuse term, per unit of the light's colour); nothing when the ray misses
// or meets another part.
std::optional<double> highlightAlong(const Primitive& prim, const Ray& ray, std::uint8_t part,
                                     const Finish& finish, const Light& light) {
    const std::optional<SurfaceHit> hit = prim.intersect(ray, kPovMinIsectDepth, kInfinity);
    if (!hit || hit->part != part) return std::nullopt;
    const Vec3 normal = facingNormal(hit->normal, ray.dir);
    const LightSample sample = pointLightSample(light.position, Vec3(1.0), hit->position);
    return directLight(finish, Vec3(0.0), normal, ray.dir, light, sample).x;
}

}  // namespace

TEST_CASE("Highlights: the range over a covered pyray holds every dense ray's highlight",
          "[highlight][property]") {
    int covered = 0, wide = 0, failures = 0;
    shapetest::forEachCase(0x4a91e7b0ull, 3000, [&](int, std::uint64_t seed, Rng& rng) {
        const Shape shape = randomSmoothShape(rng);
        const shapetest::TransformCase tc = shapetest::randomTransform(rng, 5.0);
        const Primitive prim = Primitive::make(shape, tc.worldFromObject);
        // An eye at a random place, aimed near the object's origin.
        const Vec3 origin = tc.worldFromObject.point(Vec3(0.0, 0.5, 0.0));
        const Vec3 eye = origin + rng.uniform(4.0, 40.0) * rng.unitVector();
        const Vec3 forward = glm::normalize(origin + rng.uniform(-0.5, 0.5) * rng.unitVector() - eye);
        const Vec3 right = glm::normalize(glm::cross(forward, rng.unitVector()));
        const Vec3 up = glm::cross(right, forward);
        const double width = rng.logUniform(-3.5, -1.3);  // the pyray's angular width
        auto rayAt = [&](double u, double v) {
            return Ray{eye, glm::normalize(forward + width * ((u - 0.5) * right + (v - 0.5) * up))};
        };
        const EyePyray pyray = EyePyray::make(rayAt, ImageSquare{0.0, 0.0, 1.0, 1.0}, 0, kPovMinIsectDepth);
        const ConeClass k = prim.classify(pyray.cone());
        if (k.coverage != Coverage::Full || k.creaseParts != 0) return;
        const std::optional<SurfaceHit> centre = prim.intersect(pyray.centralRay(), kPovMinIsectDepth, kInfinity);
        if (!centre) return;
        ++covered;
        const SurfaceSpread spread = SurfaceSpread::over(pyray, *centre, prim);
        // A light near the mirror direction, to meet highlights often.
        const Vec3 d = pyray.centralRay().dir;
        const Vec3 n = facingNormal(centre->normal, d);
        const Vec3 mirror = d - 2.0 * glm::dot(d, n) * n;
        Light light = pointLight(centre->position + rng.uniform(1.0, 50.0) *
                                                        glm::normalize(mirror + rng.uniform(0.0, 0.3) * rng.unitVector()));
        if (rng.chance(0.2)) {
            light.fadeDistance = rng.uniform(1.0, 10.0);
            light.fadePower = rng.chance(0.5) ? 1.0 : 2.0;
        }
        const Finish finish = randomShinyFinish(rng);
        const ValueRange range = highlightRange(finish, light, spread);
        const double error = highlightError(finish, light, spread);
        if (range.width() > 0.01) ++wide;
        bool ok = error >= 0.0 && error <= range.width() + 1e-12;
        constexpr int kDense = 24;
        for (int j = 0; j <= kDense && ok; ++j)
            for (int i = 0; i <= kDense && ok; ++i) {
                const std::optional<double> h =
                    highlightAlong(prim, rayAt(double(i) / kDense, double(j) / kDense), centre->part, finish, light);
                if (!h) continue;  // a Full cone's ray lost to rounding at the rim
                ok = *h >= range.lo - 1e-9 && *h <= range.hi + 1e-9;
                if (!ok)
                    UNSCOPED_INFO("seed " << seed << " " << tc.text << " ray " << i << "," << j << ": "
                                          << fmt(*h) << " outside [" << fmt(range.lo) << ", "
                                          << fmt(range.hi) << "]");
            }
        if (!ok) ++failures;
    });
    INFO(covered << " covered pyrays, " << wide << " with a range wider than 0.01");
    CHECK(failures == 0);
    CHECK(covered > 1000);
    CHECK(wide > 200);
}

namespace {

// A sphere under an orthographic camera (one world unit per pixel), its
// front pole in the middle of pixel (4, 4), lit from straight ahead of the
// pole: a phong highlight `size` wide in phong_size terms, nothing else.
SceneDescription poleHighlight(double phong, double phongSize) {
    SceneDescription d;
    Texture t = coverageTexture(0.0);
    t.finish.ambient = Vec3(0.0);
    t.finish.phong = phong;
    t.finish.phongSize = phongSize;
    d.objects.push_back(makeObject(SphereShape{{4.5, -4.5, 0.0}, 20.0}, t));
    d.lights.push_back(pointLight({4.5, -4.5, -5000.0}));
    d.camera = orthoCamera(9, 9);
    return d;
}

// The mean of the highlight over pixel (x, y) of poleHighlight's camera, by
// 128 x 128 point samples.
double denseHighlight(const SceneDescription& d, int x, int y) {
    const Primitive sphere = Primitive::make(d.objects[0].shape, d.objects[0].worldFromObject);
    double sum = 0.0;
    for (int j = 0; j < 128; ++j)
        for (int i = 0; i < 128; ++i) {
            const Ray ray{{x + (i + 0.5) / 128, -(y + (j + 0.5) / 128), -100.0}, {0.0, 0.0, 1.0}};
            sum += highlightAlong(sphere, ray, 0, d.objects[0].texture->finish, d.lights[0]).value_or(0.0);
        }
    return sum / (128.0 * 128.0);
}

PixelResult tracePixel(const SceneDescription& d, const AsosSettings& settings, int x, int y) {
    const auto scene = buildScene(d);
    const RayTracer tracer(*scene);
    const CameraModel camera(d.camera, 9, 9);
    const AsosTracer asos(tracer, camera, settings, 0);
    AsosScratch scratch;
    RenderCounters counters;
    return asos.tracePixel(x, y, scratch, counters);
}

}  // namespace

TEST_CASE("Highlights: a highlight narrower than a covered pixel is subdivided and measured", "[highlight][asos]") {
    const SceneDescription d = poleHighlight(1.0, 4000.0);
    const double exact = denseHighlight(d, 4, 4);
    REQUIRE(exact < 0.5);  // the one central ray sees the peak, 1
    const PixelResult on = tracePixel(d, AsosSettings{}, 4, 4);
    CHECK(on.rays > 1);
    CHECK(on.color.x == Approx(exact).margin(1.0 / 64.0));
    AsosSettings off;
    off.highlights = false;
    const PixelResult one = tracePixel(d, off, 4, 4);
    CHECK(one.rays == 1);
    CHECK(one.color.x == Approx(1.0).margin(1e-6));
    // Far from the highlight the covered pixels stay one ray.
    CHECK(tracePixel(d, AsosSettings{}, 0, 0).rays == 1);
}

TEST_CASE("Highlights: a matte sphere, or a broad highlight, costs one ray a pixel", "[highlight][asos]") {
    const SceneDescription matte = poleHighlight(0.0, 40.0);
    const SceneDescription broad = poleHighlight(1.0, 2.0);
    for (int y = 2; y < 7; ++y)
        for (int x = 2; x < 7; ++x) {
            CHECK(tracePixel(matte, AsosSettings{}, x, y).rays == 1);
            CHECK(tracePixel(broad, AsosSettings{}, x, y).rays == 1);
        }
}
