#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "asos/accel/bvh.hpp"
#include "random_direction.hpp"

using namespace asos;

namespace {

struct Hit {
    double t;
    std::uint32_t item;
};

struct Sphere {
    Vec3 centre;
    double radius;
    Bounds3 bounds() const { return {centre - Vec3(radius), centre + Vec3(radius)}; }
};

// Test-local exact intersectors (double precision): the nearest root in range.
std::optional<double> hitSphere(const Sphere& s, const Ray& ray, double tMin, double tMax) {
    const Vec3 oc = ray.origin - s.centre;
    const double b = glm::dot(oc, ray.dir);
    const double c = glm::dot(oc, oc) - s.radius * s.radius;
    const double disc = b * b - c;
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    // Stable roots of t^2 + 2bt + c = 0.
    const double q = b > 0.0 ? -b - root : -b + root;
    double t0 = q, t1 = q != 0.0 ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= tMin && t0 <= tMax) return t0;
    if (t1 >= tMin && t1 <= tMax) return t1;
    return std::nullopt;
}

std::optional<double> hitBox(const Bounds3& b, const Ray& ray, double tMin, double tMax) {
    double lo = tMin, hi = tMax;
    for (int i = 0; i < 3; ++i) {
        if (ray.dir[i] == 0.0) {
            if (ray.origin[i] < b.lo[i] || ray.origin[i] > b.hi[i]) return std::nullopt;
            continue;
        }
        double t0 = (b.lo[i] - ray.origin[i]) / ray.dir[i];
        double t1 = (b.hi[i] - ray.origin[i]) / ray.dir[i];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
    }
    if (lo > hi) return std::nullopt;
    return lo;
}

using asos::test::randomUnit;

// Directions that include exact zeros and exact axis directions, which
// stress the float slab test's handling of infinities.
Vec3 randomDirection(std::mt19937_64& rng) {
    Vec3 d = randomUnit(rng);
    switch (rng() % 6) {
        case 0: d[static_cast<int>(rng() % 3)] = 0.0; break;
        case 1: {
            d = Vec3(0.0);
            d[static_cast<int>(rng() % 3)] = rng() % 2 ? 1.0 : -1.0;
            break;
        }
        default: break;
    }
    return glm::normalize(d);
}

std::vector<Sphere> randomSpheres(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<Sphere> s(n);
    for (auto& x : s) {
        x.centre = Vec3(u01(rng), u01(rng), u01(rng)) * 10.0 - 5.0;
        x.radius = std::pow(10.0, -2.0 + 1.5 * u01(rng));
    }
    return s;
}

// Axis-aligned boxes, a fifth of them flat (an axis-aligned polygon's box),
// with corners on a coarse grid so that rays often graze faces and edges.
std::vector<Bounds3> randomBoxes(std::mt19937_64& rng, int n) {
    std::uniform_int_distribution<int> grid(-40, 40);
    std::vector<Bounds3> boxes(n);
    for (auto& b : boxes) {
        Vec3 a(grid(rng), grid(rng), grid(rng)), c(grid(rng), grid(rng), grid(rng));
        a *= 0.125;
        c = a + glm::abs(c) * (1.0 / 64.0);
        b = {glm::min(a, c), glm::max(a, c)};
        if (rng() % 5 == 0) {
            const int axis = static_cast<int>(rng() % 3);
            b.hi[axis] = b.lo[axis];
        }
    }
    return boxes;
}

// Flat boxes (one axis of zero extent) at arbitrary, non-float coordinates.
std::vector<Bounds3> randomFlatBoxes(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<Bounds3> boxes(n);
    for (auto& b : boxes) {
        const Vec3 c = (Vec3(u01(rng), u01(rng), u01(rng)) - 0.5) * 20.0;
        Vec3 h = Vec3(u01(rng), u01(rng), u01(rng)) * 0.3;
        h[static_cast<int>(rng() % 3)] = 0.0;
        b = {c - h, c + h};
    }
    return boxes;
}

Ray randomRay(std::mt19937_64& rng, bool onGrid) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Ray r;
    if (onGrid) {
        std::uniform_int_distribution<int> grid(-48, 48);
        r.origin = Vec3(grid(rng), grid(rng), grid(rng)) * 0.125;
    } else {
        r.origin = Vec3(u01(rng), u01(rng), u01(rng)) * 14.0 - 7.0;
    }
    r.dir = randomDirection(rng);
    return r;
}

