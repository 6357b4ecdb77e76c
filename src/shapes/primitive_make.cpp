// Primitive::make: checks a scene shape (POV-Ray's meaning of its
// parameters) and places its canonical local shape.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "asos/shapes/primitive.hpp"

namespace asos {

namespace {

[[noreturn]] void reject(const std::string& message) { throw std::invalid_argument(message); }

std::string str(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

void requireFinite(double v, const char* shape, const char* what) {
    if (!std::isfinite(v)) reject(std::string(shape) + ": " + what + " is not a finite number");
}

void requireFinite(const Vec3& v, const char* shape, const char* what) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        reject(std::string(shape) + ": " + what + " is not a finite vector");
}

void requireNonNegative(double v, const char* shape, const char* what) {
    requireFinite(v, shape, what);
    if (v < 0.0) reject(std::string(shape) + ": " + what + " must not be negative (got " + str(v) + ")");
}

}  // namespace

Primitive Primitive::make(const Shape& shape, const Transform& worldFromObject) {
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
        requireFinite(s->center, "sphere", "centre");
        requireNonNegative(s->radius, "sphere", "radius");
        return Primitive(Sphere(s->radius), LocalFrame::make(worldFromObject, Mat3(1.0), s->center),
                         Sphere::kName);
    }
    if (const auto* b = std::get_if<BoxShape>(&shape)) {
        requireFinite(b->corner1, "box", "first corner");
        requireFinite(b->corner2, "box", "second corner");
        return Primitive(Box(b->corner1, b->corner2),
                         LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), Box::kName);
    }
    if (const auto* p = std::get_if<PlaneShape>(&shape)) {
        requireFinite(p->normal, "plane", "normal");
        requireFinite(p->distance, "plane", "distance");
        const double len = glm::length(p->normal);
        if (!(len > 0.0)) reject("plane: the normal vector is zero");
        return Primitive(Plane(p->normal / len, p->distance),
                         LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), Plane::kName);
    }
    reject("this shape is not supported yet by the geometry module");
}

}  // namespace asos
