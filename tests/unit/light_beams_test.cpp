// The light forms' beams (lights/rectangle_light.hpp, segment_light.hpp,
// sphere_light.hpp) are the pieces of the reference beams of asos_testing
// (rect_shadow_pyray.hpp, segment_shadow_pyray.hpp, sphere_shadow_cone.hpp):
// the same regions, central rays and random rays, with cones (about the
// central ray) that hold every ray of the piece. POV-Ray's oriented disc
// (oriented_disc_light.hpp) has no reference beam: its rays end on the disc
// POV-Ray's lattice lies on, and its cones hold them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "asos/lights/light_form.hpp"
#include "asos/testing/rect_shadow_pyray.hpp"
#include "asos/testing/segment_shadow_pyray.hpp"
#include "asos/testing/sphere_shadow_cone.hpp"
#include "random_direction.hpp"

using namespace asos;

namespace {

using asos::test::randomUnit;

void checkSame(const BeamRay& a, const BeamRay& b) {
    CHECK(glm::length(a.ray.dir - b.ray.dir) <= 1e-12);
    CHECK(a.distance == Approx(b.distance).epsilon(1e-10));
}

// Rays of the piece lie in its cone and reach the light within its range.
template <AreaLightBeam Beam>
void checkInside(const Beam& beams, const LightPiece& p, std::mt19937_64& rng) {
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
    SphereLight light;
    Vec3 apex;
};
SphereLightCase randomSphereLight(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    SphereLight light;
    light.centre = Vec3(u01(rng), 6, u01(rng));
    light.radius = 0.05 + 2 * u01(rng);
    const double distance = light.radius * (1.0 + std::pow(10.0, -2.0 + 4.0 * u01(rng)));
    return {light, light.centre + randomUnit(rng) * distance};
}

}  // namespace

TEST_CASE("Rectangle beams: the shadow pyray's quarters, with cones about their central rays", "[lights]") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 150; ++trial) {
        const Vec3 a = randomUnit(rng) * (0.1 + 3 * u01(rng));
        // Rectangles mostly; some slanted parallelograms.
        Vec3 b = glm::normalize(glm::cross(a, randomUnit(rng))) * (0.1 + 3 * u01(rng));
        if (trial % 5 == 0) b += 0.5 * a;
        const RectangleLight light{Vec3(u01(rng), 5, u01(rng)), a, b};
        const Vec3 apex = light.corner + randomUnit(rng) * std::pow(10.0, -1.0 + 3.0 * u01(rng));
        const std::optional<RectangleLight::Beam> made = light.beamFrom(apex, 1e-4);
        const auto reference = RectShadowPyray::make(apex, light, 1e-4);
        REQUIRE(made.has_value() == reference.has_value());
        if (!reference) continue;
        const RectangleLight::Beam& beams = *made;
        LightPiece p = beams.root();
        RectShadowPyray q = *reference;
        for (int level = 0; level <= 4; ++level) {
            CHECK(beams.share(level) == q.weight());
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.3, 0.8}), q.sample(0.3, 0.8));
            CHECK(beams.emission(p.central.ray.dir) == Approx(q.cosTheta()));
            if (p.cone.halfAngle < 0.5 * kPi) checkInside(beams, p, rng);
            CHECK(beams.nearestLightDistance(p) <= q.nearestLightDistance() * (1 + 1e-9));
            LightPiece children[RectangleLight::Beam::kChildren];
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
        SegmentLight light;
        light.start = Vec3(u01(rng), 4, u01(rng));
        light.end = light.start + randomUnit(rng) * (0.1 + 5 * u01(rng));
        light.length = glm::length(light.end - light.start);
        const Vec3 apex = light.start + randomUnit(rng) * std::pow(10.0, -1.0 + 2.5 * u01(rng));
        const std::optional<SegmentLight::Beam> made = light.beamFrom(apex, 0.0);
        const auto reference = SegmentShadowPyray::make(apex, light.start, light.end);
        REQUIRE(made.has_value() == reference.has_value());
        if (!reference) continue;
        const SegmentLight::Beam& beams = *made;
        LightPiece p = beams.root();
        SegmentShadowPyray q = *reference;
        for (int level = 0; level <= 6; ++level) {
            CHECK(beams.share(level) == q.weight());
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.7, 0.0}), q.sample(0.7));
            CHECK(p.cone.halfAngle == Approx(q.cone().halfAngle).margin(1e-12));
            checkInside(beams, p, rng);
            LightPiece halves[SegmentLight::Beam::kChildren];
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
        const auto [light, apex] = randomSphereLight(rng);
        const std::optional<SphereLight::Beam> made = light.beamFrom(apex, 1e-4);
        const auto reference = SphereShadowCone::make(apex, light.centre, light.radius, 1e-4);
        REQUIRE(made.has_value() == reference.has_value());
        if (!reference) continue;
        const SphereLight::Beam& beams = *made;
        LightPiece p = beams.root();
        SphereShadowCone q = *reference;
        CHECK(p.cone.halfAngle == Approx(q.cone().halfAngle).margin(1e-12));
        for (int level = 0; level < 7; ++level) {  // past the table (DiscPieceTable::kLevels)
            checkSame(p.central, q.central());
            checkSame(beams.sample(p, {0.4, 0.9}), q.sample(0.4, 0.9));
            checkInside(beams, p, rng);
            LightPiece pieces[SphereLight::Beam::kChildren];
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
    // On or inside the light: no beam, no grid.
    const SphereLight unit{{Vec3(0.0), 1.0}};
    CHECK_FALSE(unit.beamFrom(Vec3(0.5, 0, 0), 0.0));
    CHECK_FALSE(unit.gridFrom(Vec3(0.5, 0, 0)));
}