template <class HitFn>
std::optional<Hit> bruteNearest(std::size_t n, const Ray& ray, double tMin, double tMax, HitFn&& hit) {
    std::optional<Hit> best;
    for (std::uint32_t i = 0; i < n; ++i) {
        if (auto t = hit(i, ray, tMin, best ? best->t : tMax)) {
            if (!best || *t < best->t) best = Hit{*t, i};
        }
    }
    return best;
}

template <class HitFn>
void checkAgainstBruteForce(const Bvh& bvh, std::size_t n, std::mt19937_64& rng, bool onGrid, HitFn&& hit) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 4000; ++trial) {
        const Ray ray = randomRay(rng, onGrid);
        const double tMin = rng() % 2 ? 0.0 : 0.5 * u01(rng);
        const double tMax = rng() % 2 ? kInfinity : tMin + 10.0 * u01(rng);
        const auto expected = bruteNearest(n, ray, tMin, tMax, hit);
        const auto got = bvh.nearest(ray, tMin, tMax,
                                     [&](std::uint32_t i, const Ray& r, double lo, double hi) -> std::optional<Hit> {
                                         if (auto t = hit(i, r, lo, hi)) return Hit{*t, i};
                                         return std::nullopt;
                                     });
        INFO("trial " << trial << " origin " << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z
                      << " dir " << ray.dir.x << "," << ray.dir.y << "," << ray.dir.z << " t [" << tMin << ","
                      << tMax << "]");
        REQUIRE(expected.has_value() == got.has_value());
        if (expected) {
            // Equal distances; where items tie (shared faces), either item.
            REQUIRE(got->t == expected->t);
            const auto again = hit(got->item, ray, tMin, tMax);
            REQUIRE(again);
            REQUIRE(*again == got->t);
        }
        const bool anyHit = bvh.any(ray, tMin, tMax, [&](std::uint32_t i, const Ray& r, double lo, double hi) {
            return hit(i, r, lo, hi).has_value();
        });
        REQUIRE(anyHit == expected.has_value());
    }
}

}  // namespace

TEST_CASE("BVH nearest and any hit equal brute force on random spheres", "[accel][bvh]") {
    std::mt19937_64 rng(1);
    for (int n : {1, 7, 300, 3000}) {
        const auto spheres = randomSpheres(rng, n);
        std::vector<Bounds3> bounds;
        for (const auto& s : spheres) bounds.push_back(s.bounds());
        const Bvh bvh = Bvh::build(bounds);
        CHECK(bvh.itemCount() == spheres.size());
        checkAgainstBruteForce(bvh, spheres.size(), rng, false,
                               [&](std::uint32_t i, const Ray& r, double lo, double hi) {
                                   return hitSphere(spheres[i], r, lo, hi);
                               });
    }
}

TEST_CASE("BVH nearest and any hit equal brute force on grazed and flat boxes", "[accel][bvh]") {
    std::mt19937_64 rng(2);
    for (int n : {5, 2000}) {
        const auto boxes = randomBoxes(rng, n);
        for (int leaf : {1, 4, 15}) {
            BvhBuildOptions options;
            options.maxLeafSize = leaf;
            const Bvh bvh = Bvh::build(boxes, options);
            checkAgainstBruteForce(bvh, boxes.size(), rng, true,
                                   [&](std::uint32_t i, const Ray& r, double lo, double hi) {
                                       return hitBox(boxes[i], r, lo, hi);
                                   });
        }
    }
}

