#include "asos/render/normal_pattern.hpp"

#include <cmath>
#include <cstdint>

#include "asos/render/map_pattern.hpp"
#include "asos/render/pov_noise.hpp"

namespace asos {

namespace {

// The four directions of POV-Ray's slope measurement (normal.cpp's
// Pyramid_Vect): a regular tetrahedron's corners.
constexpr std::array<Vec3, 4> kPyramid = {Vec3(0.942809041, -0.333333333, 0.0),
                                          Vec3(-0.471404521, -0.333333333, 0.816496581),
                                          Vec3(-0.471404521, -0.333333333, -0.816496581),
                                          Vec3(0.0, 1.0, 0.0)};

// ripples and waves: the sum over the sources of the direction from each,
// scaled by the wave there (waves: each source at its own frequency, its
// height divided by it).
Vec3 waveTilt(const Normal& normal, const Vec3& q, bool ripples) {
    const WaveSources& w = WaveSources::tables();
    Vec3 sum(0.0);
    for (int i = 0; i < WaveSources::kCount; ++i) {
        const Vec3 d = q - w.sources[static_cast<std::size_t>(i)];
        double length = glm::length(d);
        if (length == 0.0) length = 1.0;
        const double f = ripples ? 1.0 : w.frequencies[static_cast<std::size_t>(i)];
        const double index = length * normal.pattern.frequency * f + normal.pattern.phase;
        const double scalar = PovNoise::cycloidal(index) * normal.amount / f;
        sum += (scalar / (length * WaveSources::kCount)) * d;
    }
    return sum;
}

}  // namespace

WaveSources::WaveSources() {
    const PovNoise& noise = PovNoise::tables();
    std::uint32_t next = static_cast<std::uint32_t>(-560851967);
    for (int i = 0; i < kCount; ++i) {
        sources[static_cast<std::size_t>(i)] = glm::normalize(noise.dnoise(Vec3(i, 0.0, 0.0)));
        // POV-Ray's generator, its int arithmetic modulo 2^32.
        next = next * 1812433253u + 12345u;
        frequencies[static_cast<std::size_t>(i)] = static_cast<double>((next >> 16) & 0x7FFFu) * 0.000030518509476 + 0.01;
    }
}

const WaveSources& WaveSources::tables() {
    static const WaveSources waves;
    return waves;
}

Vec3 perturbedNormal(const Normal& normal, const Vec3& worldPoint, const Vec3& unitNormal) {
    const Pigment& p = normal.pattern;
    const Transform& t = p.worldFromPattern;
    const Mat3 linear(t.matrix());
    // Warp_Normal: the normal in pattern space (by the transpose of the
    // pattern's linear map), unit; the point moved by the turbulence too.
    Vec3 n = glm::normalize(glm::transpose(linear) * unitNormal);
    const Vec3 q = turbulatedPoint(p, Vec3(t.inverseMatrix() * Vec4(worldPoint, 1.0)));
    const PovNoise& noise = PovNoise::tables();
    switch (normal.kind) {
        case Normal::Kind::Bumps: n += normal.amount * noise.dnoise(q); break;
        case Normal::Kind::Dents: {
            const double v = noise.noise(q, p.noiseGenerator != 0 ? p.noiseGenerator : 2);
            n += (v * v * v * normal.amount) * noise.dnoise(q);
            break;
        }
        case Normal::Kind::Wrinkles: {
            Vec3 sum(0.0);
            double scale = 1.0;
            for (int i = 0; i < 10; ++i, scale *= 2.0) sum += glm::abs(noise.dnoise(q * scale) / scale);
            n += normal.amount * sum;
            break;
        }
        case Normal::Kind::Ripples: n += waveTilt(normal, q, true); break;
        case Normal::Kind::Waves: n += waveTilt(normal, q, false); break;
        case Normal::Kind::Pattern: {
            // POV-Ray's two fudge factors: -5, and 0.02 over the distance.
            const double amount = normal.amount * -5.0 * (0.02 / normal.accuracy);
            for (const Vec3& d : kPyramid) n += (mapPatternValueAt(p, q + normal.accuracy * d) * amount) * d;
            break;
        }
    }
    // UnWarp_Normal: back by the inverse transpose, unit.
    return glm::normalize(glm::transpose(Mat3(t.inverseMatrix())) * n);
}

}  // namespace asos
