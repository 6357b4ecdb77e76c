// The render pipeline: every method through the same scene, determinism over
// threads and regions, settings and scene checks.
#include <catch2/catch.hpp>

#include <cmath>

#include "asos/render/renderer.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// Spheres and a box on a checkered floor under a point light, one sphere
// reflective: every part of the shading and every kind of edge.
SceneDescription demoScene() {
    SceneDescription s;
    s.camera = lookAtCamera({0, 2.5, -6}, {0, 0.6, 0}, 50);
    s.background.rgb = {0.1, 0.15, 0.3};
    s.lights.push_back(pointLight({-4, 8, -5}));
    Texture floor = litTexture(Vec3(1.0));
    floor.pigment.kind = Pigment::Kind::Checker;
    floor.pigment.color2.rgb = {0.2, 0.3, 0.2};
    s.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0}, floor));
    s.objects.push_back(makeObject(SphereShape{{-1.2, 0.8, 0.5}, 0.8}, litTexture({0.9, 0.3, 0.2})));
    Texture shiny = litTexture({0.3, 0.5, 0.9});
    shiny.finish.phong = 0.8;
    shiny.finish.reflection = Vec3(0.3);
    s.objects.push_back(makeObject(BoxShape{{0.3, 0, -0.2}, {1.5, 1.2, 1.0}}, shiny));
    s.objects.push_back(makeObject(SphereShape{{0.5, 0.25, -1.3}, 0.25}, litTexture({0.9, 0.9, 0.2})));
    return s;
}

RenderOutput renderOrFail(const SceneDescription& d, const RenderSettings& s) {
    Diagnostics diagnostics;
    std::optional<RenderOutput> out = render(d, s, diagnostics);
    REQUIRE(out);
    return std::move(*out);
}

// 48 x 36 pixels, and a reference of them by an 8 x 8 grid.
RenderSettings smallImage() {
    RenderSettings s;
    s.width = 48;
    s.height = 36;
    return s;
}
RenderOutput gridReference(const SceneDescription& d) {
    RenderSettings s = smallImage();
    s.method = RenderMethod::Grid;
    s.samples = 8;
    const RenderOutput reference = renderOrFail(d, s);
    CHECK(reference.stats.counters.eyeRays == 48u * 36u * 64u);
    return reference;
}

// The mean absolute difference of two images, over all values.
double meanDifference(const RenderOutput& a, const RenderOutput& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.color.data().size(); ++i)
        sum += std::abs(a.color.data()[i] - b.color.data()[i]);
    return sum / static_cast<double>(a.color.data().size());
}

}  // namespace

TEST_CASE("Every method renders the same scene alike", "[renderer]") {
    // Without the checker, whose aliasing is no boundary of an object (the
    // classic methods do not filter patterns; ASOS does, the next test).
    SceneDescription d = demoScene();
    d.objects[0].texture = std::make_shared<const Texture>(litTexture({0.8, 0.8, 0.7}));
    const RenderOutput reference = gridReference(d);
    RenderSettings s = smallImage();
    for (RenderMethod m : {RenderMethod::Asos, RenderMethod::Single, RenderMethod::Jitter,
                           RenderMethod::Adaptive, RenderMethod::Am1}) {
        s.method = m;
        const RenderOutput out = renderOrFail(d, s);
        INFO(methodName(m));
        CHECK(out.stats.method == methodName(m));
        CHECK(out.stats.counters.pixels == 48u * 36u);
        // Mean absolute difference from the 8 x 8 grid.
        CHECK(meanDifference(out, reference) < (m == RenderMethod::Single ? 0.03 : 0.015));
        if (m == RenderMethod::Am1) {
            // The samples AOV counts every eye ray, the frames' included.
            double rays = 0.0;
            for (int y = 0; y < 36; ++y)
                for (int x = 0; x < 48; ++x) rays += out.samples.at(x, y, 0);
            CHECK(rays == double(out.stats.counters.eyeRays));
            CHECK(out.stats.counters.eyeRays > 48u * 36u + 2u * (48u + 36u));
        }
    }
}

