#include "asos/geometry/polytope.hpp"

#include <cmath>

namespace asos {

std::optional<std::vector<Vec3>> polytopeVertices(std::span<const HalfSpace> halfSpaces, const Bounds3& box) {
    if (halfSpaces.size() > kMaxPolytopeHalfSpaces || box.empty()) return std::nullopt;
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(box.lo[axis]) || !std::isfinite(box.hi[axis])) return std::nullopt;
    // The planes, each unit, the box's six first.
    std::vector<HalfSpace> planes;
    planes.reserve(halfSpaces.size() + 6);
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 n(0.0);
        n[axis] = 1.0;
        planes.push_back({n, box.hi[axis]});
        planes.push_back({-n, -box.lo[axis]});
    }
    for (const HalfSpace& h : halfSpaces) {
        const double length = glm::length(h.normal);
        if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(h.offset)) return std::nullopt;
        planes.push_back({h.normal / length, h.offset / length});
    }
    const Vec3 diagonal = box.diagonal();
    const double size = std::max({diagonal.x, diagonal.y, diagonal.z, 1e-300});
    const double scale = size + glm::length(box.center());
    const double tolerance = 1e-9 * scale;
    std::vector<Vec3> vertices;
    const std::size_t n = planes.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const Vec3 ij = glm::cross(planes[i].normal, planes[j].normal);
            for (std::size_t k = j + 1; k < n; ++k) {
                // Cramer's rule for the point on the three planes.
                const double det = glm::dot(ij, planes[k].normal);
                if (std::abs(det) < 1e-12) continue;
                const Vec3 p = (planes[i].offset * glm::cross(planes[j].normal, planes[k].normal) +
                                planes[j].offset * glm::cross(planes[k].normal, planes[i].normal) +
                                planes[k].offset * ij) /
                               det;
                bool held = true;
                for (std::size_t m = 0; m < n && held; ++m)
                    held = glm::dot(planes[m].normal, p) <= planes[m].offset + tolerance;
                if (held) vertices.push_back(p);
            }
        }
    return vertices;
}

}  // namespace asos
