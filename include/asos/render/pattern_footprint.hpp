#pragma once
// The footprint of an eye pyray in a pigment's pattern space: the image
// square's rays meet the tangent plane at the hit (docs/algorithm.md, "Point
// lights", has the footprint), and the plane's points are mapped into pattern
// space. Through a pinhole the map from image to plane is projective, so
// pattern point (x, y) = H.xyz / H.w with H = a + x b + y c, four affine
// functions of the image coordinates; for an orthographic camera H.w is 1.
// A plane of constant pattern coordinate, p_i = k, is then the image line
// H_i - k H.w = 0: the pattern filter (render/pattern_filter.hpp) clips the
// image square along such lines, and areas in the image are the weights of
// the pixel's box filter.
#include <optional>

#include "asos/geometry/beam_eye.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/render/camera.hpp"

namespace asos {

class PatternFootprint {
public:
    // The footprint of `square` on the plane through `point` with `normal`,
    // in the pattern space of `patternFromWorld` (an affine map). Nothing
    // when some ray of the square does not meet the plane in front of the
    // camera (the plane runs through the eye, or along the rays, or a corner
    // ray passes above its horizon).
    static std::optional<PatternFootprint> make(const CameraModel& camera, const ImageSquare& square,
                                                const Vec3& point, const Vec3& normal,
                                                const Mat4& patternFromWorld);

    const ImageSquare& square() const { return square_; }
    // H at image point (x, y); H.w > 0 all over the square.
    Vec4 homogeneous(double x, double y) const { return a_ + x * b_ + y * c_; }
    // The pattern-space point of image point (x, y).
    Vec3 at(double x, double y) const {
        const Vec4 h = homogeneous(x, y);
        return Vec3(h) / h.w;
    }

private:
    PatternFootprint(const ImageSquare& square, const Vec4& a, const Vec4& b, const Vec4& c)
        : square_(square), a_(a), b_(b), c_(c) {}

    ImageSquare square_;
    Vec4 a_, b_, c_;
};

}  // namespace asos