TEST_CASE("With its pattern filter ASOS renders a checkered floor as a dense grid does", "[renderer]") {
    // The scene above with its checker: without the filter ASOS aliases it
    // as one ray per pixel does; with it (the default), each covered pixel
    // still costs one ray.
    const SceneDescription d = demoScene();
    const RenderOutput reference = gridReference(d);
    RenderSettings s = smallImage();
    const RenderOutput filtered = renderOrFail(d, s);
    s.patternFilter = false;
    const RenderOutput paper = renderOrFail(d, s);
    CHECK(meanDifference(filtered, reference) < 0.01);
    CHECK(meanDifference(paper, reference) > 2.0 * meanDifference(filtered, reference));
    CHECK(filtered.stats.counters.eyeRays == paper.stats.counters.eyeRays);

    // Pattern edges keep point-sampled leaves unless the filter is asked for.
    s.patternFilter.reset();
    s.patternEdges = true;
    const RenderOutput edges = renderOrFail(d, s);
    s.patternFilter = false;
    CHECK(renderOrFail(d, s).color.data() == edges.color.data());
    CHECK(edges.stats.counters.eyeRays > filtered.stats.counters.eyeRays);
}

TEST_CASE("The pattern filter is ASOS's default, and ASOS's alone", "[renderer]") {
    RenderSettings s;
    CHECK(effectivePatternFilter(s));
    s.patternEdges = true;
    CHECK_FALSE(effectivePatternFilter(s));
    s.patternFilter = true;
    CHECK(effectivePatternFilter(s));
    s.patternEdges = false;
    s.patternFilter = false;
    CHECK_FALSE(effectivePatternFilter(s));
    CHECK(checkRenderSettings(s).empty());
    for (RenderMethod m : {RenderMethod::Single, RenderMethod::Grid, RenderMethod::Jitter,
                           RenderMethod::Adaptive, RenderMethod::Am1}) {
        RenderSettings classic;
        classic.method = m;
        CHECK_FALSE(effectivePatternFilter(classic));
        classic.patternFilter = false;
        CHECK(checkRenderSettings(classic).empty());
        classic.patternFilter = true;
        CHECK_THAT(checkRenderSettings(classic), Catch::Contains("pattern filter"));
    }
}

TEST_CASE("ASOS costs fewer rays than 4 x 4 stochastic sampling", "[renderer]") {
    const SceneDescription d = demoScene();
    RenderSettings s;
    // Large enough that edge pixels are a minority, as in the paper's images.
    s.width = 128;
    s.height = 96;
    s.method = RenderMethod::Asos;
    const RenderOutput asos = renderOrFail(d, s);
    s.method = RenderMethod::Jitter;
    const RenderOutput jitter = renderOrFail(d, s);
    // The paper: "ASOS traces less than one fourth as many rays".
    CHECK(asos.stats.counters.allRays() * 4 < jitter.stats.counters.allRays());
    CHECK(asos.stats.counters.pyraysByLevel[0] == 128u * 96u);
    CHECK(asos.stats.counters.pyraysByLevel[4] > 0);
    CHECK(asos.stats.counters.shadowPyraysByLevel[0] > 0);
    // The samples AOV counts every pyray of the image.
    double pyrays = 0.0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 128; ++x) pyrays += asos.samples.at(x, y, 0);
    std::uint64_t counted = 0;
    for (std::uint64_t n : asos.stats.counters.pyraysByLevel) counted += n;
    CHECK(pyrays == double(counted));
}

TEST_CASE("Renders are identical for any thread count and region tiling", "[renderer]") {
    const SceneDescription d = demoScene();
    for (RenderMethod m :
         {RenderMethod::Asos, RenderMethod::Jitter, RenderMethod::Adaptive, RenderMethod::Am1}) {
        INFO(methodName(m));
        RenderSettings s;
        s.width = 40;
        s.height = 30;
        s.method = m;
        s.asos.jitter = true;
        s.adaptive.jitter = true;
        s.seed = 17;
        s.threads = 1;
        const RenderOutput one = renderOrFail(d, s);
        s.threads = 2;
        s.tileSize = 7;
        const RenderOutput two = renderOrFail(d, s);
        CHECK(one.color == two.color);
        CHECK(one.samples == two.samples);
        // Every count but the cone tests, which include the objects that a
        // thread's remembered wider cone offered (render/cone_candidates.hpp).
        RenderCounters a = one.stats.counters, b = two.stats.counters;
        a.coneTests = b.coneTests = 0;
        CHECK(a == b);

        // Three regions put together give the whole image.
        Image assembled = Image::rgb(40, 30);
        for (const PixelRegion& part :
             {PixelRegion{0, 0, 40, 11}, PixelRegion{0, 11, 23, 30}, PixelRegion{23, 11, 40, 30}}) {
            s.region = part;
            const RenderOutput r = renderOrFail(d, s);
            for (int y = part.y0; y < part.y1; ++y)
                for (int x = part.x0; x < part.x1; ++x) assembled.setRgb(x, y, r.color.rgbAt(x, y));
        }
        CHECK(assembled == one.color);
    }
}