TEST_CASE("BVH keeps hits on the edges of flat boxes (float rounding of the slab test)", "[accel][bvh]") {
    // Flat boxes at arbitrary (non-float) coordinates, rays aimed at points on
    // their edges and corners from arbitrary origins: the double-precision
    // hits must survive the float node boxes and float slab arithmetic.
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const std::vector<Bounds3> boxes = randomFlatBoxes(rng, 400);
    const Bvh bvh = Bvh::build(boxes);
    int hits = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Bounds3& target = boxes[rng() % boxes.size()];
        // A point on the target's boundary: each coordinate at lo, hi or between.
        Vec3 p;
        for (int i = 0; i < 3; ++i) {
            const int pick = static_cast<int>(rng() % 3);
            p[i] = pick == 0 ? target.lo[i] : pick == 1 ? target.hi[i] : target.lo[i] + u01(rng) * (target.hi[i] - target.lo[i]);
        }
        Ray ray;
        // Half from the origin itself (exact in float: only the rounding of
        // the slab distances is then at stake), half from anywhere.
        ray.origin = trial % 2 ? Vec3(0.0) : p + randomUnit(rng) * (0.5 + 30.0 * u01(rng));
        ray.dir = glm::normalize(p - ray.origin);
        const auto hit = [&](std::uint32_t i, const Ray& r, double lo, double hi) { return hitBox(boxes[i], r, lo, hi); };
        const auto expected = bruteNearest(boxes.size(), ray, 0.0, kInfinity, hit);
        const auto got = bvh.nearest(ray, 0.0, kInfinity, [&](std::uint32_t i, const Ray& r, double lo, double hi) -> std::optional<Hit> {
            if (auto t = hit(i, r, lo, hi)) return Hit{*t, i};
            return std::nullopt;
        });
        REQUIRE(expected.has_value() == got.has_value());
        if (expected) {
            ++hits;
            REQUIRE(got->t == expected->t);
        }
    }
    CHECK(hits > 10000);
}

namespace {

// A point on a box's boundary: each coordinate at lo, hi or between.
Vec3 pointOnBoundary(const Bounds3& b, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
        const int pick = static_cast<int>(rng() % 3);
        p[i] = pick == 0 ? b.lo[i] : pick == 1 ? b.hi[i] : b.lo[i] + u01(rng) * (b.hi[i] - b.lo[i]);
    }
    return p;
}

// Packets of several kinds: an 8x8 pinhole tile (coherent, one octant or
// straddling axis planes), rays from one origin or from nearby origins aimed
// at box edges and corners (mixed octants), and random rays whose directions
// include exact zeros and axis directions (traversed alone).
std::vector<Ray> randomPacket(std::mt19937_64& rng, const std::vector<Bounds3>& boxes, int kind, int size) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<Ray> rays;
    const Vec3 eye = randomUnit(rng) * (5.0 + 20.0 * u01(rng));
    switch (kind) {
    case 0: {
        const Bounds3& target = boxes[rng() % boxes.size()];
        const Vec3 forward = glm::normalize(target.center() - eye);
        const Vec3 right = glm::normalize(glm::cross(forward, randomUnit(rng)));
        const Vec3 up = glm::cross(right, forward);
        const double step = std::pow(10.0, -4.0 + 3.0 * u01(rng));
        const int side = static_cast<int>(std::ceil(std::sqrt(size)));
        for (int i = 0; i < size; ++i)
            rays.push_back({eye, glm::normalize(forward + (i % side - side / 2) * step * right +
                                                (i / side - side / 2) * step * up)});
        break;
    }
    case 1:
    case 2: {
        // Boxes near one target, so that the rays are somewhat coherent.
        const Bounds3& target = boxes[rng() % boxes.size()];
        for (int i = 0; i < size; ++i) {
            const Bounds3* b = &boxes[rng() % boxes.size()];
            if (rng() % 4 != 0) b = &target;
            const Vec3 origin = kind == 1 ? eye : eye + randomUnit(rng) * 0.3 * u01(rng);
            rays.push_back({origin, glm::normalize(pointOnBoundary(*b, rng) - origin)});
        }
        break;
    }
    default:
        for (int i = 0; i < size; ++i) rays.push_back(randomRay(rng, i % 2 == 0));
        break;
    }
    return rays;
}

}  // namespace

