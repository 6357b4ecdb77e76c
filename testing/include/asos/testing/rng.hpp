#pragma once
// A sequential random number generator for the property tests and the
// benchmarks: mt19937_64 from a seed, so that a failing case or a bench
// figure can be replayed from its seed. (Rendering never uses it: its random
// numbers are indexed by pixel and position, render/sampling.hpp.)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "asos/geometry/vec.hpp"

namespace asos {

class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}
    // Uniform in [a, b): the top 53 bits of one draw.
    double uniform(double a = 0.0, double b = 1.0) {
        return a + (b - a) * static_cast<double>(engine_() >> 11) * 0x1p-53;
    }
    bool chance(double p) { return uniform() < p; }
    // In [0, n), by the remainder of one draw.
    int index(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
    // 10^x with x uniform in [lo10, hi10).
    double logUniform(double lo10, double hi10) { return std::pow(10.0, uniform(lo10, hi10)); }
    // Uniform on the unit sphere (Archimedes: z uniform, then the angle).
    Vec3 unitVector() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * kPi);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    Vec3 inBox(const Vec3& lo, const Vec3& hi) {
        return {uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z)};
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace asos
