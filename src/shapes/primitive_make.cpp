// Primitive::make: checks a scene shape (POV-Ray's meaning of its
// parameters) and places its canonical local shape.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <sstream>
#include <stdexcept>
#include <string>

#include "asos/geometry/frame.hpp"
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

// POV-Ray's polygon: the plane and the loops of its point list.
struct PolygonLayout {
    Mat3 objectFromLocal{1.0};
    Vec3 origin{0.0};
    std::vector<Vec2> vertices;
    std::vector<std::uint32_t> loopEnds;
};

PolygonLayout layOutPolygon(const std::vector<Vec3>& points) {
    if (points.size() < 3)
        reject("polygon: needs at least three points (got " + std::to_string(points.size()) + ")");
    for (const Vec3& p : points) requireFinite(p, "polygon", "a point");
    PolygonLayout out;
    out.origin = points[0];
    double extent = 0.0;
    for (const Vec3& p : points) extent = std::max(extent, glm::length(p - out.origin));
    // POV-Ray's normal: u = the first point away from the first, then the
    // cross product with the first later point not in line with it.
    Vec3 normal(0.0);
    std::size_t i = 1;
    Vec3 u(0.0);
    for (; i < points.size(); ++i) {
        u = points[i] - out.origin;
        if (glm::length(u) > 1e-12 * extent) break;
    }
    for (++i; i < points.size(); ++i) {
        const Vec3 v = points[i] - out.origin;
        const Vec3 w = glm::cross(u, v);
        if (glm::length(w) > 1e-9 * glm::length(u) * glm::length(v)) {
            normal = glm::normalize(w);
            break;
        }
    }
    if (normal == Vec3(0.0)) {
        // Collinear: an empty polygon (POV-Ray ignores it), bounded by its points.
        normal = glm::length(u) > 0.0 ? glm::normalize(glm::cross(u, frameAroundAxis(
                                                                         glm::normalize(u))[0]))
                                      : Vec3(0.0, 0.0, 1.0);
        out.objectFromLocal = frameAroundAxis(normal);
        for (const Vec3& p : points)
            out.vertices.emplace_back(glm::dot(p - out.origin, out.objectFromLocal[0]),
                                      glm::dot(p - out.origin, out.objectFromLocal[1]));
        return out;
    }
    for (const Vec3& p : points)
        if (std::abs(glm::dot(p - out.origin, normal)) > 1e-9 * extent)
            reject("polygon: the points are not coplanar");
    out.objectFromLocal = frameAroundAxis(normal);
    const Vec3 e1 = out.objectFromLocal[0], e2 = out.objectFromLocal[1];
    // Sub-polygons close when their first point repeats; the last one is
    // closed if it is not (POV-Ray warns and closes it).
    std::size_t start = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const bool closes = k > start && glm::all(glm::lessThan(glm::abs(points[k] - points[start]),
                                                                Vec3(1e-10)));
        if (closes) {
            out.loopEnds.push_back(static_cast<std::uint32_t>(out.vertices.size()));
            start = k + 1;
            continue;
        }
        const Vec3 d = points[k] - out.origin;
        out.vertices.emplace_back(glm::dot(d, e1), glm::dot(d, e2));
    }
    if (start < points.size()) out.loopEnds.push_back(static_cast<std::uint32_t>(out.vertices.size()));
    return out;
}

// The rigid placement of an axis from base to cap; throws when they coincide.
struct AxisPlacement {
    Mat3 objectFromLocal;
    double length;
};

