// The renderer's light beams (render/light_beams.hpp) are the pieces of
// geometry/beam_rect.hpp, beam_segment.hpp and beam_sphere.hpp: the same
// regions, central rays and random rays, with cones (about the central ray)
// that hold every ray of the piece.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "asos/geometry/beam_rect.hpp"
#include "asos/geometry/beam_segment.hpp"
#include "asos/geometry/beam_sphere.hpp"
#include "asos/render/light_beams.hpp"
#include "random_direction.hpp"

using namespace asos;

namespace {

using asos::test::randomUnit;

void checkSame(const BeamRay& a, const BeamRay& b) {
    CHECK(glm::length(a.ray.dir - b.ray.dir) <= 1e-12);
    CHECK(a.distance == Approx(b.distance).epsilon(1e-10));
}

// Rays of the piece lie in its cone and reach the light within its range.
void checkInside(const LightBeams& beams, const LightPiece& p, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int k = 0; k < 28; ++k) {
        // The corners, points along each of the four edges, then inside.
        const double along = u01(rng);
        const int edge = (k - 4) / 4;
        const Vec2 xi = k < 4    ? Vec2(k & 1, k >> 1 & 1)
                        : k < 20 ? (edge < 2 ? Vec2(edge, along) : Vec2(along, edge - 2))
                                 : Vec2(u01(rng), u01(rng));
        const BeamRay r = k == 0 ? p.central : beams.sample(p, xi);
        CHECK(angleBetween(p.cone.axis, r.ray.dir) <= p.cone.halfAngle);
        CHECK(r.distance <= p.cone.tMax);
        CHECK(r.distance >= beams.nearestLightDistance(p) * (1.0 - 1e-12));
    }
}

// A spherical light and a point outside it, from just outside to far away.
struct SphereLightCase {
    LightModel model;
    Vec3 apex;
};
SphereLightCase randomSphereLight(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    LightModel m;
    m.shape = LightShape::Sphere;
    m.position = Vec3(u01(rng), 6, u01(rng));
    m.radius = 0.05 + 2 * u01(rng);
    const double distance = m.radius * (1.0 + std::pow(10.0, -2.0 + 4.0 * u01(rng)));
    return {m, m.position + randomUnit(rng) * distance};
}

}  // namespace

TEST_CASE("Rectangle beams: the shadow pyray's quarters, with cones about their central rays", "[lights]") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 150; ++trial) {
        LightModel m;
        m.shape = LightShape::Rectangle;
        const Vec3 a = randomUnit(rng) * (0.1 + 3 * u01(rng));
        // Rectangles mostly; some slanted parallelograms.
        Vec3 b = glm::normalize(glm::cross(a, randomUnit(rng))) * (0.1 + 3 * u01(rng));
        if (trial % 5 == 0) b += 0.5 * a;
        m.rectangle = {Vec3(u01(rng), 5, u01(rng)), a, b};
        const Vec3 apex = m.rectangle.corner + randomUnit(rng) * std::pow(10.0, -1.0 + 3.0 * u01(rng));
        const LightBeams beams(m, apex, 1e-4);
        const auto reference = RectShadowPyray::make(apex, m.rectangle, 1e-4);
        REQUIRE(beams.valid() == reference.has_value());
        if (!reference) continue;
        LightPiece p = beams.root();
        RectShadowPyray q = *reference;
        for (int level = 0; level <= 4; ++level) {
            CHECK(beams.share(level) == q.weight());
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.3, 0.8}), q.sample(0.3, 0.8));
            CHECK(beams.emission(p.central.ray.dir) == Approx(q.cosTheta()));
            if (p.cone.halfAngle < 0.5 * kPi) checkInside(beams, p, rng);
            CHECK(beams.nearestLightDistance(p) <= q.nearestLightDistance() * (1 + 1e-9));
            LightPiece children[LightBeams::kMaxChildren];
            REQUIRE(beams.split(p, children) == 4);
            const auto quarters = q.split();
            const int pick = int(rng() % 4);
            for (int i = 0; i < 4; ++i) {
                CHECK(children[i].level == level + 1);
                CHECK(children[i].path == 4 * p.path + std::uint64_t(i));
                CHECK(children[i].a0 == quarters[i].region().s0);
                CHECK(children[i].b1 == quarters[i].region().t1);
            }
            p = children[pick];
            q = quarters[pick];
        }
    }
}

