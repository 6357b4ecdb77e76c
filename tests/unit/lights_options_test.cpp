// The area light options of the renderer and of `asos render`:
// --light-method, --light-samples, --shadow-apex; their defaults and errors.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "asos/render/renderer.hpp"
#include "render_scenes.hpp"

namespace fs = std::filesystem;
using namespace asos;
using namespace asos::testing;

namespace {

fs::path scratchDir() {
    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-output" / "lights_options";
    fs::create_directories(dir);
    return dir;
}

// Runs `asos render` on a small scene with an area light; returns the exit
// status and what it wrote on stderr.
std::pair<int, std::string> renderWith(const std::string& name, const std::string& options) {
    const fs::path dir = scratchDir();
    const fs::path scene = dir / "area.pov";
    std::ofstream(scene) << "camera { location <0, 3, -6> look_at 0 }\n"
                            "light_source { <0, 5, 0>, 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 3 }\n"
                            "plane { y, 0 pigment { color rgb 1 } }\n"
                            "sphere { <0, 1, 0>, 0.8 pigment { color rgb 1 } }\n";
    const fs::path err = dir / (name + ".err");
    const std::string command = std::string(ASOS_EXE) + " render '" + scene.string() + "' -o '" +
                                (dir / (name + ".png")).string() + "' -W 16 -H 12 --quiet " + options +
                                " 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    std::ifstream in(err);
    std::ostringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
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
    SceneDescription d;
    d.camera = lookAtCamera({0, 3, -6}, {0, 0.5, 0}, 50);
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, litTexture(Vec3(1.0))));
    d.objects.push_back(makeObject(SphereShape{{0, 1, 0}, 0.8}, litTexture(Vec3(1.0))));
    Light light = pointLight({0.5, 5, -0.5});
    AreaLight area;
    area.axis1 = {2, 0, 0};
    area.axis2 = {0, 0, 2};
    area.size1 = area.size2 = 8;
    light.area = area;
    d.lights.push_back(light);
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
    CHECK(renderWith("default", "").first == 0);
    CHECK(renderWith("grid", "--method jitter --samples 2 --light-method grid --light-samples 3").first == 0);
    CHECK(renderWith("behind", "--shadow-apex behind").first == 0);
    const auto [badMethod, badMethodText] = renderWith("bad_method", "--light-method stochastic");
    CHECK(badMethod == 1);
    CHECK_THAT(badMethodText, Catch::Contains("--light-method"));
    const auto [badApex, badApexText] = renderWith("bad_apex", "--method single --shadow-apex behind");
    CHECK(badApex == 1);
    CHECK_THAT(badApexText, Catch::Contains("behind"));
    CHECK_FALSE(fs::exists(scratchDir() / "bad_apex.png"));
    CHECK(renderWith("bad_samples", "--light-samples 0").first == 1);
}