TEST_CASE("Bad render settings are rejected with every problem named", "[renderer]") {
    RenderSettings s;
    CHECK(checkRenderSettings(s).empty());
    s.width = 0;
    s.samples = 0;
    s.asos.eps = -1.0;
    s.asos.maxLevel = 11;
    s.adaptive.depth = 9;
    s.region = PixelRegion{0, 0, 10, 10};
    const std::string problems = checkRenderSettings(s);
    CHECK_THAT(problems, Catch::Contains("image size"));
    CHECK_THAT(problems, Catch::Contains("samples"));
    CHECK_THAT(problems, Catch::Contains("eps"));
    CHECK_THAT(problems, Catch::Contains("depth"));
    Diagnostics diagnostics;
    CHECK_THROWS_AS(render(demoScene(), s, diagnostics), std::invalid_argument);

    RenderSettings regionOutside;
    regionOutside.width = 8;
    regionOutside.height = 8;
    regionOutside.region = PixelRegion{4, 4, 9, 8};
    CHECK_THAT(checkRenderSettings(regionOutside), Catch::Contains("region"));
    CHECK(parseMethod("asos") == RenderMethod::Asos);
    CHECK(parseMethod("adaptive") == RenderMethod::Adaptive);
    CHECK(parseMethod("am1") == RenderMethod::Am1);
    CHECK_FALSE(parseMethod("stochastic"));
}

TEST_CASE("Scenes the renderer cannot render are reported with their locations", "[renderer]") {
    SceneDescription d = demoScene();
    d.objects[1].asos.maxLevel = 40;
    d.objects[1].loc.line = 7;
    d.lights[0].area = AreaLight{};
    d.lights[0].area->circular = true;  // a flat disc light: not rendered
    d.lights[0].loc.line = 3;
    Diagnostics diagnostics;
    RenderSettings s;
    s.width = 8;
    s.height = 6;
    CHECK_FALSE(render(d, s, diagnostics));
    REQUIRE(diagnostics.all().size() == 2);
    CHECK(diagnostics.all()[0].loc.line == 7);
    CHECK_THAT(diagnostics.all()[0].message, Catch::Contains("max"));
    CHECK(diagnostics.all()[1].loc.line == 3);
    CHECK_THAT(diagnostics.all()[1].message, Catch::Contains("circular"));
}

TEST_CASE("Command-line ASOS options override global_settings, and objects refine both", "[renderer]") {
    GlobalSettings g;
    g.asos.eps = 0.1;
    g.asos.maxLevel = 2;
    AsosOptions commandLine;
    commandLine.maxLevel = 5;
    const AsosSettings scene = sceneAsosSettings(g, commandLine);
    CHECK(scene.eps == 0.1);
    CHECK(scene.maxLevel == 5);
    CHECK_FALSE(scene.jitter);
    AsosOptions own;
    own.jitter = true;
    const AsosSettings object = scene.refinedBy(own);
    CHECK(object == AsosSettings{0.1, 5, true});
    CHECK(scene.finest(AsosSettings{0.5, 7, false}) == AsosSettings{0.1, 7, false});
    CHECK(AsosSettings{} == AsosSettings{1.0 / 64.0, 4, false});
}

TEST_CASE("max_trace_level is capped at POV-Ray's 256, and two mirrors fit a worker's stack", "[renderer]") {
    // Two facing mirrors: every eye ray reflects until the trace level stops
    // it. A description asking for 100000 levels gets 256, on worker threads
    // (TBB's stacks are smaller than the main thread's).
    SceneDescription s;
    s.camera = lookAtCamera({0, 0, -0.5}, {0, 0, 1}, 30);
    s.lights.push_back(pointLight({0, 0, 0}));
    Texture mirror = litTexture(Vec3(0.5));
    mirror.finish.reflection = Vec3(1.0);
    s.objects.push_back(makeObject(PlaneShape{{0, 0, 1}, 1}, mirror));
    s.objects.push_back(makeObject(PlaneShape{{0, 0, -1}, 1}, mirror));
    s.globals.maxTraceLevel = 100000;
    RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.method = RenderMethod::Single;
    settings.threads = 4;
    const RenderOutput out = renderOrFail(s, settings);
    CHECK(out.stats.counters.eyeRays == 64u);
    CHECK(out.stats.counters.reflectedRays == 64u * (kMaxTraceLevelLimit - 1));
}
