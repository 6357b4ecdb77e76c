#pragma once
#include <algorithm>

#include "asos/geometry/vec.hpp"

namespace asos {

// Axis-aligned box; empty when lo > hi on any axis (the default).
struct Bounds3 {
    Vec3 lo{kInfinity};
    Vec3 hi{-kInfinity};

    static Bounds3 of(const Vec3& p) { return {p, p}; }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const Vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void extend(const Bounds3& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    Vec3 center() const { return 0.5 * (lo + hi); }
    Vec3 diagonal() const { return hi - lo; }
    double surfaceArea() const {
        if (empty()) return 0.0;
        const Vec3 d = diagonal();
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
    Vec3 corner(int i) const {
        return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    }
};

inline Bounds3 unionOf(Bounds3 a, const Bounds3& b) {
    a.extend(b);
    return a;
}

}  // namespace asos
