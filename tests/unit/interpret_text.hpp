#pragma once
// Runs scene text through the interpreter, for the language's tests: the
// description it gives, its diagnostics as "line:col: message" lines, and
// the value of an expression read back through a sphere's centre.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "asos/lang/interpreter.hpp"

namespace asos::test {

struct Run {
    std::optional<SceneDescription> scene;
    Diagnostics diagnostics;

    std::string errors() const {
        std::string s;
        for (const auto& d : diagnostics.all())
            s += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message + "\n";
        return s;
    }
};

inline Run run(const std::string& text, const lang::InterpreterOptions& options = {}) {
    Run r;
    r.scene = lang::interpretText(text, "t.pov", options, r.diagnostics);
    return r;
}

inline const SceneDescription& ok(const Run& r) {
    INFO(r.errors());
    REQUIRE(r.scene);
    return *r.scene;
}

// The centre of the one sphere of `text`, which places `sphere { VALUE, 1 }`.
inline Vec3 valueOf(const std::string& declarations, const std::string& value) {
    Run r = run(declarations + "\nsphere { " + value + ", 1 }");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 1);
    return std::get<SphereShape>(scene.objects[0].shape).center;
}
inline double floatOf(const std::string& expression, const std::string& declarations = "") {
    return valueOf(declarations + "\n#declare Value__ = " + expression + ";", "<Value__, 0, 0>").x;
}

// The messages of the #debug directives of `text` (which must run), in order.
inline std::vector<std::string> debugOf(const std::string& text) {
    Run r = run(text + "\nsphere { 0, 1 }");
    ok(r);
    std::vector<std::string> lines;
    for (const auto& d : r.diagnostics.all())
        if (d.severity == Severity::Debug) lines.push_back(d.message);
    return lines;
}

inline std::filesystem::path scratchDir(const std::string& name) {
    auto dir = std::filesystem::path(ASOS_BINARY_DIR) / "test-scratch" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}
inline void writeFile(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace asos::test
