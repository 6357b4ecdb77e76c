#pragma once
// How far an image is from a reference, as `asos-bench accuracy` reports it
// (docs/performance.md): on display values, the sRGB-encoded values an 8-bit
// file would hold before rounding (the scene's working gamma decoded first,
// clipped to [0, 1]), so that an error means the same on dark and light pixels
// as it does to the eye and to the idiff comparisons of scripts/.
#include <optional>

#include "asos/image/image.hpp"

namespace asos {

// The error 1/64 the share of pixels off is counted against.
inline constexpr double kOffByValue = 1.0 / 64.0;

struct ImageError {
    double rmse = 0.0;      // over every channel of every pixel
    double maxError = 0.0;  // the largest difference of one channel
    double offShare = 0.0;  // share of pixels with a channel more than kOffByValue off
};

// The errors of `image` against `reference`, both linear RGB in the working
// space of a scene with `assumedGamma`. Throws std::invalid_argument when
// their sizes differ or either has fewer than 3 channels.
ImageError imageError(const Image& image, const Image& reference, std::optional<double> assumedGamma);

}  // namespace asos
