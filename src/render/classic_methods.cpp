#include "asos/render/classic_methods.hpp"

#include <cmath>

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

bool adaptiveColorsDiffer(const Vec3& a, const Vec3& b, const AdaptiveSettings& s) {
    double distance = 0.0;
    for (int i = 0; i < 3; ++i)
        distance += std::fabs(encodeForComparison(a[i], s) - encodeForComparison(b[i], s));
    return distance >= s.threshold;
}

}  // namespace asos
