#include "asos/shapes/triangle.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace asos {

SmoothTriangle::SmoothTriangle(Polygon face, const std::array<Vec3, 3>& normals)
    : face_(std::move(face)), normals_(normals) {
    const std::vector<Vec2>& v = face_.vertices();
    const Vec2 e1 = v[1] - v[0], e2 = v[2] - v[0];
    const double det = e1.x * e2.y - e1.y * e2.x;  // not 0: the face is not on one line
    inv_[0] = e2.y / det;
    inv_[1] = -e2.x / det;
    inv_[2] = -e1.y / det;
    inv_[3] = e1.x / det;
}

std::optional<LocalHit> SmoothTriangle::intersect(const Ray& ray, double tMin, double tMax) const {
    std::optional<LocalHit> hit = face_.intersect(ray, tMin, tMax);
    if (!hit) return hit;
    const Vec2 d = Vec2(hit->point.x, hit->point.y) - face_.vertices()[0];
    const double b1 = inv_[0] * d.x + inv_[1] * d.y;
    const double b2 = inv_[2] * d.x + inv_[3] * d.y;
    const Vec3 n = (1.0 - b1 - b2) * normals_[0] + b1 * normals_[1] + b2 * normals_[2];
    // Where the corners' normals cancel, the face's own.
    if (glm::dot(n, n) > 0.0) hit->normal = n;
    return hit;
}

namespace {

PolygonShape corners(const TriangleMesh& mesh, const TriangleMesh::Face& face) {
    return PolygonShape{{mesh.vertices[face.vertex[0]], mesh.vertices[face.vertex[1]], mesh.vertices[face.vertex[2]]}};
}

}  // namespace

std::vector<ShapeIssue> validate(const TriangleShape& record) {
    IssueList issues;
    if (!record.mesh || record.face >= record.mesh->faces.size()) {
        issues.add(0, "a triangle of a mesh that has no such face");
        return issues.take();
    }
    const TriangleMesh& mesh = *record.mesh;
    const TriangleMesh::Face& face = mesh.faces[record.face];
    // The statement's arguments: triangle { a, b, c }, smooth_triangle { a,
    // na, b, nb, c, nc }.
    const auto cornerArgument = [&](int i) { return face.smooth ? 2 * i : i; };
    bool known = true;
    for (int i = 0; i < 3; ++i) {
        if (face.vertex[i] >= mesh.vertices.size()) {
            issues.add(cornerArgument(i), "the triangle's corner " + std::to_string(face.vertex[i]) +
                                              " is not among the mesh's " + std::to_string(mesh.vertices.size()) +
                                              " vertices");
            known = false;
        }
        if (face.smooth && face.normal[i] >= mesh.normals.size()) {
            issues.add(2 * i + 1, "the triangle's normal " + std::to_string(face.normal[i]) +
                                      " is not among the mesh's " + std::to_string(mesh.normals.size()) + " normals");
            known = false;
        }
    }
    if (!known) return issues.take();
    bool finite = true;
    for (int i = 0; i < 3; ++i)
        finite &= issues.finite(cornerArgument(i), mesh.vertices[face.vertex[i]], "a triangle's corner");
    // Polygon's own test of a plane through the corners (place needs one).
    if (finite && !validate(corners(mesh, face)).empty())
        issues.add(0, "the triangle's corners lie on one line (a degenerate triangle)");
    if (face.smooth)
        for (int i = 0; i < 3; ++i) {
            const Vec3& n = mesh.normals[face.normal[i]];
            if (!isFinite(n) || n == Vec3(0.0))
                issues.add(2 * i + 1, "the smooth triangle's normal " + formatVector(n) + " must be finite and not zero");
        }
    return issues.take();
}

std::variant<Placed<Polygon>, Placed<SmoothTriangle>> place(const TriangleShape& record,
                                                            const Transform& worldFromObject) {
    const TriangleMesh& mesh = *record.mesh;
    const TriangleMesh::Face& face = mesh.faces[record.face];
    Placed<Polygon> flat = place(corners(mesh, face), worldFromObject);
    if (!face.smooth) return Placed<Polygon>{std::move(flat.shape), flat.frame, "triangle"};
    // The corners' normals in the world (the inverse transpose), then in the
    // local frame, which the polygon keeps rigid (a rotation and a uniform
    // scale: normals turn as vectors do).
    std::array<Vec3, 3> local;
    for (int i = 0; i < 3; ++i) {
        const Vec3 world = glm::normalize(worldFromObject.normal(mesh.normals[face.normal[i]]));
        local[i] = flat.frame.kind == LocalFrame::Kind::Translate ? world : flat.frame.localFromWorld * world;
    }
    return Placed<SmoothTriangle>{SmoothTriangle(std::move(flat.shape), local), flat.frame, SmoothTriangle::kName};
}

}  // namespace asos
