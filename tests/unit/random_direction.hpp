#pragma once
// Uniformly distributed unit vectors for the randomised tests.
#include <random>

#include <glm/geometric.hpp>

#include "asos/geometry/vec.hpp"

namespace asos::test {

// A direction uniform on the sphere: a normal 3-vector, normalised.
inline Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const Vec3 d(n(rng), n(rng), n(rng));
        const double l = glm::length(d);
        if (l > 1e-6) return d / l;
    }
}

}  // namespace asos::test
