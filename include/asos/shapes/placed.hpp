#pragma once
#include "asos/shapes/local_frame.hpp"

namespace asos {

// A description record made a local shape (its `place`, beside the shape):
// the shape in its canonical local frame, the frame placing it in the world,
// and the record's POV-Ray keyword (Primitive::kindName). A record may be
// placed as one of a few local shapes (a disc as a Disc or, under a
// non-uniform scale, an EllipticDisc): its `place` then returns a
// std::variant of their Placed forms.
template <class S>
struct Placed {
    S shape;
    LocalFrame frame;
    const char* keyword;
};

}  // namespace asos
