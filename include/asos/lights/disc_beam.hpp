#pragma once
// The beam of a disc light from a point (lights/light_form.hpp,
// AreaLightBeam): a sphere's apparent disc (the tangent cone,
// geometry/tangent_cone.hpp, cut by the equal-area concentric map) or
// POV-Ray's oriented disc (geometry/facing_disc.hpp, cut by POV-Ray's map).
// Both are a disc perpendicular to the line from the point to the light's
// centre, seen through the unit disc's points (x, y): the pieces are the
// images of the unit square's quadtree cells under the map
// (geometry/concentric_disc.hpp), each bounded by the cone about its central
// ray through the corners of the polar rectangle that holds it
// (docs/accel.md, "Sphere pieces"), and each carrying 4^-level of the light.
// `Geometry` answers frame, tanAlpha, halfAngle(), ray(),
// distanceAtRadius() and endCircle() as TangentCone does.
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/lights/beam_apex.hpp"
#include "asos/lights/disc_piece_table.hpp"
#include "asos/lights/light_lattice.hpp"
#include "asos/lights/light_piece.hpp"

namespace asos {

template <class Geometry, DiscMap Map>
class DiscBeam {
public:
    static constexpr int kChildren = 4;  // pieces of equal share
    // Not for these pieces: their central rays are not placed symmetrically
    // about their parent's.
    static constexpr bool kSingleEdgeHalving = false;

    // The beam from `apex` (rays from tMin on) through `disc`.
    static DiscBeam make(const Vec3& apex, double tMin, const Geometry& disc) {
        DiscBeam b;
        b.apex_ = {apex, tMin};
        b.disc_ = disc;
        b.alpha_ = disc.halfAngle();
        return b;
    }

    LightPiece root() const;  // the whole disc
    // The layout of the first levels does not depend on the apex: they come
    // from discPieceTable().
    int split(const LightPiece& piece, LightPiece* out, bool cones = true) const;
    // Made from the table where its levels reach.
    template <class F>
    void forEachDescendant(const LightPiece& piece, int depth, F&& f) const {
        const DiscPieceTable& table = discPieceTable(Map);
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

    // Uniform over the piece's cell of the square (so, by the map, over its
    // share of the disc).
    BeamRay sample(const LightPiece& piece, const Vec2& xi) const {
        return disc_.ray(apex_.point, discPoint(Map, piece.a0 + xi.x * (piece.a1 - piece.a0),
                                                piece.b0 + xi.y * (piece.b1 - piece.b0)));
    }
    // The rays end at the disc (a sphere's near cap, inside its tangent
    // circle; POV-Ray's flat disc), within the geometry's ray length of the
    // apex: the pyramid over the square about the disc's bounding circle
    // holds them.
    std::optional<BeamHull> hull(double endGap) const;
    double share(int level) const { return exactShare(2 * level); }  // 4^-level
    double nearestLightDistance(const LightPiece& piece) const {
        const double r = innerRadius(DiscCell{piece.a0, piece.a1, piece.b0, piece.b1});
        return padDown(disc_.distanceAtRadius(r, -1.0));
    }
    // Toward the images of its cell's edges' midpoints (for the whole disc,
    // opposite points of its rim): 4.
    int probeRays(const LightPiece& piece, BeamRay* out) const;
    // Over the pieces in their map's coordinates; over the whole disc.
    std::pair<double, double> ruleWeights(const LightPiece& piece) const {
        return piece.level == 0 ? std::pair{0.5, 0.125} : std::pair{1.0 / 3.0, 1.0 / 6.0};
    }
    // The tracer finds it from the piece's rays.
    HorizonSide horizonSide(const LightPiece&, const Vec3&) const { return HorizonSide::Unknown; }
    double emission(const Vec3&) const { return 1.0; }  // the same every way

private:
    DiscBeam() = default;

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
    double alpha_ = 0.0;  // the angle from the axis to the disc's rim
    Geometry disc_;
};

}  // namespace asos
