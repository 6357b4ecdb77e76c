#pragma once
// POV-Ray's triangle and smooth_triangle, and a mesh's faces (TriangleShape):
// a flat face is a Polygon of three points; a smooth one is the same Polygon
// with its corners' normals, interpolated across the face for shading
// (SmoothTriangle). Its classification is the polygon's: the geometry is.
#include <array>
#include <optional>
#include <variant>
#include <vector>

#include "asos/shapes/polygon.hpp"

namespace asos {

class SmoothTriangle {
public:
    static constexpr const char* kName = "smooth_triangle";

    // `face` is a triangle (its three vertices, in the record's order);
    // `normals` its corners' normals in the local frame.
    SmoothTriangle(Polygon face, const std::array<Vec3, 3>& normals);

    const Polygon& face() const { return face_; }

    BoundingSphere boundingSphere() const { return face_.boundingSphere(); }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const {
        return face_.worldBounds(worldFromLocal, offset);
    }
    // The face's hit, with the corners' normals interpolated at it
    // (barycentric, as POV-Ray's).
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const { return face_.intersectAny(ray, tMin, tMax); }
    ConeClass classify(const LocalCone& cone) const { return face_.classify(cone); }
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return face_.classifyRanging(cone, t0, t1, back);
    }
    bool inside(const Vec3& p) const { return face_.inside(p); }
    bool convex() const { return face_.convex(); }
    bool canShadowItself() const { return false; }  // flat
    bool raysLeave(const LocalRays& rays) const { return face_.raysLeave(rays); }
    HoldingPlanes holdingPlanes(const Vec3& p) const { return face_.holdingPlanes(p); }
    double support(const Vec3& dir) const { return face_.support(dir); }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    Polygon face_;
    std::array<Vec3, 3> normals_;
    // Barycentric coordinates from the local (x, y): the inverse of the
    // matrix of the edges from vertex 0.
    double inv_[4];
};

// A face of a mesh: finite corners, not on one line; a smooth face's normals
// finite and not zero.
std::vector<ShapeIssue> validate(const TriangleShape& record);
// Its Polygon (a flat face) or SmoothTriangle, in the plane of its corners.
std::variant<Placed<Polygon>, Placed<SmoothTriangle>> place(const TriangleShape& record,
                                                            const Transform& worldFromObject);

}  // namespace asos
