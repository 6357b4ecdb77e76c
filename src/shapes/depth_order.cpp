#include "asos/shapes/depth_order.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"

namespace asos {

namespace {

// The least and largest w.d over the unit directions d of the cone, widened
// past their rounding.
conegeom::DotRange dotsOver(const PreparedCone& cone, const Vec3& w) {
    const double len = glm::length(w);
    if (!(len > 0.0)) return {0.0, 0.0};
    const Vec3 n = w / len;
    const double k = glm::dot(n, cone.axis), g = glm::length(glm::cross(n, cone.axis));
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double hi = conegeom::angleWithin(k, g, c, s) ? 1.0 : k * c + g * s;
    const double lo = conegeom::angleWithin(-k, g, c, s) ? -1.0 : k * c - g * s;
    return {(lo - kThousandsOfUlps) * len, (hi + kThousandsOfUlps) * len};
}

// A length the size of the coordinates involved, for the tolerances.
double sizeOf(const Primitive& p) {
    if (!p.bounded()) return 0.0;
    const Bounds3 b = p.worldBounds();
    return l1Norm(b.lo) + l1Norm(b.hi);
}

// Whether every first hit of `x` (classified `kx` for the cone; its planes
// `xs`) on the rays of the cone, y, has the height p.normal.y - p.offset > c;
// `pad` covers the rounding of those heights.
bool hitsAbove(const Primitive& x, const HoldingPlanes& xs, const ConeClass& kx, const HalfSpace& p,
               double c, const PreparedCone& cone, double pad) {
    // The whole shape: its least height is -support(-n) - offset.
    if (x.bounded() && -x.support(-p.normal) - p.offset > c + pad) return true;
    // The part of the cone between the depths of its hits: the height along
    // the ray d is he + t (n.d), t in [tNear, tFar].
    const double he = glm::dot(p.normal, cone.apex) - p.offset;
    if (std::isfinite(kx.tFar)) {
        const conegeom::DotRange u = dotsOver(cone, p.normal);
        const double least = he + std::min(std::max(kx.tNear, 0.0) * u.lo, kx.tFar * u.lo);
        if (least > c + pad) return true;
    }
    // A flat shape whose plane (normal m turned away from the apex, at
    // distance sigma > 0) every ray crosses ahead: the ray along d meets it
    // at t = sigma / (m.d), where the height less c is
    // ((he - c) m + sigma n).d / (m.d). Exact over the cone: the two planes'
    // line of intersection misses it.
    if (xs.flat) {
        HalfSpace q = xs.planes[0];
        double sigma = q.offset - glm::dot(q.normal, cone.apex);
        if (sigma < 0.0) {
            q.normal = -q.normal;
            sigma = -sigma;
        }
        if (sigma > pad && dotsOver(cone, q.normal).lo > 0.0 &&
            dotsOver(cone, (he - c) * q.normal + sigma * p.normal).lo > 0.0)
            return true;
    }
    return false;
}

}  // namespace

bool surelyInFront(const Primitive& front, const ConeClass& frontClass, const Primitive& back,
                   const ConeClass& backClass, const PreparedCone& cone) {
    if (frontClass.tFar < backClass.tNear) return true;
    if (!cone.valid) return false;
    // What a CSG leaf keeps inside the solid of another leaf that every ray
    // meets (a hole's wall inside the box it is cut in) lies past that
    // leaf's entry hit on each ray.
    if (frontClass.coverage == Coverage::Full && back.keptWithin(front, cone)) return true;
    const HoldingPlanes fs = front.holdingPlanes(cone.apex);
    const HoldingPlanes bs = back.holdingPlanes(cone.apex);
    const double size = l1Norm(cone.apex) + sizeOf(front) + sizeOf(back);
    // A plane that holds `back`, the apex strictly outside it: `front`'s
    // hits on the apex's side of it (or on it, where it is seen there on no
    // area) come first. A ray that met `back` first would meet it on the
    // segment from the apex to its hit of `front`, which lies on the apex's
    // side but for that end.
    for (int i = 0; i < bs.count; ++i) {
        const HalfSpace& p = bs.planes[i];
        const double scale = size + std::abs(p.offset);
        const double tol = kPositionTolerance * scale, pad = kThousandsOfUlps * scale;
        if (!(glm::dot(p.normal, cone.apex) - p.offset > tol)) continue;
        if (hitsAbove(front, fs, frontClass, p, fs.thinContact ? -tol : tol, cone, pad)) return true;
    }
    // A flat `front`, `back`'s hits strictly beyond its plane.
    if (fs.flat) {
        HalfSpace p = fs.planes[0];
        if (glm::dot(p.normal, cone.apex) - p.offset > 0.0) p = {-p.normal, -p.offset};
        const double scale = size + std::abs(p.offset);
        const double tol = kPositionTolerance * scale, pad = kThousandsOfUlps * scale;
        if (glm::dot(p.normal, cone.apex) - p.offset < -tol && hitsAbove(back, bs, backClass, p, tol, cone, pad))
            return true;
    }
    return false;
}

}  // namespace asos