TEST_CASE("BVH packet traversal hands every ray each leaf its own traversal accepts", "[accel][bvh][packet]") {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // Grid boxes (a fifth flat) and flat boxes at arbitrary coordinates.
    std::vector<std::vector<Bounds3>> scenes{randomBoxes(rng, 2000)};
    scenes.push_back(randomFlatBoxes(rng, 600));
    int rays = 0, hits = 0;
    for (const auto& boxes : scenes) {
        for (int leafSize : {1, 4}) {
            BvhBuildOptions options;
            options.maxLeafSize = leafSize;
            const Bvh bvh = Bvh::build(boxes, options);
            const auto hit = [&](std::uint32_t i, const Ray& r, double lo, double hi) {
                return hitBox(boxes[i], r, lo, hi);
            };
            for (int trial = 0; trial < 400; ++trial) {
                const int size = std::array<int, 5>{1, 5, 64, 64, 150}[trial % 5];
                const auto packet = randomPacket(rng, boxes, trial / 5 % 4, size);
                const double tMin = trial % 3 == 0 ? 0.5 * u01(rng) : 0.0;
                std::vector<double> tMax(packet.size());
                for (auto& t : tMax) t = rng() % 3 == 0 ? tMin + 30.0 * u01(rng) : kInfinity;
                // A NaN limit (that ray is traversed alone) must not cost
                // the other rays of the packet their leaves.
                if (trial % 7 == 6) tMax[rng() % tMax.size()] = std::nan("");

                // A fixed far limit: the leaves a lone ray's traversal
                // accepts must all reach that ray in the packet.
                std::vector<std::set<std::uint32_t>> handed(packet.size());
                bvh.traversePacket(packet, tMin, tMax, [&](std::uint32_t i, std::uint32_t first, std::uint32_t) {
                    handed[i].insert(first);
                    return tMax[i];
                });
                for (std::size_t i = 0; i < packet.size(); ++i) {
                    std::set<std::uint32_t> alone;
                    bvh.traverse<true>(packet[i], tMin, tMax[i], [&](std::uint32_t first, std::uint32_t) {
                        alone.insert(first);
                        return tMax[i];
                    });
                    for (const std::uint32_t first : alone) REQUIRE(handed[i].count(first) == 1);
                }

                // A shrinking far limit: each ray's nearest hit.
                std::vector<std::optional<double>> nearest(packet.size());
                std::vector<double> far = tMax;
                bvh.traversePacket(packet, tMin, tMax, [&](std::uint32_t i, std::uint32_t first, std::uint32_t count) {
                    for (std::uint32_t k = first; k < first + count; ++k) {
                        if (const auto t = hit(bvh.itemOrder()[k], packet[i], tMin, far[i])) {
                            far[i] = *t;
                            nearest[i] = t;
                        }
                    }
                    return far[i];
                });
                for (std::size_t i = 0; i < packet.size(); ++i) {
                    if (std::isnan(tMax[i])) continue;  // no nearest hit to speak of
                    const auto expected = bruteNearest(boxes.size(), packet[i], tMin, tMax[i], hit);
                    ++rays;
                    REQUIRE(expected.has_value() == nearest[i].has_value());
                    if (expected) {
                        ++hits;
                        REQUIRE(*nearest[i] == expected->t);
                    }
                }
            }
        }
    }
    CHECK(hits > rays / 4);
}

TEST_CASE("BVH handles coincident items, far coordinates and degenerate input", "[accel][bvh]") {
    std::mt19937_64 rng(3);
    // 1000 identical boxes: no SAH split exists; median splits must still
    // give a valid tree.
    std::vector<Bounds3> same(1000, Bounds3{Vec3(1, 1, 1), Vec3(2, 2, 2)});
    const Bvh bvh = Bvh::build(same);
    CHECK(bvh.itemCount() == 1000);
    CHECK(bvh.depth() < bvh_detail::kMaxDepth);
    int count = 0;
    bvh.cone(Cone{Vec3(0.0), glm::normalize(Vec3(1, 1, 1)), 0.01, 0.0, kInfinity},
             [&](std::uint32_t) { ++count; });
    CHECK(count == 1000);
    const Ray ray{Vec3(1.5, 1.5, 0), Vec3(0, 0, 1)};
    CHECK(bvh.any(ray, 0.0, kInfinity, [](std::uint32_t, const Ray&, double, double) { return true; }));

    // Far away (1e5) small items: float boxes rounded outward keep the hits.
    std::vector<Sphere> far;
    for (int i = 0; i < 500; ++i) far.push_back({Vec3(1e5) + randomUnit(rng) * 3.0, 0.01 + 0.001 * i});
    std::vector<Bounds3> farBounds;
    for (const auto& s : far) farBounds.push_back(s.bounds());
    const Bvh farBvh = Bvh::build(farBounds);
    for (int trial = 0; trial < 2000; ++trial) {
        const Sphere& target = far[rng() % far.size()];
        Ray r;
        r.origin = Vec3(0.0);
        r.dir = glm::normalize(target.centre + randomUnit(rng) * target.radius * 0.999 - r.origin);
        const auto expected = bruteNearest(far.size(), r, 0.0, kInfinity,
                                           [&](std::uint32_t i, const Ray& q, double lo, double hi) {
                                               return hitSphere(far[i], q, lo, hi);
                                           });
        REQUIRE(expected);
        const auto got = farBvh.nearest(r, 0.0, kInfinity,
                                        [&](std::uint32_t i, const Ray& q, double lo, double hi) -> std::optional<Hit> {
                                            if (auto t = hitSphere(far[i], q, lo, hi)) return Hit{*t, i};
                                            return std::nullopt;
                                        });
        REQUIRE(got);
        REQUIRE(got->t == expected->t);
    }

    // Empty input, empty items, bad bounds.
    CHECK(Bvh::build(std::vector<Bounds3>{}).empty());
    const Bvh skipped = Bvh::build(std::vector<Bounds3>{Bounds3{}, Bounds3{Vec3(0.0), Vec3(1.0)}});
    CHECK(skipped.itemCount() == 1);
    CHECK(skipped.itemOrder()[0] == 1);
    CHECK_FALSE(skipped.nearest(Ray{Vec3(5.0), Vec3(0, 0, 1)}, 0.0, kInfinity,
                                [](std::uint32_t, const Ray&, double, double) { return std::optional<Hit>(); }));
    CHECK_THROWS_AS(Bvh::build(std::vector<Bounds3>{Bounds3{Vec3(0.0), Vec3(kInfinity)}}), std::invalid_argument);
    CHECK_THROWS_AS(Bvh::build(std::vector<Bounds3>{Bounds3{Vec3(std::nan("")), Vec3(1.0)}}),
                    std::invalid_argument);
    BvhBuildOptions bad;
    bad.maxLeafSize = 16;
    CHECK_THROWS_AS(Bvh::build(same, bad), std::invalid_argument);
}

