#pragma once
// What the charting benchmarks (accuracy, stability) share: CPU time, other
// programs (povray, gnuplot) run through the shell, numbers as text.
#include <memory>
#include <optional>
#include <string>

#include "asos/lang/interpreter.hpp"
#include "asos/scene/description.hpp"
#include "asos/scene/scene.hpp"

namespace asos::bench {

// The CPU seconds this process has used (steadier than wall time on a shared machine).
double processCpuSeconds();

// `s` quoted for the shell.
std::string shellQuoted(const std::string& s);

// Whether `program` is on the PATH.
bool onPath(const std::string& program);

// `v` by printf's `format`.
std::string number(double v, const char* format = "%.6g");

// A scene file interpreted with `options` and built; nothing (its
// diagnostics printed on stderr, as every warning is) when either fails.
struct LoadedScene {
    SceneDescription description;
    std::unique_ptr<Scene> scene;
};
std::optional<LoadedScene> loadScene(const std::string& path, const lang::InterpreterOptions& options);

}  // namespace asos::bench
