#include "asos/testing/image_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace asos {
namespace {

bool sameShape(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() && a.channels() == b.channels();
}

// One value's difference, as OpenImageIO's compare takes it: in float.
double difference(float u, float v) {
    if (std::isnan(u) && std::isnan(v)) return 0.0;
    if (!std::isfinite(u) || !std::isfinite(v)) return u == v ? 0.0 : std::numeric_limits<double>::infinity();
    return std::fabs(u - v);
}

}  // namespace

std::string ImageComparison::summary() const {
    if (!error.empty()) return "cannot compare: " + error;
    char line[320];
    std::snprintf(line, sizeof line,
                  "%s: mean error %.6g, RMS %.6g, PSNR %.2f dB, max error %.6g at (%d, %d) "
                  "channel %d; %zu of %zu pixels over the failure threshold, %zu over the "
                  "warning threshold",
                  passed ? "PASS" : "FAIL", meanError, rmsError, psnr, maxError, maxX, maxY,
                  maxChannel, failPixels, pixels, warnPixels);
    return line;
}

ImageComparison compareImages(const Image& a, const Image& b, const CompareThresholds& t) {
    ImageComparison r;
    if (!sameShape(a, b)) {
        r.error = "image sizes differ: " + std::to_string(a.width()) + "x" +
                  std::to_string(a.height()) + "x" + std::to_string(a.channels()) + " and " +
                  std::to_string(b.width()) + "x" + std::to_string(b.height()) + "x" +
                  std::to_string(b.channels());
        return r;
    }
    if (a.empty()) {
        r.error = "images are empty";
        return r;
    }
    // The thresholds as idiff holds them: in float.
    const double failValue = static_cast<float>(t.failValue);
    const double warnValue = static_cast<float>(t.warnValue);
    double sum = 0.0, sumOfSquares = 0.0;
    double peak = 1.0;  // PSNR's signal: 1, or the largest value when larger
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            bool fails = false, warns = false;
            for (int c = 0; c < a.channels(); ++c) {
                const float u = a.at(x, y, c), v = b.at(x, y, c);
                const double d = difference(u, v);
                if (std::isfinite(u)) peak = std::max(peak, double(u));
                if (std::isfinite(v)) peak = std::max(peak, double(v));
                sum += d;
                sumOfSquares += d * d;
                if (d > r.maxError) {
                    r.maxError = d;
                    r.maxX = x;
                    r.maxY = y;
                    r.maxChannel = c;
                }
                fails = fails || d > failValue;
                warns = warns || d > warnValue;
            }
            r.failPixels += fails;
            r.warnPixels += warns;
        }
    r.pixels = static_cast<std::size_t>(a.width()) * static_cast<std::size_t>(a.height());
    const double values = static_cast<double>(r.pixels) * a.channels();
    r.meanError = sum / values;
    r.rmsError = std::sqrt(sumOfSquares / values);
    r.psnr = 20.0 * std::log10(peak / r.rmsError);
    r.passed = static_cast<double>(r.failPixels) <= t.failPercent / 100.0 * static_cast<double>(r.pixels) &&
               r.maxError <= t.hardFail;
    return r;
}

Image absoluteDifference(const Image& a, const Image& b) {
    if (!sameShape(a, b)) throw std::invalid_argument("absoluteDifference: image sizes differ");
    Image d(a.width(), a.height(), a.channelNames());
    for (std::size_t i = 0; i < a.data().size(); ++i) d.data()[i] = std::fabs(a.data()[i] - b.data()[i]);
    return d;
}

}  // namespace asos
