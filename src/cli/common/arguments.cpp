#include "cli/common/arguments.hpp"

#include <cctype>
#include <charconv>

#include "asos/lang/words.hpp"

namespace asos::cli {

namespace {

bool isIdentifier(std::string_view s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return !lang::isReservedWord(s);
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

std::optional<lang::Define> parseDefine(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || !isIdentifier(std::string_view(text).substr(0, eq))) return std::nullopt;
    return lang::Define{text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace asos::cli
