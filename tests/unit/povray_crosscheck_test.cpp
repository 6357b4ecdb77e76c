// Cross-checks of the camera, shading and output encoding against POV-Ray 3.7
// itself. Each scene in tests/golden/povray/*.pov is mirrored here as a
// SceneDescription and traced with a minimal test-only tracer (spheres and
// planes, point-light shadow rays, POV-Ray's intersection tolerances), one ray
// through each pixel centre or asos::estimateAdaptive, shaded with
// asos::shadeSurface and written with asos::writeImage. The reference PNGs are
// POV-Ray's own renders (-A, or +AM2 -J); scripts/update-goldens.sh
// regenerates them by running `povray` (ASOS_UPDATE_GOLDENS=1); a failing
// comparison never rewrites them.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "asos/image/image_io.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/classic_methods.hpp"
#include "asos/render/shading.hpp"

using namespace asos;
namespace fs = std::filesystem;

namespace {

constexpr double kMinIsectDepth = kPovMinIsectDepth;
constexpr double kShadowTolerance = kPovShadowTolerance;
constexpr int kWidth = 160, kHeight = 90;

std::optional<SurfaceHit> intersect(const Object& object, const Ray& ray, double tMin, double tMax) {
    SurfaceHit hit;
    if (const auto* s = std::get_if<SphereShape>(&object.shape)) {
        const Vec3 oc = ray.origin - s->center;
        const double b = glm::dot(oc, ray.dir);
        const double c = glm::dot(oc, oc) - s->radius * s->radius;
        const double disc = b * b - c;
        if (disc < 0.0) return std::nullopt;
        const double root = std::sqrt(disc);
        double t = -b - root;
        if (t <= tMin) t = -b + root;
        if (t <= tMin || t >= tMax) return std::nullopt;
        hit.t = t;
        hit.position = ray.at(t);
        hit.normal = (hit.position - s->center) / s->radius;
    } else if (const auto* p = std::get_if<PlaneShape>(&object.shape)) {
        const double denom = glm::dot(p->normal, ray.dir);
        if (std::fabs(denom) < 1e-12) return std::nullopt;
        const double t = (p->distance - glm::dot(p->normal, ray.origin)) / denom;
        if (t <= tMin || t >= tMax) return std::nullopt;
        hit.t = t;
        hit.position = ray.at(t);
        hit.normal = p->normal;
    } else {
        FAIL("the cross-check tracer handles spheres and planes only");
    }
    hit.objectPoint = hit.position;
    return hit;
}

struct MiniTracer {
    const SceneDescription& scene;
    ShadingSettings settings = ShadingSettings::from(scene.globals);

    std::optional<SurfaceHit> nearest(const Ray& ray, double tMin, double tMax) const {
        std::optional<SurfaceHit> best;
        for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i)
            if (auto h = intersect(scene.objects[i], ray, tMin, best ? best->t : tMax)) {
                best = h;
                best->objectIndex = i;
            }
        return best;
    }

    Vec3 radiance(const Ray& ray, int depth, double weight) const {
        const auto hit = nearest(ray, kMinIsectDepth, kInfinity);
        if (!hit) return backgroundColor(scene);
        LightSample sample;
        auto lightArriving = [&](const ShadingPoint& p) -> std::span<const LightSample> {
            sample = pointLightSample(p.light->position, p.light->color, p.position);
            if (!p.light->shadowless &&
                nearest({p.position, sample.direction}, kShadowTolerance,
                        sample.distance - kShadowTolerance))
                return {};
            return {&sample, 1};
        };
        auto reflected = [&](const Ray& r, int d, double w) { return radiance(r, d, w); };
        const Texture& texture = *scene.objects[hit->objectIndex].texture;
        return shadeSurface({*hit, texture, ray, depth, weight}, scene.lights, settings,
                            lightArriving, reflected);
    }

