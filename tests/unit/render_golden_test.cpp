// Golden renders through the whole pipeline (scene file -> interpreter ->
// renderer -> PNG):
//  - against POV-Ray 3.7: the scenes of tests/golden/povray, rendered with
//    one ray per pixel, the adaptive method and the am1 method, must match
//    POV-Ray's own renders of the same files (-A, +A0.3 +AM2 +R3 -J and
//    +A0.3 +AM1 +R3 -J);
//  - against our own references: every primitive by ASOS, and the six
//    primitives by every method, in tests/golden/render (96 x 72).
// Images are compared with OpenImageIO's test-suite thresholds
// (compareImages). The golden switch (goldens.hpp, scripts/update-goldens.sh)
// rewrites the references: ours from this build, POV-Ray's by running
// `povray` on the scenes of tests/golden/povray; a failing test never
// rewrites one. On failure the rendered and difference images are left in
// the build tree (build/golden-out/tests/golden/...) and the worst pixel is
// printed.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "golden_images.hpp"

namespace fs = std::filesystem;
using namespace asos;
using test::compareWithReference;
using test::renderSceneFile;
using test::renderSceneForFile;

namespace {

fs::path sourceDir(const char* folder) { return fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / folder; }

// POV-Ray's render of one of tests/golden/povray's scenes, at 160 x 90,
// rewritten by running povray when updating (its log beside what the test
// got, in the build tree).
fs::path povrayReference(const std::string& scene, const std::string& reference,
                         const std::string& povrayOptions) {
    const fs::path dir = sourceDir("povray");
    const fs::path png = dir / (reference + ".png");
    if (test::updatingGoldens()) {
        const std::string command = "povray -D -GA +I'" + (dir / (scene + ".pov")).string() + "' +O'" +
                                    png.string() + "' +W160 +H90 " + povrayOptions + " +FN8 > '" +
                                    test::goldenOutput(dir / (reference + ".povray.log")).string() + "' 2>&1";
        INFO(command);
        REQUIRE(std::system(command.c_str()) == 0);
    }
    return png;
}

RenderSettings settingsFor(RenderMethod method, int width, int height) {
    RenderSettings s;
    s.method = method;
    s.width = width;
    s.height = height;
    return s;
}

// A scene of tests/golden/povray rendered by `method` at 160 x 90 against
// POV-Ray's render of it with `povrayOptions`, kept as <scene><suffix>.png;
// written in the scene's working gamma, as both programs write it.
void compareWithPovray(const std::string& scene, RenderMethod method, const std::string& suffix,
                       const std::string& povrayOptions) {
    INFO(scene);
    compareWithReference(renderSceneForFile(sourceDir("povray") / (scene + ".pov"),
                                            settingsFor(method, 160, 90)),
                         povrayReference(scene, scene + suffix, povrayOptions), false);
}

}  // namespace

// Every scene of tests/golden/povray against POV-Ray's own render of it:
// camera mappings (tilted perspective, orthographic), the checker pattern, the
// background and 8-bit encoding (flat_*), the lighting model (lighting), the
// recursion of reflection (reflection), the six primitives (primitives), the
// brick pattern (brick), the working gamma: none (gamma_off, a scene
// without #version or assumed_gamma) and 2.2 (assumed_gamma), and the map
// patterns with POV-Ray's noise and turbulence (map_*).
TEST_CASE("The renderer matches POV-Ray with one ray per pixel", "[golden][povray]") {
    for (const char* scene : {"flat_perspective", "flat_orthographic", "lighting", "reflection", "primitives",
                              "brick", "gamma_off", "assumed_gamma", "map_plain", "map_noise", "map_turbulence"})
        compareWithPovray(scene, RenderMethod::Single, "", "-A");
}

// POV-Ray's defaults: threshold 0.3, depth +R3 (two subdivisions); -J turns
// its jitter off so that the sample positions coincide.
TEST_CASE("The adaptive method matches POV-Ray's +AM2", "[golden][povray]") {
    for (const char* scene : {"flat_perspective", "lighting", "primitives", "brick", "gamma_off", "assumed_gamma"})
        compareWithPovray(scene, RenderMethod::Adaptive, "_am2", "+A0.3 +AM2 +R3 -J");
}

// POV-Ray's default method with its default threshold and depth, over its
// default 32-pixel render blocks (+BS32), whose borders the method sees.
TEST_CASE("The am1 method matches POV-Ray's +AM1", "[golden][povray]") {
    for (const char* scene : {"flat_perspective", "lighting", "primitives", "brick", "gamma_off", "assumed_gamma"})
        compareWithPovray(scene, RenderMethod::Am1, "_am1", "+A0.3 +AM1 +R3 -J");
}

TEST_CASE("Golden ASOS renders of every primitive", "[golden]") {
    for (const char* name : {"sphere", "box", "cone", "cylinder", "disc", "polygon", "plane"}) {
        INFO(name);
        const fs::path dir = sourceDir("render");
        compareWithReference(
            renderSceneFile(dir / (std::string(name) + ".pov"), settingsFor(RenderMethod::Asos, 96, 72)),
            dir / (std::string(name) + ".png"), true);
    }
    // The checkered plane with pattern edges subdivided too.
    RenderSettings patterns = settingsFor(RenderMethod::Asos, 96, 72);
    patterns.patternEdges = true;
    compareWithReference(renderSceneFile(sourceDir("render") / "plane.pov", patterns),
                         sourceDir("render") / "plane_pattern_edges.png", true);
}

TEST_CASE("Golden renders of the six primitives by every method", "[golden]") {
    const fs::path dir = sourceDir("render");
    for (RenderMethod m : {RenderMethod::Asos, RenderMethod::Single, RenderMethod::Grid,
                           RenderMethod::Jitter, RenderMethod::Adaptive, RenderMethod::Am1}) {
        INFO(methodName(m));
        compareWithReference(renderSceneFile(dir / "methods.pov", settingsFor(m, 96, 72)),
                             dir / ("methods_" + std::string(methodName(m)) + ".png"), true);
    }
    // ASOS with jittered MAX-rays, and the adaptive method with jitter.
    RenderSettings jittered = settingsFor(RenderMethod::Asos, 96, 72);
    jittered.asos.jitter = true;
    jittered.seed = 3;
    compareWithReference(renderSceneFile(dir / "methods.pov", jittered), dir / "methods_asos_jitter.png", true);
    jittered.method = RenderMethod::Adaptive;
    jittered.adaptive.jitter = true;
    compareWithReference(renderSceneFile(dir / "methods.pov", jittered),
                         dir / "methods_adaptive_jitter.png", true);
}
