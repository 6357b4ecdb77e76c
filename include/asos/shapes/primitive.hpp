#pragma once
// The one face every primitive shows the rest of the renderer: bounds, the
// nearest ray hit, an any-hit test for shadows, and the classification of a
// cone (paper: "Detection Phase"). A Primitive is a concrete local shape in a
// std::variant plus the frame placing it in the world, so dispatch is a jump
// on the variant's index, without virtual calls, and rays and cones reach the
// shape through the cheapest path its frame allows (see LocalFrame). Every
// answer is the shape's own (PrimitiveShape, primitive_shape.hpp): Primitive
// carries rays, cones and points into the local frame and dispatches once.
#include <cstddef>
#include <memory>
#include <optional>
#include <variant>

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/hit.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/box.hpp"
#include "asos/shapes/cylinder.hpp"
#include "asos/shapes/disc.hpp"
#include "asos/shapes/elliptic_disc.hpp"
#include "asos/shapes/extrusion.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_frame.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/plane.hpp"
#include "asos/shapes/polygon.hpp"
#include "asos/shapes/primitive_shape.hpp"
#include "asos/shapes/quadric.hpp"
#include "asos/shapes/sphere.hpp"
#include "asos/shapes/poly.hpp"
#include "asos/shapes/torus.hpp"
#include "asos/shapes/triangle.hpp"
#include "asos/shapes/truncated_cone.hpp"

namespace asos {

struct CsgClip;
class CsgSolidCache;

// A sphere placed by a translation only, as Sphere's static tests take it:
// the local ray is the world ray shifted by localOffset. The scene keeps these
// in a compact array so that its ray search tests such spheres without
// reaching the Primitive (same arithmetic, same answers).
struct TranslatedSphere {
    Vec3 localOffset{0.0};
    double radius = 0.0;
};

class Primitive {
public:
    // The record's shape (validate, place: beside each shape) placed by
    // worldFromObject. Throws std::invalid_argument with the record's first
    // issue (shape_issue.hpp) for a meaningless shape, or for a singular
    // transform. A CsgShape makes its leaf's primitive with the clip that
    // keeps the part of its surface bounding the tree's solid (csg_clip.hpp);
    // every answer below is then that part's.
    static Primitive make(const Shape& shape, const Transform& worldFromObject);
    // The same, a CSG leaf sharing its object's solid (csg_clip.hpp) with
    // the leaf made before it where that is of the same object.
    static Primitive make(const Shape& shape, const Transform& worldFromObject, CsgSolidCache& solids);

    bool bounded() const;         // false for planes (unless a CSG bounds them)
    Bounds3 worldBounds() const;  // tight-ish, conservative; unspecified when !bounded()
    // The nearest hit with t in [tMin, tMax] of a ray with a unit direction.
    std::optional<SurfaceHit> intersect(const Ray& worldRay, double tMin, double tMax) const;
    // The same in two phases, for a search over many primitives: the hit in
    // the local frame (t is the world ray's), cheap to compute and discard,
    // then the world record for the nearest one only.
    // surfaceHit(ray, *intersectLocal(ray, lo, hi)) == *intersect(ray, lo, hi).
    std::optional<LocalHit> intersectLocal(const Ray& worldRay, double tMin, double tMax) const;
    SurfaceHit surfaceHit(const Ray& worldRay, const LocalHit& hit) const;
    bool intersectAny(const Ray& worldRay, double tMin, double tMax) const;
    // Every crossing of the shape's surface (without a CSG's clip) with t in
    // [tMin, tMax], nearest first, in the local frame: each shape's
    // intersect picks the nearest of candidates that do not depend on tMin,
    // so asking again just past the last one found is exact.
    Crossings crossings(const Ray& worldRay, double tMin, double tMax) const;
    // Whether a world point is inside the shape (PrimitiveShape's inside;
    // a CSG's clip aside).
    bool inside(const Vec3& worldPoint) const;
    // The same for many rays from one origin (an area light's point samples):
    // the origin is carried into the local frame once, by originToLocal, and
    // intersectAnyFrom(originToLocal(o), d, lo, hi) == intersectAny({o, d}, lo, hi).
    Vec3 originToLocal(const Vec3& worldOrigin) const { return frame_.pointToLocal(worldOrigin); }
    bool intersectAnyFrom(const Vec3& localOrigin, const Vec3& worldDir, double tMin, double tMax) const;
    // The same as a loop's body, for rays from one world origin: calls
    // f(test) once, where test(worldDir, tMin, tMax) ==
    // intersectAny({worldOrigin, worldDir}, tMin, tMax), with the shape's kind
    // resolved (no dispatch per ray) and what does not depend on the
    // direction computed once where the shape allows it (a capped cylinder
    // or cone: FrustumFromOrigin; a box: BoxFromOrigin).
    template <class F>
    decltype(auto) withAnyTestFrom(const Vec3& worldOrigin, F&& f) const;
    ConeClass classify(const Cone& worldCone) const;
    // The same, for a cone whose trigonometry is done once for many objects.
    ConeClass classify(const PreparedCone& worldCone) const;

