#pragma once
// An affine transform with its inverse, named by its frames at the point of
// use (worldFromObject, objectFromWorld). Column-vector convention: p' = M p.
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

class Transform {
public:
    Transform() = default;
    Transform(const Mat4& m, const Mat4& inv) : m_(m), inv_(inv) {}
    explicit Transform(const Mat4& m);  // computes the inverse

    static Transform translate(const Vec3& d);
    static Transform scale(const Vec3& s);
    // POV-Ray's rotate <x,y,z>: degrees about x, then y, then z (left-handed).
    static Transform rotateDegrees(const Vec3& degrees);
    // POV-Ray's `matrix <m00,m01,m02, m10,m11,m12, m20,m21,m22, m30,m31,m32>`
    // (row vectors, translation in the last row).
    static Transform fromPovMatrix(const double v[12]);

    const Mat4& matrix() const { return m_; }
    const Mat4& inverseMatrix() const { return inv_; }
    Transform inverse() const { return {inv_, m_}; }
    bool isIdentity() const { return m_ == Mat4(1.0); }

    // The 12 numbers of POV-Ray's `matrix` keyword for this transform.
    void toPovMatrix(double out[12]) const;

    Vec3 point(const Vec3& p) const { return Vec3(m_ * Vec4(p, 1.0)); }
    Vec3 vector(const Vec3& v) const { return Vec3(m_ * Vec4(v, 0.0)); }
    // Normals transform by the inverse transpose; the result is not normalised.
    Vec3 normal(const Vec3& n) const { return Vec3(glm::transpose(inv_) * Vec4(n, 0.0)); }
    Ray ray(const Ray& r) const { return {point(r.origin), vector(r.dir)}; }
    Bounds3 bounds(const Bounds3& b) const;

    // this ∘ other: apply `other` first, then this.
    Transform operator*(const Transform& other) const {
        return {m_ * other.m_, other.inv_ * inv_};
    }
    bool operator==(const Transform& o) const { return m_ == o.m_; }

private:
    Mat4 m_{1.0};
    Mat4 inv_{1.0};
};

}  // namespace asos
