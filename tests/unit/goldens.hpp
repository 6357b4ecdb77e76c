#pragma once
// The one golden switch of the test suite, for parse dumps, diagnostics and
// image references alike (docs/goldens.md says how to review and update):
//  - ASOS_UPDATE_GOLDENS=1 (or true, yes, on) rewrites every golden a test
//    compares against from what the test got (scripts/update-goldens.sh);
//    unset, empty, 0, false, no or off only compare; any other value is an
//    error, so that a misspelt switch does not pass as a comparison.
//  - What a test got for a golden it does not match stays in the build tree
//    at golden-out/ + the golden's path in the source tree, e.g.
//    build/golden-out/tests/golden/render/sphere.png (and, for an image, the
//    difference beside it, sphere.diff.png); a golden that matches leaves no
//    file there.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace asos::test {

inline bool updatingGoldens() {
    const char* value = std::getenv("ASOS_UPDATE_GOLDENS");
    std::string v = value ? value : "";
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (v == "1" || v == "true" || v == "yes" || v == "on") return true;
    if (v.empty() || v == "0" || v == "false" || v == "no" || v == "off") return false;
    throw std::invalid_argument("ASOS_UPDATE_GOLDENS='" + std::string(value) +
                                "': use 1 (or true, yes, on) to update the goldens, 0 or nothing to compare");
}

// Where a test leaves what it got for `golden` (a file of the source tree),
// its folder made.
inline std::filesystem::path goldenOutput(const std::filesystem::path& golden) {
    const std::filesystem::path out = std::filesystem::path(ASOS_BINARY_DIR) / "golden-out" /
                                      std::filesystem::relative(golden, ASOS_SOURCE_DIR);
    std::filesystem::create_directories(out.parent_path());
    return out;
}

}  // namespace asos::test