TEST_CASE("Segment beams: the shadow pyray's halves", "[lights]") {
    std::mt19937_64 rng(32);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 150; ++trial) {
        LightModel m;
        m.shape = LightShape::Segment;
        m.start = Vec3(u01(rng), 4, u01(rng));
        m.end = m.start + randomUnit(rng) * (0.1 + 5 * u01(rng));
        const Vec3 apex = m.start + randomUnit(rng) * std::pow(10.0, -1.0 + 2.5 * u01(rng));
        const LightBeams beams(m, apex, 0.0);
        const auto reference = SegmentShadowPyray::make(apex, m.start, m.end);
        REQUIRE(beams.valid() == reference.has_value());
        if (!reference) continue;
        LightPiece p = beams.root();
        SegmentShadowPyray q = *reference;
        for (int level = 0; level <= 6; ++level) {
            CHECK(beams.share(level) == q.weight());
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.7, 0.0}), q.sample(0.7));
            CHECK(p.cone.halfAngle == Approx(q.cone().halfAngle).margin(1e-12));
            checkInside(beams, p, rng);
            LightPiece halves[LightBeams::kMaxChildren];
            REQUIRE(beams.split(p, halves) == 2);
            const int pick = int(rng() % 2);
            p = halves[pick];
            q = q.split()[pick];
        }
    }
}

TEST_CASE("Sphere beams: the tangent cone's equal-area pieces", "[lights]") {
    std::mt19937_64 rng(33);
    for (int trial = 0; trial < 100; ++trial) {
        const auto [m, apex] = randomSphereLight(rng);
        const LightBeams beams(m, apex, 1e-4);
        const auto reference = SphereShadowCone::make(apex, m.position, m.radius, 1e-4);
        REQUIRE(beams.valid() == reference.has_value());
        if (!reference) continue;
        LightPiece p = beams.root();
        SphereShadowCone q = *reference;
        CHECK(p.cone.halfAngle == Approx(q.cone().halfAngle).margin(1e-12));
        for (int level = 0; level < 7; ++level) {  // past the table (DiscPieceTable::kLevels)
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.4, 0.9}), q.sample(0.4, 0.9));
            checkInside(beams, p, rng);
            LightPiece pieces[LightBeams::kMaxChildren];
            REQUIRE(beams.split(p, pieces) == 4);
            const auto reference4 = q.split();
            for (int i = 0; i < 4; ++i) {
                CHECK(pieces[i].a0 == reference4[i].region().s0);
                CHECK(pieces[i].a1 == reference4[i].region().s1);
                CHECK(pieces[i].b0 == reference4[i].region().t0);
                CHECK(pieces[i].b1 == reference4[i].region().t1);
                checkInside(beams, pieces[i], rng);
            }
            const int pick = int(rng() % 4);
            p = pieces[pick];
            q = reference4[pick];
        }
    }
    // On or inside the light: no beam.
    LightModel m;
    m.shape = LightShape::Sphere;
    m.position = Vec3(0.0);
    m.radius = 1.0;
    CHECK_FALSE(LightBeams(m, Vec3(0.5, 0, 0), 0.0).valid());
}

TEST_CASE("Sphere beams: the level-K pieces' central rays are the 2^K x 2^K grid's points, bit for bit", "[lights]") {
    // The grid method places a spherical light's n x n points at the images
    // of the cells' centres under the concentric map (render/grid_light.cpp):
    // ASOS pieces subdivided to level K sample the same points.
    std::mt19937_64 rng(58);
    for (int trial = 0; trial < 20; ++trial) {
        const auto [m, apex] = randomSphereLight(rng);
        const LightBeams beams(m, apex, 1e-4);
        const auto reference = SphereShadowCone::make(apex, m.position, m.radius, 1e-4);
        REQUIRE(reference);
        for (int level = 1; level <= 6; ++level) {
            std::vector<BeamRay> rays;
            beams.forEachCentralRay(beams.root(), level, [&](const BeamRay& r) { rays.push_back(r); });
            const int n = 1 << level;
            REQUIRE(rays.size() == std::size_t(n) * std::size_t(n));
            int found = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    // The grid's point (render/grid_light.cpp makes it so).
                    const Vec2 d = concentricDisc((i + 0.5) / n, (j + 0.5) / n);
                    const BeamRay point = reference->rayAt(d.x, d.y);
                    found += std::count_if(rays.begin(), rays.end(), [&](const BeamRay& r) {
                        return r.ray.dir == point.ray.dir && r.distance == point.distance;
                    }) == 1;
                }
            INFO("trial " << trial << " level " << level);
            CHECK(found == n * n);
        }
    }
}

