#pragma once
// Where a primitive's local frame sits in the world. Each primitive is stored
// in a canonical local frame (a cylinder along +z from the origin, a disc in
// z = 0, ...) placed by a rigid objectFromLocal motion; the world sees it
// through worldFromObject. The composition is classified once so that the
// common cases run without matrix work: Translate (rays and cones are only
// shifted), Similarity (rotation and uniform scale: cones stay circular and
// exact) and General (non-uniform scale or shear).
#include <cstdint>

#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

struct LocalFrame {
    enum class Kind : std::uint8_t { Translate, Similarity, General };
    // The fields a ray test reads come first, so that they share cache lines.
    Kind kind = Kind::Translate;
    Vec3 localOffset{0.0};
    Mat3 localFromWorld{1.0};  // local = localFromWorld * world + localOffset
    Mat3 worldFromLocal{1.0};  // world = worldFromLocal * local + worldOffset
    Vec3 worldOffset{0.0};
    double worldPerLocal = 1.0;  // Similarity: world length of a unit local length
    double localPerWorld = 1.0;  // its reciprocal
    // Similarity: localFromWorld * worldPerLocal, the rotation alone (a
    // world unit vector maps to a local unit vector with one product).
    Mat3 localRotation{1.0};
    double sigmaMax = 1.0;  // largest and smallest singular values of localFromWorld
    double sigmaMin = 1.0;
    // General: the trace and determinant of the Gram matrix G of
    // localFromWorld, which give the singular values of its restriction to
    // the plane across a cone's axis in closed form (Primitive::classify).
    double gramTrace = 3.0;
    double gramDeterminant = 1.0;
    Mat3 gram{1.0};  // General: G itself
    Mat3 objectFromLocal{1.0};  // object = objectFromLocal * local + objectOffset
    Vec3 objectOffset{0.0};

    // worldFromObject after the rigid placement (objectFromLocal, objectOffset).
    // Throws std::invalid_argument when the transform is singular or not finite.
    static LocalFrame make(const Transform& worldFromObject, const Mat3& objectFromLocal,
                           const Vec3& objectOffset);

    Ray rayToLocal(const Ray& r) const {
        if (kind == Kind::Translate) return {r.origin + localOffset, r.dir};
        return {localFromWorld * r.origin + localOffset, localFromWorld * r.dir};
    }
    Vec3 pointToLocal(const Vec3& p) const {
        if (kind == Kind::Translate) return p + localOffset;
        return localFromWorld * p + localOffset;
    }
    Vec3 pointToWorld(const Vec3& p) const {
        if (kind == Kind::Translate) return p - localOffset;
        return worldFromLocal * p + worldOffset;
    }
    // Unit world normal of a local normal (inverse transpose).
    Vec3 normalToWorld(const Vec3& n) const {
        if (kind == Kind::Translate) return glm::normalize(n);
        return glm::normalize(n * localFromWorld);
    }
    Vec3 pointToObject(const Vec3& p) const { return objectFromLocal * p + objectOffset; }

    // A flat shape in the local plane z = 0 is, under any frame, a flat shape
    // in a world plane, which a rigid frame can hold: `frame` puts that plane
    // at its own z = 0, its +z on the side normalToWorld gives, its x and y
    // turned by `angle` (radians) from a fixed choice, and `inPlane` takes
    // this frame's local (x, y) to its (x, y). For every point of the plane
    // its pointToObject is this frame's. (A polygon or a disc under a
    // non-uniform scale, so relaid, has its cones classified exactly, without
    // the General frames' bounding cone.)
    struct Flattened;
    Flattened flattened(double angle = 0.0) const;
};

struct LocalFrame::Flattened {
    LocalFrame frame;
    glm::dmat2 inPlane{1.0};
};

}  // namespace asos
