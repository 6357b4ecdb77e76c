#pragma once
// POV-Ray 3.7's normal patterns (core/material/normal.cpp, Perturb_Normal
// with the pattern's Warp_Normal and UnWarp_Normal): the surface normal
// taken into pattern space, tilted there and brought back, unit. bumps,
// dents and wrinkles add vector noise (PovNoise::dnoise), ripples and waves
// POV-Ray's ten wave sources, and a map pattern its slope, measured at four
// points `accuracy` away. docs/rendering.md, "Normal patterns".
#include <array>

#include "asos/geometry/vec.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// POV-Ray's wave sources (its Initialize_Waves, number_of_waves 10): unit
// points from the vector noise at <i, 0, 0>, and frequencies from its
// generator.
struct WaveSources {
    static constexpr int kCount = 10;
    std::array<Vec3, kCount> sources{};
    std::array<double, kCount> frequencies{};
    // Built once (they depend on nothing) and then only read.
    static const WaveSources& tables();

private:
    WaveSources();
};

// The unit normal `unitNormal` (turned toward the ray, as POV-Ray tilts it)
// tilted by the normal pattern at a world point.
Vec3 perturbedNormal(const Normal& normal, const Vec3& worldPoint, const Vec3& unitNormal);

}  // namespace asos
