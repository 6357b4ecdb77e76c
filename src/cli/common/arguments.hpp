#pragma once
// Values the commands of both programs (asos, asos-bench) read from their
// options: numbers, fractions such as `1/64`, and `-D NAME=VALUE`
// declarations. Each returns nothing when the text is not one; the command
// names the option in its error.
#include <optional>
#include <string>
#include <string_view>

#include "asos/lang/interpreter.hpp"

namespace asos::cli {

// The whole text as a number ("0.015", "1e-3"), nothing else around it.
std::optional<double> parseNumber(std::string_view text);

// A number or a fraction A/B of numbers with B not zero ("1/64").
std::optional<double> parseFraction(std::string_view text);

// `NAME=VALUE` with NAME an identifier that is not a keyword.
std::optional<lang::Define> parseDefine(const std::string& text);

}  // namespace asos::cli
