// Golden renders of the paper's Figure 6 arrangement (examples/figure6.pov:
// the six primitives above a ground plane) under each of the four light
// kinds, by ASOS shadows, and under the rectangular light by the classic
// grid, at 96 x 72. References live in tests/golden/lights and are rewritten
// only by scripts/update-goldens.sh (ASOS_UPDATE_GOLDENS=1); images are
// compared with OpenImageIO's test-suite thresholds (compareImages). On
// failure the rendered and difference images are written into the build tree.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

bool updating() {
    const char* update = std::getenv("ASOS_UPDATE_GOLDENS");
    return update && *update;
}

fs::path outputDir() {
    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-output" / "golden_lights";
    fs::create_directories(dir);
    return dir;
}

Image renderFigure6(int light, RenderSettings settings) {
    lang::InterpreterOptions options;
    options.imageWidth = settings.width = 96;
    options.imageHeight = settings.height = 72;
    options.defines.push_back({"Light", std::to_string(light)});
    Diagnostics diagnostics;
    const std::optional<SceneDescription> description =
        lang::interpretFile(fs::path(ASOS_SOURCE_DIR) / "examples" / "figure6.pov", options, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) UNSCOPED_INFO(formatDiagnostic(d));
    REQUIRE(description);
    settings.threads = 2;
    std::optional<RenderOutput> out = render(*description, settings, diagnostics);
    REQUIRE(out);
    return std::move(out->color);
}

void compareWithReference(const Image& rendered, const std::string& name) {
    const fs::path reference = fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / "lights" / (name + ".png");
    const fs::path ours = outputDir() / (name + ".png");
    REQUIRE(writeImage(rendered, ours).ok());
    if (updating()) fs::copy_file(ours, reference, fs::copy_options::overwrite_existing);
    const ReadResult mine = readImage(ours);
    const ReadResult theirs = readImage(reference);
    INFO("reference " << reference.string() << ": " << theirs.error);
    REQUIRE(mine.ok());
    REQUIRE(theirs.ok());
    const ImageComparison cmp = compareImages(mine.image, theirs.image);
    const fs::path diff = outputDir() / (name + ".diff.png");
    if (!cmp.passed && cmp.error.empty())
        (void)writeImage(absoluteDifference(mine.image, theirs.image), diff, {.transfer = Transfer::Raw});
    INFO(name << ": " << cmp.summary() << "; rendered " << ours.string() << ", difference " << diff.string());
    CHECK(cmp.passed);
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
