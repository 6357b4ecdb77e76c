#include "bench_tools.hpp"

#include <time.h>

#include <cstdio>
#include <cstdlib>

#include "asos/diag/diagnostics.hpp"

namespace asos::bench {

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string shellQuoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

bool onPath(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::string number(double v, const char* format) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::optional<LoadedScene> loadScene(const std::string& path, const lang::InterpreterOptions& options) {
    Diagnostics diagnostics;
    std::optional<SceneDescription> description = lang::interpretFile(path, options, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
    if (!description) return std::nullopt;
    diagnostics.clear();
    std::unique_ptr<Scene> scene = Scene::build(*description, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
    if (!scene) return std::nullopt;
    return LoadedScene{std::move(*description), std::move(scene)};
}

}  // namespace asos::bench
