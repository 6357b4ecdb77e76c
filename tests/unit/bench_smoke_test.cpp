// asos-bench runs: a tiny case of each benchmark exits 0, and bad options are
// refused. What the benchmarks print (figures, their layout) is theirs, not
// the test suite's.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "run_asos.hpp"

namespace fs = std::filesystem;

namespace {

using Result = asos::test::ProgramResult;

// The working folder is not the source tree: default scenes are found by
// the program itself.
const fs::path kDir = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "bench-smoke";

Result runBench(std::vector<std::string> args) {
    return asos::test::runProgram(ASOS_BENCH_EXE, kDir, std::move(args));
}

}  // namespace

TEST_CASE("asos-bench runs a tiny case of each benchmark", "[bench]") {
    const std::vector<std::vector<std::string>> cases = {
        {"parse", "--max-exponent", "3"},
        {"bvh", "--sizes", "100", "--width", "8", "--random-rays", "64", "--cones", "16", "--passes", "1"},
        {"intersect", "--queries", "16", "--probes", "16"},
        {"render", "-W", "16", "-H", "12", "--threads", "1", "--repeat", "1"},
        {"render", fs::path(ASOS_SOURCE_DIR) / "examples" / "bench" / "spheres.pov", "-W", "16", "-H", "12",
         "--threads", "1", "--repeat", "1"},
        {"lights", "-W", "16", "-H", "12", "--threads", "1", "--lights", "point,rectangular", "--grids", "2",
         "--eps", "1/4", "--reference", "2"},
        {"stability", "-W", "16", "-H", "12", "--frames", "3", "--quick", "--no-gnuplot", "-o", "stability"},
        {"eps", "-W", "16", "-H", "12", "--max", "4", "--eps", "16"},
        {"scale", "-W", "16", "-H", "12", "--quick", "--no-gnuplot", "-o", "scale"},
    };
    for (const auto& args : cases) {
        INFO(args[0] << (args.size() > 1 ? " " + args[1] : ""));
        const Result r = runBench(args);
        INFO(r.err);
        CHECK(r.exitCode == 0);
        CHECK_FALSE(r.out.empty());
    }
}

TEST_CASE("asos-bench refuses bad options, and asos has no bench", "[bench]") {
    const std::vector<std::vector<std::string>> cases = {
        {},
        {"frobnicate"},
        {"intersect", "--transforms", "shear"},
        {"render", "no-such-scene.pov"},
        {"render", "-W", "0"},
        {"lights", "--lights", "torch"},
    };
    for (const auto& args : cases) {
        INFO((args.empty() ? std::string("(no arguments)") : args[0] + " " + args.back()));
        const Result r = runBench(args);
        CHECK(r.exitCode > 0);
        CHECK_FALSE(r.err.empty());
    }
    CHECK(asos::test::runAsos(kDir, {"bench", "intersect"}).exitCode > 0);
}
