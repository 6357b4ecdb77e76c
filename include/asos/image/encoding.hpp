#pragma once
// How linear colour becomes file values, matching what POV-Ray 3.7 writes.
// Measured with the installed povray (docs/rendering.md, "Output encoding"):
// with `assumed_gamma 1` its 8- and 16-bit PNGs carry the sRGB transfer
// function (not a 2.2 power), values are clipped to [0, 1] and rounded to the
// nearest code, and there is no dithering. Its EXR output is linear.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace asos {

// IEC 61966-2-1 sRGB transfer function; input clipped to [0, 1] (NaN to 0).
inline double srgbEncode(double linear) {
    if (!(linear > 0.0)) return 0.0;
    if (linear >= 1.0) return 1.0;
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

inline double srgbDecode(double encoded) {
    const double x = std::clamp(encoded, 0.0, 1.0);
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

// A rendered value in the scene's working space (POV-Ray's assumed_gamma)
// to linear light: POV-Ray decodes with the working gamma before encoding for
// the file. With assumed_gamma 1 (the only value the project promises to
// match) this is the identity.
inline double workingToLinear(double value, double assumedGamma) {
    if (assumedGamma == 1.0) return value;
    return value <= 0.0 ? 0.0 : std::pow(value, assumedGamma);
}

// The file code for a value: sRGB-encoded, clipped, rounded to nearest.
inline std::uint8_t encodeSrgb8(double value, double assumedGamma = 1.0) {
    return static_cast<std::uint8_t>(
        std::lround(srgbEncode(workingToLinear(value, assumedGamma)) * 255.0));
}
inline std::uint16_t encodeSrgb16(double value, double assumedGamma = 1.0) {
    return static_cast<std::uint16_t>(
        std::lround(srgbEncode(workingToLinear(value, assumedGamma)) * 65535.0));
}

}  // namespace asos
