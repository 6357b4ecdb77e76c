#include "asos/lights/rectangle_light.hpp"

namespace asos {

bool RectangleLight::beamHolds(const Vec3& apex, const Vec3& p) const {
    const Vec3 d = p - apex;
    const Vec3 n = glm::cross(edgeA, edgeB);
    const double along = glm::dot(d, n);
    if (along == 0.0) return false;
    const double t = glm::dot(corner - apex, n) / along;
    if (!(t > 0.0)) return false;
    const Vec3 rel = apex + t * d - corner;
    const double nn = glm::dot(n, n);
    const double s = glm::dot(glm::cross(rel, edgeB), n) / nn;
    const double u = glm::dot(glm::cross(edgeA, rel), n) / nn;
    return s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0;
}

std::optional<RectangleLight::Beam> RectangleLight::beamFrom(const Vec3& apex, double tMin) const {
    Beam b;
    b.light_ = *this;
    b.apex_ = {apex, tMin};
    const Vec3 n = glm::cross(edgeA, edgeB);
    const double area = glm::length(n);
    if (!(area > 0.0)) return std::nullopt;
    b.normal_ = n / area;
    const Vec3 rel = apex - corner;
    b.height_ = std::abs(glm::dot(rel, b.normal_));
    // Below rounding, the apex is in the plane (as RectShadowPyray decides).
    const double scale = glm::length(edgeA) + glm::length(edgeB) + glm::length(rel);
    if (!(b.height_ > kThousandsOfUlps * scale)) return std::nullopt;
    // Rectangular to rounding.
    b.rectangular_ =
        std::abs(glm::dot(edgeA, edgeB)) <= kThousandsOfUlps * glm::length(edgeA) * glm::length(edgeB);
    b.footS_ = glm::dot(rel, edgeA) / glm::dot(edgeA, edgeA);
    b.footT_ = glm::dot(rel, edgeB) / glm::dot(edgeB, edgeB);
    return b;
}

std::optional<RectangleLight::GridPoints> RectangleLight::gridFrom(const Vec3& point) const {
    return GridPoints(*this, point);
}

LightPiece RectangleLight::Beam::root() const {
    LightPiece p{0.0, 0.0, 1.0, 1.0, 0, 0, {}, {}};
    p.central = apex_.toward(point(0.5, 0.5));
    const Vec3 dirs[4] = {point(0.0, 0.0) - apex_.point, point(1.0, 0.0) - apex_.point,
                          point(1.0, 1.0) - apex_.point, point(0.0, 1.0) - apex_.point};
    double farthest2 = 0.0;
    for (const Vec3& d : dirs) farthest2 = std::max(farthest2, glm::dot(d, d));
    const PieceCone c = apex_.coneAbout(p.central.ray.dir, dirs, 4, std::sqrt(farthest2));
    p.cone = c.cone;
    p.tanHalf = c.tanHalf;
    return p;
}

int RectangleLight::Beam::split(const LightPiece& p, LightPiece* out, bool cones) const {
    // The quarters share the nine points of a 3 x 3 lattice over the piece:
    // each is made once (unnormalised: coneAbout needs no unit directions).
    const double s[3] = {p.a0, 0.5 * (p.a0 + p.a1), p.a1};
    const double t[3] = {p.b0, 0.5 * (p.b0 + p.b1), p.b1};
    Vec3 dirs[3][3];
    double lengths2[3][3];
    if (cones)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                dirs[j][i] = point(s[i], t[j]) - apex_.point;
                lengths2[j][i] = glm::dot(dirs[j][i], dirs[j][i]);
            }
    for (int q = 0; q < 4; ++q) {
        const int i = q & 1, j = q >> 1;
        LightPiece& c = out[q];
        c = LightPiece{s[i], t[j], s[i + 1], t[j + 1], p.level + 1, 4 * p.path + std::uint64_t(q), {}, {}};
        c.central = apex_.toward(point(0.5 * (s[i] + s[i + 1]), 0.5 * (t[j] + t[j + 1])));
        if (!cones) continue;
        const Vec3 corners[4] = {dirs[j][i], dirs[j][i + 1], dirs[j + 1][i + 1], dirs[j + 1][i]};
        const double farthest2 = std::max(std::max(lengths2[j][i], lengths2[j][i + 1]),
                                          std::max(lengths2[j + 1][i + 1], lengths2[j + 1][i]));
        const PieceCone cone = apex_.coneAbout(c.central.ray.dir, corners, 4, std::sqrt(farthest2));
        c.cone = cone.cone;
        c.tanHalf = cone.tanHalf;
    }
    return kChildren;
}

BeamRay RectangleLight::Beam::sample(const LightPiece& p, const Vec2& xi) const {
    return apex_.toward(point(p.a0 + xi.x * (p.a1 - p.a0), p.b0 + xi.y * (p.b1 - p.b0)));
}

std::optional<BeamHull> RectangleLight::Beam::hull(double endGap) const {
    const Vec3 corners[4] = {point(0.0, 0.0), point(1.0, 0.0), point(1.0, 1.0), point(0.0, 1.0)};
    double farthest2 = 0.0;
    for (const Vec3& c : corners) farthest2 = std::max(farthest2, glm::dot(c - apex_.point, c - apex_.point));
    return BeamHull::over(apex_.point, corners, 4, padUp(std::sqrt(farthest2)), endGap);
}

double RectangleLight::Beam::nearestLightDistance(const LightPiece& p) const {
    if (!rectangular_) return height_;
    const Vec3 nearest = point(std::clamp(footS_, p.a0, p.a1), std::clamp(footT_, p.b0, p.b1));
    return std::max(height_, padDown(glm::length(nearest - apex_.point)));
}

int RectangleLight::Beam::probeRays(const LightPiece& p, BeamRay* out) const {
    const double sm = 0.5 * (p.a0 + p.a1), tm = 0.5 * (p.b0 + p.b1);
    out[0] = apex_.toward(point(p.a0, tm));
    out[1] = apex_.toward(point(p.a1, tm));
    out[2] = apex_.toward(point(sm, p.b0));
    out[3] = apex_.toward(point(sm, p.b1));
    return 4;
}

}  // namespace asos
