#pragma once
// What every shape answers, named: a local shape (an alternative of
// Primitive's LocalShape) answers PrimitiveShape, a description record (an
// alternative of Shape) answers ShapeRecord. Primitive checks every
// alternative against them, so a shape that leaves an answer out does not
// compile; there is no default answer.
#include <concepts>
#include <optional>
#include <type_traits>
#include <variant>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

namespace primitive_shape_detail {
// Stands for withAnyTestFrom's caller: it takes the test the shape hands it,
// test(localDir, tMin, tMax) -> bool. (Defined: the tests are local types.)
struct AnyTestUser {
    template <class Test>
        requires std::is_invocable_r_v<bool, const Test&, const Vec3&, double, double>
    bool operator()(const Test& test) const {
        return test(Vec3(0.0), 0.0, 0.0);
    }
};
}  // namespace primitive_shape_detail

template <class S>
concept PrimitiveShape = requires(const S& shape, const Mat3& worldFromLocal, const Vec3& point,
                                  const Ray& ray, double t, const LocalCone& cone,
                                  LocalCone& unrangedCone, const RigidBounds& back,
                                  const LocalRays& rays, primitive_shape_detail::AnyTestUser user) {
    // Bounds: a ball holding the shape in its local frame; its world box
    // under worldFromLocal and an offset.
    { shape.boundingSphere() } -> std::same_as<BoundingSphere>;
    { shape.worldBounds(worldFromLocal, point) } -> std::same_as<Bounds3>;
    // The nearest hit and whether there is one, for t in [tMin, tMax].
    { shape.intersect(ray, t, t) } -> std::same_as<std::optional<LocalHit>>;
    { shape.intersectAny(ray, t, t) } -> std::same_as<bool>;
    // The cone's classification (paper: "Detection Phase"), and the same
    // from a rigid frame for a cone whose range [t0, t1] the shape sets
    // itself, past any answer of a fast path that needs none, with its
    // depths held against the world range through `back` (Primitive).
    { shape.classify(cone) } -> std::same_as<ConeClass>;
    { shape.classifyRanging(unrangedCone, t, t, back) } -> std::same_as<ConeClass>;
    // Whether a local point is inside, as POV-Ray's Inside (the object not
    // inverted): the solid of a closed shape, the side below a flat shape's
    // normal (a disc's, a plane's), nothing for a polygon (POV-Ray's
    // non-solid objects). CSG asks it (csg_clip.hpp).
    { shape.inside(point) } -> std::same_as<bool>;
    // Whether the shape is a convex set (Primitive::convex).
    { shape.convex() } -> std::same_as<bool>;
    // Whether no ray of `rays` meets it (Primitive::raysLeave; conservative).
    { shape.raysLeave(rays) } -> std::same_as<bool>;
    // Whether it can cast a shadow on itself where it faces a light: a
    // surface neither convex nor flat.
    { shape.canShadowItself() } -> std::same_as<bool>;
    // For the depth order of two objects over a cone (depth_order.hpp): the
    // planes it lies behind as seen from a point (holding_planes.hpp), and
    // its support, the largest dir.x over it (+inf where it is unbounded
    // that way), to rounding.
    { shape.holdingPlanes(point) } -> std::same_as<HoldingPlanes>;
    { shape.support(point) } -> std::same_as<double>;
    // Calls user(test) once with its any-hit test for rays from one local
    // origin, test(dir, tMin, tMax) == intersectAny(Ray{origin, dir}, tMin,
    // tMax), what does not depend on the direction computed once where the
    // shape has a way to (Primitive::withAnyTestFrom).
    { shape.withAnyTestFrom(point, user) } -> std::same_as<bool>;
};

// Whether every alternative of a std::variant is a PrimitiveShape.
template <class Variant>
inline constexpr bool kEveryAlternativePrimitiveShape = false;
template <class... S>
inline constexpr bool kEveryAlternativePrimitiveShape<std::variant<S...>> = (PrimitiveShape<S> && ...);

template <class R>
concept ShapeRecord = requires(const R& record, const Transform& worldFromObject) {
    // Every issue of the record (shape_issue.hpp).
    { validate(record) } -> std::same_as<std::vector<ShapeIssue>>;
    // A record validate accepts as its local shape and frame: a Placed, or a
    // std::variant of those (placed.hpp).
    place(record, worldFromObject);
};

// Whether every alternative of a std::variant is a ShapeRecord.
template <class Variant>
inline constexpr bool kEveryAlternativeShapeRecord = false;
// A CSG leaf (CsgShape) is made from its tree's records instead
// (Primitive::make, csg_clip.hpp).
template <class... R>
inline constexpr bool kEveryAlternativeShapeRecord<std::variant<R...>> =
    ((ShapeRecord<R> || std::is_same_v<R, CsgShape>) && ...);

}  // namespace asos
