#pragma once
// POV-Ray 3.7's spectral bands for dispersion (core/colour/spectral.h): a
// ray refracted by a dispersive interior splits into N bands of equal width
// between 380 and 730 nm; each is refracted with its own ior and weighted
// by its hue, so that the N hues add up to white (docs/rendering.md,
// "Dispersion").
#include "asos/geometry/vec.hpp"

namespace asos {

struct SpectralBand {
    static constexpr double kViolet = 380.0;
    static constexpr double kRed = 730.0;
    static constexpr double kBandwidth = kRed - kViolet;
    static constexpr double kCentre = 0.5 * (kViolet + kRed);

    float wavelength = 0.0f;  // the band's peak, nm (POV-Ray keeps floats)
    float bandwidth = 0.0f;

    // Band `band` of `bands` (0: the violet end).
    static SpectralBand of(unsigned band, unsigned bands) {
        return {static_cast<float>(kViolet + kBandwidth * ((static_cast<float>(band) + 0.5f) / static_cast<float>(bands))),
                static_cast<float>(kBandwidth / static_cast<float>(bands))};
    }
    // The ior for this band of a surface of nominal ior ratio `ior` and
    // dispersion ratio `dispersion` (the violet end's ior over the red's).
    double ior(double nominalIor, double dispersion) const;
    // The band's colour: the hue integral over its width, scaled so that a
    // full spectrum's bands average to white.
    Vec3 hue() const;
};

}  // namespace asos
