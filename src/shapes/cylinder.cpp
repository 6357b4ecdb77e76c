#include "asos/shapes/cylinder.hpp"

#include <cmath>

namespace asos {

std::optional<LocalHit> Cylinder::intersect(const Ray& ray, double tMin, double tMax) const {
    if (!(radius_ > 0.0)) return std::nullopt;
    const Vec3& d = ray.dir;
    // Solve from the point of the line nearest the middle of the axis: well
    // conditioned however far the ray starts.
    const double shift = glm::dot(Vec3(0.0, 0.0, 0.5 * length_) - ray.origin, d) / glm::dot(d, d);
    const Vec3 o = ray.origin + shift * d;
    // The side's interval: |o + t d|^2 <= R^2 in the xy-plane, discriminant
    // from the closest approach.
    double sideLo = -kInfinity, sideHi = kInfinity;
    const double a = d.x * d.x + d.y * d.y;
    const double c = o.x * o.x + o.y * o.y - radius_ * radius_;
    if (a > 0.0) {
        const double b = o.x * d.x + o.y * d.y;
        const double fx = o.x - (b / a) * d.x, fy = o.y - (b / a) * d.y;
        const double disc = a * (radius_ * radius_ - (fx * fx + fy * fy));
        if (disc < 0.0) return std::nullopt;
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        sideLo = q / a;
        sideHi = q != 0.0 ? c / q : sideLo;
        if (sideLo > sideHi) std::swap(sideLo, sideHi);
    } else if (c > 0.0) {
        return std::nullopt;
    }
    double t;
    int part;  // 0 side, 1 base cap, 2 top cap
    if (open_) {
        // The side alone, between the rims.
        t = kInfinity;
        part = 0;
        for (const double r : {sideLo, sideHi}) {
            const double z = o.z + r * d.z;
            if (std::isfinite(r) && z >= 0.0 && z <= length_ && shift + r >= tMin &&
                shift + r <= tMax && shift + r < t)
                t = shift + r;
        }
        if (t == kInfinity) return std::nullopt;
    } else {
        // The solid's interval: the side's and the slab's together, which
        // leaves no crack at the rims.
        double lo = sideLo, hi = sideHi;
        int loPart = 0, hiPart = 0;
        if (d.z == 0.0) {
            if (o.z < 0.0 || o.z > length_) return std::nullopt;
        } else {
            double z0 = -o.z / d.z, z1 = (length_ - o.z) / d.z;
            int p0 = 1, p1 = 2;
            if (z0 > z1) {
                std::swap(z0, z1);
                std::swap(p0, p1);
            }
            if (z0 > lo) {
                lo = z0;
                loPart = p0;
            }
            if (z1 < hi) {
                hi = z1;
                hiPart = p1;
            }
        }
        if (!(lo <= hi)) return std::nullopt;
        if (shift + lo >= tMin && shift + lo <= tMax) {
            t = shift + lo;
            part = loPart;
        } else if (shift + hi >= tMin && shift + hi <= tMax) {
            t = shift + hi;
            part = hiPart;
        } else {
            return std::nullopt;
        }
    }
    Vec3 point = ray.at(t);
    if (part == 0) return LocalHit{t, point, Vec3(point.x, point.y, 0.0)};
    point.z = part == 1 ? 0.0 : length_;
    return LocalHit{t, point, Vec3(0.0, 0.0, part == 1 ? -1.0 : 1.0), static_cast<std::uint8_t>(part)};
}

std::vector<ShapeIssue> validate(const CylinderShape& record) {
    IssueList issues;
    const bool baseFinite = issues.finite(0, record.base, "the base point of a cylinder");
    const bool capFinite = issues.finite(1, record.cap, "the cap point of a cylinder");
    issues.positive(2, record.radius, "the radius of a cylinder");
    if (baseFinite && capFinite && !frustumAxis(record.base, record.cap))
        issues.add(1, "the base and cap points of a cylinder are the same point");
    return issues.take();
}

Placed<Cylinder> place(const CylinderShape& record, const Transform& worldFromObject) {
    const FrustumAxis axis = *frustumAxis(record.base, record.cap);
    return {Cylinder(record.radius, axis.length, record.open),
            LocalFrame::make(worldFromObject, axis.objectFromLocal, record.base), Cylinder::kName};
}

}  // namespace asos
