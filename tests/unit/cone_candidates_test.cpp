#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "asos/render/cone_candidates.hpp"

using namespace asos;

// BeamCandidateCache's bounding-sphere test must never drop a sphere that
// holds a point of the cone: sample points of each rejected sphere and check
// that none lies in the cone's solid; and it must reject spheres clearly away.
TEST_CASE("Beam candidates: the sphere test is conservative", "[lights]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto unit = [&] {
        for (;;) {
            const Vec3 v(u(rng), u(rng), u(rng));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    };
    int rejected = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Cone cone{Vec3(u(rng), u(rng), u(rng)) * 3.0, unit(), 0.05 + 0.6 * (0.5 + 0.5 * u(rng)), 0.001,
                        2.0 + 4.0 * (0.5 + 0.5 * u(rng))};
        const PreparedCone prepared(cone);
        const Vec3 center = cone.apex + Vec3(u(rng), u(rng), u(rng)) * 6.0;
        const double radius = 0.05 + 0.5 * (0.5 + 0.5 * u(rng));
        if (BeamCandidateCache::sphereMayMeet(prepared, center, radius)) continue;
        ++rejected;
        for (int k = 0; k < 400; ++k) {
            const Vec3 p = center + unit() * (radius * std::cbrt(0.5 + 0.5 * u(rng)));
            const Vec3 v = p - cone.apex;
            const double d = glm::length(v);
            const bool inside = d >= cone.tMin && d <= cone.tMax &&
                                glm::dot(v, cone.axis) >= d * std::cos(cone.halfAngle);
            REQUIRE_FALSE(inside);
        }
    }
    CHECK(rejected > 500);  // the test rejects most spheres placed at random away from the cone
    // Straight ahead, in reach: kept; behind the apex, beyond reach, off to the side: dropped.
    const PreparedCone ahead(Cone{Vec3(0.0), Vec3(0, 0, 1), 0.2, 0.0, 10.0});
    CHECK(BeamCandidateCache::sphereMayMeet(ahead, Vec3(0, 0, 5), 0.1));
    CHECK_FALSE(BeamCandidateCache::sphereMayMeet(ahead, Vec3(0, 0, -5), 1.0));
    CHECK_FALSE(BeamCandidateCache::sphereMayMeet(ahead, Vec3(0, 0, 12), 1.0));
    CHECK_FALSE(BeamCandidateCache::sphereMayMeet(ahead, Vec3(3, 0, 5), 1.0));
    CHECK(BeamCandidateCache::sphereMayMeet(ahead, Vec3(1.5, 0, 5), 1.0));
}
