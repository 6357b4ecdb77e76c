#include "asos/geometry/transform.hpp"

#include <cmath>

namespace asos {

Transform::Transform(const Mat4& m) : m_(m), inv_(glm::inverse(m)) {}

Transform Transform::translate(const Vec3& d) {
    Mat4 m(1.0), inv(1.0);
    m[3] = Vec4(d, 1.0);
    inv[3] = Vec4(-d, 1.0);
    return {m, inv};
}

Transform Transform::scale(const Vec3& s) {
    Mat4 m(1.0), inv(1.0);
    for (int i = 0; i < 3; ++i) {
        m[i][i] = s[i];
        inv[i][i] = 1.0 / s[i];
    }
    return {m, inv};
}

namespace {
// Rotation about one axis by `degrees`, as POV-Ray does it: exact for
// multiples of 90 degrees so that axis-aligned scenes stay exact.
Mat4 axisRotation(int axis, double degrees) {
    double s, c;
    const double q = degrees / 90.0;
    if (q == std::floor(q)) {
        // fmod is exact, and defined for any whole q (a cast to an integer is
        // not, beyond its range).
        const double r = std::fmod(q, 4.0);
        const auto k = static_cast<int>(r < 0 ? r + 4.0 : r);
        const double ss[4] = {0, 1, 0, -1}, cc[4] = {1, 0, -1, 0};
        s = ss[k];
        c = cc[k];
    } else {
        const double r = degrees * kPi / 180.0;
        s = std::sin(r);
        c = std::cos(r);
    }
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    Mat4 m(1.0);
    // Column-vector form of POV-Ray's left-handed rotation matrices.
    m[a][a] = c;
    m[b][b] = c;
    m[a][b] = s;
    m[b][a] = -s;
    return m;
}
}  // namespace

Transform Transform::rotateDegrees(const Vec3& degrees) {
    Mat4 m(1.0);
    for (int axis = 0; axis < 3; ++axis)
        if (degrees[axis] != 0.0) m = axisRotation(axis, degrees[axis]) * m;
    return {m, glm::transpose(m)};
}

Transform Transform::fromPovMatrix(const double v[12]) {
    Mat4 m(1.0);
    // POV-Ray: p' = p * M with row vectors; column j of our matrix is row j of its.
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) m[row][col] = v[row * 3 + col];
    m[3] = Vec4(v[9], v[10], v[11], 1.0);
    return Transform(m);
}

void Transform::toPovMatrix(double out[12]) const {
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out[row * 3 + col] = m_[row][col];
    out[9] = m_[3][0];
    out[10] = m_[3][1];
    out[11] = m_[3][2];
}

Bounds3 Transform::bounds(const Bounds3& b) const {
    Bounds3 out;
    if (b.empty()) return out;
    for (int i = 0; i < 8; ++i) out.extend(point(b.corner(i)));
    return out;
}

}  // namespace asos
