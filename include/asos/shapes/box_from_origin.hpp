#pragma once
// Shadow rays from one origin against a box (an area light's point samples):
// each slab's offsets from the origin (lo - o, hi - o) and whether the origin
// lies between a slab's planes are found once, and each ray does the rest of
// Box's slab test in its order, on the same operands: the answer is
// Box::intersectAny's bit for bit, with no margin and no fallback.
#include <utility>

#include "asos/geometry/vec.hpp"

namespace asos {

class BoxFromOrigin {
public:
    // The box's corners lo <= hi (Box::lo, Box::hi) and `origin` in its
    // local frame.
    BoxFromOrigin(const Vec3& lo, const Vec3& hi, const Vec3& origin) {
        for (int i = 0; i < 3; ++i) {
            lo_[i] = lo[i] - origin[i];
            hi_[i] = hi[i] - origin[i];
            outside_[i] = origin[i] < lo[i] || origin[i] > hi[i];
        }
    }

    // Box::intersectAny(Ray{origin, d}, tMin, tMax).
    bool intersectAny(const Vec3& d, double tMin, double tMax) const {
        double tEnter = -kInfinity, tExit = kInfinity;
        int enterAxis = -1, exitAxis = -1;
        for (int i = 0; i < 3; ++i) {
            if (d[i] == 0.0) {
                if (outside_[i]) return false;
                continue;
            }
            const double inv = 1.0 / d[i];
            double t0 = lo_[i] * inv, t1 = hi_[i] * inv;
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > tEnter) {
                tEnter = t0;
                enterAxis = i;
            }
            if (t1 < tExit) {
                tExit = t1;
                exitAxis = i;
            }
        }
        return tEnter <= tExit && ((tEnter >= tMin && tEnter <= tMax && enterAxis >= 0) ||
                                   (tExit >= tMin && tExit <= tMax && exitAxis >= 0));
    }

private:
    double lo_[3], hi_[3];
    bool outside_[3];
};

}  // namespace asos
