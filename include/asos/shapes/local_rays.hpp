#pragma once
// Rays from one point of a shape's local frame, as the shapes' answers about
// many rays from one origin see them (an area light's point samples).
#include <glm/geometric.hpp>

#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

// The rays from `origin` along the non-negative combinations of `count`
// directions (of any length, at most 8), in the local frame
// (Primitive::raysLeave). A shape shows that none of them meets it by a plane
// that holds it on one side while every such ray starts on or beyond the
// plane and moves away from it.
struct LocalRays {
    static constexpr int kMaxDirections = 8;

    Vec3 origin{0.0};
    Vec3 directions[kMaxDirections];
    int count = 0;

    // Every direction turned along n (the normal of such a plane, pointing
    // away from the shape), by a margin far above rounding (a cosine above
    // 1e-9; the rays are tested from t > 0 on).
    bool awayFrom(const Vec3& n) const {
        const double nn = glm::length(n);
        for (int i = 0; i < count; ++i)
            if (!(glm::dot(directions[i], n) > 1e-9 * nn * glm::length(directions[i]))) return false;
        return true;
    }
    // For a flat shape in the plane z = 0: its own plane, from the origin's side.
    bool leaveZPlane() const {
        const Vec3 z(0.0, 0.0, 1.0);
        return (origin.z >= 0.0 && awayFrom(z)) || (origin.z <= 0.0 && awayFrom(-z));
    }
};

// A shape's any-hit test for rays from one local origin by its own ray test,
// for a shape without a faster one (its withAnyTestFrom): test(dir, tMin,
// tMax) == shape.intersectAny(Ray{origin, dir}, tMin, tMax).
template <class S>
auto exactAnyTestFrom(const S& shape, const Vec3& origin) {
    return [&shape, origin](const Vec3& dir, double tMin, double tMax) {
        return shape.intersectAny(Ray{origin, dir}, tMin, tMax);
    };
}

}  // namespace asos