TEST_CASE("Oriented disc beams: POV-Ray's disc facing the point, cut by POV-Ray's map", "[lights]") {
    std::mt19937_64 rng(34);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
        OrientedDiscLight light;
        light.centre = Vec3(u01(rng), 6, u01(rng));
        light.radius = 0.05 + 2 * u01(rng);
        // From well inside the disc's radius to far away; some along z
        // (POV-Ray then turns its axes about y).
        Vec3 offset = randomUnit(rng);
        if (trial % 10 == 0) offset = glm::normalize(Vec3(0.001 * u01(rng), 0.001, 1.0));
        const Vec3 apex = light.centre - offset * (light.radius * std::pow(10.0, -1.0 + 3.0 * u01(rng)));
        const std::optional<OrientedDiscLight::Beam> made = light.beamFrom(apex, 1e-4);
        REQUIRE(made);
        const OrientedDiscLight::Beam& beams = *made;
        const Frame frame = povrayOrientFrame(glm::normalize(light.centre - apex));
        CHECK(std::abs(glm::dot(frame.u, frame.v)) < 1e-12);
        CHECK(glm::length(glm::cross(frame.u, frame.v) - frame.w) < 1e-12);
        // Where a ray of the beam ends: on the disc, at its map's point.
        const auto endsAt = [&](const BeamRay& r, const Vec2& xi) {
            const Vec2 d = povrayDisc(xi.x, xi.y);
            const Vec3 expected = light.centre + light.radius * (d.x * frame.u + d.y * frame.v);
            return glm::length(r.ray.origin + r.distance * r.ray.dir - expected) <= 1e-9 * (1.0 + glm::length(light.centre - apex));
        };
        LightPiece p = beams.root();
        CHECK(p.central.distance == Approx(glm::length(light.centre - apex)));
        for (int level = 0; level < 7; ++level) {  // past the table (DiscPieceTable::kLevels)
            CHECK(beams.share(level) == std::ldexp(1.0, -2 * level));
            const Vec2 xi(0.4, 0.9);
            CHECK(endsAt(beams.sample(p, xi), Vec2(p.a0 + xi.x * (p.a1 - p.a0), p.b0 + xi.y * (p.b1 - p.b0))));
            CHECK(endsAt(p.central, Vec2(0.5 * (p.a0 + p.a1), 0.5 * (p.b0 + p.b1))));
            checkInside(beams, p, rng);
            LightPiece pieces[OrientedDiscLight::Beam::kChildren];
            REQUIRE(beams.split(p, pieces) == 4);
            for (int i = 0; i < 4; ++i) {
                CHECK(pieces[i].a1 - pieces[i].a0 == 0.5 * (p.a1 - p.a0));
                checkInside(beams, pieces[i], rng);
            }
            p = pieces[int(rng() % 4)];
        }
    }
    // At the centre: no beam, no grid.
    const OrientedDiscLight unit{Vec3(0.0), 1.0};
    CHECK_FALSE(unit.beamFrom(Vec3(0.0), 0.0));
    CHECK_FALSE(unit.gridFrom(Vec3(0.0)));
}

