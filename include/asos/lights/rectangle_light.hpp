#pragma once
// A rectangular light (paper: "Rectangular Light Sources", Figure 5a): the
// parallelogram corner + s edgeA + t edgeB, s and t in [0, 1], centred on
// the light's position (`area_light <a>, <b>, n1, n2` with both axes in
// use). As every light form (lights/light_form.hpp) it answers:
//   - its beam from a point: the pyray to its four corners, bounded by the
//     cone about its central ray through its widest corner (one
//     arctangent; the smallest cone of the corners, rect_shadow_pyray.hpp in
//     asos_testing, tries forty pairs and triples), split into the four
//     quarters of the rectangle (Morton order: quarter q = i + 2 j), each
//     carrying 4^-level of the light;
//   - its grid's points seen from a point (render/grid_light.hpp);
//   - its emitted radiance with the paper's emitter: intensity colour /
//     area, weighted along a direction by |cos theta| to its normal, so that
//     a point far in front of it receives its colour, as from a point light
//     at its centre (POV-Ray's emitter asks only how much of it a point
//     sees: its points are isotropic).
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

struct RectangleLight {
    static constexpr const char* kName = "rectangular";

    Vec3 corner{0.0};
    Vec3 edgeA{1.0, 0.0, 0.0};
    Vec3 edgeB{0.0, 1.0, 0.0};

    // Its area.
    double size() const { return glm::length(glm::cross(edgeA, edgeB)); }
    // Half the side of the square of its area.
    double halfWidth() const { return 0.5 * std::sqrt(size()); }
    Bounds3 bounds() const {
        Bounds3 b = Bounds3::of(corner);
        b.extend(corner + edgeA);
        b.extend(corner + edgeB);
        b.extend(corner + edgeA + edgeB);
        return b;
    }
    // The ray from the apex through p meets the parallelogram.
    bool beamHolds(const Vec3& apex, const Vec3& p) const;
    // None where the apex lies in the light's plane (below rounding): it
    // sees the light edge on and receives nothing.
    class Beam;
    std::optional<Beam> beamFrom(const Vec3& apex, double tMin) const;
    class GridPoints;
    std::optional<GridPoints> gridFrom(const Vec3& point) const;
};

// The answers of an AreaLightBeam (lights/light_form.hpp) for a rectangle.
class RectangleLight::Beam {
public:
    static constexpr int kChildren = 4;  // quarters
    // A straight occluder edge is a straight line in the light's plane.
    static constexpr bool kSingleEdgeHalving = true;

    LightPiece root() const;
    int split(const LightPiece& piece, LightPiece* out, bool cones = true) const;
    // Made without the levels between.
    template <class F>
    void forEachDescendant(const LightPiece& piece, int depth, F&& f) const {
        descend(piece.a0, piece.b0, piece.a1, piece.b1, piece.level, piece.path, depth, f);
    }
    std::optional<LightLattice> lattice(const LightPiece& piece, int depth) const {
        if (depth < 0 || depth > LightLattice::kMaxDepth) return std::nullopt;
        return LightLattice::ofRectangle(apex_, light_.corner, light_.edgeA, light_.edgeB, piece, depth);
    }

    BeamRay sample(const LightPiece& piece, const Vec2& xi) const;
    // The pyramid over its corners.
    std::optional<BeamHull> hull(double endGap) const;
    double share(int level) const { return exactShare(2 * level); }  // 4^-level
    // The distance to the apex's foot clamped to the piece; for other
    // parallelograms a lower bound, the height above the plane.
    double nearestLightDistance(const LightPiece& piece) const;
    // Toward the midpoints of the piece's opposite edges: 4.
    int probeRays(const LightPiece& piece, BeamRay* out) const;
    // A square piece's.
    std::pair<double, double> ruleWeights(const LightPiece&) const { return {1.0 / 3.0, 1.0 / 6.0}; }
    // Exact up to rounding (Across where it is in doubt): the height of a
    // point of the light above the plane is affine in its coordinates, so
    // its range over the piece is at the piece's corners.
    HorizonSide horizonSide(const LightPiece& piece, const Vec3& normal) const {
        const double h0 = glm::dot(normal, light_.corner - apex_.point), hA = glm::dot(normal, light_.edgeA);
        const double hB = glm::dot(normal, light_.edgeB);
        const double lo = h0 + std::min(piece.a0 * hA, piece.a1 * hA) + std::min(piece.b0 * hB, piece.b1 * hB);
        const double hi = h0 + std::max(piece.a0 * hA, piece.a1 * hA) + std::max(piece.b0 * hB, piece.b1 * hB);
        const double margin = kThousandsOfUlps * (std::abs(h0) + std::abs(hA) + std::abs(hB));
        if (lo > margin) return HorizonSide::Above;
        if (hi < -margin) return HorizonSide::Below;
        return HorizonSide::Across;
    }
    // |cos theta| to the normal.
    double emission(const Vec3& dir) const { return std::abs(dot3(normal_, dir)); }

private:
    friend struct RectangleLight;
    Beam() = default;

    template <class F>
    void descend(double a0, double b0, double a1, double b1, int level, std::uint64_t path, int depth, F& f) const {
        if (depth == 0) {
            LightPiece p{a0, b0, a1, b1, level, path, {}, {}};
            p.central = apex_.toward(point(0.5 * (a0 + a1), 0.5 * (b0 + b1)));
            f(std::as_const(p));
            return;
        }
        // The midpoints of dyadic ranges are exact, and the central rays are
        // made by the same expressions as split()'s.
        const double s[3] = {a0, 0.5 * (a0 + a1), a1};
        const double t[3] = {b0, 0.5 * (b0 + b1), b1};
        for (int q = 0; q < 4; ++q) {
            const int i = q & 1, j = q >> 1;
            descend(s[i], t[j], s[i + 1], t[j + 1], level + 1, 4 * path + std::uint64_t(q), depth - 1, f);
        }
    }
    Vec3 point(double s, double t) const { return light_.corner + s * light_.edgeA + t * light_.edgeB; }

    RectangleLight light_;
    BeamApex apex_;
    Vec3 normal_{0.0};
    bool rectangular_ = false;  // edges at right angles: nearest points by clamping
    double footS_ = 0.0, footT_ = 0.0, height_ = 0.0;
};

// The answers of AreaLightGridPoints (lights/light_form.hpp) for a rectangle.
class RectangleLight::GridPoints {
public:
    BeamRay toward(double s, double t) const {
        return rayToward(point_, light_.corner + s * light_.edgeA + t * light_.edgeB);
    }
    // |cos theta| to the normal (normalised as the grid always has: its
    // images depend on these bits).
    double emission(const Vec3& dir) const { return std::abs(glm::dot(normal_, dir)); }

private:
    friend struct RectangleLight;
    GridPoints(const RectangleLight& light, const Vec3& point)
        : light_(light), point_(point), normal_(glm::normalize(glm::cross(light.edgeA, light.edgeB))) {}

    RectangleLight light_;
    Vec3 point_;
    Vec3 normal_;
};

}  // namespace asos
