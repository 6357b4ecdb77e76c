// `asos bench intersect` as a user runs it (small, so that it is quick): the
// paper's Table 3 with one row per primitive, its name first and the ratio
// last, then the classes of the probed cones. The figures themselves are not
// checked (speed is the bench's business, not a test's); their shape is.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "run_asos.hpp"

namespace fs = std::filesystem;

namespace {

using Result = asos::test::ProgramResult;

const fs::path kDir = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli-bench";

Result runAsos(std::vector<std::string> args) { return asos::test::runAsos(kDir, std::move(args)); }

const std::vector<std::string> kPrimitives = {"sphere", "polygon", "disc", "box",
                                              "cone",   "cylinder", "plane"};

// The rows of stdout that start with a primitive's name, split into fields,
// in order of appearance (a primitive's first row is Table 3's).
std::multimap<std::string, std::vector<std::string>> rowsByPrimitive(const std::string& out) {
    std::multimap<std::string, std::vector<std::string>> rows;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::vector<std::string> fields;
        for (std::string w; words >> w;) fields.push_back(w);
        if (!fields.empty())
            for (const std::string& p : kPrimitives)
                if (fields[0] == p) rows.emplace(p, fields);
    }
    return rows;
}

}  // namespace

TEST_CASE("asos bench intersect prints a row per primitive, its name first and the ratio last",
          "[cli][bench]") {
    const Result r = runAsos({"bench", "intersect", "--queries", "64", "--probes", "64"});
    REQUIRE(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("each round in a fresh order") != std::string::npos);
    const auto rows = rowsByPrimitive(r.out);
    for (const std::string& p : kPrimitives) {
        INFO(p);
        // Table 3's row, then the classes' row.
        REQUIRE(rows.count(p) == 2);
        const std::vector<std::string>& table = rows.find(p)->second;
        // primitive, ray_ns, cone_ns, cone+trig_ns, paper, ratio
        REQUIRE(table.size() == 6);
        const double rayNs = std::stod(table[1]), coneNs = std::stod(table[2]);
        const double ratio = std::stod(table[5]);
        CHECK(rayNs > 0.0);
        CHECK(coneNs > 0.0);
        CHECK(ratio == Approx(coneNs / rayNs).epsilon(0.02));
        CHECK((table[4] == "-") == (p == "plane"));
        // primitive, miss%, full%, marginal%, ..., spurious/cones%: the classes sum to 100
        const std::vector<std::string>& classes = std::next(rows.find(p))->second;
        REQUIRE(classes.size() == 10);
        CHECK(std::stod(classes[1]) + std::stod(classes[2]) + std::stod(classes[3]) ==
              Approx(100.0).margin(0.05));
    }
}

TEST_CASE("asos bench intersect --only times one primitive, and bad options are refused",
          "[cli][bench]") {
    const Result one = runAsos({"bench", "intersect", "--queries", "32", "--probes", "0", "--only",
                                "disc", "--transforms", "scale"});
    REQUIRE(one.exitCode == 0);
    const auto rows = rowsByPrimitive(one.out);
    CHECK(rows.size() == 1);
    CHECK(rows.count("disc") == 1);

    const Result bad = runAsos({"bench", "intersect", "--transforms", "shear"});
    CHECK(bad.exitCode != 0);
    CHECK(bad.err.find("--transforms") != std::string::npos);
    const Result none = runAsos({"bench", "intersect", "--queries", "0"});
    CHECK(none.exitCode != 0);
    const Result unknown = runAsos({"bench", "intersect", "--only", "torus"});
    CHECK(unknown.exitCode != 0);
    CHECK(unknown.err.find("torus") != std::string::npos);
}
