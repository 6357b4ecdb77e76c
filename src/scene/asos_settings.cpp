#include "asos/scene/asos_settings.hpp"

#include <cmath>

#include "asos/diag/format_number.hpp"

namespace asos {

std::string epsProblem(double eps) {
    if (!(eps > 0) || !std::isfinite(eps)) return "eps must be positive, not " + formatNumber(eps);
    if (eps > kMaxAsosEps) return "eps must be at most " + formatNumber(kMaxAsosEps) + ", not " + formatNumber(eps);
    return {};
}

std::string checkAsosOptions(const AsosOptions& options, const std::string& what) {
    if (options.eps)
        if (std::string e = epsProblem(*options.eps); !e.empty()) return what + ": " + e;
    if (options.maxLevel && (*options.maxLevel < 0 || *options.maxLevel > kMaxAsosLevel))
        return what + ": max must be between 0 and " + std::to_string(kMaxAsosLevel) + ", not " +
               std::to_string(*options.maxLevel);
    return {};
}

}  // namespace asos
