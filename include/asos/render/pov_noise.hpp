#pragma once
// POV-Ray 3.7's solid noise, number for number, so that patterns built on it
// (bozo, granite, marble and wood with turbulence, ...) look as they do in
// POV-Ray: its lattice hash of 4096 entries shuffled by its generator, its
// table of 267 random gradients, the s-curve interpolation and the three
// generators `noise_generator` chooses (1: the original, 2: the original
// with its range corrected, POV-Ray's default; 3: Perlin's improved noise),
// the vector noise turbulence displaces points with, and fractal sums of both
// (turbulence with octaves, omega and lambda). docs/algorithm.md, "Map
// patterns", names the POV-Ray source each part follows.
#include <array>
#include <cstdint>

#include "asos/geometry/vec.hpp"

namespace asos {

class PovNoise {
public:
    // The tables, built once (they depend on nothing) and then only read.
    static const PovNoise& tables();

    // Scalar noise in [0, 1] at a point; generator 1, 2 or 3.
    double noise(const Vec3& p, int generator) const;
    // Vector noise (POV-Ray's DNoise), each component about in [-1, 1].
    Vec3 dnoise(const Vec3& p) const;
    // Fractal sums (POV-Ray's Turbulence and DTurbulence): octave i adds the
    // noise at p * lambda^(i-1) weighted omega^(i-1).
    double turbulence(const Vec3& p, int octaves, double omega, double lambda, int generator) const;
    Vec3 dturbulence(const Vec3& p, int octaves, double omega, double lambda) const;
    // POV-Ray's sine of a fraction of a turn (cycloidal): sin(2 pi x). (3.7
    // computes it; later versions look it up in a table of 1000, which
    // would move wood's rings and the sine wave by up to 4/255 here.)
    static double cycloidal(double x);
    // POV-Ray's Hash3d: the lattice hash of an integer cell, 0..4095 (each
    // coordinate taken modulo 4096), as crackle picks its cells' points.
    int hash3d(int x, int y, int z) const {
        const int xy = hash_[static_cast<std::size_t>(hash_[static_cast<std::size_t>(x & 0xFFF)] ^ (y & 0xFFF))];
        return hash_[static_cast<std::size_t>(xy ^ (z & 0xFFF))];
    }

private:
    // A point's lattice cell: the fractions, their s-curves and the hashes
    // of the cell's four columns, which Noise and DNoise share.
    struct Cell {
        double x0, y0, z0, x1, y1, z1, sx, sy, sz, tx, ty, tz;
        int h00, h10, h01, h11, iz;
    };
    PovNoise();
    Cell cellOf(const Vec3& p) const;
    double solidNoise(const Vec3& p) const;
    // POV-Ray's octave loop: octave i at p * lambda^(i-1), weighted omega^(i-1).
    template <class T, class Octave>
    static T sumOctaves(T value, const Vec3& p, int octaves, double omega, double lambda, Octave octave) {
        double l = lambda, o = omega;
        for (int i = 2; i <= octaves; ++i) {
            value += o * octave(p * l);
            if (i < octaves) {
                l *= lambda;
                o *= omega;
            }
        }
        return value;
    }

    std::array<std::uint16_t, 8192> hash_{};
    std::array<double, 534> rtable_{};
    // Perlin's generator (3): a permutation and unit gradients.
    static constexpr int kEntries = 2048;
    std::array<int, 2 * (kEntries + 1)> permutation_{};
    std::array<Vec3, 2 * (kEntries + 1)> gradients_{};
};

// POV-Ray's triangle wave over a value's fraction: 0 → 1 → 0.
double triangleWave(double x);

}  // namespace asos
