// The area light options of the renderer and of `asos render`:
// --light-method, --light-samples, --shadow-apex; their defaults and errors.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "asos/render/renderer.hpp"
#include "render_scenes.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;
using namespace asos::testing;

namespace {

fs::path scratchDir() {
    return asos::test::testCaseDir("lights_options", Catch::getResultCapture().getCurrentTestName());
}

// Runs `asos render` on a small scene with an area light; returns the exit
// status and what it wrote on stderr.
std::pair<int, std::string> renderWith(const std::string& name, std::vector<std::string> options) {
    const fs::path dir = scratchDir();
    std::ofstream(dir / "area.pov") << "camera { location <0, 3, -6> look_at 0 }\n"
                                       "light_source { <0, 5, 0>, 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 3 }\n"
                                       "plane { y, 0 pigment { color rgb 1 } }\n"
                                       "sphere { <0, 1, 0>, 0.8 pigment { color rgb 1 } }\n";
    std::vector<std::string> args{"render", "area.pov", "-o", name + ".png", "-W", "16", "-H", "12", "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const asos::test::ProgramResult r = asos::test::runAsos(dir, std::move(args));
    return {r.exitCode, r.err};
}

// A white sphere on a white plane under a 2 x 2 area light of size x size
// points.
SceneDescription sphereUnderAreaLight(int size) {
    SceneDescription d;
    d.camera = lookAtCamera({0, 3, -6}, {0, 0.5, 0}, 50);
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, litTexture(Vec3(1.0))));
    d.objects.push_back(makeObject(SphereShape{{0, 1, 0}, 0.8}, litTexture(Vec3(1.0))));
    Light light = pointLight({0.5, 5, -0.5});
    AreaLight area;
    area.axis1 = {2, 0, 0};
    area.axis2 = {0, 0, 2};
    area.size1 = area.size2 = size;
    light.area = area;
    d.lights.push_back(light);
    return d;
}

}  // namespace

TEST_CASE("Area lights default to ASOS beams under ASOS, the grid under the classic methods", "[lights]") {
    RenderSettings s;
    CHECK(effectiveLightMethod(s) == LightMethod::Asos);
    s.method = RenderMethod::Jitter;
    CHECK(effectiveLightMethod(s) == LightMethod::Grid);
    s.lightMethod = LightMethod::Asos;
    CHECK(effectiveLightMethod(s) == LightMethod::Asos);

    RenderSettings bad;
    bad.lightSamples = 0;
    bad.shadowApex = ShadowApex::Behind;
    bad.lightMethod = LightMethod::Grid;
    const std::string problems = checkRenderSettings(bad);
    CHECK_THAT(problems, Catch::Contains("light samples"));
    CHECK_THAT(problems, Catch::Contains("behind"));
    RenderSettings behind;
    behind.shadowApex = ShadowApex::Behind;
    CHECK(checkRenderSettings(behind).empty());
}

TEST_CASE("Every method renders an area light, to nearly the same image", "[lights]") {
    const SceneDescription d = sphereUnderAreaLight(8);
    auto rendered = [&](RenderSettings s) {
        s.width = 32;
        s.height = 24;
        s.threads = 2;
        Diagnostics diagnostics;
        std::optional<RenderOutput> out = render(d, s, diagnostics);
        REQUIRE(out);
        return std::move(out->color);
    };
    RenderSettings reference;
    reference.method = RenderMethod::Grid;
    reference.samples = 3;
    reference.lightSamples = 24;
    const Image truth = rendered(reference);
    RenderSettings asos;  // ASOS eye and light methods
    RenderSettings classicAsos = reference;
    classicAsos.lightMethod = LightMethod::Asos;
    for (const RenderSettings& s : {asos, classicAsos}) {
        const Image image = rendered(s);
        double worst = 0.0, sum = 0.0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const double e = std::abs(image.at(x, y, 0) - truth.at(x, y, 0));
                worst = std::max(worst, e);
                sum += e;
            }
        INFO("mean " << sum / (32 * 24) << ", worst " << worst);
        // Edges of objects differ between eye methods; shadows agree.
        CHECK(sum / (32 * 24) < 0.01);
    }
}

TEST_CASE("asos render: area light options, and their errors", "[lights][cli]") {
    CHECK(renderWith("default", {}).first == 0);
    CHECK(renderWith("grid", {"--method", "jitter", "--samples", "2", "--light-method", "grid", "--light-samples", "3"}).first == 0);
    CHECK(renderWith("behind", {"--shadow-apex", "behind"}).first == 0);
    const auto [badMethod, badMethodText] = renderWith("bad_method", {"--light-method", "stochastic"});
    CHECK(badMethod == 2);  // a bad command line
    CHECK_THAT(badMethodText, Catch::Contains("--light-method"));
    const auto [badApex, badApexText] = renderWith("bad_apex", {"--method", "single", "--shadow-apex", "behind"});
    CHECK(badApex == 2);
    CHECK_THAT(badApexText, Catch::Contains("behind"));
    CHECK_FALSE(fs::exists(scratchDir() / "bad_apex.png"));
    CHECK(renderWith("bad_samples", {"--light-samples", "0"}).first == 2);
}

TEST_CASE("Area light renders are deterministic over threads and regions", "[lights]") {
    SceneDescription d = sphereUnderAreaLight(4);
    Light& light = d.lights.back();
    light.area->jitter = true;
    light.asos.jitter = true;
    light.asos.maxLevel = 3;
    for (LightMethod method : {LightMethod::Asos, LightMethod::Grid}) {
        auto rendered = [&](int threads, std::optional<PixelRegion> region) {
            RenderSettings s;
            s.width = 32;
            s.height = 24;
            s.threads = threads;
            s.seed = 11;
            s.lightMethod = method;
            s.region = region;
            Diagnostics diagnostics;
            std::optional<RenderOutput> out = render(d, s, diagnostics);
            REQUIRE(out);
            return std::move(out->color);
        };
        const Image one = rendered(1, std::nullopt), two = rendered(2, std::nullopt);
        const Image part = rendered(2, PixelRegion{5, 3, 27, 20});
        bool same = true, partSame = true;
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 32; ++x)
                for (int c = 0; c < 3; ++c) {
                    same = same && one.at(x, y, c) == two.at(x, y, c);
                    if (x >= 5 && x < 27 && y >= 3 && y < 20) partSame = partSame && one.at(x, y, c) == part.at(x, y, c);
                }
        INFO(lightMethodName(method));
        CHECK(same);
        CHECK(partSame);
    }
}
