#include "asos/render/pattern_footprint.hpp"

#include <cmath>

namespace asos {

std::optional<PatternFootprint> PatternFootprint::make(const CameraModel& camera,
                                                       const ImageSquare& square, const Vec3& point,
                                                       const Vec3& normal,
                                                       const Mat4& patternFromWorld) {
    // CameraModel::ray: u = x / width - 1/2, v = 1/2 - y / height, so the
    // image-plane offset o + u right + v up is affine in (x, y).
    const Vec3 dx = camera.right() / double(camera.width());
    const Vec3 dy = -camera.up() / double(camera.height());
    const Vec3 half = 0.5 * (camera.up() - camera.right());
    Vec4 a, b, c;  // the world point's homogeneous coordinates
    if (camera.orthographic()) {
        // Rays from o(x, y) = location + offset along the fixed direction w
        // meet the plane at o + w n.(point - o) / n.w: affine in (x, y).
        const Vec3 w = glm::normalize(camera.direction());
        const double nw = glm::dot(normal, w);
        if (nw == 0.0) return std::nullopt;
        const Vec3 o0 = camera.location() + half;
        a = Vec4(o0 + w * (glm::dot(normal, point - o0) / nw), 1.0);
        b = Vec4(dx - w * (glm::dot(normal, dx) / nw), 0.0);
        c = Vec4(dy - w * (glm::dot(normal, dy) / nw), 0.0);
    } else {
        // Rays from the eye E along d(x, y) = direction + offset meet the
        // plane at E + d / D with D = n.d / n.(point - E), affine in (x, y):
        // the homogeneous point is (E D + d, D), in front where D > 0.
        const Vec3& eye = camera.location();
        const double reach = glm::dot(normal, point - eye);
        if (reach == 0.0 || !std::isfinite(reach)) return std::nullopt;
        const Vec3 d0 = camera.direction() + half;
        auto homogeneous = [&](const Vec3& d, const Vec3& origin) {
            const double depth = glm::dot(normal, d) / reach;
            return Vec4(origin * depth + d, depth);
        };
        a = homogeneous(d0, eye);
        b = homogeneous(dx, eye);
        c = homogeneous(dy, eye);
    }
    const PatternFootprint f(square, patternFromWorld * a, patternFromWorld * b, patternFromWorld * c);
    const double us[2] = {square.u0, square.u1}, vs[2] = {square.v0, square.v1};
    for (double u : us)
        for (double v : vs) {
            const Vec4 h = f.homogeneous(u, v);
            if (!(h.w > 0.0) || !std::isfinite(h.x / h.w) || !std::isfinite(h.y / h.w) ||
                !std::isfinite(h.z / h.w))
                return std::nullopt;
        }
    return f;
}

}  // namespace asos
