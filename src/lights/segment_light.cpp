#include "asos/lights/segment_light.hpp"

namespace asos {

bool SegmentLight::beamHolds(const Vec3& apex, const Vec3& p) const {
    const Vec3 d = p - apex;
    const Vec3 a = start - apex, b = end - apex;
    const Vec3 normal = glm::cross(a, b);
    const double area = glm::length(normal);
    if (!(area > 0.0)) return false;
    const Vec3 unit = normal / area;
    const Vec3 q = d - glm::dot(d, unit) * unit;
    return glm::dot(glm::cross(a, q), unit) >= 0.0 && glm::dot(glm::cross(q, b), unit) >= 0.0 &&
           glm::dot(q, a + b) > 0.0;
}

std::optional<SegmentLight::Beam> SegmentLight::beamFrom(const Vec3& apex, double tMin) const {
    Beam b;
    b.apex_ = {apex, tMin};
    b.corner_ = start;
    b.edgeA_ = end - start;
    const double edge = glm::length(b.edgeA_);
    if (!(edge > 0.0)) return std::nullopt;
    const double f = std::clamp(glm::dot(apex - start, b.edgeA_) / (edge * edge), 0.0, 1.0);
    const double offLine = glm::length(apex - (start + f * b.edgeA_));
    // On the line to rounding: no beam.
    if (!(offLine > kThousandsOfUlps * (edge + glm::length(apex - start)))) return std::nullopt;
    b.footS_ = glm::dot(apex - start, b.edgeA_) / (edge * edge);
    return b;
}

std::optional<SegmentLight::GridPoints> SegmentLight::gridFrom(const Vec3& point) const {
    return GridPoints(*this, point);
}

LightPiece SegmentLight::Beam::make(double a0, double a1, int level, std::uint64_t path, bool cone) const {
    LightPiece p{a0, 0.0, a1, 1.0, level, path, {}, {}};
    p.central = apex_.toward(corner_ + 0.5 * (a0 + a1) * edgeA_);
    if (!cone) return p;
    const Vec3 d0 = corner_ + a0 * edgeA_ - apex_.point, d1 = corner_ + a1 * edgeA_ - apex_.point;
    const double l0 = glm::length(d0), l1 = glm::length(d1);
    const Vec3 u = d0 / l0, v = d1 / l1;
    const Vec3 sum = u + v;
    const double sumLength = glm::length(sum);
    p.tanHalf = glm::length(u - v) / sumLength;
    p.cone = {apex_.point, sum / sumLength, std::atan(p.tanHalf) + kConeAnglePad, apex_.tMin,
              padUp(std::max(l0, l1))};
    return p;
}

}  // namespace asos