    // This primitive as a TranslatedSphere, when it is a sphere under a pure
    // translation: Sphere::intersect(ray shifted by localOffset, radius, ...)
    // then equals intersectLocal(ray, ...).
    std::optional<TranslatedSphere> translatedSphere() const;

    // Whether the primitive is a convex set: a closed solid (a sphere, a box,
    // a capped cylinder or cone) or a flat convex region (a disc without a
    // hole, a polygon of one convex loop). From a point outside it, a ray
    // then meets its surface within [tMin, tMax] iff that stretch of the ray
    // meets the set and ends outside it (ConvexLattice's use, in
    // area_light_shadow.cpp).
    bool convex() const;

    // Whether no ray from `worldOrigin` along a non-negative combination of
    // `directions` (world, of any length, at most 8) meets the primitive at
    // any t > 0, shown by a plane that holds the primitive on one side while
    // every such ray starts on or beyond it and moves away from it: a face's
    // plane (a box's, a cap's, a flat shape's own), the plane tangent to a
    // cylinder's or cone's side along the generator facing the origin, the
    // plane across a sphere facing it. Conservative: false where no such
    // plane is found. (The point samples of an area light's piece:
    // area_light_shadow.cpp.)
    bool raysLeave(const Vec3& worldOrigin, const Vec3* directions, int count) const;

    // Whether the primitive lies outside the region a shadow beam's rays run
    // through (BeamHull): its world box does, or, for a plane, the region
    // lies on one side of it. Conservative: false where neither shows it.
    bool outside(const BeamHull& hull) const;

    // Whether every point this CSG leaf keeps lies inside `solid`'s closed
    // convex solid (a box, sphere or capped cylinder or cone of the same CSG
    // object, not inverted, that the leaf's hits must be inside: the hole
    // cut in a box inside that box), with the cone's start points outside
    // that solid's box; each ray of the cone then meets `solid`'s surface
    // before any such point. False for anything else.
    bool keptWithin(const Primitive& solid, const PreparedCone& cone) const;
    // Whether the primitive can cast a shadow on itself where it faces a
    // light: a surface neither convex nor flat (an open cylinder or cone).
    // The shadow tests leave the shaded object out otherwise.
    bool canShadowItself() const;

    // Which rays from a point on the primitive's own surface can meet it
    // again (past a tolerance), for the shadow tests of a point it holds:
    // None, no ray (a plane, a flat shape: the ray leaves its plane at
    // once); Interior, exactly the rays into the solid, those below the
    // plane tangent at the point (outward normal), met where they leave it,
    // within the world box's diagonal (a sphere, a box, a capped cylinder or
    // cone); Any, where neither is shown (a surface that can shadow itself,
    // or a shape not sorted here).
    enum class SelfOcclusion { None, Interior, Any };
    SelfOcclusion selfOcclusion() const;

