#include "asos/lights/sphere_light.hpp"

namespace asos {

namespace {

// Whether `point` lies outside the sphere, past rounding: only then does it
// see a tangent cone.
bool outside(const SphereLight& light, const Vec3& point) {
    return light.radius > 0.0 && glm::length(light.centre - point) > padUp(light.radius);
}

}  // namespace

bool SphereLight::beamHolds(const Vec3& apex, const Vec3& p) const {
    const Vec3 d = p - apex;
    const Vec3 toCentre = centre - apex;
    const double distance = glm::length(toCentre);
    if (!(distance > radius)) return false;
    return angleBetween(d, toCentre) <= std::asin(radius / distance);
}

std::optional<SphereLight::Beam> SphereLight::beamFrom(const Vec3& apex, double tMin) const {
    if (!outside(*this, apex)) return std::nullopt;
    Beam b;
    b.apex_ = {apex, tMin};
    b.tangent_ = TangentCone::make(apex, centre, radius);
    b.alpha_ = std::asin(b.tangent_.sinAlpha);
    return b;
}

std::optional<SphereLight::GridPoints> SphereLight::gridFrom(const Vec3& point) const {
    if (!outside(*this, point)) return std::nullopt;
    return GridPoints(TangentCone::make(point, centre, radius), point);
}

LightPiece SphereLight::Beam::root() const {
    LightPiece p{0.0, 0.0, 1.0, 1.0, 0, 0, {}, {}};
    p.central = tangent_.ray(apex_.point, 0.0, 0.0, 0.0, 1.0);
    p.cone = {apex_.point, tangent_.frame.w, alpha_ + kConeAnglePad, apex_.tMin,
              padUp(tangent_.distanceAtRadius(1.0, 1.0))};
    return p;
}

std::optional<BeamHull> SphereLight::Beam::hull(double endGap) const {
    // The tangent circle: at d cos^2 alpha along the axis, of radius
    // d cos alpha sin alpha, padded against rounding.
    const TangentCone& c = tangent_;
    const double cosAlpha = std::sqrt(c.cos2Alpha);
    const Vec3 centre = apex_.point + c.distance * c.cos2Alpha * c.frame.w;
    const double rim = padUp(c.distance * cosAlpha * c.sinAlpha);
    const Vec3 square[4] = {centre + rim * (c.frame.u + c.frame.v), centre + rim * (c.frame.v - c.frame.u),
                            centre - rim * (c.frame.u + c.frame.v), centre + rim * (c.frame.u - c.frame.v)};
    return BeamHull::over(apex_.point, square, 4, padUp(c.distance * cosAlpha), endGap);
}

Vec3 SphereLight::Beam::discOffset(double r, const DiscPieceTable::Trig& t) const {
    const double k = tangent_.tanAlpha * r;
    return tangent_.frame.toWorld(k * t.c, k * t.s, 1.0);
}

LightPiece SphereLight::Beam::makePiece(const DiscPieceTable::Piece& d, int level, std::uint64_t path,
                                        bool cone) const {
    LightPiece p{d.cell.s0, d.cell.t0, d.cell.s1, d.cell.t1, level, path, {}, {}};
    p.central = tangent_.ray(apex_.point, d.centre.x, d.centre.y, d.rho2, d.rim);
    if (!cone) return p;
    // Unnormalised: coneAbout needs no unit directions.
    const Vec3 corners[4] = {discOffset(d.r0, d.at0), discOffset(d.r0, d.at1), discOffset(d.r1, d.at0),
                             discOffset(d.r1, d.at1)};
    const PieceCone c = apex_.coneAbout(p.central.ray.dir, corners, 4, tangent_.distanceAtRadius(d.r1, 1.0));
    p.cone = c.cone;
    p.tanHalf = c.tanHalf;
    return p;
}

int SphereLight::Beam::split(const LightPiece& p, LightPiece* out, bool cones) const {
    const int level = p.level + 1;
    if (const DiscPieceTable::Piece* d = discPieceTable().children(p.level, p.path)) {
        for (int q = 0; q < 4; ++q) out[q] = makePiece(d[q], level, 4 * p.path + std::uint64_t(q), cones);
        return kChildren;
    }
    // Deeper: the cell's quarters, as in the table.
    const double s[3] = {p.a0, 0.5 * (p.a0 + p.a1), p.a1}, t[3] = {p.b0, 0.5 * (p.b0 + p.b1), p.b1};
    for (int q = 0; q < 4; ++q) {
        const int i = q & 1, j = q >> 1;
        out[q] = makePiece(DiscPieceTable::piece(DiscCell{s[i], s[i + 1], t[j], t[j + 1]}), level,
                           4 * p.path + std::uint64_t(q), cones);
    }
    return kChildren;
}

int SphereLight::Beam::probeRays(const LightPiece& p, BeamRay* out) const {
    if (p.level == 0) {
        // Opposite points of the rim: angles 0 and pi, pi/2 and 3 pi/2.
        for (int i = 0; i < 4; ++i) {
            const double phi = 0.5 * kPi * ((i & 1) * 2 + (i >> 1));
            out[i] = tangent_.ray(apex_.point, Vec2(std::cos(phi), std::sin(phi)));
        }
        return 4;
    }
    // The images of the cell's edges' midpoints.
    const double sm = 0.5 * (p.a0 + p.a1), tm = 0.5 * (p.b0 + p.b1);
    out[0] = tangent_.ray(apex_.point, concentricDisc(p.a0, tm));
    out[1] = tangent_.ray(apex_.point, concentricDisc(p.a1, tm));
    out[2] = tangent_.ray(apex_.point, concentricDisc(sm, p.b0));
    out[3] = tangent_.ray(apex_.point, concentricDisc(sm, p.b1));
    return 4;
}

}  // namespace asos
