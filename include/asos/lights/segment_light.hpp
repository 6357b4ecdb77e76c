#pragma once
// A linear light (paper: "Linear Light Sources", Figure 5c): the segment
// from start to end, centred on the light's position (`area_light` with one
// axis of zero length or a count of 1: POV-Ray's linear light). As every
// light form (lights/light_form.hpp) it answers:
//   - its beam from a point: the triangle of rays to its ends, bounded by
//     the cone about the bisector of the end rays, split into two halves,
//     each carrying 2^-level of the light;
//   - its grid's points seen from a point (render/grid_light.hpp): one row;
//   - its emitted radiance: intensity colour / length, the same along every
//     direction (each point of the line lights as a point light).
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/lights/beam_apex.hpp"
#include "asos/lights/light_lattice.hpp"
#include "asos/lights/light_piece.hpp"

namespace asos {

struct SegmentLight {
    static constexpr const char* kName = "linear";

    Vec3 start{0.0}, end{0.0};
    double length = 0.0;  // |end - start|, as the scene's axis gives it

    // Its length.
    double size() const { return length; }
    double halfWidth() const { return 0.5 * length; }
    Bounds3 bounds() const {
        // The end as the beams make it (start + the edge): the same box.
        Bounds3 b = Bounds3::of(start);
        b.extend(start + (end - start));
        return b;
    }
    // A triangle holds no area: p's projection onto the triangle's plane
    // lies in it (so the beam spans p's extent along the light).
    bool beamHolds(const Vec3& apex, const Vec3& p) const;
    // None where the apex lies on the segment's line (below rounding).
    class Beam;
    std::optional<Beam> beamFrom(const Vec3& apex, double tMin) const;
    class GridPoints;
    std::optional<GridPoints> gridFrom(const Vec3& point) const;
};

// The answers of an AreaLightBeam (lights/light_form.hpp) for a segment.
class SegmentLight::Beam {
public:
    static constexpr int kChildren = 2;  // halves
    // A straight occluder edge crosses the segment at one point.
    static constexpr bool kSingleEdgeHalving = true;

    LightPiece root() const { return make(0.0, 1.0, 0, 0, true); }
    int split(const LightPiece& piece, LightPiece* out, bool cones = true) const {
        const double mid = 0.5 * (piece.a0 + piece.a1);
        out[0] = make(piece.a0, mid, piece.level + 1, 2 * piece.path, cones);
        out[1] = make(mid, piece.a1, piece.level + 1, 2 * piece.path + 1, cones);
        return kChildren;
    }
    // Made without the levels between.
    template <class F>
    void forEachDescendant(const LightPiece& piece, int depth, F&& f) const {
        descend(piece.a0, piece.a1, piece.level, piece.path, depth, f);
    }
    // One row.
    std::optional<LightLattice> lattice(const LightPiece& piece, int depth) const {
        if (depth < 0 || depth > LightLattice::kMaxDepth) return std::nullopt;
        return LightLattice::ofSegment(apex_, corner_, edgeA_, piece, depth);
    }

    // From the first number.
    BeamRay sample(const LightPiece& piece, const Vec2& xi) const {
        return apex_.toward(corner_ + (piece.a0 + xi.x * (piece.a1 - piece.a0)) * edgeA_);
    }
    // The triangle of its ends.
    std::optional<BeamHull> hull(double endGap) const {
        const Vec3 ends[2] = {corner_, corner_ + edgeA_};
        const double reach = std::max(glm::length(ends[0] - apex_.point), glm::length(ends[1] - apex_.point));
        return BeamHull::over(apex_.point, ends, 2, padUp(reach), endGap);
    }
    double share(int level) const { return exactShare(level); }  // 2^-level
    double nearestLightDistance(const LightPiece& piece) const {
        const Vec3 nearest = corner_ + std::clamp(footS_, piece.a0, piece.a1) * edgeA_;
        return padDown(glm::length(nearest - apex_.point));
    }
    // Toward the piece's two ends: 2.
    int probeRays(const LightPiece& piece, BeamRay* out) const {
        out[0] = apex_.toward(corner_ + piece.a0 * edgeA_);
        out[1] = apex_.toward(corner_ + piece.a1 * edgeA_);
        return 2;
    }
    // Simpson's rule.
    std::pair<double, double> ruleWeights(const LightPiece&) const { return {2.0 / 3.0, 1.0 / 6.0}; }
    // Exact up to rounding (Across where it is in doubt): the height of a
    // point of the segment above the plane is affine along it.
    HorizonSide horizonSide(const LightPiece& piece, const Vec3& normal) const {
        const double h0 = glm::dot(normal, corner_ - apex_.point), hA = glm::dot(normal, edgeA_);
        const double lo = h0 + std::min(piece.a0 * hA, piece.a1 * hA);
        const double hi = h0 + std::max(piece.a0 * hA, piece.a1 * hA);
        const double margin = kThousandsOfUlps * (std::abs(h0) + std::abs(hA));
        if (lo > margin) return HorizonSide::Above;
        if (hi < -margin) return HorizonSide::Below;
        return HorizonSide::Across;
    }
    double emission(const Vec3&) const { return 1.0; }  // the same every way

private:
    friend struct SegmentLight;
    Beam() = default;

    // The piece s in [a0, a1]: its central ray and, with `cone`, the cone
    // about the bisector of its end rays, the smallest that holds the
    // triangle. For unit u and v, tan(angle / 2) = |u - v| / |u + v|: one
    // arctangent, and the tangent spares the cone's users theirs.
    LightPiece make(double a0, double a1, int level, std::uint64_t path, bool cone) const;
    template <class F>
    void descend(double a0, double a1, int level, std::uint64_t path, int depth, F& f) const {
        if (depth == 0) {
            LightPiece p{a0, 0.0, a1, 1.0, level, path, {}, {}};
            p.central = apex_.toward(corner_ + 0.5 * (a0 + a1) * edgeA_);
            f(std::as_const(p));
            return;
        }
        const double mid = 0.5 * (a0 + a1);
        descend(a0, mid, level + 1, 2 * path, depth - 1, f);
        descend(mid, a1, level + 1, 2 * path + 1, depth - 1, f);
    }

    BeamApex apex_;
    Vec3 corner_{0.0}, edgeA_{0.0};  // corner + s edgeA
    double footS_ = 0.0;             // the apex's foot on the line
};

// The answers of AreaLightGridPoints (lights/light_form.hpp) for a segment.
class SegmentLight::GridPoints {
public:
    // The point s (t unused).
    BeamRay toward(double s, double) const { return rayToward(point_, light_.start + s * (light_.end - light_.start)); }
    double emission(const Vec3&) const { return 1.0; }

private:
    friend struct SegmentLight;
    GridPoints(const SegmentLight& light, const Vec3& point) : light_(light), point_(point) {}

    SegmentLight light_;
    Vec3 point_;
};

}  // namespace asos
