#pragma once
// The map from image coordinates to world rays, exactly as POV-Ray 3.7 makes
// its camera rays (source/backend/render/tracepixel.cpp, CreateCameraRay; the
// mapping was checked against the installed `povray`, see docs/rendering.md).
//
// Image coordinates are continuous: x in [0, width] left to right, y in
// [0, height] top to bottom; pixel (i, j) covers [i, i+1] x [j, j+1] and its
// centre is (i + 0.5, j + 0.5). The image plane is spanned by the camera's
// `right` and `up` vectors whatever the image's aspect ratio (POV-Ray's rule:
// a 4:3 `right` rendered at 16:9 is stretched, not cropped):
//
//   u = x / width - 0.5,   v = 0.5 - y / height
//   perspective:  origin = location,                  dir = normalize(direction + u right + v up)
//   orthographic: origin = location + u right + v up,  dir = normalize(direction)
#include <optional>

#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/scene/description.hpp"

namespace asos {

class CameraModel {
public:
    // Throws std::invalid_argument when width or height is not positive or
    // when direction, right and up do not span space (a camera that cannot
    // produce an image).
    CameraModel(const Camera& camera, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    bool orthographic() const { return orthographic_; }
    const Vec3& location() const { return location_; }
    const Vec3& direction() const { return direction_; }
    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }

    // The world ray through image point (x, y); its direction has unit length.
    Ray ray(double x, double y) const {
        const double u = x * invWidth_ - 0.5;
        const double v = 0.5 - y * invHeight_;
        if (orthographic_) return {location_ + u * right_ + v * up_, unitDirection_};
        return {location_, glm::normalize(direction_ + u * right_ + v * up_)};
    }
    Ray pixelCenterRay(int i, int j) const { return ray(i + 0.5, j + 0.5); }

    // The point of image point (x, y) on the image plane, which lies at
    // location + direction. Corners of a pixel's pyray pass through these.
    Vec3 imagePlanePoint(double x, double y) const {
        const double u = x * invWidth_ - 0.5;
        const double v = 0.5 - y * invHeight_;
        return location_ + direction_ + u * right_ + v * up_;
    }

    // The image point whose ray passes through world point p, or nothing when
    // p is behind the camera (perspective: not in front of the eye;
    // orthographic: behind the plane through location spanned by right and up).
    std::optional<Vec2> project(const Vec3& p) const;

private:
    Vec3 location_, direction_, right_, up_;
    Vec3 unitDirection_;
    Mat3 basisInverse_;  // inverse of the matrix with columns right, up, direction
    bool orthographic_ = false;
    int width_ = 0, height_ = 0;
    double invWidth_ = 0.0, invHeight_ = 0.0;
};

}  // namespace asos