    // Without anti-aliasing: one ray through each pixel centre.
    Image render() const {
        const CameraModel camera(scene.camera, kWidth, kHeight);
        Image image = Image::rgb(kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                image.setRgb(x, y, radiance(camera.pixelCenterRay(x, y), 1, 1.0));
        return image;
    }

    // With the adaptive method (POV-Ray's +AM2, no jitter).
    Image renderAdaptive(const AdaptiveSettings& settings) const {
        const CameraModel camera(scene.camera, kWidth, kHeight);
        auto eye = [&](const Ray& r) { return radiance(r, 1, 1.0); };
        Image image = Image::rgb(kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const PixelCorners corners{eye(camera.ray(x, y)), eye(camera.ray(x + 1, y)),
                                           eye(camera.ray(x, y + 1)), eye(camera.ray(x + 1, y + 1)), 1};
                image.setRgb(x, y, estimateAdaptive(camera, x, y, corners, settings,
                                                    PixelRandom(0, x, y), eye).color);
            }
        return image;
    }
};

// The scenes' shared camera: `look_at` worked out as the .pov files do.
Camera tiltedCamera(Camera::Projection projection, double dirLength, double right, double up) {
    const Vec3 loc{1.5, 2.2, -6}, lookAt{0.2, 0.4, 0};
    const Vec3 d = glm::normalize(lookAt - loc);
    const Vec3 r = glm::normalize(glm::cross(Vec3(0, 1, 0), d));
    const Vec3 u = glm::cross(d, r);
    Camera c;
    c.projection = projection;
    c.location = loc;
    c.direction = dirLength * d;
    c.right = right * r;
    c.up = up * u;
    return c;
}

Object sphere(const Vec3& c, double r, const Pigment& pigment, const Finish& finish) {
    Object o;
    o.shape = SphereShape{c, r};
    o.texture = std::make_shared<const Texture>(Texture{pigment, finish});
    return o;
}

Object groundPlane(const Pigment& pigment, const Finish& finish) {
    Object o;
    o.shape = PlaneShape{{0, 1, 0}, 0.0};
    o.texture = std::make_shared<const Texture>(Texture{pigment, finish});
    return o;
}

Pigment solid(const Vec3& rgb) {
    Pigment p;
    p.color1.rgb = rgb;
    return p;
}

Pigment checker(const Vec3& a, const Vec3& b, const Transform& worldFromPattern) {
    Pigment p;
    p.kind = Pigment::Kind::Checker;
    p.color1.rgb = a;
    p.color2.rgb = b;
    p.worldFromPattern = worldFromPattern;
    return p;
}

Finish finish(double ambient, double diffuse) {
    Finish f;
    f.ambient = Vec3(ambient);
    f.diffuse = diffuse;
    return f;
}

SceneDescription flatScene(Camera::Projection projection) {
    SceneDescription s;
    s.camera = projection == Camera::Projection::Perspective
                   ? tiltedCamera(projection, 1.7, 1.6, 1.0)
                   : tiltedCamera(projection, 1.0, 5.2, 3.0);
    s.background.rgb = {0.1, 0.2, 0.4};
    const Finish flat = finish(1.0, 0.0);
    s.objects.push_back(sphere({0, 0.5, 0}, 0.5, solid({1, 0.5, 0.25}), flat));
    s.objects.push_back(sphere({1.2, 0.3, 0.8}, 0.3, solid({0.2, 0.9, 0.3}), flat));
    s.objects.push_back(sphere({-1.3, 0.8, 1.5}, 0.8, solid({0.7, 0.7, 0.9}), flat));
    s.objects.push_back(sphere({2.6, 1.4, 3}, 0.05, solid(Vec3(1.0)), flat));
    const Transform pattern = Transform::translate({0.1, 0, 0.2}) *
                              Transform::rotateDegrees({0, 30, 0}) * Transform::scale(Vec3(0.7));
    s.objects.push_back(groundPlane(checker(Vec3(0.9), Vec3(0.05), pattern), flat));
    return s;
}

SceneDescription lightingScene() {
    SceneDescription s;
    s.camera = tiltedCamera(Camera::Projection::Perspective, 1.7, 1.6, 1.0);
    s.globals.ambientLight = {0.8, 0.9, 1.0};
    s.background.rgb = {0.02, 0.02, 0.05};
    Light key;
    key.position = {-4, 6, -3};
    key.color = {1.0, 0.95, 0.9};
    key.fadeDistance = 6.0;
    key.fadePower = 2.0;
    Light fill;
    fill.position = {3, 2, -4};
    fill.color = {0.2, 0.25, 0.4};
    fill.shadowless = true;
    s.lights = {key, fill};

    Finish f1 = finish(0.1, 0.7);
    f1.phong = 0.8;
    f1.phongSize = 30.0;
    s.objects.push_back(sphere({0, 0.5, 0}, 0.5, solid({1, 0.5, 0.25}), f1));
    Finish f2 = finish(0.2, 0.5);
    f2.brilliance = 3.0;
    f2.specular = 0.6;
    f2.roughness = 0.02;
    s.objects.push_back(sphere({1.2, 0.3, 0.8}, 0.3, solid({0.2, 0.9, 0.3}), f2));
    Finish f3 = finish(0.1, 0.6);
    f3.specular = 0.3;
    f3.phong = 0.3;
    s.objects.push_back(sphere({-1.3, 0.8, 1.5}, 0.8,
                               checker({0.8, 0.2, 0.2}, Vec3(0.9), Transform::scale(Vec3(0.25))), f3));
    s.objects.push_back(groundPlane(solid({0.7, 0.7, 0.6}), finish(0.05, 0.8)));
    return s;
}

SceneDescription reflectionScene() {
    SceneDescription s;
    s.camera = tiltedCamera(Camera::Projection::Perspective, 1.7, 1.6, 1.0);
    s.globals.maxTraceLevel = 3;
    s.background.rgb = {0.3, 0.5, 0.8};
    Light light;
    light.position = {-4, 6, -3};
    light.color = Vec3(1.0);
    s.lights = {light};

    Finish f1 = finish(0.1, 0.3);
    f1.reflection = {0.6, 0.6, 0.5};
    s.objects.push_back(sphere({0, 0.5, 0}, 0.5, solid({0.3, 0.3, 0.35}), f1));
    Finish f2 = finish(0.1, 0.6);
    f2.reflection = Vec3(0.9);
    f2.phong = 1.0;
    s.objects.push_back(sphere({1.2, 0.3, 0.8}, 0.3, solid({0.9, 0.2, 0.1}), f2));
    Finish f3 = finish(0.1, 0.6);
    f3.reflection = Vec3(0.3);
    s.objects.push_back(sphere({-1.3, 0.8, 1.5}, 0.8,
                               checker({0.8, 0.2, 0.2}, Vec3(0.9), Transform::scale(Vec3(0.25))), f3));
    Finish f4 = finish(0.1, 0.5);
    f4.reflection = Vec3(0.4);
    s.objects.push_back(groundPlane(checker(Vec3(1.0), Vec3(0.1), Transform()), f4));
    return s;
}

// Compares `rendered` with POV-Ray's render of tests/golden/povray/<pov>.pov
// made with `povrayOptions`, stored as <referenceName>.png.
void crossCheck(const std::string& pov, const std::string& referenceName,
                const std::string& povrayOptions, const Image& rendered) {
    const fs::path golden = fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / "povray";
    const fs::path scene = golden / (pov + ".pov");
    const fs::path reference = golden / (referenceName + ".png");
    const fs::path outDir = fs::path(ASOS_BINARY_DIR) / "test-output" / "povray";
    fs::create_directories(outDir);

    const char* update = std::getenv("ASOS_UPDATE_GOLDENS");
    if (update && *update) {
        // The reference is POV-Ray's render, never ours.
        const std::string command = "povray -D -GA +I'" + scene.string() + "' +O'" +
                                    reference.string() + "' +W" + std::to_string(kWidth) + " +H" +
                                    std::to_string(kHeight) + " " + povrayOptions + " +FN8 > '" +
                                    (outDir / (referenceName + ".povray.log")).string() + "' 2>&1";
        INFO(command);
        REQUIRE(std::system(command.c_str()) == 0);
    }

    const fs::path ours = outDir / (referenceName + ".png");
    const IoStatus written = writeImage(rendered, ours);
    REQUIRE(written.ok());
    const ReadResult mine = readImage(ours);
    const ReadResult theirs = readImage(reference);
    INFO("reference " << reference.string() << ": " << theirs.error);
    REQUIRE(mine.ok());
    REQUIRE(theirs.ok());
    const ImageComparison cmp = compareImages(mine.image, theirs.image);
    if (!cmp.passed && cmp.error.empty())
        (void)writeImage(absoluteDifference(mine.image, theirs.image),
                         outDir / (referenceName + ".diff.png"), {.transfer = Transfer::Raw});
    INFO(referenceName << " against POV-Ray: " << cmp.summary() << "; ours: " << ours.string());
    CHECK(cmp.passed);
}

void crossCheck(const std::string& name, const SceneDescription& scene) {
    crossCheck(name, name, "-A", MiniTracer{scene}.render());
}

}  // namespace