TEST_CASE("Oriented disc grid: POV-Ray's lattice, squeezed onto the disc a thousandth off centre", "[lights]") {
    // Seen from below, the disc faces up: POV-Ray's first axis is
    // cross(w, z) = cross(y, z) = x, its second cross(w, x) = -z.
    const OrientedDiscLight light{Vec3(0, 5, 0), 1.0};
    const std::optional<OrientedDiscLight::GridPoints> grid = light.gridFrom(Vec3(0.0));
    REQUIRE(grid);
    const auto point = [&](double s, double t) {
        const BeamRay r = grid->toward(s, t);
        return r.ray.origin + r.distance * r.ray.dir;
    };
    // The lattice's corner (s, t) = (0, 0): (-0.499, -0.499) of the square,
    // kept on its diagonal at the radius of its square ring, 0.499 of the
    // axes' length 2.
    const double r = 0.499 * 2.0 / std::sqrt(2.0);
    CHECK(glm::length(point(0.0, 0.0) - Vec3(-r, 5, r)) < 1e-12);
    // The middle of the lattice's right edge: (0.501, 0.001), on the ring of
    // radius 0.501, turned by atan(0.001 / 0.501).
    const Vec3 edge = point(1.0, 0.5) - Vec3(0, 5, 0);
    CHECK(glm::length(edge) == Approx(1.002).epsilon(1e-12));
    CHECK(std::atan2(-edge.z, edge.x) == Approx(std::atan(0.001 / 0.501)).epsilon(1e-9));
    // The centre of an odd lattice: a thousandth of the axes off centre.
    CHECK(glm::length(point(0.5, 0.5) - Vec3(0.002 / std::sqrt(2.0), 5, -0.002 / std::sqrt(2.0))) < 1e-12);
    // POV-Ray's turn near the z axis: axes about y.
    const OrientedDiscLight ahead{Vec3(0, 0, 5), 1.0};
    const std::optional<OrientedDiscLight::GridPoints> side = ahead.gridFrom(Vec3(0.0));
    REQUIRE(side);
    const BeamRay toEdge = side->toward(1.0, 0.5);
    const Vec3 off = toEdge.ray.origin + toEdge.distance * toEdge.ray.dir - Vec3(0, 0, 5);
    CHECK(std::abs(off.z) < 1e-12);
    CHECK(std::abs(off.y) < 0.01);  // cross(z, y) = -x: the first axis along x
    CHECK(std::abs(std::abs(off.x) - 1.002) < 1e-3);
}

TEST_CASE("Sphere beams: the level-K pieces' central rays are the 2^K x 2^K grid's points, bit for bit", "[lights]") {
    // The grid method places a spherical light's n x n points at the images
    // of the cells' centres under the concentric map (SphereLight::GridPoints):
    // ASOS pieces subdivided to level K sample the same points.
    std::mt19937_64 rng(58);
    for (int trial = 0; trial < 20; ++trial) {
        const auto [light, apex] = randomSphereLight(rng);
        const std::optional<SphereLight::Beam> beams = light.beamFrom(apex, 1e-4);
        const std::optional<SphereLight::GridPoints> grid = light.gridFrom(apex);
        REQUIRE((beams && grid));
        for (int level = 1; level <= 6; ++level) {
            std::vector<BeamRay> rays;
            beams->forEachDescendant(beams->root(), level, [&](const LightPiece& p) { rays.push_back(p.central); });
            const int n = 1 << level;
            REQUIRE(rays.size() == std::size_t(n) * std::size_t(n));
            int found = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    // The grid's point without jitter (render/grid_light.cpp).
                    const BeamRay point = grid->toward((i + 0.5) / n, (j + 0.5) / n);
                    found += std::count_if(rays.begin(), rays.end(), [&](const BeamRay& r) {
                        return r.ray.dir == point.ray.dir && r.distance == point.distance;
                    }) == 1;
                }
            INFO("trial " << trial << " level " << level);
            CHECK(found == n * n);
        }
    }
}

