#pragma once
// What POV-Ray 3.7 makes of an object's bounded_by (its Link_To_Frame and
// Parse_Object_Mods, with the default Remove_Bounds=on). It keeps the bound
// of a CSG (union, merge, intersection, difference), a text, an unbounded
// quadric, and of any object inside another: it then tests the object only
// on the rays that meet the bound. Any other object placed on its own loses
// its bound, but takes the bound's box as its bounding box where that box is
// the smaller: POV-Ray's bounding hierarchy then shows the object only on
// the rays that meet that box. asos clips the object to the bound, or to the
// box, which is the same image where the object lies within it; where that
// is not shown, the interpreter warns.
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

struct BoundsFate {
    enum class Kind : std::uint8_t {
        Dropped,  // changes nothing: ignore it
        Bound,    // POV-Ray keeps it: clip by its objects
        Box,      // POV-Ray drops it but takes its box: clip by `box`
    };
    Kind kind = Kind::Dropped;
    bool contained = true;  // the object lies within what clips it: POV-Ray's image
    Bounds3 box;            // Kind::Box
};

// The fate of tree.bounds (not empty, not linked to the clips), by the
// object as it stands (its clips count, its members' bounds do not);
// `placed`: the object stands alone in the scene, not inside another.
BoundsFate boundsFate(const ObjectTree& tree, bool placed);

// The relative tolerance of "within": a point counts as inside a bound
// that grown by this fraction about its centre holds.
inline constexpr double kBoundTolerance = 1e-3;

}  // namespace asos::lang
