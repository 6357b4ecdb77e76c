#pragma once
// Scene descriptions built in code for the renderer's tests: cameras whose
// image maps simply onto world coordinates, flat ("coverage") and lit
// textures, and the primitives.
#include <cmath>
#include <memory>

#include "asos/scene/asos_settings.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/ray_tracer.hpp"
#include "asos/scene/description.hpp"
#include "asos/scene/scene.hpp"

namespace asos::testing {

// An orthographic camera looking along +z from z = -100 whose image of
// width x height pixels covers world x in [x0, x0 + width * pixel] (left to
// right) and y in [y0 - height * pixel, y0] (top to bottom): image point
// (u, v) sees world (x0 + u * pixel, y0 - v * pixel).
inline Camera orthoCamera(int width, int height, double pixel = 1.0, double x0 = 0.0, double y0 = 0.0) {
    Camera c;
    c.projection = Camera::Projection::Orthographic;
    c.location = {x0 + 0.5 * width * pixel, y0 - 0.5 * height * pixel, -100.0};
    c.direction = {0.0, 0.0, 1.0};
    c.right = {width * pixel, 0.0, 0.0};
    c.up = {0.0, height * pixel, 0.0};
    return c;
}

// A perspective camera at `location` looking at `target`, horizontal field
// of view `angleDegrees`, as POV-Ray's look_at and angle make it.
inline Camera lookAtCamera(const Vec3& location, const Vec3& target, double angleDegrees,
                           double aspect = 4.0 / 3.0) {
    Camera c;
    c.location = location;
    const Vec3 d = glm::normalize(target - location);
    const Vec3 r = glm::normalize(glm::cross(Vec3(0, 1, 0), d));
    const Vec3 u = glm::cross(d, r);
    c.right = aspect * r;
    c.up = u;
    c.direction = 0.5 * aspect / std::tan(angleDegrees * kPi / 360.0) * d;
    return c;
}

// White, lit by ambient only: the rendered value is the covered fraction.
inline Texture coverageTexture(double value = 1.0) {
    Texture t;
    t.pigment.color1.rgb = Vec3(value);
    t.finish.ambient = Vec3(1.0);
    t.finish.diffuse = 0.0;
    return t;
}

inline Texture litTexture(const Vec3& rgb, double ambient = 0.1, double diffuse = 0.6) {
    Texture t;
    t.pigment.color1.rgb = rgb;
    t.finish.ambient = Vec3(ambient);
    t.finish.diffuse = diffuse;
    return t;
}

inline Object makeObject(const Shape& shape, const Texture& texture,
                         const Transform& worldFromObject = {}) {
    Object o;
    o.shape = shape;
    o.texture = std::make_shared<const Texture>(texture);
    o.worldFromObject = worldFromObject;
    return o;
}

inline Light pointLight(const Vec3& position, const Vec3& color = Vec3(1.0)) {
    Light l;
    l.position = position;
    l.color = color;
    return l;
}

// The area of the part of [x0, x1] x [y0, y1] where a x + b y <= c (exact,
// by clipping the square's polygon).
inline double halfPlaneArea(double x0, double y0, double x1, double y1, double a, double b, double c) {
    const Vec2 square[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    Vec2 kept[8];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        const Vec2 p = square[i], q = square[(i + 1) % 4];
        const double fp = a * p.x + b * p.y - c, fq = a * q.x + b * q.y - c;
        if (fp <= 0.0) kept[n++] = p;
        if ((fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0)) kept[n++] = p + (q - p) * (fp / (fp - fq));
    }
    double area = 0.0;
    for (int i = 0; i < n; ++i) {
        const Vec2 p = kept[i], q = kept[(i + 1) % n];
        area += p.x * q.y - q.x * p.y;
    }
    return std::abs(area) / 2.0;
}

inline std::unique_ptr<Scene> buildScene(const SceneDescription& d) {
    Diagnostics diagnostics;
    auto scene = Scene::build(d, diagnostics);
    if (!scene) throw std::invalid_argument("test scene does not build");
    return scene;
}

}  // namespace asos::testing