TEST_CASE("Descendants and lattices: the pieces of repeated splits, in order, bit for bit", "[lights]") {
    std::mt19937_64 rng(57);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // The pieces `depth` levels below `p` by repeated split(), in order.
    const auto bySplits = [](const auto& beams, const LightPiece& p, int depth) {
        std::vector<LightPiece> pieces{p};
        for (int d = 0; d < depth; ++d) {
            std::vector<LightPiece> next;
            for (const LightPiece& q : pieces) {
                LightPiece children[4];
                const int n = beams.split(q, children, false);
                next.insert(next.end(), children, children + n);
            }
            pieces = next;
        }
        return pieces;
    };
    const auto sameRay = [](const BeamRay& a, const BeamRay& b) {
        return a.ray.dir == b.ray.dir && a.ray.origin == b.ray.origin && a.distance == b.distance;
    };
    const auto check = [&](const auto& beams, bool segment) {
        LightPiece p = beams.root();
        for (int level = 0; level <= 3; ++level) {
            for (int depth = 0; depth <= 4; ++depth) {
                const std::vector<LightPiece> expected = bySplits(beams, p, depth);
                // forEachDescendant: the same pieces in the same order.
                std::size_t k = 0;
                bool same = true;
                beams.forEachDescendant(p, depth, [&](const LightPiece& piece) {
                    same = same && k < expected.size() && sameRay(piece.central, expected[k].central) &&
                           piece.a0 == expected[k].a0 && piece.a1 == expected[k].a1 &&
                           piece.b0 == expected[k].b0 && piece.b1 == expected[k].b1 &&
                           piece.level == expected[k].level && piece.path == expected[k].path;
                    ++k;
                });
                CHECK(same);
                CHECK(k == expected.size());
                // The lattice: the same rays in the same order, each at the
                // place of its piece's region.
                const std::optional<LightLattice> lattice = beams.lattice(p, depth);
                REQUIRE(lattice);
                REQUIRE(lattice->count() == int(expected.size()));
                bool sameLattice = true;
                const double ds = (p.a1 - p.a0) / lattice->columns(), dt = (p.b1 - p.b0) / lattice->rows();
                for (int n = 0; n < lattice->count(); ++n) {
                    const LightLattice::Place at = lattice->place(n);
                    const LightPiece& e = expected[std::size_t(n)];
                    sameLattice = sameLattice && sameRay(lattice->ray(at.i, at.j), e.central) &&
                                  e.a0 == p.a0 + at.i * ds && (segment || e.b0 == p.b0 + at.j * dt);
                }
                CHECK(sameLattice);
            }
            CHECK_FALSE(beams.lattice(p, LightLattice::kMaxDepth + 1));
            LightPiece children[4];
            const int n = beams.split(p, children);
            p = children[int(rng() % std::uint64_t(n))];
        }
    };
    for (int trial = 0; trial < 40; ++trial) {
        if (trial % 4 == 3) {
            SegmentLight light;
            light.start = Vec3(u01(rng), 5, u01(rng));
            light.end = light.start + randomUnit(rng) * (0.1 + 3 * u01(rng));
            light.length = glm::length(light.end - light.start);
            const Vec3 apex = Vec3(u01(rng), 5, u01(rng)) + randomUnit(rng) * (0.5 + 5.0 * u01(rng));
            if (const auto beams = light.beamFrom(apex, 1e-4)) check(*beams, true);
        } else {
            const Vec3 a = randomUnit(rng) * (0.1 + 3 * u01(rng));
            Vec3 b = glm::normalize(glm::cross(a, randomUnit(rng))) * (0.1 + 3 * u01(rng));
            if (trial % 4 == 2) b += 0.3 * a;
            const RectangleLight light{Vec3(u01(rng), 5, u01(rng)), a, b};
            const Vec3 apex = Vec3(u01(rng), 5, u01(rng)) + randomUnit(rng) * (0.5 + 5.0 * u01(rng));
            if (const auto beams = light.beamFrom(apex, 1e-4)) check(*beams, false);
        }
    }
}
