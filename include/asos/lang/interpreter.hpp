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
    std::string value;  // an expression: a number, a vector, a quoted string (an error otherwise)
};

struct InterpreterOptions {
    // #include looks beside the including file, beside the scene, in each of
    // `includePaths` (-L), then in each of `libraryPaths` (POV-Ray's own
    // include folders: povrayLibraryPaths()).
    std::vector<std::filesystem::path> includePaths;
    std::vector<std::filesystem::path> libraryPaths;
    // Where the files a scene writes (#fopen … write/append) go, relative
    // names taken from it, as POV-Ray takes them from the current folder;
    // empty: the current folder. #fopen … read and file_exists() look here
    // first, then where #include looks.
    std::filesystem::path writeFolder;
    std::vector<Define> defines;                      // -D, declared before the scene runs
    double clock = 0.0;                               // the value of `clock`
    bool clockOn = false;                             // `clock_on`: the clock was given
    // An animation's frame (`asos render --frames`), POV-Ray's values; all 0
    // for a still, as POV-Ray gives them without +KFI/+KFF.
    int frameNumber = 0;                              // `frame_number`
    int initialFrame = 0, finalFrame = 0;             // `initial_frame`, `final_frame`
    double initialClock = 0.0, finalClock = 0.0;      // `initial_clock`, `final_clock`
    double clockDelta = 0.0;                          // `clock_delta`: the clock's step from frame to frame
    int imageWidth = 320;                             // `image_width` (POV-Ray's default size)
    int imageHeight = 240;                            // `image_height`
    std::size_t maxErrors = 100;                      // then stop: one mistake in a loop repeats
    std::size_t maxLoopIterations = 100'000'000;      // all #while/#for iterations together
    // What a scene may ask for, checked before it is allocated: past one, a
    // located error names the limit and its option (docs/manual/limits.md).
    std::size_t maxArrayElements = 10'000'000;        // in one array (--max-array-elements)
    std::size_t maxObjects = 50'000'000;              // shapes and lights in the scene or a union (--max-objects)
    std::size_t maxStringLength = 16'777'216;         // characters in one string (--max-string-length)
    std::size_t maxMemoryMiB = 8'192;                 // objects, unions, arrays and strings, estimated (--max-memory)
};

// POV-Ray's include folders where POV-Ray is installed: the Library_Path
// entries of its configuration (~/.povray/3.7/povray.ini, then
// /etc/povray/3.7/povray.ini and /usr/local/etc/povray/3.7/povray.ini), then
// its standard include folder (/usr/share/povray-3.7/include,
// /usr/local/share/povray-3.7/include); only folders that exist, each once.
std::vector<std::filesystem::path> povrayLibraryPaths();

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
