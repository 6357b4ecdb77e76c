#pragma once
// Image comparison for golden tests: OpenImageIO's test-suite rule
// (testsuite/runtest.py, idiff) on the product's Image, in plain C++ so that
// the product keeps OpenImageIO in one translation unit.
#include <cstddef>
#include <string>

#include "asos/image/image.hpp"

namespace asos {

// A comparison fails when more than `failPercent` percent of the pixels have
// a channel differing by more than `failValue`, or when any value differs by
// more than `hardFail`. Pixels over `warnValue` are counted as warnings.
struct CompareThresholds {
    double failValue = 0.004;
    double failPercent = 0.02;
    double hardFail = 0.012;
    double warnValue = 0.008;
};

struct ImageComparison {
    double meanError = 0.0, rmsError = 0.0, psnr = 0.0, maxError = 0.0;
    int maxX = 0, maxY = 0, maxChannel = 0;  // where the largest difference is
    std::size_t failPixels = 0, warnPixels = 0, pixels = 0;
    bool passed = false;
    std::string error;  // set when the images cannot be compared (sizes differ)

    // One line: verdict, mean, RMS, max error and where it is.
    std::string summary() const;
};

// Values are compared as idiff does: each difference taken in float, NaN
// equal to NaN and an infinity to the same infinity; any other non-finite
// difference is infinite (a hard failure).
ImageComparison compareImages(const Image& a, const Image& b, const CompareThresholds& thresholds = {});

// |a - b| per value, for failure reports. Sizes and channels must match
// (std::invalid_argument otherwise).
Image absoluteDifference(const Image& a, const Image& b);

}  // namespace asos
