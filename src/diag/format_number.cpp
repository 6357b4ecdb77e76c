#include "asos/diag/format_number.hpp"

#include <charconv>
#include <cmath>

namespace asos {

std::string formatNumber(double v) {
    if (v == 0.0) return "0";
    if (std::isnan(v)) return "nan";  // its sign bit means nothing (to_chars writes "-nan")
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

}  // namespace asos
