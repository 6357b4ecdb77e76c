#pragma once
// Syntax tree → scene description. The interpreter runs the directives
// (#declare, #if, #while, #for, #include, …), evaluates expressions, and
// builds the plain-data SceneDescription: unions flattened, transforms and
// textures resolved with POV-Ray 3.7's meaning, the camera's final vectors
// computed. Every semantic error of a file is reported (with its location)
// before it gives up; library code never prints.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/scene/description.hpp"

namespace asos::lang {

struct Define {
    std::string name;
    std::string value;  // parsed as a float/vector expression, else taken as a string
};

struct InterpreterOptions {
    std::vector<std::filesystem::path> includePaths;  // -L, searched after the including file's folder
    std::vector<Define> defines;                      // -D, declared before the scene runs
    double clock = 0.0;                               // the value of `clock`
    int imageWidth = 320;                             // `image_width` (POV-Ray's default size)
    int imageHeight = 240;                            // `image_height`
    std::size_t maxErrors = 100;                      // then stop: one mistake in a loop repeats
    std::size_t maxLoopIterations = 100'000'000;      // all #while/#for iterations together
};

// Reads and runs a scene file. Returns nothing when an error was reported.
std::optional<SceneDescription> interpretFile(const std::filesystem::path& scene,
                                              const InterpreterOptions& options,
                                              Diagnostics& diagnostics);

// Runs scene text; `fileName` names it in locations, and #include looks
// beside it.
std::optional<SceneDescription> interpretText(std::string text, const std::string& fileName,
                                              const InterpreterOptions& options,
                                              Diagnostics& diagnostics);

}  // namespace asos::lang
