#include "asos/render/point_light_shadow.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/render/shading.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos {

namespace {

// A footprint corner must meet the tangent plane within this factor of the
// hit's depth (nearer or farther) for the plane to be used.
constexpr double kFootprintDepthRatio = 2.0;
// Shadow cones wider than this are not convex enough to bound the pyramid
// they should hold; such a footprint gets a plain shadow ray.
constexpr double kWidestShadowCone = 0.45 * kPi;

// The shadow pyray from the light through the footprint of one square.
struct ShadowPyray {
    Cone cone;  // about the ray from the light toward the footprint of the square's centre
    double centralDistance;
    // No footprint point of the square is nearer the light than this.
    double nearestFootprint;
    double diameter;  // of the footprint
    bool valid;
};

// From the footprint points of a square's corners and centre.
ShadowPyray makeShadowPyray(const Vec3& light, const Footprint& footprint,
                            const std::array<Vec3, 4>& corners, const Vec3& centre) {
    ShadowPyray p{};
    const Vec3 toCentre = centre - light;
    p.centralDistance = glm::length(toCentre);
    if (!(p.centralDistance > 2.0 * kPovShadowTolerance)) return p;
    const Vec3 axis = toCentre / p.centralDistance;
    // The widest corner, by the tangent of its angle from the axis (one atan
    // for the cone rather than one per corner).
    double widestTangent = 0.0, farthest = p.centralDistance, nearestCorner = p.centralDistance;
    double diameter = 0.0;
    for (int i = 0; i < 4; ++i) {
        const Vec3 d = corners[i] - light;
        const double distance = glm::length(d);
        farthest = std::max(farthest, distance);
        nearestCorner = std::min(nearestCorner, distance);
        const double along = glm::dot(d, axis);
        if (!(along > 0.0)) return p;  // a corner at right angles to the axis or behind
        widestTangent = std::max(widestTangent, glm::length(glm::cross(d, axis)) / along);
        for (int j = i + 1; j < 4; ++j)
            diameter = std::max(diameter, glm::length(corners[i] - corners[j]));
    }
    double halfAngle = std::atan(widestTangent);
    // Every footprint point lies within `diameter` of a corner.
    p.nearestFootprint = nearestCorner - diameter;
    p.diameter = diameter;
    if (!footprint.onTangentPlane() && p.nearestFootprint > 0.0) {
        // A cross-section is curved (a cap of the sphere of the hit's depth
        // about the eye): widen by its sagitta as seen from the light.
        const double depth = glm::length(footprint.point() - light) + diameter;
        halfAngle += diameter * diameter / (8.0 * depth * p.nearestFootprint);
    }
    if (!(halfAngle < kWidestShadowCone) || !(p.nearestFootprint > 2.0 * kPovShadowTolerance))
        return p;
    p.cone = {light, axis, halfAngle + kConeAnglePad, kPovShadowTolerance, padUp(farthest)};
    p.valid = true;
    return p;
}

ShadowPyray makeShadowPyray(const Vec3& light, const Footprint& footprint, const ImageSquare& sq) {
    return makeShadowPyray(light, footprint,
                           {footprint.at(sq.u0, sq.v0), footprint.at(sq.u1, sq.v0),
                            footprint.at(sq.u1, sq.v1), footprint.at(sq.u0, sq.v1)},
                           footprint.at(sq.uMid(), sq.vMid()));
}

std::uint64_t subKey(std::uint64_t key, int level, std::uint32_t ix, std::uint32_t iy) {
    return mix64(key ^ subPosition(level, ix, iy));
}

}  // namespace

Footprint::Footprint(const CameraModel& camera, const ImageSquare& square, const Vec3& point,
                     const Vec3& normal, double depth)
    : camera_(&camera), square_(square), point_(point), normal_(normal), depth_(depth) {
    const double us[4] = {square.u0, square.u1, square.u1, square.u0};
    const double vs[4] = {square.v0, square.v0, square.v1, square.v1};
    Ray rays[4];
    double ts[4];
    for (int i = 0; i < 4; ++i) {
        rays[i] = camera.ray(us[i], vs[i]);
        ts[i] = planeDistance(rays[i]);
        if (!(ts[i] >= depth / kFootprintDepthRatio && ts[i] <= depth * kFootprintDepthRatio))
            tangentPlane_ = false;
    }
    for (int i = 0; i < 4; ++i) corners_[i] = rays[i].at(tangentPlane_ ? ts[i] : depth_);
    centre_ = at(square.uMid(), square.vMid());
}

double Footprint::planeDistance(const Ray& ray) const {
    const double denominator = glm::dot(ray.dir, normal_);
    if (denominator == 0.0) return kInfinity;
    return glm::dot(point_ - ray.origin, normal_) / denominator;
}

Vec3 Footprint::at(double u, double v) const {
    const Ray ray = camera_->ray(u, v);
    return ray.at(tangentPlane_ ? planeDistance(ray) : depth_);
}

