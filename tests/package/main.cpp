// Uses the installed asos package (find_package(asos), asos::asos): makes a
// scene description in code, renders it small, writes the image and reads it
// back, checks pixels, and interprets a line of scene text. Prints what went
// wrong and exits 1 when anything is not as expected.
//   asos_package_test OUTPUT_FOLDER
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/version.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: asos_package_test OUTPUT_FOLDER\n");
        return 2;
    }
    int failures = 0;
    const auto check = [&](bool ok, const std::string& what) {
        if (!ok) {
            std::fprintf(stderr, "asos_package_test: %s\n", what.c_str());
            ++failures;
        }
    };
    check(std::string(asos::kVersion) == ASOS_PACKAGE_VERSION,
          std::string("the headers say version ") + asos::kVersion + ", the package " + ASOS_PACKAGE_VERSION);

    // A red sphere in the middle of a square view, lit from the camera, on a
    // blue background.
    asos::SceneDescription scene;
    scene.camera.location = {0.0, 0.0, -5.0};
    scene.camera.right = {1.0, 0.0, 0.0};
    asos::Light light;
    light.position = {0.0, 0.0, -10.0};
    scene.lights.push_back(light);
    auto red = std::make_shared<asos::Texture>();
    red->pigment.color1.rgb = {1.0, 0.0, 0.0};
    asos::Object sphere;
    sphere.shape = asos::SphereShape{{0.0, 0.0, 0.0}, 1.0};
    sphere.texture = red;
    scene.objects.push_back(sphere);
    scene.background.rgb = {0.0, 0.0, 1.0};

    asos::RenderSettings settings;
    settings.width = settings.height = 16;
    settings.threads = 1;
    asos::Diagnostics diagnostics;
    const std::optional<asos::RenderOutput> out = asos::render(scene, settings, diagnostics);
    check(out.has_value(), "the scene did not render");
    if (!out) return 1;
    const asos::Vec3 middle = out->color.rgbAt(8, 8), corner = out->color.rgbAt(0, 0);
    check(middle.x > 0.5 && middle.y == 0.0 && middle.z == 0.0, "the middle pixel is not the red sphere");
    check(corner == asos::Vec3(0.0, 0.0, 1.0), "the corner pixel is not the blue background");

    // Through OpenImageIO, which the package links for its users.
    const std::filesystem::path png = std::filesystem::path(argv[1]) / "package.png";
    const asos::IoStatus written = asos::writeImage(out->color, png);
    check(written.ok(), "cannot write " + png.string() + ": " + written.error);
    const asos::ReadResult read = asos::readImage(png);
    check(read.ok() && read.image.rgbAt(0, 0) == asos::Vec3(0.0, 0.0, 1.0),
          "the image read back from " + png.string() + " is not the one written");

    const std::optional<asos::SceneDescription> parsed =
        asos::lang::interpretText("sphere { <0, 1, 0>, 2 }", "text", {}, diagnostics);
    check(parsed && parsed->objects.size() == 1, "the scene text did not interpret to one sphere");

    if (failures == 0) std::printf("asos %s: rendered, wrote, read and interpreted\n", asos::kVersion);
    return failures == 0 ? 0 : 1;
}
