#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

// A ray hit in a primitive's local frame: the ray parameter (the same t as
// the world ray's), the local point and the local outward normal (not
// necessarily unit).
struct LocalHit {
    double t = kInfinity;
    Vec3 point{0.0};
    Vec3 normal{0.0, 0.0, 1.0};
    std::uint8_t part = 0;  // SurfaceHit::part
};

// Every crossing of a ray with a primitive's surface within a range, nearest
// first (Primitive::crossings). A torus meets a line up to four times;
// every other shape at most twice (a convex solid, a quadric's side, a flat
// shape once).
struct Crossings {
    static constexpr int kMax = 4;
    std::array<LocalHit, kMax> hits{};
    int count = 0;
};

// A sphere holding the whole primitive, in its local frame.
struct BoundingSphere {
    Vec3 center{0.0};
    double radius = 0.0;
};

// Where a ray crosses the plane z = 0 within [tMin, tMax] (Disc, Polygon):
// the ray parameter and the crossing's x and y.
struct ZPlaneCrossing {
    double t;
    double x;
    double y;
};

inline std::optional<ZPlaneCrossing> crossZPlane(const Ray& ray, double tMin, double tMax) {
    if (ray.dir.z == 0.0) return std::nullopt;
    const double t = -ray.origin.z / ray.dir.z;
    if (!(t >= tMin && t <= tMax)) return std::nullopt;
    return ZPlaneCrossing{t, ray.origin.x + t * ray.dir.x, ray.origin.y + t * ray.dir.y};
}

}  // namespace asos
