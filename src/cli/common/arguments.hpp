#pragma once
// Values the commands of both programs (asos, asos-bench) read from their
// options: numbers, fractions such as `1/64`, and `-D NAME=VALUE`
// declarations. Each returns nothing when the text is not one; the command
// names the option in its error.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "asos/lang/interpreter.hpp"

namespace asos::cli {

// The whole text as a number ("0.015", "1e-3"), nothing else around it.
std::optional<double> parseNumber(std::string_view text);

// A number or a fraction A/B of numbers with B not zero ("1/64").
std::optional<double> parseFraction(std::string_view text);

// The whole text as a whole number 0 ... 2^64 - 1, digits only: "-1" is
// refused, not wrapped.
std::optional<std::uint64_t> parseUnsigned(std::string_view text);

// A size in bytes: a number with an optional binary unit K, M, G or T
// (also KiB, MiB, GiB, TiB): "16G", "512MiB", "1000000".
std::optional<std::uint64_t> parseByteSize(std::string_view text);

// `bytes` for a message: "192 GiB", "1.5 MiB", "800 bytes".
std::string formatByteSize(std::uint64_t bytes);

// `NAME=VALUE` with NAME an identifier that is not a keyword.
std::optional<lang::Define> parseDefine(const std::string& text);

// -L, -D and --clock as `asos parse` and `asos render` take them.
struct SceneInputs {
    std::vector<std::string> includePaths;
    std::vector<std::string> defines;
    std::optional<std::string> clock;
    std::optional<std::string> writeFolder;  // --write-folder: where #fopen … write puts files
    // --max-objects, --max-string-length, --max-array-elements (these fields
    // of `limits` only) and --max-memory, a size ("8G", "512M", bytes): what
    // a scene may ask for, and for `asos render` its images too.
    lang::InterpreterOptions limits;
    std::string maxMemory = "8G";
};

struct CheckedSceneInputs {
    lang::InterpreterOptions options;  // with POV-Ray's library paths and the limits
    std::uint64_t maxMemoryBytes = 0;  // --max-memory, when it is a size
    // What is wrong, each as the lines to print: "COMMAND: error: ..." or,
    // for a -D value that does not parse or evaluate, the located error
    // ("-D NAME:1:3: error: ..." with the value and a caret).
    std::vector<std::string> problems;
};

// Checks them before any scene is read: every -L an existing folder, every
// -D NAME=VALUE with NAME an identifier and a value that is a number, a
// vector or a quoted string (an expression that parses and evaluates),
// --clock a finite number, --max-memory a size. `command` ("asos render") prefixes the messages.
CheckedSceneInputs checkSceneInputs(const SceneInputs& inputs, const std::string& command);

// Why the scene file cannot be read (missing, a folder, a FIFO, a device),
// empty when it is a regular file: checked before reading, so that a FIFO
// never blocks.
std::string unreadableScene(const std::string& path);

}  // namespace asos::cli
