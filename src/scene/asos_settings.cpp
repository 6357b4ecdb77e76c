#include "asos/scene/asos_settings.hpp"

#include <cmath>
#include <sstream>

namespace asos {

std::string checkAsosOptions(const AsosOptions& options, const std::string& what) {
    if (options.eps && (!std::isfinite(*options.eps) || *options.eps < 0.0)) {
        std::ostringstream out;
        out << what << ": eps must be a finite number >= 0, not " << *options.eps;
        return out.str();
    }
    if (options.maxLevel && (*options.maxLevel < 0 || *options.maxLevel > kMaxAsosLevel))
        return what + ": max must be between 0 and " + std::to_string(kMaxAsosLevel) + ", not " +
               std::to_string(*options.maxLevel);
    return {};
}

}  // namespace asos