TEST_CASE("Perspective camera and flat shading match POV-Ray", "[povray][golden]") {
    crossCheck("flat_perspective", flatScene(Camera::Projection::Perspective));
}

TEST_CASE("Orthographic camera matches POV-Ray", "[povray][golden]") {
    crossCheck("flat_orthographic", flatScene(Camera::Projection::Orthographic));
}

TEST_CASE("Lighting model matches POV-Ray", "[povray][golden]") {
    crossCheck("lighting", lightingScene());
}

TEST_CASE("Recursive reflection matches POV-Ray", "[povray][golden]") {
    crossCheck("reflection", reflectionScene());
}

TEST_CASE("Adaptive anti-aliasing matches POV-Ray's +AM2", "[povray][golden]") {
    // POV-Ray's defaults: threshold 0.3, depth +R3 (two subdivisions); -J
    // turns its jitter off so that the sample positions coincide.
    const AdaptiveSettings settings;
    crossCheck("lighting", "lighting_am2", "+A0.3 +AM2 +R3 -J",
               MiniTracer{lightingScene()}.renderAdaptive(settings));
    crossCheck("flat_perspective", "flat_perspective_am2", "+A0.3 +AM2 +R3 -J",
               MiniTracer{flatScene(Camera::Projection::Perspective)}.renderAdaptive(settings));
}
