#include "asos/render/camera.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "asos/geometry/margins.hpp"

namespace asos {

CameraModel::CameraModel(const Camera& camera, int width, int height)
    : location_(camera.location),
      direction_(camera.direction),
      right_(camera.right),
      up_(camera.up),
      orthographic_(camera.projection == Camera::Projection::Orthographic),
      width_(width),
      height_(height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is not positive");
    const Mat3 basis(right_, up_, direction_);
    // Scale-free test for a degenerate frame: |det| against the product of the
    // lengths is the sine-like volume of the three unit vectors.
    const double lengths = glm::length(right_) * glm::length(up_) * glm::length(direction_);
    const double det = glm::determinant(basis);
    if (!(lengths > 0.0) || !std::isfinite(det) || std::abs(det) <= kThousandsOfUlps * lengths)
        throw std::invalid_argument(
            "camera direction, right and up vectors do not span space (one is zero or "
            "they are coplanar)");
    basisInverse_ = glm::inverse(basis);
    unitDirection_ = glm::normalize(direction_);
    invWidth_ = 1.0 / width;
    invHeight_ = 1.0 / height;
}

std::optional<Vec2> CameraModel::project(const Vec3& p) const {
    // p - location = a right + b up + c direction.
    const Vec3 abc = basisInverse_ * (p - location_);
    double u, v;
    if (orthographic_) {
        if (abc.z < 0.0) return std::nullopt;
        u = abc.x;
        v = abc.y;
    } else {
        if (!(abc.z > 0.0)) return std::nullopt;
        u = abc.x / abc.z;
        v = abc.y / abc.z;
    }
    return Vec2((u + 0.5) * width_, (0.5 - v) * height_);
}

}  // namespace asos
