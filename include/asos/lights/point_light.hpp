#pragma once
// A point light: all its power from the light's position (LightModel). It
// has no area, so no beam of pieces and no grid: its shadows are the point
// light shadow pyrays (render/point_light_shadow.hpp) and plain shadow rays
// (render/ray_tracer.hpp), and it sends a point its whole colour.
namespace asos {

struct PointLight {
    static constexpr const char* kName = "point";
    // Its size (area, length): none.
    double size() const { return 0.0; }
};

}  // namespace asos
