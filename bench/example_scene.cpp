#include <system_error>

#include "benchmarks.hpp"

namespace asos::bench {

std::filesystem::path exampleScene(const std::filesystem::path& relative) {
    namespace fs = std::filesystem;
    // Where the program runs from decides, not the working directory: an
    // installed asos-bench finds its prefix's share folder wherever the
    // prefix was moved; one in the build tree has none and reads the source
    // tree's examples (both paths compiled in by bench/CMakeLists.txt).
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = program.parent_path() / ASOS_INSTALLED_EXAMPLES_FROM_BIN / relative;
        if (fs::exists(installed, ec)) return installed.lexically_normal();
    }
    return fs::path(ASOS_SOURCE_EXAMPLES) / relative;
}

}  // namespace asos::bench