TEST_CASE("Central rays of descendants: the pieces' of repeated splits, in order, bit for bit", "[lights]") {
    std::mt19937_64 rng(57);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // The pieces `depth` levels below `p` by repeated split(), in order.
    const auto bySplits = [](const LightBeams& beams, const LightPiece& p, int depth) {
        std::vector<LightPiece> pieces{p};
        for (int d = 0; d < depth; ++d) {
            std::vector<LightPiece> next;
            for (const LightPiece& q : pieces) {
                LightPiece children[LightBeams::kMaxChildren];
                const int n = beams.split(q, children, false);
                next.insert(next.end(), children, children + n);
            }
            pieces = next;
        }
        return pieces;
    };
    for (int trial = 0; trial < 40; ++trial) {
        LightModel m;
        if (trial % 4 == 3) {
            m.shape = LightShape::Segment;
            m.start = Vec3(u01(rng), 5, u01(rng));
            m.end = m.start + randomUnit(rng) * (0.1 + 3 * u01(rng));
        } else {
            m.shape = LightShape::Rectangle;
            const Vec3 a = randomUnit(rng) * (0.1 + 3 * u01(rng));
            Vec3 b = glm::normalize(glm::cross(a, randomUnit(rng))) * (0.1 + 3 * u01(rng));
            if (trial % 4 == 2) b += 0.3 * a;
            m.rectangle = {Vec3(u01(rng), 5, u01(rng)), a, b};
        }
        const Vec3 apex = Vec3(u01(rng), 5, u01(rng)) + randomUnit(rng) * (0.5 + 5.0 * u01(rng));
        const LightBeams beams(m, apex, 1e-4);
        if (!beams.valid()) continue;
        LightPiece p = beams.root();
        for (int level = 0; level <= 3; ++level) {
            for (int depth = 0; depth <= 4; ++depth) {
                const std::vector<LightPiece> expected = bySplits(beams, p, depth);
                // The lattice: the same rays in the same order, each at the
                // place of its piece's region.
                REQUIRE(beams.hasLattice(depth));
                const LightBeams::Lattice lattice = beams.lattice(p, depth);
                REQUIRE(lattice.count() == int(expected.size()));
                bool sameLattice = true;
                const double ds = (p.a1 - p.a0) / lattice.columns(), dt = (p.b1 - p.b0) / lattice.rows();
                for (int n = 0; n < lattice.count(); ++n) {
                    const LightBeams::Lattice::Place at = lattice.place(n);
                    const BeamRay r = lattice.ray(at.i, at.j);
                    const LightPiece& e = expected[std::size_t(n)];
                    sameLattice = sameLattice && r.ray.dir == e.central.ray.dir &&
                                  r.ray.origin == e.central.ray.origin && r.distance == e.central.distance &&
                                  e.a0 == p.a0 + at.i * ds &&
                                  (m.shape == LightShape::Segment || e.b0 == p.b0 + at.j * dt);
                }
                CHECK(sameLattice);
                std::size_t k = 0;
                bool same = true;
                beams.forEachCentralRay(p, depth, [&](const BeamRay& r) {
                    same = same && k < expected.size() && r.ray.dir == expected[k].central.ray.dir &&
                           r.ray.origin == expected[k].central.ray.origin &&
                           r.distance == expected[k].central.distance;
                    ++k;
                });
                CHECK(same);
                CHECK(k == expected.size());
            }
            LightPiece children[LightBeams::kMaxChildren];
            const int n = beams.split(p, children);
            p = children[int(rng() % std::uint64_t(n))];
        }
    }
}
