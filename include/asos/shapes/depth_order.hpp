#pragma once
// Which of two objects the rays of a cone meet first where their depth
// ranges over the cone overlap: a rug lying on a floor, papers on a desk, a
// picture hung on a wall, a box standing on the floor (docs/algorithm.md,
// "Surfaces in contact"). The tracer uses it to drop objects hidden behind a
// Full one and to leave uncounted a Full object that no other one crosses.
#include "asos/geometry/cone.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/primitive.hpp"

namespace asos {

// Whether, on every ray of the cone that meets both (their answers for it
// `frontClass` and `backClass`, neither a Miss), `front`'s first hit comes
// before `back`'s. Shown by a plane with the apex strictly on one side,
// `back` on the other (or on it) and `front`'s first hits in the cone on the
// apex's side (or on it, where `front` is seen there on a set of rays of no
// area: HoldingPlanes::thinContact); "on it" to within kPositionTolerance of
// the coordinates. The planes tried: those that hold `back` (a flat shape's
// own, a box's faces, a cylinder's or cone's caps), and a flat `front`'s
// own. `front`'s side is shown from its support, from the depths of its
// hits (the part of the cone between them), or, for a flat `front` whose
// plane every ray crosses, exactly (two planes whose line of intersection
// misses the cone). Conservative: false where none of those shows it.
bool surelyInFront(const Primitive& front, const ConeClass& frontClass, const Primitive& back,
                   const ConeClass& backClass, const PreparedCone& cone);

}  // namespace asos
