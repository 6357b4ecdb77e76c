#pragma once
#include "asos/geometry/vec.hpp"

namespace asos {

// The nearest intersection of a ray with a surface.
struct SurfaceHit {
    double t = kInfinity;    // ray parameter (a world distance for unit world rays)
    Vec3 position{0.0};      // world space
    Vec3 normal{0.0, 0.0, 1.0};  // world space, unit, on the outward side of the surface
    Vec3 objectPoint{0.0};   // object space (before worldFromObject)
    int objectIndex = -1;    // index into SceneDescription::objects, set by the scene
};

}  // namespace asos
