#include "cli/common/arguments.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "asos/lang/source_kind.hpp"
#include "asos/lang/words.hpp"

namespace asos::cli {

namespace {

bool isIdentifier(std::string_view s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return !lang::isReservedWord(s);
}

std::string error(const std::string& command, const std::string& message) {
    return command + ": error: " + message + "\n";
}

}  // namespace

std::optional<double> parseNumber(std::string_view text) {
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<double> parseFraction(std::string_view text) {
    const auto slash = text.find('/');
    if (slash == std::string_view::npos) return parseNumber(text);
    const auto a = parseNumber(text.substr(0, slash));
    const auto b = parseNumber(text.substr(slash + 1));
    if (!a || !b || *b == 0.0) return std::nullopt;
    return *a / *b;
}

std::optional<std::uint64_t> parseUnsigned(std::string_view text) {
    std::uint64_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<std::uint64_t> parseByteSize(std::string_view text) {
    std::size_t digits = 0;
    while (digits < text.size() && (std::isdigit(static_cast<unsigned char>(text[digits])) || text[digits] == '.'))
        ++digits;
    const std::optional<double> number = parseNumber(text.substr(0, digits));
    if (!number) return std::nullopt;
    std::string unit(text.substr(digits));
    for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (unit.ends_with("IB")) unit.erase(unit.size() - 2);
    else if (unit.size() == 2 && unit.back() == 'B') unit.pop_back();
    int shift = 0;
    if (unit.empty() || unit == "B") shift = 0;
    else if (unit == "K") shift = 10;
    else if (unit == "M") shift = 20;
    else if (unit == "G") shift = 30;
    else if (unit == "T") shift = 40;
    else return std::nullopt;
    const double bytes = *number * std::ldexp(1.0, shift);
    if (!(bytes >= 1.0) || bytes >= 0x1p63) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

std::string formatByteSize(std::uint64_t bytes) {
    static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 6) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    if (unit == 0 || value >= 100.0 || value == std::floor(value))
        std::snprintf(text, sizeof text, "%.0f %s", value, kUnits[unit]);
    else
        std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
    return text;
}

std::optional<lang::Define> parseDefine(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || !isIdentifier(std::string_view(text).substr(0, eq))) return std::nullopt;
    return lang::Define{text.substr(0, eq), text.substr(eq + 1)};
}

CheckedSceneInputs checkSceneInputs(const SceneInputs& inputs, const std::string& command) {
    CheckedSceneInputs checked;
    lang::InterpreterOptions& options = checked.options;
    for (const std::string& dir : inputs.includePaths) {
        std::error_code ec;
        if (!std::filesystem::is_directory(dir, ec))
            checked.problems.push_back(error(command, "-L: '" + dir + "' is not a folder" +
                                                          (std::filesystem::exists(dir, ec) ? "" : " (it does not exist)")));
        options.includePaths.emplace_back(dir);
    }
    for (const std::string& text : inputs.defines) {
        std::optional<lang::Define> define = parseDefine(text);
        if (!define) {
            checked.problems.push_back(
                error(command, "-D wants NAME=VALUE with NAME an identifier that is not a keyword, not '" + text + "'"));
            continue;
        }
        // The value alone, evaluated as the scene's run would: its errors are
        // located in it ("-D NAME:1:3").
        lang::InterpreterOptions alone;
        alone.defines.push_back(*define);
        Diagnostics diagnostics;
        if (!lang::interpretText("", "-D", alone, diagnostics)) {
            std::string shown;
            for (const Diagnostic& d : diagnostics.all()) shown += formatDiagnostic(d);
            checked.problems.push_back(shown + error(command, "-D " + define->name +
                                                                  ": a value is a number, a vector or a quoted string"));
        }
        options.defines.push_back(std::move(*define));
    }
    if (inputs.writeFolder) {
        std::error_code ec;
        if (!std::filesystem::is_directory(*inputs.writeFolder, ec))
            checked.problems.push_back(error(command, "--write-folder: '" + *inputs.writeFolder + "' is not a folder" +
                                                          (std::filesystem::exists(*inputs.writeFolder, ec) ? "" : " (it does not exist)")));
        options.writeFolder = *inputs.writeFolder;
    }
    if (inputs.clock) {
        const std::optional<double> clock = parseNumber(*inputs.clock);
        if (!clock || !std::isfinite(*clock))
            checked.problems.push_back(error(command, "--clock wants a finite number, not '" + *inputs.clock + "'"));
        else
            options.clock = *clock;
        options.clockOn = true;  // `clock_on` is 1 when --clock is given, as with POV-Ray's +K
    }
    options.maxObjects = inputs.limits.maxObjects;
    options.maxStringLength = inputs.limits.maxStringLength;
    options.maxArrayElements = inputs.limits.maxArrayElements;
    if (const std::optional<std::uint64_t> bytes = parseByteSize(inputs.maxMemory); bytes && *bytes > 0) {
        checked.maxMemoryBytes = *bytes;
        options.maxMemoryMiB = static_cast<std::size_t>(std::max<std::uint64_t>(1, *bytes >> 20));
    } else {
        checked.problems.push_back(error(command, "--max-memory wants a size such as 8G, 512M or a number of bytes, not '" +
                                                      inputs.maxMemory + "'"));
    }
    options.libraryPaths = lang::povrayLibraryPaths();
    return checked;
}

std::string unreadableScene(const std::string& path) {
    const lang::SourceCheck c = lang::checkSource(path);
    const char* what = nullptr;
    switch (c.kind) {
    case lang::SourceKind::Regular: return {};
    case lang::SourceKind::Unreachable: return "cannot read '" + path + "': " + std::strerror(c.error);
    case lang::SourceKind::Folder: what = "a folder"; break;
    case lang::SourceKind::Fifo: what = "a FIFO"; break;
    case lang::SourceKind::Device: what = "a device"; break;
    case lang::SourceKind::Other: what = "a socket"; break;
    }
    return "cannot read '" + path + "': it is " + std::string(what) + ", not a scene file";
}

}  // namespace asos::cli
