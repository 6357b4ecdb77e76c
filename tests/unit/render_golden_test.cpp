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
#include <utility>
#include <vector>

#include "golden_images.hpp"

namespace fs = std::filesystem;
using namespace asos;
using test::compareWithReference;
using test::renderSceneFile;
using test::renderSceneForFile;

namespace {

fs::path sourceDir(const char* folder) { return fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / folder; }

// POV-Ray's render of one of tests/golden/povray's scenes, at 160 x 90 (or
// the size given), rewritten by running povray when updating (its log beside
// what the test got, in the build tree).
fs::path povrayReference(const std::string& scene, const std::string& reference,
                         const std::string& povrayOptions, int width = 160, int height = 90) {
    const fs::path dir = sourceDir("povray");
    const fs::path png = dir / (reference + ".png");
    if (test::updatingGoldens()) {
        const std::string command = "povray -D -GA +I'" + (dir / (scene + ".pov")).string() + "' +O'" +
                                    png.string() + "' +W" + std::to_string(width) + " +H" + std::to_string(height) +
                                    " " + povrayOptions + " +FN8 > '" +
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
// without #version or assumed_gamma) and 2.2 (assumed_gamma), the map
// patterns with POV-Ray's noise and turbulence, the function pattern and
// crackle (map_*), CSG (csg),
// layered textures (layered, and layered_legacy for a scene older than 3.7),
// the normal patterns (normals) and their values as pigment patterns
// (map_normal_patterns), sky_sphere with fog (atmosphere, and
// atmosphere_legacy for a scene older than 3.7), transparency without an
// interior (transparency) and with one (refraction), the reflection { }
// block with fresnel, falloff, exponent and metallic (reflection_block),
// dispersion (dispersion), clipped_by and bounded_by (clip), pigment_map and
// average (pigment_map).
TEST_CASE("The renderer matches POV-Ray with one ray per pixel", "[golden][povray]") {
    for (const char* scene : {"flat_perspective", "flat_orthographic", "lighting", "reflection", "primitives",
                              "brick", "gamma_off", "assumed_gamma", "map_plain", "map_noise", "map_turbulence",
                              "csg", "layered", "layered_legacy", "normals", "atmosphere", "atmosphere_legacy",
                              "map_normal_patterns", "map_function", "map_crackle", "transparency", "refraction",
                              "reflection_block", "dispersion", "clip", "pigment_map"})
        compareWithPovray(scene, RenderMethod::Single, "", "-A");
}

// The torus (tests/golden/povray/torus.pov: tilted, squashed, thin with
// sturm, horn, cut from a box), the triangles and meshes (mesh.pov:
// triangle, smooth_triangle, mesh, a smooth mesh2, a mesh in a difference)
// and poly's surfaces (quartic.pov: two tori and shapesq.inc's Piriform as
// quartics, an ellipsoid as poly 2).
TEST_CASE("Tori, meshes and polys match POV-Ray with one ray per pixel", "[golden][povray]") {
    for (const char* scene : {"torus", "mesh", "quartic"}) compareWithPovray(scene, RenderMethod::Single, "", "-A");
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

// Area lights under POV-Ray's meaning (tests/golden/povray/area_lights.pov:
// primitives before a wall, the horizontal 3 x 1.5 rectangle), at
// 160 x 120, each form with and without adaptive, and area_illumination.
struct AreaLightCase {
    const char* name;
    std::vector<std::pair<std::string, std::string>> declares;
};
const std::vector<AreaLightCase>& areaLightCases() {
    static const std::vector<AreaLightCase> cases = {
        {"rectangular", {}},
        {"rectangular_adaptive", {{"Adaptive", "1"}}},
        {"rectangular_illumination", {{"Illumination", "1"}}},
        {"linear", {{"Light", "2"}}},
        {"linear_adaptive", {{"Light", "2"}, {"Adaptive", "0"}}},
        {"circular", {{"Light", "3"}}},
        {"circular_adaptive", {{"Light", "3"}, {"Adaptive", "1"}}},
    };
    return cases;
}
// POV-Ray's command-line declarations.
std::string povrayDeclares(const std::vector<std::pair<std::string, std::string>>& declares) {
    std::string out;
    for (const auto& [name, value] : declares) out += " Declare=" + name + "=" + value;
    return out;
}

// The grid light method on POV-Ray's unjittered lattice, one ray per pixel,
// is POV-Ray's -A render.
TEST_CASE("Area lights by the grid match POV-Ray with one ray per pixel", "[golden][povray][lights]") {
    for (const AreaLightCase& c : areaLightCases()) {
        INFO(c.name);
        RenderSettings s = settingsFor(RenderMethod::Single, 160, 120);
        s.lightMethod = LightMethod::Grid;
        const std::string reference = std::string("area_lights_") + c.name;
        compareWithReference(renderSceneFile(sourceDir("povray") / "area_lights.pov", s, c.declares),
                             povrayReference("area_lights", reference, "-A" + povrayDeclares(c.declares), 160, 120),
                             false);
    }
}

// The ASOS light method against POV-Ray's render converged in the light:
// +A0.0 +AM2 +R3 -J (POV-Ray's 5 x 5 eye samples wherever neighbours differ
// at all), on lattices dense enough to converge (17 x 9 points on the
// rectangle, 65 along the line, 17 x 17 on the disc: 2^k + 1, POV-Ray's
// trapezoid rule) and without adaptive (POV-Ray's corner scheme misses parts
// of shadows). asos takes the same eye samples (adaptive, threshold 0, depth
// 2: the same positions, the same subdivisions but where the light differs),
// so that the images differ by their light only: ASOS beams at EPS 1/64 and
// MAX 4 (8 along the linear light, whose pieces are halved). Tolerance: no
// value more than 0.04 off, at most 0.5 % of the pixels more than 0.004 off
// (docs/lights.md, "POV-Ray's renders", has what was measured).
TEST_CASE("Area lights by ASOS beams match POV-Ray's converged render", "[golden][povray][lights]") {
    struct Converged {
        const char* name;
        const char* light;
        const char* samples;
        int maxLevel;
    };
    const Converged cases[] = {{"rectangular", "1", "17", 4}, {"linear", "2", "65", 8}, {"circular", "3", "17", 4}};
    CompareThresholds tolerance;
    tolerance.failPercent = 0.5;
    tolerance.hardFail = 0.04;
    for (const Converged& c : cases) {
        INFO(c.name);
        RenderSettings s = settingsFor(RenderMethod::Adaptive, 160, 120);
        s.adaptive.threshold = 0.0;
        s.adaptive.depth = 2;
        s.lightMethod = LightMethod::Asos;
        s.asos.maxLevel = c.maxLevel;
        const std::vector<std::pair<std::string, std::string>> declares = {{"Light", c.light}, {"Samples", c.samples}};
        const std::string reference = std::string("area_lights_") + c.name + "_converged";
        compareWithReference(
            renderSceneFile(sourceDir("povray") / "area_lights.pov", s, {{"Light", c.light}}),
            povrayReference("area_lights", reference, "+A0.0 +AM2 +R3 -J" + povrayDeclares(declares), 160, 120),
            false, tolerance);
    }
}

// Spotlights, a cylinder light and a parallel light
// (tests/golden/povray/spotlight.pov) with one ray per pixel; and with the
// spotlight an area light (Area=1) on POV-Ray's lattice, as its
// lights/arealit*.pov use one.
TEST_CASE("Spotlights, cylinder and parallel lights match POV-Ray", "[golden][povray][lights][spotlight]") {
    compareWithPovray("spotlight", RenderMethod::Single, "", "-A");
    RenderSettings s = settingsFor(RenderMethod::Single, 160, 90);
    s.lightMethod = LightMethod::Grid;
    const std::vector<std::pair<std::string, std::string>> declares = {{"Area", "1"}};
    compareWithReference(renderSceneFile(sourceDir("povray") / "spotlight.pov", s, declares),
                         povrayReference("spotlight", "spotlight_area", "-A" + povrayDeclares(declares)), false);
}

// prism (tests/golden/povray/prism.pov): each spline kind, sub-prisms,
// open, and heights written high first, with one ray per pixel.
TEST_CASE("Prisms match POV-Ray with one ray per pixel", "[golden][povray][prism]") {
    compareWithPovray("prism", RenderMethod::Single, "", "-A");
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
