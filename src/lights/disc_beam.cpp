#include "asos/lights/disc_beam.hpp"

#include "asos/geometry/facing_disc.hpp"
#include "asos/geometry/tangent_cone.hpp"

namespace asos {

template <class Geometry, DiscMap Map>
LightPiece DiscBeam<Geometry, Map>::root() const {
    LightPiece p{0.0, 0.0, 1.0, 1.0, 0, 0, {}, {}};
    p.central = disc_.ray(apex_.point, 0.0, 0.0, 0.0, 1.0);
    p.cone = {apex_.point, disc_.frame.w, alpha_ + kConeAnglePad, apex_.tMin,
              padUp(disc_.distanceAtRadius(1.0, 1.0))};
    return p;
}

template <class Geometry, DiscMap Map>
std::optional<BeamHull> DiscBeam<Geometry, Map>::hull(double endGap) const {
    const EndCircle e = disc_.endCircle();
    const Frame& f = disc_.frame;
    const Vec3 centre = apex_.point + e.distance * f.w;
    const double rim = padUp(e.radius);
    const Vec3 square[4] = {centre + rim * (f.u + f.v), centre + rim * (f.v - f.u), centre - rim * (f.u + f.v),
                            centre + rim * (f.u - f.v)};
    return BeamHull::over(apex_.point, square, 4, padUp(e.reach), endGap);
}

template <class Geometry, DiscMap Map>
Vec3 DiscBeam<Geometry, Map>::discOffset(double r, const DiscPieceTable::Trig& t) const {
    const double k = disc_.tanAlpha * r;
    return disc_.frame.toWorld(k * t.c, k * t.s, 1.0);
}

template <class Geometry, DiscMap Map>
LightPiece DiscBeam<Geometry, Map>::makePiece(const DiscPieceTable::Piece& d, int level, std::uint64_t path,
                                              bool cone) const {
    LightPiece p{d.cell.s0, d.cell.t0, d.cell.s1, d.cell.t1, level, path, {}, {}};
    p.central = disc_.ray(apex_.point, d.centre.x, d.centre.y, d.rho2, d.rim);
    if (!cone) return p;
    // Unnormalised: coneAbout needs no unit directions.
    const Vec3 corners[4] = {discOffset(d.r0, d.at0), discOffset(d.r0, d.at1), discOffset(d.r1, d.at0),
                             discOffset(d.r1, d.at1)};
    const PieceCone c = apex_.coneAbout(p.central.ray.dir, corners, 4, disc_.distanceAtRadius(d.r1, 1.0));
    p.cone = c.cone;
    p.tanHalf = c.tanHalf;
    return p;
}

template <class Geometry, DiscMap Map>
int DiscBeam<Geometry, Map>::split(const LightPiece& p, LightPiece* out, bool cones) const {
    const int level = p.level + 1;
    if (const DiscPieceTable::Piece* d = discPieceTable(Map).children(p.level, p.path)) {
        for (int q = 0; q < 4; ++q) out[q] = makePiece(d[q], level, 4 * p.path + std::uint64_t(q), cones);
        return kChildren;
    }
    // Deeper: the cell's quarters, as in the table.
    const double s[3] = {p.a0, 0.5 * (p.a0 + p.a1), p.a1}, t[3] = {p.b0, 0.5 * (p.b0 + p.b1), p.b1};
    for (int q = 0; q < 4; ++q) {
        const int i = q & 1, j = q >> 1;
        out[q] = makePiece(DiscPieceTable::piece(DiscCell{s[i], s[i + 1], t[j], t[j + 1]}, Map), level,
                           4 * p.path + std::uint64_t(q), cones);
    }
    return kChildren;
}

template <class Geometry, DiscMap Map>
int DiscBeam<Geometry, Map>::probeRays(const LightPiece& p, BeamRay* out) const {
    if (p.level == 0) {
        // Opposite points of the rim: angles 0 and pi, pi/2 and 3 pi/2.
        for (int i = 0; i < 4; ++i) {
            const double phi = 0.5 * kPi * ((i & 1) * 2 + (i >> 1));
            out[i] = disc_.ray(apex_.point, Vec2(std::cos(phi), std::sin(phi)));
        }
        return 4;
    }
    // The images of the cell's edges' midpoints.
    const double sm = 0.5 * (p.a0 + p.a1), tm = 0.5 * (p.b0 + p.b1);
    out[0] = disc_.ray(apex_.point, discPoint(Map, p.a0, tm));
    out[1] = disc_.ray(apex_.point, discPoint(Map, p.a1, tm));
    out[2] = disc_.ray(apex_.point, discPoint(Map, sm, p.b0));
    out[3] = disc_.ray(apex_.point, discPoint(Map, sm, p.b1));
    return 4;
}

// The two disc lights: the sphere's apparent disc, POV-Ray's oriented disc.
template class DiscBeam<TangentCone, DiscMap::Concentric>;
template class DiscBeam<FacingDisc, DiscMap::Povray>;

}  // namespace asos
