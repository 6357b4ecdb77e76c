#include <catch2/catch.hpp>

#include "asos/render/stats.hpp"

using namespace asos;

namespace {
RenderStats example() {
    RenderStats s;
    s.method = "asos";
    s.width = 64;
    s.height = 48;
    s.threads = 2;
    s.counters.pixels = 3072;
    s.counters.eyeRays = 4000;
    s.counters.reflectedRays = 500;
    s.counters.shadowRays = 1500;
    s.counters.coneTests = 9000;
    s.counters.rayTests = 12000;
    s.counters.countPyray(0);
    s.counters.countPyray(2);
    s.counters.countPyray(2);
    s.counters.countShadowPyray(1);
    s.times = {0.25, 0.5, 2.0};
    return s;
}
}  // namespace

TEST_CASE("Counters add up and clamp deep levels into the last slot", "[stats]") {
    RenderCounters a, b;
    a.eyeRays = 3;
    a.countPyray(1);
    b.eyeRays = 4;
    b.shadowRays = 2;
    b.countPyray(1);
    b.countPyray(99);
    b.countPyray(-3);
    a += b;
    CHECK(a.eyeRays == 7);
    CHECK(a.allRays() == 9);
    CHECK(a.pyraysByLevel[0] == 1);
    CHECK(a.pyraysByLevel[1] == 2);
    CHECK(a.pyraysByLevel[kStatLevels - 1] == 1);
}

TEST_CASE("Stats JSON has every figure", "[stats]") {
    const RenderStats s = example();
    CHECK(s.raysPerSecond() == Approx(6000.0 / 2.0));
    const std::string expected =
        "{\n"
        "  \"method\": \"asos\",\n"
        "  \"width\": 64,\n"
        "  \"height\": 48,\n"
        "  \"threads\": 2,\n"
        "  \"pixels\": 3072,\n"
        "  \"rays\": {\"eye\": 4000, \"reflected\": 500, \"shadow\": 1500, \"total\": 6000},\n"
        "  \"pyrays_by_level\": [1, 0, 2],\n"
        "  \"shadow_pyrays_by_level\": [0, 1],\n"
        "  \"cone_tests\": 9000,\n"
        "  \"ray_tests\": 12000,\n"
        "  \"times\": {\"parse\": 0.25, \"build\": 0.5, \"render\": 2, \"total\": 2.75},\n"
        "  \"rays_per_second\": 3000\n"
        "}\n";
    CHECK(statsToJson(s) == expected);
}

TEST_CASE("Stats JSON escapes strings and writes no NaN", "[stats]") {
    RenderStats s;
    s.method = "a\"b\\c\nd\x01";
    s.times.renderSeconds = std::nan("");
    const std::string j = statsToJson(s);
    CHECK_THAT(j, Catch::Contains(R"("method": "a\"b\\c\nd\u0001")"));
    CHECK_THAT(j, Catch::Contains("\"render\": null"));
    CHECK_THAT(j, Catch::Contains("\"pyrays_by_level\": []"));
    CHECK_THAT(j, Catch::Contains("\"rays_per_second\": 0"));
}

TEST_CASE("Stats table lists each quantity on its own line", "[stats]") {
    const std::string t = formatStatsTable(example());
    CHECK_THAT(t, Catch::StartsWith("Render statistics\n"));
    CHECK_THAT(t, Catch::Contains("  method                   asos\n"));
    CHECK_THAT(t, Catch::Contains("  image                    64 x 48\n"));
    CHECK_THAT(t, Catch::Contains("  pyrays level 2           2\n"));
    CHECK_THAT(t, Catch::Contains("  shadow pyrays level 1    1\n"));
    CHECK_THAT(t, Catch::Contains("  render time              2.000 s\n"));
    CHECK_THAT(t, Catch::Contains("  rays per second          3000\n"));
    CHECK_THAT(t, Catch::EndsWith("\n"));
}
