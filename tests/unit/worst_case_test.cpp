// The worst-case scenes of examples/bench/ (worst_*.pov, and the contact and
// checker scenes; docs/performance.md, "Worst cases"): ASOS renders each
// within its bound, at MAX 2 and 4, with and without jitter: no pixel deeper
// than MAX, no pixel with more pyrays than the full quadtree to MAX
// (1 + 4 + … + 4^MAX; the alternating and fan scenes reach it), and every
// value finite. What each method's error is
// there is the benchmark's to chart, not this test's.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"

namespace fs = std::filesystem;
using namespace asos;

TEST_CASE("ASOS stays within its bound on the worst-case scenes", "[asos][worst]") {
    const fs::path bench = fs::path(ASOS_SOURCE_DIR) / "examples" / "bench";
    for (const char* name : {"worst_alternating", "worst_fan", "worst_subthin", "worst_grazing", "contact",
                             "checker"}) {
        lang::InterpreterOptions options;
        options.imageWidth = 48;
        options.imageHeight = 36;
        Diagnostics diagnostics;
        const std::optional<SceneDescription> description =
            lang::interpretFile(bench / (std::string(name) + ".pov"), options, diagnostics);
        INFO(name);
        REQUIRE(description);
        for (int maxLevel : {2, 4})
            for (bool jitter : {false, true}) {
                INFO("MAX " << maxLevel << (jitter ? ", jitter" : ""));
                RenderSettings settings;
                settings.width = 48;
                settings.height = 36;
                settings.threads = 2;
                settings.asos.maxLevel = maxLevel;
                settings.asos.jitter = jitter;
                const std::optional<RenderOutput> out = render(*description, settings, diagnostics);
                REQUIRE(out);
                const int rays = out->samples.channelIndex("rays");
                const int level = out->samples.channelIndex("level");
                REQUIRE(rays >= 0);
                REQUIRE(level >= 0);
                const double quadtree = double((1 << (2 * (maxLevel + 1))) - 1) / 3.0;  // 1 + 4 + … + 4^MAX
                double deepest = 0.0, most = 0.0;
                bool finite = true;
                for (int y = 0; y < settings.height; ++y)
                    for (int x = 0; x < settings.width; ++x) {
                        deepest = std::max(deepest, double(out->samples.at(x, y, level)));
                        most = std::max(most, double(out->samples.at(x, y, rays)));
                        for (int c = 0; c < 3; ++c) finite = finite && std::isfinite(out->color.at(x, y, c));
                    }
                INFO(name << " MAX " << maxLevel << " jitter " << jitter << ": deepest " << deepest << ", most " << most);
                CHECK(deepest <= maxLevel);
                CHECK(most <= quadtree);
                CHECK(most >= 1.0);
                CHECK(finite);
                // The alternating comb and the fan's centre are worst cases:
                // some pixel there takes the whole quadtree.
                if (std::string(name) == "worst_alternating" || std::string(name) == "worst_fan")
                    CHECK(most == quadtree);
            }
    }
}
