#pragma once
// The corners of a convex polytope given by half-spaces: what shows that a
// solid bounded by planes (an intersection of planes, a box cut by one) lies
// within another (lang/object_bounds.hpp).
#include <optional>
#include <span>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/half_space.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

// At most this many half-spaces are taken (the search tries every three).
inline constexpr std::size_t kMaxPolytopeHalfSpaces = 64;

// The vertices of the polytope that the half-spaces cut from `box` (a
// finite, non-empty box): every point where three of the planes (the box's
// faces included) meet and that the others hold, to a tolerance relative to
// the box's size. Their convex hull is the polytope: an empty list when
// the half-spaces leave nothing of the box. Nullopt for more than
// kMaxPolytopeHalfSpaces half-spaces or a box not finite.
std::optional<std::vector<Vec3>> polytopeVertices(std::span<const HalfSpace> halfSpaces, const Bounds3& box);

}  // namespace asos