    // What the depth order of two objects over a cone asks
    // (shapes/depth_order.hpp), in the world: the planes (unit normals) the
    // primitive lies behind, as seen from `worldPoint` (holding_planes.hpp),
    // and its support, the largest dir.x over it (+inf where unbounded that
    // way), to rounding.
    HoldingPlanes holdingPlanes(const Vec3& worldPoint) const;
    double support(const Vec3& worldDir) const;

    // The POV-Ray keyword of the shape ("sphere", "cone", ...).
    const char* kindName() const;

private:
    // The local shapes, each answering PrimitiveShape. A description record
    // (an alternative of Shape, answering ShapeRecord) becomes one of them.
    using LocalShape =
        std::variant<Sphere, Box, TruncatedCone, Cylinder, Disc, Polygon, Plane, EllipticDisc,
                     Quadric, Torus, SmoothTriangle, Extrusion, Poly>;
    static_assert(kEveryAlternativePrimitiveShape<LocalShape>,
                  "every local shape answers PrimitiveShape (primitive_shape.hpp)");

    Primitive(LocalShape shape, LocalFrame frame, const char* name);
    // What a record's place returns (Placed, or a variant of Placed).
    template <class S>
    static Primitive fromPlaced(Placed<S>&& placed);
    template <class... S>
    static Primitive fromPlaced(std::variant<Placed<S>...>&& placed);
    template <bool kScaled>
    ConeClass classifyRigid(const PreparedCone& cone) const;
    ConeClass classifyGeneral(const PreparedCone& cone) const;
    template <class F>
    decltype(auto) visit(F&& f) const;
    ConeClass classifyOwn(const PreparedCone& cone) const;
    // A CSG leaf's answer from its clip's tests over the depths of its
    // nearest crossings and of its later ones (docs/geometry.md, "CSG").
    ConeClass clippedClass(const PreparedCone& cone) const;
    // A CSG leaf of a closed convex solid (a box; a sphere or capped
    // cylinder under a translation or similarity) over a cone whose apex
    // lies within the solid or on its surface, its rays counted from
    // cone.tMin on: a ray from there meets the surface only where it
    // leaves the solid, once (and from the surface only if it heads into
    // it), so the leaf's crossings in the cone are those exits, whose
    // depths are bounded (a box's from its slab planes, a sphere's or a
    // cylinder side's from the chord, a cap's from its plane) and asked of
    // the clip: Miss where every exit is dropped or, from the surface,
    // every ray heads away from the solid, else Marginal over the exits'
    // depths. None where the apex is not shown within or tMin is too small.
    std::optional<ConeClass> exitsClass(const PreparedCone& cone) const;
    // A CSG leaf's answers (clip_ set), out of line.
    std::optional<LocalHit> clippedHit(const Ray& worldRay, double tMin, double tMax) const;
    bool clippedAny(const Ray& worldRay, double tMin, double tMax) const;
    static Primitive makeCsgLeaf(const CsgShape& shape, const Transform& worldFromObject, CsgSolidCache& solids);