double pointLightLitFraction(const Scene& scene, const Footprint& footprint,
                             const PointShadowQuery& q, ShadowScratch& s, RenderCounters& counters) {
    const Vec3& light = q.lightPosition;
    const int maxLevel = q.settings.maxLevel;

    // A plain shadow ray from a footprint point toward the light, through
    // the whole scene.
    auto plainRayLit = [&](const Vec3& target) {
        const Vec3 d = light - target;
        const double distance = glm::length(d);
        if (!(distance > 2.0 * kPovShadowTolerance)) return 1.0;
        ++counters.shadowRays;
        return scene.occluded({target, d / distance}, kPovShadowTolerance,
                              distance - kPovShadowTolerance)
                   ? 0.0
                   : 1.0;
    };
    // Whether the shadow ray from the light toward `target` meets one of the
    // occluders items[first, first + count); marks each one it meets.
    // How far before its footprint point a ray ignores the shaded object
    // (set below to the footprint's diameter: see selfCone).
    double selfMargin = 0.0;
    auto rayBlocked = [&](const Vec3& target, const std::vector<ShadowScratch::Item>& items,
                          std::uint32_t first, std::uint32_t count, std::uint8_t* marks) {
        const Vec3 d = target - light;
        const double distance = glm::length(d);
        ++counters.shadowRays;
        if (!(distance > 2.0 * kPovShadowTolerance)) return false;
        const Ray ray{light, d / distance};
        bool blocked = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            // Without marks to keep, the first occluder decides.
            if (blocked && !marks) break;
            ++counters.rayTests;
            const double end = distance - kPovShadowTolerance -
                               (items[i].object == q.shadedObject ? selfMargin : 0.0);
            const bool hit = end > kPovShadowTolerance &&
                             scene.primitive(items[i].object).intersectAny(ray, kPovShadowTolerance, end);
            if (marks) marks[i] = hit;
            blocked = blocked || hit;
        }
        return blocked;
    };

    // At MAX the footprint is a point sample ("Jittering of MAX-rays").
    if (q.level >= maxLevel) {
        if (!q.settings.jitter) return plainRayLit(footprint.point());
        const Vec2 xi = q.rng.uniform2(SampleStream::ShadowJitter, subKey(q.jitterKey, q.level, q.ix, q.iy));
        const Vec2 p = footprint.square().pointAt(xi);
        return plainRayLit(footprint.at(p.x, p.y));
    }

    const ShadowPyray root = makeShadowPyray(light, footprint, footprint.corners(), footprint.centre());
    if (!root.valid) return plainRayLit(footprint.point());
    counters.countShadowPyray(q.level);

    // How the occluders of a pyray decide it: a Full occluder wholly between
    // the light and the footprint blocks it all; with none left it is lit;
    // with no Marginal one, a plain ray decides; otherwise it is marginal.
    enum class Verdict { Lit, Blocked, Plain, Marginal };
    auto verdict = [&](const std::vector<ShadowScratch::Item>& items, std::uint32_t first,
                       std::uint32_t count, double nearestFootprint) {
        if (count == 0) return Verdict::Lit;
        bool marginal = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const ConeClass& k = items[i].cls;
            if (k.coverage == Coverage::Full && k.tFar < nearestFootprint - kPovShadowTolerance)
                return Verdict::Blocked;
            marginal = marginal || k.coverage == Coverage::Marginal;
        }
        return marginal ? Verdict::Marginal : Verdict::Plain;
    };

    // Detection: the occluders of the whole footprint.
    std::vector<ShadowScratch::Item>& rootItems = s.items[0];
    rootItems.clear();
    const PreparedCone rootCone(root.cone);
    // The shaded object, where it may shadow itself, meets every ray at the
    // footprint, and a curved surface does so a little before the
    // footprint's tangent plane: it is asked only about the part of the cone
    // that ends a footprint's diameter before the nearest footprint point.
    // It shadows the footprint from farther away (the rim of an open tube),
    // and blocking nearer than that is the surface curving at the footprint.
    auto selfCone = [&](const ShadowPyray& p) {
        Cone cone = p.cone;
        cone.tMax = p.nearestFootprint - p.diameter - kPovShadowTolerance;
        return PreparedCone(cone);
    };
    const PreparedCone rootSelfCone = selfCone(root);
    selfMargin = root.diameter;
    if (s.candidates.size() <= q.lightIndex) s.candidates.resize(q.lightIndex + 1);
    s.candidates[q.lightIndex].visit(scene, root.cone, [&](std::uint32_t object) {
        if (scene.object(object).noShadow || scene.transparent(object)) return;  // transparent: filtered by the caller
        if (object == q.shadedObject && !q.shadedCanSelfShadow) return;
        ++counters.coneTests;
        const ConeClass k =
            scene.primitive(object).classify(object == q.shadedObject ? rootSelfCone : rootCone);
        if (k.coverage != Coverage::Miss) rootItems.push_back({object, k});
    });
    sortByObject(rootItems.data(), rootItems.data() + rootItems.size());
    const auto rootCount = static_cast<std::uint32_t>(rootItems.size());
    switch (verdict(rootItems, 0, rootCount, root.nearestFootprint)) {
        case Verdict::Lit: return 1.0;
        case Verdict::Blocked: return 0.0;
        case Verdict::Plain:
            return rayBlocked(footprint.point(), rootItems, 0, rootCount, nullptr) ? 0.0 : 1.0;
        case Verdict::Marginal: break;
    }

    // Subdivision ("subdivide it in the same manner"), level by level over
    // the footprint's occluders only.
    s.hits[0].assign(rootCount, 0);
    s.nodes[0].clear();
    const ImageSquare& rootSquare = footprint.square();
    s.nodes[0].push_back({rootSquare, q.level, q.ix, q.iy, 0, rootCount, false});
    s.nodes[0].back().blocked =
        rayBlocked(footprint.centre(), rootItems, 0, rootCount, s.hits[0].data());
    double lit = 0.0;
    int cur = 0;
    for (int level = q.level;; ++level) {
        std::vector<ShadowScratch::Node>& nodes = s.nodes[cur];
        const std::vector<ShadowScratch::Item>& items = s.items[cur];
        const std::vector<std::uint8_t>& hits = s.hits[cur];
        const double weight = std::ldexp(1.0, -2 * (level - q.level));

        s.tally.clear();
        for (const ShadowScratch::Node& n : nodes)
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
                s.tally.add(items[i].object, hits[i] != 0,
                            items[i].cls.coverage == Coverage::Marginal && items[i].cls.singleEdge);
        if (stopSubdividing(s.tally, level, q.settings.eps, maxLevel)) {
            for (const ShadowScratch::Node& n : nodes)
                if (!n.blocked) lit += weight;
            break;
        }

        const int childLevel = level + 1;
        const double childWeight = 0.25 * weight;
        if (childLevel >= maxLevel) {
            // MAX-pyrays: point samples, no detection.
            for (const ShadowScratch::Node& n : nodes)
                for (int quarter = 0; quarter < 4; ++quarter) {
                    const ImageSquare sq = n.square.quarter(quarter);
                    const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
                    Vec3 target;
                    if (q.settings.jitter) {
                        const Vec2 p = sq.pointAt(q.rng.uniform2(
                            SampleStream::ShadowJitter, subKey(q.jitterKey, childLevel, ix, iy)));
                        target = footprint.at(p.x, p.y);
                    } else {
                        target = footprint.at(sq.uMid(), sq.vMid());
                    }
                    counters.countShadowPyray(childLevel);
                    if (!rayBlocked(target, items, n.first, n.count, nullptr)) lit += childWeight;
                }
            break;
        }

        const int next = 1 - cur;
        std::vector<ShadowScratch::Item>& childItems = s.items[next];
        std::vector<std::uint8_t>& childHits = s.hits[next];
        std::vector<ShadowScratch::Node>& childNodes = s.nodes[next];
        childItems.clear();
        childHits.clear();
        childNodes.clear();
        for (const ShadowScratch::Node& n : nodes)
            for (int quarter = 0; quarter < 4; ++quarter) {
                const ImageSquare sq = n.square.quarter(quarter);
                const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
                counters.countShadowPyray(childLevel);
                const ShadowPyray child = makeShadowPyray(light, footprint, sq);
                if (!child.valid) {
                    if (!rayBlocked(footprint.at(sq.uMid(), sq.vMid()), items, n.first, n.count,
                                    nullptr))
                        lit += childWeight;
                    continue;
                }
                const auto first = static_cast<std::uint32_t>(childItems.size());
                const PreparedCone cone(child.cone);
                const PreparedCone childSelfCone = selfCone(child);
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    ++counters.coneTests;
                    const ConeClass k = scene.primitive(items[i].object)
                                            .classify(items[i].object == q.shadedObject ? childSelfCone
                                                                                        : cone);
                    if (k.coverage != Coverage::Miss) childItems.push_back({items[i].object, k});
                }
                const auto count = static_cast<std::uint32_t>(childItems.size()) - first;
                switch (verdict(childItems, first, count, child.nearestFootprint)) {
                    case Verdict::Lit: lit += childWeight; break;
                    case Verdict::Blocked: break;
                    case Verdict::Plain:
                        if (!rayBlocked(footprint.at(sq.uMid(), sq.vMid()), childItems, first,
                                        count, nullptr))
                            lit += childWeight;
                        break;
                    case Verdict::Marginal: {
                        childHits.resize(childItems.size(), 0);
                        ShadowScratch::Node node{sq, childLevel, ix, iy, first, count, false};
                        node.blocked = rayBlocked(footprint.at(sq.uMid(), sq.vMid()), childItems,
                                                  first, count, childHits.data());
                        childNodes.push_back(node);
                        break;
                    }
                }
            }
        if (childNodes.empty()) break;
        cur = next;
    }
    return std::min(lit, 1.0);
}

}  // namespace asos
