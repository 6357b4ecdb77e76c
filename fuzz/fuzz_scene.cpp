// libFuzzer target: scene text → parse → interpret → dump, and the dump's
// fixed point. Any input may be refused with diagnostics; none may crash,
// hang, leak or trip a sanitizer. An accepted scene's canonical dump must
// itself be accepted and dump to the same text (docs/robustness.md).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/fuzz_options.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/scene/dump.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& first, const std::string& second) {
    std::fprintf(stderr, "fuzz_scene: %s\n--- first dump\n%s\n--- second\n%s\n", what, first.c_str(),
                 second.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const asos::lang::InterpreterOptions options = asos::fuzzSceneOptions();
    std::string text(reinterpret_cast<const char*>(data), size);
    asos::Diagnostics diagnostics;
    const auto scene = asos::lang::interpretText(std::move(text), "fuzz.pov", options, diagnostics);
    if (!scene) return 0;
    // Without the location comments, which name the file each was read from.
    const asos::DumpOptions plain{.locations = false};
    const std::string first = asos::dumpScene(*scene, plain);
    asos::Diagnostics again;
    const auto reread = asos::lang::interpretText(first, "dump.pov", options, again);
    if (!reread) {
        std::string errors;
        for (const auto& d : again.all()) errors += d.message + "\n";
        fail("the dump of an accepted scene is refused", first, errors);
    }
    const std::string second = asos::dumpScene(*reread, plain);
    if (second != first) fail("the dump is not a fixed point", first, second);
    return 0;
}
