#pragma once
#include <cstdint>

#include "asos/geometry/vec.hpp"

namespace asos {

// The nearest intersection of a ray with a surface.
struct SurfaceHit {
    double t = kInfinity;    // ray parameter (a world distance for unit world rays)
    Vec3 position{0.0};      // world space
    Vec3 normal{0.0, 0.0, 1.0};  // world space, unit, on the outward side of the surface
    Vec3 objectPoint{0.0};   // object space (before worldFromObject)
    int objectIndex = -1;    // index into SceneDescription::objects, set by the scene
    // Which part of the surface: a box's face (2 axis + 1 on the high
    // side), a cylinder's or cone's side (0), base cap (1) or top cap (2);
    // 0 for a shape of one part. Parts meet at creases (ConeClass::creaseParts).
    std::uint8_t part = 0;
};

}  // namespace asos
