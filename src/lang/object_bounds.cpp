#include "src/lang/object_bounds.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "asos/geometry/polytope.hpp"
#include "asos/shapes/primitive.hpp"

namespace asos::lang {

namespace {

// Far beyond any scene: a polytope reaching it is taken as unbounded.
constexpr double kFar = 1e8;

const Bounds3 kFarBox{Vec3(-kFar), Vec3(kFar)};

Bounds3 boxOf(const std::vector<Vec3>& points) {
    Bounds3 b;
    for (const Vec3& p : points) b.extend(p);
    return b;
}

Bounds3 intersectionOf(const Bounds3& a, const Bounds3& b) { return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)}; }

// The world box of a shape object's surface (a solid's: of its inside too);
// nullopt where it is unbounded.
std::optional<Bounds3> shapeBox(const ObjectTree& t) {
    if (t.mesh) {
        Bounds3 b;
        for (const Vec3& v : t.mesh->vertices) b.extend(t.worldFromObject.point(v));
        return b;
    }
    try {
        const Primitive p = Primitive::make(t.shape, t.worldFromObject);
        if (!p.bounded()) return std::nullopt;
        return p.worldBounds();
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

// The half-space of a plane object (its inside, or its outside inverted),
// in the world.
std::optional<HalfSpace> halfSpaceOf(const ObjectTree& t, bool inverted) {
    if (t.kind != ObjectTree::Kind::Shape || t.mesh || !clipsOf(t).empty()) return std::nullopt;
    const auto* plane = std::get_if<PlaneShape>(&t.shape);
    if (!plane) return std::nullopt;
    const double length = glm::length(plane->normal);
    if (!(length > 0.0)) return std::nullopt;
    // dot(n, p) <= d in the object; p = A^-1 (w - t) in the world.
    const Vec3 n = plane->normal / length;
    const Vec3 worldNormal = t.worldFromObject.normal(n);
    const Vec3 origin = t.worldFromObject.point(Vec3(0.0));
    HalfSpace h{worldNormal, plane->distance + glm::dot(worldNormal, origin)};
    if (inverted != t.inverse) h = {-h.normal, -h.offset};
    return h;
}

std::optional<std::vector<Vec3>> hullPoints(const ObjectTree& t);

// The constraints an intersection gathers: half-spaces, and a box from its
// bounded members.
struct Cut {
    std::vector<HalfSpace> halfSpaces;
    Bounds3 box = kFarBox;
    bool bounded = false;  // some member's box is in `box`

    // A member that holds the intersection (not inverted, or a plane
    // inverted: its outside's half-space).
    void add(const ObjectTree& member, bool inverted) {
        if (member.kind == ObjectTree::Kind::Light) return;
        if (const std::optional<HalfSpace> h = halfSpaceOf(member, inverted)) {
            halfSpaces.push_back(*h);
            return;
        }
        if (inverted) return;  // an inverted solid holds nothing bounded
        if (const std::optional<std::vector<Vec3>> points = hullPoints(member)) {
            box = intersectionOf(box, boxOf(*points));
            bounded = true;
        }
    }
    std::optional<std::vector<Vec3>> points() const {
        if (halfSpaces.empty()) {
            if (!bounded) return std::nullopt;
            if (box.empty()) return std::vector<Vec3>{};
            std::vector<Vec3> corners;
            for (int i = 0; i < 8; ++i) corners.push_back(box.corner(i));
            return corners;
        }
        if (box.empty()) return std::vector<Vec3>{};
        std::optional<std::vector<Vec3>> vertices = polytopeVertices(halfSpaces, box);
        if (!vertices) return std::nullopt;
        if (!bounded)
            for (const Vec3& v : *vertices)
                if (glm::any(glm::greaterThanEqual(glm::abs(v), Vec3(0.999 * kFar)))) return std::nullopt;
        return vertices;
    }
};

// Points whose convex hull holds the object's solid and surface (what its
// clips keep of them); nullopt where none is found (an unbounded solid: a
// plane, anything inverted, a union holding one).
std::optional<std::vector<Vec3>> hullPoints(const ObjectTree& t) {
    if (t.kind == ObjectTree::Kind::Light) return std::vector<Vec3>{};
    if (t.inverse) return std::nullopt;
    std::optional<std::vector<Vec3>> own;
    Cut cut;
    const bool intersection = t.kind == ObjectTree::Kind::Union &&
                              (t.op == CsgTree::Op::Intersection || t.op == CsgTree::Op::Difference);
    if (intersection) {
        bool first = true;
        for (const ObjectTree& child : t.children) {
            if (child.kind == ObjectTree::Kind::Light) continue;
            cut.add(child, t.op == CsgTree::Op::Difference && !first);
            first = false;
        }
    } else if (t.kind == ObjectTree::Kind::Union) {
        std::vector<Vec3> all;
        bool unbounded = false;
        for (const ObjectTree& child : t.children) {
            const std::optional<std::vector<Vec3>> points = hullPoints(child);
            if (!points) {
                unbounded = true;
                break;
            }
            all.insert(all.end(), points->begin(), points->end());
        }
        if (!unbounded) own = std::move(all);
    } else if (!halfSpaceOf(t, false)) {
        if (const std::optional<Bounds3> box = shapeBox(t)) {
            std::vector<Vec3> corners;
            for (int i = 0; i < 8; ++i) corners.push_back(box->corner(i));
            own = std::move(corners);
        }
    } else {
        cut.add(t, false);  // a plane: its half-space, cut below
    }
    if (clipsOf(t).empty() && !intersection) return own;
    if (own) {
        cut.box = intersectionOf(cut.box, boxOf(*own));
        cut.bounded = true;
    }
    for (const ObjectTree& clip : clipsOf(t)) cut.add(clip, false);
    return cut.points();
}

// A solid that holds every point of the convex bound it is part of, with
// the centre it is grown about by the tolerance.
struct ConvexSolid {
    Primitive solid;
    Vec3 centre;
};

// The convex solids whose intersection is the bound (a sphere, a box, a
// cylinder, a cone, or an intersection of them), each made once for all the
// points asked of it; false where the bound is not one of those.
bool convexSolids(const ObjectTree& bound, std::vector<ConvexSolid>& out) {
    if (bound.kind == ObjectTree::Kind::Light || bound.inverse) return false;
    if (bound.kind == ObjectTree::Kind::Union) {
        if (bound.op != CsgTree::Op::Intersection) return false;
        for (const ObjectTree& member : bound.children)
            if (!convexSolids(member, out)) return false;
        return true;
    }
    if (bound.mesh || !clipsOf(bound).empty()) return false;
    const bool convex = std::holds_alternative<SphereShape>(bound.shape) ||
                        std::holds_alternative<BoxShape>(bound.shape) ||
                        std::holds_alternative<CylinderShape>(bound.shape) ||
                        std::holds_alternative<ConeShape>(bound.shape);
    if (!convex) return false;
    try {
        Primitive solid = Primitive::make(bound.shape, bound.worldFromObject);
        const Vec3 centre = solid.worldBounds().center();
        out.push_back({std::move(solid), centre});
        return true;
    } catch (const std::invalid_argument&) {
        return false;
    }
}

// Whether every point lies within each solid grown by the tolerance about
// its centre (the point drawn toward the centre instead).
bool allWithin(const std::vector<ConvexSolid>& solids, const std::vector<Vec3>& points) {
    for (const ConvexSolid& s : solids)
        for (const Vec3& p : points)
            if (!s.solid.inside(s.centre + (p - s.centre) / (1.0 + kBoundTolerance))) return false;
    return true;
}

// Whether POV-Ray keeps the bound of an object placed alone: a CSG, a
// text, a quadric without a finite box of its own, a poly.
bool keepsBound(const ObjectTree& t) {
    if (t.kind == ObjectTree::Kind::Union) return true;
    if (t.mesh) return false;
    if (const auto* extrusion = std::get_if<ExtrusionShape>(&t.shape))
        return std::string_view(extrusion->keyword) == "text";
    if (std::holds_alternative<QuadricShape>(t.shape)) return !shapeBox(t);
    // A poly's box is POV-Ray's infinite one (Poly::Compute_BBox), whatever
    // asos shows of it.
    if (std::holds_alternative<PolyShape>(t.shape)) return true;
    return false;
}

double volumeOf(const Bounds3& b) {
    if (b.empty()) return 0.0;
    const Vec3 d = b.diagonal();
    return d.x * d.y * d.z;
}

// Whether `inner` lies in `outer` grown by the tolerance.
bool within(const Bounds3& inner, const Bounds3& outer) {
    const Vec3 slack = kBoundTolerance * (outer.diagonal() + Vec3(glm::length(outer.center())));
    return glm::all(glm::greaterThanEqual(inner.lo, outer.lo - slack)) &&
           glm::all(glm::lessThanEqual(inner.hi, outer.hi + slack));
}

}  // namespace

BoundsFate boundsFate(const ObjectTree& tree, bool placed) {
    BoundsFate fate;
    const std::optional<std::vector<Vec3>> points = hullPoints(tree);
    if (!placed || keepsBound(tree)) {
        fate.kind = BoundsFate::Kind::Bound;
        std::vector<ConvexSolid> solids;
        bool convex = true;
        for (const ObjectTree& bound : boundsOf(tree)) convex = convex && convexSolids(bound, solids);
        fate.contained = points && convex && allWithin(solids, *points);
        return fate;
    }
    // The bound's box: its objects' (but inverted ones') boxes intersected.
    Bounds3 box = kFarBox;
    bool bounded = false;
    for (const ObjectTree& bound : boundsOf(tree)) {
        if (bound.inverse) continue;
        if (const std::optional<std::vector<Vec3>> b = hullPoints(bound)) {
            box = intersectionOf(box, boxOf(*b));
            bounded = true;
        }
    }
    if (!bounded) return fate;  // POV-Ray's box of the object stays
    if (points) {
        const Bounds3 own = boxOf(*points);
        if (volumeOf(box) >= volumeOf(own) || within(own, box)) return fate;
    }
    fate.kind = BoundsFate::Kind::Box;
    fate.contained = false;
    fate.box = box;
    return fate;
}

}  // namespace asos::lang
