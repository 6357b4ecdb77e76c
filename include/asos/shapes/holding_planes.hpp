#pragma once
// What a shape tells the depth order of two objects over a cone
// (shapes/depth_order.hpp): the planes it lies behind, whether it is flat,
// and whether a point can see its surface lie on such a plane over an area.
#include <array>

#include "asos/geometry/half_space.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

struct HoldingPlanes {
    static constexpr int kMax = 6;
    // The shape lies in each of these half-spaces: a box's faces, a capped
    // or open cylinder's or cone's cap planes, a flat shape's plane both
    // ways.
    std::array<HalfSpace, kMax> planes{};
    int count = 0;
    // The shape lies in the plane of planes[0] (a disc, a polygon, a plane).
    bool flat = false;
    // Seen from the point asked about, the surface meets a plane that holds
    // the whole shape on the point's side only where it is not seen first
    // (or on a set of no area): a sphere or an open tube always (curved,
    // they touch a plane along a point or a line), a box or a capped solid
    // from outside (its face on such a plane faces away from the point),
    // never a flat shape (it may lie on the plane).
    bool thinContact = false;

    void add(const Vec3& normal, double offset) { planes[count++] = {normal, offset}; }
};

// A flat shape in the plane z = 0 (a disc, a polygon): that plane, both ways.
inline HoldingPlanes zPlaneHolding() {
    HoldingPlanes h;
    h.add(Vec3(0.0, 0.0, 1.0), 0.0);
    h.add(Vec3(0.0, 0.0, -1.0), 0.0);
    h.flat = true;
    return h;
}

}  // namespace asos
