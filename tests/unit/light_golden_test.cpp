// Golden renders of the paper's Figure 6 arrangement (examples/figure6.pov:
// the six primitives above a ground plane) under each of the four light
// kinds, by ASOS shadows, and under the rectangular light by the classic
// grid, at 96 x 72. References live in tests/golden/lights and are rewritten
// only by the golden switch (goldens.hpp, scripts/update-goldens.sh); images
// are compared with OpenImageIO's test-suite thresholds (compareImages). On
// failure the rendered and difference images are left in the build tree
// (build/golden-out/tests/golden/lights).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "golden_images.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

Image renderFigure6(int light, RenderSettings settings) {
    settings.width = 96;
    settings.height = 72;
    return test::renderSceneFile(fs::path(ASOS_SOURCE_DIR) / "examples" / "figure6.pov", settings,
                                 {{"Light", std::to_string(light)}});
}

void compareWithReference(const Image& rendered, const std::string& name) {
    test::compareWithReference(rendered,
                               fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / "lights" / (name + ".png"));
}

}  // namespace

TEST_CASE("Golden renders of Figure 6 under each light kind", "[golden][lights]") {
    const char* names[] = {"figure6_point", "figure6_spherical", "figure6_linear", "figure6_rectangular"};
    for (int light = 0; light < 4; ++light) {
        INFO(names[light]);
        compareWithReference(renderFigure6(light, RenderSettings{}), names[light]);
    }
}

TEST_CASE("Golden renders of Figure 6 by the classic light model and jittered beams", "[golden][lights]") {
    RenderSettings grid;
    grid.lightMethod = LightMethod::Grid;
    compareWithReference(renderFigure6(3, grid), "figure6_rectangular_grid");
    RenderSettings adaptive;
    adaptive.method = RenderMethod::Adaptive;
    adaptive.lightSamples = 5;
    compareWithReference(renderFigure6(2, adaptive), "figure6_linear_adaptive_grid");
    RenderSettings jittered;
    jittered.asos.jitter = true;
    jittered.seed = 5;
    compareWithReference(renderFigure6(1, jittered), "figure6_spherical_jitter");
}
