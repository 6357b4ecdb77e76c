#pragma once
// The one face every primitive shows the rest of the renderer: bounds, the
// nearest ray hit, an any-hit test for shadows, and the classification of a
// cone (paper: "Detection Phase"). A Primitive is a concrete local shape in a
// std::variant plus the frame placing it in the world, so dispatch is a jump
// on the variant's index, without virtual calls, and rays and cones reach the
// shape through the cheapest path its frame allows (see LocalFrame).
#include <cstddef>
#include <optional>
#include <type_traits>
#include <variant>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/hit.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/box.hpp"
#include "asos/shapes/box_from_origin.hpp"
#include "asos/shapes/cylinder.hpp"
#include "asos/shapes/disc.hpp"
#include "asos/shapes/elliptic_disc.hpp"
#include "asos/shapes/frustum_from_origin.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_frame.hpp"
#include "asos/shapes/plane.hpp"
#include "asos/shapes/polygon.hpp"
#include "asos/shapes/sphere.hpp"
#include "asos/shapes/truncated_cone.hpp"

namespace asos {

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
    // Throws std::invalid_argument with a clear message for meaningless shapes.
    static Primitive make(const Shape& shape, const Transform& worldFromObject);

    bool bounded() const;         // false for planes
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

    // The POV-Ray keyword of the shape ("sphere", "cone", ...).
    const char* kindName() const;

private:
    using LocalShape =
        std::variant<Sphere, Box, TruncatedCone, Cylinder, Disc, Polygon, Plane, EllipticDisc>;

    Primitive(LocalShape shape, LocalFrame frame, const char* name);
    template <bool kScaled>
    ConeClass classifyRigid(const PreparedCone& cone) const;
    ConeClass classifyGeneral(const PreparedCone& cone) const;
    template <class F>
    decltype(auto) visit(F&& f) const;

    LocalShape shape_;
    LocalFrame frame_;
    const char* name_;
    Bounds3 worldBounds_;
    BoundingSphere localSphere_;
    double sphereTolerance_ = 0.0;  // scale of the local coordinates, for rounding tolerances
};

namespace primitive_detail {
// A jump on the variant's index to the concrete shape: no virtual call, and
// no valueless check (a LocalShape is never valueless).
template <std::size_t I = 0, class Variant, class F>
decltype(auto) dispatch(const Variant& v, F& f) {
    if constexpr (I + 1 == std::variant_size_v<Variant>) {
        return f(*std::get_if<I>(&v));
    } else {
        if (v.index() == I) return f(*std::get_if<I>(&v));
        return dispatch<I + 1>(v, f);
    }
}
}  // namespace primitive_detail

template <class F>
decltype(auto) Primitive::visit(F&& f) const {
    return primitive_detail::dispatch(shape_, f);
}

template <class F>
decltype(auto) Primitive::withAnyTestFrom(const Vec3& worldOrigin, F&& f) const {
    const Vec3 localOrigin = originToLocal(worldOrigin);
    return visit([&](const auto& shape) {
        const LocalFrame& frame = frame_;
        const auto exact = [&shape, &frame, localOrigin](const Vec3& localDir, double tMin, double tMax) {
            return shape.intersectAny(Ray{localOrigin, localDir}, tMin, tMax);
        };
        // The direction's local image, written out (glm's product is a call).
        const auto toLocal = [&frame](const Vec3& w) {
            if (frame.kind == LocalFrame::Kind::Translate) return w;
            const Mat3& m = frame.localFromWorld;
            return Vec3(m[0][0] * w.x + m[1][0] * w.y + m[2][0] * w.z, m[0][1] * w.x + m[1][1] * w.y + m[2][1] * w.z,
                        m[0][2] * w.x + m[1][2] * w.y + m[2][2] * w.z);
        };
        using S = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<S, TruncatedCone> || std::is_same_v<S, Cylinder>) {
            const FrustumFromOrigin fast(shape.frustum(), localOrigin);
            if (fast.usable()) {
                return f([&](const Vec3& worldDir, double tMin, double tMax) {
                    const Vec3 d = toLocal(worldDir);
                    const int answer = fast.decide(d, tMin, tMax);
                    return answer == FrustumFromOrigin::kUndecided ? exact(d, tMin, tMax) : answer != 0;
                });
            }
        }
        if constexpr (std::is_same_v<S, Box>) {
            const BoxFromOrigin fast(shape, localOrigin);
            return f([&](const Vec3& worldDir, double tMin, double tMax) {
                return fast.intersectAny(toLocal(worldDir), tMin, tMax);
            });
        }
        return f([&](const Vec3& worldDir, double tMin, double tMax) {
            return exact(toLocal(worldDir), tMin, tMax);
        });
    });
}

// Inline: it is the inner loop of every nearest-hit search.
inline std::optional<LocalHit> Primitive::intersectLocal(const Ray& worldRay, double tMin,
                                                         double tMax) const {
    const Ray ray = frame_.rayToLocal(worldRay);
    return visit([&](const auto& s) { return s.intersect(ray, tMin, tMax); });
}

}  // namespace asos
