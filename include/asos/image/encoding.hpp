#pragma once
// How linear colour becomes file values, matching what POV-Ray 3.7 writes.
// Measured with the installed povray (docs/rendering.md, "Output encoding"):
// with `assumed_gamma 1` its 8- and 16-bit PNGs carry the sRGB transfer
// function (not a 2.2 power), values are clipped to [0, 1] and rounded to the
// nearest code, and there is no dithering. Its EXR output is linear.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

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
// the file. With assumed_gamma 1 this is the identity. No gamma (std::nullopt)
// is POV-Ray's gamma correction turned off, for a scene older than 3.7 that
// does not set assumed_gamma: its working space is then the display's, sRGB,
// and the decoding continues both pieces of the curve outside [0, 1]
// (measured: povray writes 1.5 as 2.537 and -0.2 as -0.01548 in EXR).
inline double workingToLinear(double value, std::optional<double> assumedGamma) {
    if (!assumedGamma)
        return value <= 0.04045 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4);
    if (*assumedGamma == 1.0) return value;
    return value <= 0.0 ? 0.0 : std::pow(value, *assumedGamma);
}

// The sRGB-encoded value, in [0, 1], that an integer file holds for a working
// value. With gamma correction off the value is already encoded: POV-Ray
// writes it as it is (measured: 0.2, 0.5, 0.05 become codes 51, 128, 13).
inline double workingToSrgb(double value, std::optional<double> assumedGamma) {
    if (!assumedGamma) return value > 0.0 ? std::min(value, 1.0) : 0.0;
    return srgbEncode(workingToLinear(value, assumedGamma));
}

// The file code for a value: sRGB-encoded, clipped, rounded to nearest.
inline std::uint8_t encodeSrgb8(double value, std::optional<double> assumedGamma = 1.0) {
    return static_cast<std::uint8_t>(std::lround(workingToSrgb(value, assumedGamma) * 255.0));
}
inline std::uint16_t encodeSrgb16(double value, std::optional<double> assumedGamma = 1.0) {
    return static_cast<std::uint16_t>(std::lround(workingToSrgb(value, assumedGamma) * 65535.0));
}

}  // namespace asos
