#pragma once
// The shadow pyray toward a linear light (paper: "Linear Light Sources",
// Figure 5c): the triangle of rays from a shaded point to a segment of the
// light, split in two halves when marginal. Each piece carries its share of
// the light's length; the point its central ray reaches on the line acts as a
// point light. A reference: the renderer's beams (lights/segment_light.hpp)
// make the same pieces for speed; the tests compare them.
#include <array>
#include <optional>

#include "asos/geometry/beam.hpp"

namespace asos {

class SegmentShadowPyray {
public:
    // The level-0 pyray from `point` (rays start at distance tMin) to the
    // segment [a, b]. Empty when the point lies on the segment. Throws
    // std::invalid_argument when a == b.
    static std::optional<SegmentShadowPyray> make(const Vec3& point, const Vec3& a, const Vec3& b,
                                                  double tMin = 0.0);

    // The two level K+1 halves: [s0, mid] and [mid, s1].
    std::array<SegmentShadowPyray, 2> split() const;

    // Toward the middle of the (sub-)segment; distance: to the light.
    BeamRay central() const { return toward(0.5); }
    // Toward the point at fraction xi of the (sub-)segment (uniform in length
    // for uniform xi in [0, 1)).
    BeamRay sample(double xi) const { return toward(xi); }

    // The share of the light's length: 2^-level, exactly.
    double weight() const;
    double length() const;  // of the (sub-)segment
    Vec3 start() const { return lightPoint(s0_); }
    Vec3 end() const { return lightPoint(s1_); }
    double s0() const { return s0_; }
    double s1() const { return s1_; }
    const Vec3& point() const { return point_; }
    int level() const { return level_; }
    // The nearest distance from the point to the (sub-)segment.
    double nearestLightDistance() const;

    // The smallest cone holding the rays to both ends (and so the triangle),
    // for t in [tMin, the farther end].
    const Cone& cone() const { return cone_; }

private:
    SegmentShadowPyray(const Vec3& point, const Vec3& a, const Vec3& b, double s0, double s1,
                       int level, double tMin);
    Vec3 lightPoint(double s) const { return a_ + s * (b_ - a_); }
    BeamRay toward(double xi) const;

    Vec3 point_{0.0}, a_{0.0}, b_{0.0};
    double s0_ = 0.0, s1_ = 1.0;
    int level_ = 0;
    double tMin_ = 0.0;
    Cone cone_;
};

}  // namespace asos
