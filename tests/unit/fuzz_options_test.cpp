// fuzz_scene's limits (asos/fuzz_options.hpp): its seeds include the
// bad-scene corpus, whose limit scenes must stop at a located error at once
// under them, not run for a minute into the fuzzer's -timeout or its memory
// limit (docs/robustness.md).
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/fuzz_options.hpp"
#include "asos/lang/interpreter.hpp"

using namespace asos;
namespace fs = std::filesystem;

namespace {
const fs::path kErrors = fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / "errors";
}

TEST_CASE("fuzz_scene's limits stop a doubling union at its copy", "[lang][fuzz]") {
    const auto start = std::chrono::steady_clock::now();
    Diagnostics diagnostics;
    const auto scene = lang::interpretFile(kErrors / "limit_union_doubling.pov", fuzzSceneOptions(), diagnostics);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK_FALSE(scene);
    REQUIRE(diagnostics.all().size() == 1);
    const Diagnostic& first = diagnostics.all().front();
    // 64 MiB: a copy of line 17's A on line 18.
    CHECK(first.loc.line == 18);
    CHECK(first.loc.column == 31);
    CHECK(first.message.find("over the limit of 64 MiB") != std::string::npos);
    // With the defaults it ran for a minute; here milliseconds, even under
    // the sanitizers on a loaded machine.
    CHECK(seconds < 5.0);
}

TEST_CASE("fuzz_scene's limits refuse each limit scene of the corpus", "[lang][fuzz]") {
    for (const auto& entry : fs::directory_iterator(kErrors)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("limit_", 0) != 0 || entry.path().extension() != ".pov") continue;
        INFO(name);
        Diagnostics diagnostics;
        CHECK_FALSE(lang::interpretFile(entry.path(), fuzzSceneOptions(), diagnostics));
        CHECK(diagnostics.hasErrors());
    }
}
