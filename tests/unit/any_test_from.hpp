#pragma once
// Shared check for Primitive::withAnyTestFrom (the area light's point samples
// from one origin): its test must answer as Primitive::intersectAny.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "asos/shapes/primitive.hpp"

namespace asos::test {

// For each primitive and three origins around it, 2000 rays toward random
// points of its bounds (grown by a fifth), half of them ending there.
inline void checkAnyTestFromMatchesIntersectAny(const std::vector<Primitive>& prims, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const Primitive& p : prims) {
        for (const Vec3 origin : {Vec3(0.3, 0.0, -3.2), Vec3(3.5, 0.0, -0.4), Vec3(-1.0, 0.5, 2.0)}) {
            const Bounds3 b = p.worldBounds();
            p.withAnyTestFrom(origin, [&](const auto& test) {
                for (int i = 0; i < 2000; ++i) {
                    const Vec3 target = b.lo + (b.hi - b.lo) * (0.5 + 0.6 * Vec3(u(rng), u(rng), u(rng)));
                    const Vec3 d = glm::normalize(target - origin);
                    const double tMax = i % 2 ? kInfinity : glm::length(target - origin);
                    CHECK(test(d, 1e-6, tMax) == p.intersectAny(Ray{origin, d}, 1e-6, tMax));
                }
            });
        }
    }
}

}  // namespace asos::test