AxisPlacement placeAxis(const Vec3& base, const Vec3& cap, const char* shape) {
    const Vec3 axis = cap - base;
    const double length = glm::length(axis);
    const double scale = std::abs(base.x) + std::abs(base.y) + std::abs(base.z) + std::abs(cap.x) +
                         std::abs(cap.y) + std::abs(cap.z);
    if (!(length > 1e-12 * scale) || length == 0.0)
        reject(std::string(shape) + ": the base and cap points coincide (degenerate " + shape + ")");
    return {frameAroundAxis(axis / length), length};
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
    if (const auto* c = std::get_if<CylinderShape>(&shape)) {
        requireFinite(c->base, "cylinder", "base point");
        requireFinite(c->cap, "cylinder", "cap point");
        requireNonNegative(c->radius, "cylinder", "radius");
        const AxisPlacement axis = placeAxis(c->base, c->cap, "cylinder");
        return Primitive(Cylinder(c->radius, axis.length, c->open),
                         LocalFrame::make(worldFromObject, axis.objectFromLocal, c->base),
                         Cylinder::kName);
    }
    if (const auto* c = std::get_if<ConeShape>(&shape)) {
        requireFinite(c->base, "cone", "base point");
        requireFinite(c->cap, "cone", "cap point");
        requireNonNegative(c->baseRadius, "cone", "base radius");
        requireNonNegative(c->capRadius, "cone", "cap radius");
        const AxisPlacement axis = placeAxis(c->base, c->cap, "cone");
        const LocalFrame frame = LocalFrame::make(worldFromObject, axis.objectFromLocal, c->base);
        if (c->baseRadius == c->capRadius)  // as POV-Ray: really a cylinder
            return Primitive(Cylinder(c->baseRadius, axis.length, c->open), frame,
                             TruncatedCone::kName);
        return Primitive(TruncatedCone(c->baseRadius, c->capRadius, axis.length, c->open), frame,
                         TruncatedCone::kName);
    }
    if (const auto* d = std::get_if<DiscShape>(&shape)) {
        requireFinite(d->center, "disc", "centre");
        requireFinite(d->normal, "disc", "normal");
        requireNonNegative(d->radius, "disc", "radius");
        requireNonNegative(d->holeRadius, "disc", "hole radius");
        const double len = glm::length(d->normal);
        if (!(len > 0.0)) reject("disc: the normal vector is zero");
        const Disc disc(d->radius, d->holeRadius);
        const LocalFrame frame =
            LocalFrame::make(worldFromObject, frameAroundAxis(d->normal / len), d->center);
        if (frame.kind != LocalFrame::Kind::General || disc.empty())
            return Primitive(disc, frame, Disc::kName);
        // An affine image of a circle is an ellipse: the disc is laid out
        // again in a rigid frame whose x and y run along the axes of the
        // ellipse {A x : |x| <= radius} (A = inPlane), the eigenvectors of
        // A A^T, its semi-axes radius times the rows' lengths there.
        const glm::dmat2 a = frame.flattened().inPlane;
        const glm::dmat2 p = a * glm::transpose(a);
        const double angle = 0.5 * std::atan2(2.0 * p[1][0], p[0][0] - p[1][1]);
        const LocalFrame::Flattened flat = frame.flattened(angle);
        const glm::dmat2& b = flat.inPlane;
        return Primitive(EllipticDisc(d->radius * std::hypot(b[0][0], b[1][0]),
                                      d->radius * std::hypot(b[0][1], b[1][1]),
                                      d->holeRadius / d->radius),
                         flat.frame, Disc::kName);
    }
    if (const auto* p = std::get_if<PolygonShape>(&shape)) {
        PolygonLayout layout = layOutPolygon(p->points);
        LocalFrame frame = LocalFrame::make(worldFromObject, layout.objectFromLocal, layout.origin);
        if (frame.kind == LocalFrame::Kind::General) {
            // An affine image of a planar polygon is a planar polygon: in a
            // rigid frame its cones stay circular and are classified exactly.
            const LocalFrame::Flattened flat = frame.flattened();
            for (Vec2& v : layout.vertices) v = flat.inPlane * v;
            frame = flat.frame;
        }
        return Primitive(Polygon(std::move(layout.vertices), std::move(layout.loopEnds)), frame,
                         Polygon::kName);
    }
    if (const auto* p = std::get_if<PlaneShape>(&shape)) {
        requireFinite(p->normal, "plane", "normal");
        requireFinite(p->distance, "plane", "distance");
        const double len = glm::length(p->normal);
        if (!(len > 0.0)) reject("plane: the normal vector is zero");
        return Primitive(Plane(p->normal / len, p->distance),
                         LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), Plane::kName);
    }
    reject("unknown shape");
}

}  // namespace asos