namespace {

// Dense evidence that a cone touches a box (as in cone_box_test.cpp): box
// grid points inside the cone, or points of the cone's rays inside the box.
bool coneTouchesBox(const ConeBoxTest& test, const Bounds3& b) {
    const Cone& c = test.cone();
    constexpr int n = 5;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 f(i / double(n - 1), j / double(n - 1), k / double(n - 1));
                if (test.contains(b.lo + f * (b.hi - b.lo))) return true;
            }
    const Vec3 a = std::abs(c.axis.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(c.axis, a)), v = glm::cross(c.axis, u);
    const double far = std::isfinite(c.tMax) ? c.tMax : c.tMin + 30.0;
    for (int ring = 0; ring <= 3; ++ring) {
        const int azimuths = ring == 0 ? 1 : 16;
        for (int az = 0; az < azimuths; ++az) {
            const double psi = c.halfAngle * ring / 3.0, phi = 2 * kPi * az / azimuths;
            const Vec3 d = std::cos(psi) * c.axis + std::sin(psi) * (std::cos(phi) * u + std::sin(phi) * v);
            for (int s = 0; s <= 60; ++s)
                if (b.contains(c.apex + (c.tMin + (far - c.tMin) * s / 60.0) * d)) return true;
        }
    }
    return false;
}

}  // namespace

TEST_CASE("BVH cone traversal visits every item whose box the cone touches", "[accel][bvh][cone]") {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const auto spheres = randomSpheres(rng, 1500);
    std::vector<Bounds3> bounds;
    for (const auto& s : spheres) bounds.push_back(s.bounds());
    const Bvh bvh = Bvh::build(bounds);
    std::size_t visitedTotal = 0, touchedTotal = 0;
    for (int trial = 0; trial < 100; ++trial) {
        Cone c;
        c.apex = Vec3(u01(rng), u01(rng), u01(rng)) * 12.0 - 6.0;
        c.axis = randomDirection(rng);
        const double angles[] = {0.0, 1e-3, 0.02, 0.2, 1.2, 2.2};
        c.halfAngle = angles[rng() % 6];
        c.tMin = rng() % 2 ? 0.0 : u01(rng);
        c.tMax = rng() % 2 ? kInfinity : c.tMin + 8.0 * u01(rng);
        const ConeBoxTest test(c);
        std::set<std::uint32_t> visited;
        bvh.cone(c, [&](std::uint32_t i) { CHECK(visited.insert(i).second); });
        for (std::uint32_t i = 0; i < spheres.size(); ++i) {
            if (coneTouchesBox(test, bounds[i])) {
                ++touchedTotal;
                if (!visited.count(i)) FAIL("cone trial " << trial << " missed item " << i);
            }
        }
        visitedTotal += visited.size();
    }
    // It prunes: narrow cones visit a small part of the scene.
    CHECK(touchedTotal > 0);
    CHECK(visitedTotal < 100 * spheres.size() / 2);
}

