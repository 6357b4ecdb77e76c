#include "asos/render/spectral.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

namespace {

// POV-Ray 3.7's table of RGB colours by wavelength, integrated over the
// wavelength from 375 nm in steps of 5 nm (core/colour/spectral.cpp, the
// variant it compiles: its older dispersion hues' formula).
constexpr int kHueTableSize = 74;
constexpr double kHueTableBase = 375.0;
constexpr double kHueTableStep = 5.0;
constexpr float kHueIntegral[kHueTableSize][3] = {
    {0.0000f, 0.0000f, 0.0000f}, {0.0009f, 0.0000f, 0.0038f}, {0.0029f, 0.0000f, 0.0113f},
    {0.0058f, 0.0000f, 0.0222f}, {0.0094f, 0.0000f, 0.0363f}, {0.0135f, 0.0000f, 0.0534f},
    {0.0178f, 0.0000f, 0.0734f}, {0.0223f, 0.0000f, 0.0960f}, {0.0267f, 0.0000f, 0.1210f},
    {0.0308f, 0.0000f, 0.1482f}, {0.0344f, 0.0000f, 0.1775f}, {0.0374f, 0.0000f, 0.2085f},
    {0.0394f, 0.0000f, 0.2412f}, {0.0404f, 0.0000f, 0.2753f}, {0.0404f, 0.0000f, 0.3106f},
    {0.0404f, 0.0000f, 0.3470f}, {0.0404f, 0.0000f, 0.3841f}, {0.0404f, 0.0000f, 0.4219f},
    {0.0404f, 0.0000f, 0.4600f}, {0.0404f, 0.0000f, 0.4984f}, {0.0404f, 0.0000f, 0.5368f},
    {0.0404f, 0.0000f, 0.5750f}, {0.0404f, 0.0000f, 0.6128f}, {0.0404f, 0.0000f, 0.6500f},
    {0.0404f, 0.0000f, 0.6864f}, {0.0404f, 0.0045f, 0.7218f}, {0.0404f, 0.0131f, 0.7560f},
    {0.0404f, 0.0256f, 0.7888f}, {0.0404f, 0.0417f, 0.8200f}, {0.0404f, 0.0612f, 0.8494f},
    {0.0404f, 0.0839f, 0.8768f}, {0.0404f, 0.1095f, 0.9020f}, {0.0404f, 0.1378f, 0.9248f},
    {0.0404f, 0.1684f, 0.9449f}, {0.0404f, 0.2013f, 0.9623f}, {0.0404f, 0.2360f, 0.9767f},
    {0.0404f, 0.2724f, 0.9878f}, {0.0404f, 0.3102f, 0.9956f}, {0.0404f, 0.3492f, 0.9997f},
    {0.0404f, 0.3891f, 1.0000f}, {0.0429f, 0.4297f, 1.0000f}, {0.0502f, 0.4707f, 1.0000f},
    {0.0620f, 0.5119f, 1.0000f}, {0.0780f, 0.5530f, 1.0000f}, {0.0979f, 0.5937f, 1.0000f},
    {0.1215f, 0.6340f, 1.0000f}, {0.1483f, 0.6733f, 1.0000f}, {0.1781f, 0.7117f, 1.0000f},
    {0.2105f, 0.7487f, 1.0000f}, {0.2454f, 0.7841f, 1.0000f}, {0.2823f, 0.8178f, 1.0000f},
    {0.3210f, 0.8494f, 1.0000f}, {0.3611f, 0.8786f, 1.0000f}, {0.4024f, 0.9054f, 1.0000f},
    {0.4446f, 0.9293f, 1.0000f}, {0.4873f, 0.9501f, 1.0000f}, {0.5302f, 0.9677f, 1.0000f},
    {0.5731f, 0.9817f, 1.0000f}, {0.6155f, 0.9919f, 1.0000f}, {0.6573f, 0.9981f, 1.0000f},
    {0.6982f, 1.0000f, 1.0000f}, {0.7377f, 1.0000f, 1.0000f}, {0.7756f, 1.0000f, 1.0000f},
    {0.8116f, 1.0000f, 1.0000f}, {0.8454f, 1.0000f, 1.0000f}, {0.8767f, 1.0000f, 1.0000f},
    {0.9052f, 1.0000f, 1.0000f}, {0.9306f, 1.0000f, 1.0000f}, {0.9525f, 1.0000f, 1.0000f},
    {0.9707f, 1.0000f, 1.0000f}, {0.9849f, 1.0000f, 1.0000f}, {0.9947f, 1.0000f, 1.0000f},
    {0.9998f, 1.0000f, 1.0000f}, {1.0000f, 1.0000f, 1.0000f},
};

Vec3 hueIntegral(double wavelength) {
    double offset = std::clamp((wavelength - kHueTableBase) / kHueTableStep, 0.0, kHueTableSize - 1.0);
    const int i = std::min(static_cast<int>(offset), kHueTableSize - 2);
    offset -= i;
    const Vec3 a(kHueIntegral[i][0], kHueIntegral[i][1], kHueIntegral[i][2]);
    const Vec3 b(kHueIntegral[i + 1][0], kHueIntegral[i + 1][1], kHueIntegral[i + 1][2]);
    return (1.0 - offset) * a + offset * b;
}

}  // namespace

double SpectralBand::ior(double nominalIor, double dispersion) const {
    return nominalIor * std::pow(dispersion, -(wavelength - kCentre) / kBandwidth);
}

Vec3 SpectralBand::hue() const {
    return (hueIntegral(wavelength + bandwidth / 2) - hueIntegral(wavelength - bandwidth / 2)) *
           (kBandwidth / bandwidth);
}

}  // namespace asos
