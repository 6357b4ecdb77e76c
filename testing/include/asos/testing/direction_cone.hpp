#pragma once
// The smallest cone of a few directions, tried through every pair and
// triple of them: the reference beams' cones (quad_pyray.hpp,
// rect_shadow_pyray.hpp, segment_shadow_pyray.hpp, sphere_shadow_cone.hpp),
// against which the renderer's cheaper cones about central rays are tested.
#include <span>

#include "asos/geometry/beam.hpp"

namespace asos {

// The axis and half-angle of the smallest circular cone (apex at the origin)
// holding every given unit direction. The directions must lie in an open
// hemisphere (then the cone also holds every positive combination of them,
// i.e. the whole pyramid they span, since its half-angle is below pi/2);
// otherwise the result is a cone about their mean of half-angle pi (all
// directions). The half-angle is the largest angle from the axis to a
// direction plus kConeAnglePad, so the directions are inside despite rounding.
struct DirectionCone {
    Vec3 axis{0.0, 0.0, 1.0};
    double halfAngle = 0.0;
};
DirectionCone smallestEnclosingCone(std::span<const Vec3> directions);

}  // namespace asos