TEST_CASE("BVH cone traversal stops early and honours a shrinking far limit", "[accel][bvh][cone]") {
    // A row of unit boxes along +z; a cone down the row.
    std::vector<Bounds3> row;
    for (int i = 0; i < 64; ++i) row.push_back({Vec3(-0.5, -0.5, 2.0 * i), Vec3(0.5, 0.5, 2.0 * i + 1.0)});
    const Bvh bvh = Bvh::build(row);
    const Cone c{Vec3(0, 0, -1), Vec3(0, 0, 1), 0.01, 0.0, kInfinity};
    std::set<std::uint32_t> all;
    bvh.cone(c, [&](std::uint32_t i) { all.insert(i); });
    CHECK(all.size() == 64);
    int visits = 0;
    bvh.cone(c, [&](std::uint32_t) { return ++visits < 3; });
    CHECK(visits == 3);
    // Item 10 blocks everything past z = 21: items whose boxes start beyond
    // it are skipped; all nearer ones are visited.
    std::set<std::uint32_t> seen;
    bvh.cone(c, [&](std::uint32_t i) {
        seen.insert(i);
        return i == 10 ? 22.0 : kInfinity;
    });
    for (std::uint32_t i = 0; i <= 10; ++i) CHECK(seen.count(i) == 1);
    for (std::uint32_t i = 12; i < 64; ++i) CHECK(seen.count(i) == 0);
}

TEST_CASE("BVH cone prefilter (float) keeps every box the cone touches", "[accel][bvh][cone]") {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    int kept = 0, dropped = 0;
    for (int trial = 0; trial < 6000; ++trial) {
        Cone c;
        c.apex = (Vec3(u01(rng), u01(rng), u01(rng)) - 0.5) * 20.0;
        c.axis = randomDirection(rng);
        const double angles[] = {0.0, 1e-5, 1e-3, 0.05, 0.5, 1.5, 2.5};
        c.halfAngle = angles[rng() % 7];
        c.tMin = rng() % 2 ? 0.0 : 2.0 * u01(rng);
        c.tMax = rng() % 3 == 0 ? kInfinity : c.tMin + 10.0 * u01(rng);
        const ConeBoxTest test(c);
        bvh_detail::Node node;
        Bounds3 boxes[4];
        for (int k = 0; k < 4; ++k) {
            // Near the cone's rim at a random distance, of random size and shape.
            const Vec3 a = std::abs(c.axis.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
            const Vec3 u = glm::normalize(glm::cross(c.axis, a)), v = glm::cross(c.axis, u);
            const double phi = 2 * kPi * u01(rng), t = c.tMin + u01(rng) * (std::isfinite(c.tMax) ? c.tMax - c.tMin : 10.0);
            const Vec3 rim = c.apex + t * (std::cos(c.halfAngle) * c.axis +
                                           std::sin(c.halfAngle) * (std::cos(phi) * u + std::sin(phi) * v));
            const double size = std::pow(10.0, -3.0 + 3.0 * u01(rng));
            Vec3 half(size * u01(rng), size * u01(rng), size * u01(rng));
            if (rng() % 4 == 0) half[static_cast<int>(rng() % 3)] = 0.0;
            const Vec3 centre = rim + (Vec3(u01(rng), u01(rng), u01(rng)) - 0.5) * (3.0 * size);
            boxes[k] = {glm::floor((centre - half) * 4096.0) / 4096.0, glm::ceil((centre + half) * 4096.0) / 4096.0};
            for (int axis = 0; axis < 3; ++axis) {
                node.box[0][axis][k] = static_cast<float>(boxes[k].lo[axis]);
                node.box[1][axis][k] = static_cast<float>(boxes[k].hi[axis]);
            }
        }
        const unsigned mask = bvh_detail::ConePrefilter(test.cone()).keep(node);
        for (int k = 0; k < 4; ++k) {
            const bool keep = (mask >> k) & 1u;
            kept += keep;
            dropped += !keep;
            if (!keep && coneTouchesBox(test, boxes[k])) FAIL("prefilter dropped a touching box, trial " << trial);
        }
    }
    CHECK(dropped > 2000);
    CHECK(kept > 2000);
}
