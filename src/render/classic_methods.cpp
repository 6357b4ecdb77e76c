#include "asos/render/classic_methods.hpp"

#include <cmath>
#include <string>

#include "asos/image/encoding.hpp"

namespace asos {

namespace {
// POV-Ray compares anti-aliasing samples after a transcoding gamma curve:
// decode the working gamma, encode with antialias_gamma (PowerLawGammaCurve).
double encodeForComparison(double c, const AdaptiveSettings& s) {
    const double linear = workingToLinear(c, s.assumedGamma);
    if (!(linear > 0.0)) return 0.0;
    return s.gamma > 0.0 ? std::pow(linear, 1.0 / s.gamma) : linear;
}
}  // namespace

std::string checkAdaptiveSettings(const AdaptiveSettings& s) {
    if (s.depth < 0 || s.depth > kMaxAdaptiveDepth)
        return "the antialiasing depth (adaptive, am1) must be between 0 and " +
               std::to_string(kMaxAdaptiveDepth) + ", not " + std::to_string(s.depth);
    if (!(s.threshold >= 0.0) || !std::isfinite(s.threshold))
        return "the antialiasing threshold (adaptive, am1) must be a non-negative number";
    if (!(s.jitterAmount >= 0.0) || !std::isfinite(s.jitterAmount))
        return "the antialiasing jitter amount (adaptive, am1) must be a non-negative number";
    if (!(s.gamma >= 0.0) || !std::isfinite(s.gamma) || !(s.assumedGamma > 0.0) ||
        !std::isfinite(s.assumedGamma))
        return "the antialiasing gamma and assumed_gamma (adaptive, am1) must be positive numbers";
    return {};
}

bool adaptiveColorsDiffer(const Vec3& a, const Vec3& b, const AdaptiveSettings& s) {
    double distance = 0.0;
    for (int i = 0; i < 3; ++i)
        distance += std::fabs(encodeForComparison(a[i], s) - encodeForComparison(b[i], s));
    return distance >= s.threshold;
}

}  // namespace asos
