#pragma once
// A spherical light (paper: "Spherical Light Sources", Figure 5b): a sphere
// of `radius` about `centre` (`area_light` with `circular orient`: POV-Ray's
// disc that always faces the point, here the sphere of its diameter). As
// every light form (lights/light_form.hpp) it answers:
//   - its beam from a point: the cone tangent to the sphere, split into four
//     pieces of equal area of its apparent disc (the concentric images of a
//     square cell's quarters, geometry/concentric_disc.hpp), each bounded by
//     the cone about its central ray through the corners of the polar
//     rectangle that holds it (docs/accel.md, "Sphere pieces") and carrying
//     4^-level of the light;
//   - its grid's points seen from a point (render/grid_light.hpp): the
//     images of the grid's cells' centres, so that a piece's central ray at
//     level K is the point of the 2^K x 2^K grid, bit for bit;
//   - its emitted radiance: intensity colour / (pi r^2), the same along every
//     direction (a disc facing the point sends it the light's colour).
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/geometry/tangent_cone.hpp"
#include "asos/lights/beam_apex.hpp"
#include "asos/lights/disc_piece_table.hpp"
#include "asos/lights/light_lattice.hpp"
#include "asos/lights/light_piece.hpp"

namespace asos {

struct SphereLight {
    static constexpr const char* kName = "spherical";

    Vec3 centre{0.0};
    double radius = 1.0;

    // The area of the disc of its radius (the paper's A in I A).
    double size() const { return kPi * radius * radius; }
    double halfWidth() const { return radius; }
    Bounds3 bounds() const {
        Bounds3 b = Bounds3::of(centre - Vec3(radius));
        b.extend(centre + Vec3(radius));
        return b;
    }
    // The tangent cone from the apex holds p.
    bool beamHolds(const Vec3& apex, const Vec3& p) const;
    // None, and no grid, where the point lies on or inside the sphere.
    class Beam;
    std::optional<Beam> beamFrom(const Vec3& apex, double tMin) const;
    class GridPoints;
    std::optional<GridPoints> gridFrom(const Vec3& point) const;
};

// The answers of an AreaLightBeam (lights/light_form.hpp) for a sphere.
class SphereLight::Beam {
public:
    static constexpr int kChildren = 4;  // equal-area pieces
    // Not for the equal-area pieces: their central rays are not placed
    // symmetrically about their parent's.
    static constexpr bool kSingleEdgeHalving = false;

    LightPiece root() const;  // the tangent cone
    // The layout of the first levels does not depend on the apex: they come
    // from discPieceTable().
    int split(const LightPiece& piece, LightPiece* out, bool cones = true) const;
    // Made from the table where its levels reach.
    template <class F>
    void forEachDescendant(const LightPiece& piece, int depth, F&& f) const {
        const DiscPieceTable& table = discPieceTable();
        if (depth > 0 && table.children(piece.level + depth - 1, 0)) {
            descend(table, piece.level, piece.path, depth, f);
            return;
        }
        if (depth == 0) {
            f(piece);
            return;
        }
        LightPiece children[kChildren];
        const int count = split(piece, children, false);
        for (int i = 0; i < count; ++i) forEachDescendant(children[i], depth - 1, f);
    }
    // No lattice: the pieces' central points are no affine image of a grid.
    std::optional<LightLattice> lattice(const LightPiece&, int) const { return std::nullopt; }

    // Uniform over its area of the apparent disc.
    BeamRay sample(const LightPiece& piece, const Vec2& xi) const {
        return tangent_.ray(apex_.point,
                            concentricDisc(piece.a0 + xi.x * (piece.a1 - piece.a0), piece.b0 + xi.y * (piece.b1 - piece.b0)));
    }
    // The rays end on the sphere's near side, the cap inside the tangent
    // circle, within the tangent length of the apex: the pyramid over the
    // square about that circle holds them.
    std::optional<BeamHull> hull(double endGap) const;
    double share(int level) const { return exactShare(2 * level); }  // 4^-level
    double nearestLightDistance(const LightPiece& piece) const {
        const double r = innerRadius(DiscCell{piece.a0, piece.a1, piece.b0, piece.b1});
        return padDown(tangent_.distanceAtRadius(r, -1.0));
    }
    // Toward the images of its cell's edges' midpoints (for the whole disc,
    // opposite points of its rim): 4.
    int probeRays(const LightPiece& piece, BeamRay* out) const;
    // Over the pieces in their equal-area coordinates; over the whole disc.
    std::pair<double, double> ruleWeights(const LightPiece& piece) const {
        return piece.level == 0 ? std::pair{0.5, 0.125} : std::pair{1.0 / 3.0, 1.0 / 6.0};
    }
    // The tracer finds it from the piece's rays.
    HorizonSide horizonSide(const LightPiece&, const Vec3&) const { return HorizonSide::Unknown; }
    double emission(const Vec3&) const { return 1.0; }  // the same every way

private:
    friend struct SphereLight;
    Beam() = default;

    // Pieces whose layouts are all in the table: made from it.
    template <class F>
    void descend(const DiscPieceTable& table, int level, std::uint64_t path, int depth, F& f) const {
        const DiscPieceTable::Piece* d = table.children(level, path);
        for (int q = 0; q < 4; ++q) {
            const std::uint64_t child = 4 * path + std::uint64_t(q);
            if (depth == 1) {
                const LightPiece piece = makePiece(d[q], level + 1, child, false);
                f(piece);
            } else {
                descend(table, level + 1, child, depth - 1, f);
            }
        }
    }
    LightPiece makePiece(const DiscPieceTable::Piece& d, int level, std::uint64_t path, bool cone) const;
    // The offset (not normalised) through the disc's point of radius r at
    // the angle of t.
    Vec3 discOffset(double r, const DiscPieceTable::Trig& t) const;

    BeamApex apex_;
    double alpha_ = 0.0;  // the tangent cone's half-angle
    TangentCone tangent_;
};

// The answers of AreaLightGridPoints (lights/light_form.hpp) for a sphere.
class SphereLight::GridPoints {
public:
    // Through the image of (s, t) on the apparent disc, to the sphere's near side.
    BeamRay toward(double s, double t) const { return tangent_.ray(point_, concentricDisc(s, t)); }
    double emission(const Vec3&) const { return 1.0; }

private:
    friend struct SphereLight;
    GridPoints(const TangentCone& tangent, const Vec3& point) : tangent_(tangent), point_(point) {}

    TangentCone tangent_;
    Vec3 point_;
};

}  // namespace asos