    // A CSG leaf's: which of its hits bound the tree's solid (null: all).
    // First, beside the shape the ray tests read (not on a cache line of
    // its own).
    std::shared_ptr<const CsgClip> clip_;
    LocalShape shape_;
    LocalFrame frame_;
    const char* name_;
    Bounds3 worldBounds_;
    BoundingSphere localSphere_;
    double sphereTolerance_ = 0.0;  // scale of the local coordinates, for rounding tolerances
    bool bounded_ = false;
};

namespace primitive_detail {
// A chain of tests of the variant's index, the first shapes (the commonest)
// first, to the concrete shape: no virtual call, and no valueless check (a
// LocalShape is never valueless).
template <std::size_t I = 0, class Variant, class F>
decltype(auto) dispatch(const Variant& v, F& f) {
    if constexpr (I + 1 == std::variant_size_v<Variant>) {
        return f(*std::get_if<I>(&v));
    } else {
        if (v.index() == I) return f(*std::get_if<I>(&v));
        return dispatch<I + 1>(v, f);
    }
}

// The same as one jump (a switch on the index, a jump table) for the cone
// classification, where every shape is as likely as the next. A case per
// alternative, up to kJumpCases of them.
inline constexpr std::size_t kJumpCases = 16;

template <std::size_t I, class R, class Variant, class F>
__attribute__((always_inline)) inline R jumpCase(const Variant& v, F& f) {
    if constexpr (I < std::variant_size_v<Variant>) return f(*std::get_if<I>(&v));
    else __builtin_unreachable();
}

template <class R, class Variant, class F>
__attribute__((always_inline)) inline R jump(const Variant& v, F& f) {
    static_assert(std::variant_size_v<Variant> <= kJumpCases, "jump: add cases up to the alternatives");
    switch (v.index()) {
        case 0: return jumpCase<0, R>(v, f);
        case 1: return jumpCase<1, R>(v, f);
        case 2: return jumpCase<2, R>(v, f);
        case 3: return jumpCase<3, R>(v, f);
        case 4: return jumpCase<4, R>(v, f);
        case 5: return jumpCase<5, R>(v, f);
        case 6: return jumpCase<6, R>(v, f);
        case 7: return jumpCase<7, R>(v, f);
        case 8: return jumpCase<8, R>(v, f);
        case 9: return jumpCase<9, R>(v, f);
        case 10: return jumpCase<10, R>(v, f);
        case 11: return jumpCase<11, R>(v, f);
        case 12: return jumpCase<12, R>(v, f);
        case 13: return jumpCase<13, R>(v, f);
        case 14: return jumpCase<14, R>(v, f);
        case 15: return jumpCase<15, R>(v, f);
        default: __builtin_unreachable();
    }
}
}  // namespace primitive_detail

template <class F>
decltype(auto) Primitive::visit(F&& f) const {
    return primitive_detail::dispatch(shape_, f);
}

template <class F>
decltype(auto) Primitive::withAnyTestFrom(const Vec3& worldOrigin, F&& f) const {
    if (clip_) [[unlikely]]
        return f([this, worldOrigin](const Vec3& worldDir, double tMin, double tMax) {
            return clippedAny(Ray{worldOrigin, worldDir}, tMin, tMax);
        });
    const Vec3 localOrigin = originToLocal(worldOrigin);
    const LocalFrame& frame = frame_;
    // The direction's local image, written out (glm's product is a call).
    const auto toLocal = [&frame](const Vec3& w) {
        if (frame.kind == LocalFrame::Kind::Translate) return w;
        const Mat3& m = frame.localFromWorld;
        return Vec3(m[0][0] * w.x + m[1][0] * w.y + m[2][0] * w.z, m[0][1] * w.x + m[1][1] * w.y + m[2][1] * w.z,
                    m[0][2] * w.x + m[1][2] * w.y + m[2][2] * w.z);
    };
    return visit([&](const auto& shape) {
        return shape.withAnyTestFrom(localOrigin, [&](const auto& localTest) {
            return f([&](const Vec3& worldDir, double tMin, double tMax) {
                return localTest(toLocal(worldDir), tMin, tMax);
            });
        });
    });
}

// Inline: it is the inner loop of every nearest-hit search.
inline std::optional<LocalHit> Primitive::intersectLocal(const Ray& worldRay, double tMin,
                                                         double tMax) const {
    if (clip_) [[unlikely]]
        return clippedHit(worldRay, tMin, tMax);
    const Ray ray = frame_.rayToLocal(worldRay);
    return visit([&](const auto& s) { return s.intersect(ray, tMin, tMax); });
}

}  // namespace asos
