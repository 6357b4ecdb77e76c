// CSG (shapes/csg_clip.hpp): the primitives' inside tests and crossings it
// is built on, known answers for rays through differences, intersections,
// merges and inversions, and the conservative cone classification of a
// leaf's kept part (the property test shared with the primitives).
#include <catch2/catch.hpp>

#include <memory>

#include "asos/shapes/csg_clip.hpp"
#include "asos/shapes/depth_order.hpp"
#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

namespace {

using namespace asos;

using Op = CsgTree::Op;

// A tree built node by node: add a leaf or a compound, get its index.
struct TreeBuilder {
    std::shared_ptr<CsgTree> tree = std::make_shared<CsgTree>();
    std::uint32_t leaf(Shape shape, bool inverse = false, const Transform& t = {}) {
        const auto node = static_cast<std::uint32_t>(tree->nodes.size());
        CsgTree::Node n;
        n.op = Op::Leaf;
        n.inverse = inverse;
        n.leaf = static_cast<std::uint32_t>(tree->leaves.size());
        tree->nodes.push_back(n);
        tree->leaves.push_back({std::move(shape), t, node});
        return node;
    }
    // The root first (index 0), its children added after and attached.
    std::uint32_t compound(Op op, bool inverse = false) {
        CsgTree::Node n;
        n.op = op;
        n.inverse = inverse;
        tree->nodes.push_back(n);
        return static_cast<std::uint32_t>(tree->nodes.size() - 1);
    }
    void attach(std::uint32_t parent, std::uint32_t child) { tree->nodes[parent].children.push_back(child); }
    Primitive make(std::uint32_t leafIndex, const Transform& t = {}) const {
        return Primitive::make(CsgShape{tree, leafIndex}, t);
    }
};

std::optional<double> hitT(const Primitive& p, const Ray& ray) {
    const auto hit = p.intersect(ray, 1e-6, kInfinity);
    if (!hit) return std::nullopt;
    return hit->t;
}

}  // namespace

TEST_CASE("Every primitive answers POV-Ray's inside test", "[shapes][csg]") {
    const auto inside = [](const Shape& s, const Vec3& p, const Transform& t = {}) {
        return Primitive::make(s, t).inside(p);
    };
    CHECK(inside(SphereShape{{1, 0, 0}, 1}, {1.5, 0, 0}));
    CHECK_FALSE(inside(SphereShape{{1, 0, 0}, 1}, {2.5, 0, 0}));
    CHECK_FALSE(inside(SphereShape{{1, 0, 0}, 1}, {2, 0, 0}));  // strictly within
    CHECK(inside(BoxShape{{0, 0, 0}, {1, 2, 3}}, {1, 2, 3}));   // faces included
    CHECK_FALSE(inside(BoxShape{{0, 0, 0}, {1, 2, 3}}, {1, 2.1, 3}));
    CHECK(inside(CylinderShape{{0, 0, 0}, {0, 2, 0}, 1, false}, {0.5, 1, 0.5}));
    CHECK_FALSE(inside(CylinderShape{{0, 0, 0}, {0, 2, 0}, 1, false}, {0.5, 2.5, 0}));
    CHECK_FALSE(inside(CylinderShape{{0, 0, 0}, {0, 2, 0}, 1, false}, {1, 1, 0}));  // capped: surface out
    CHECK(inside(CylinderShape{{0, 0, 0}, {0, 2, 0}, 1, true}, {1, 1, 0}));         // open: surface in
    CHECK(inside(ConeShape{{0, 0, 0}, 1, {0, 2, 0}, 0, false}, {0.4, 1, 0}));
    CHECK_FALSE(inside(ConeShape{{0, 0, 0}, 1, {0, 2, 0}, 0, false}, {0.6, 1, 0}));
    CHECK(inside(ConeShape{{0, 0, 0}, 1, {0, 2, 0}, 0.5, false}, {0.7, 0.2, 0}));  // truncated
    CHECK(inside(PlaneShape{{0, 1, 0}, 1}, {5, 0.5, -7}));
    CHECK_FALSE(inside(PlaneShape{{0, 1, 0}, 1}, {5, 1.5, -7}));
    // A disc's inside is the half-space below its normal, however far out.
    CHECK(inside(DiscShape{{0, 1, 0}, {0, 1, 0}, 0.5, 0}, {10, 0.9, 10}));
    CHECK_FALSE(inside(DiscShape{{0, 1, 0}, {0, 1, 0}, 0.5, 0}, {0, 1.1, 0}));
    // Under a non-uniform scale (an elliptic disc): the plane moved to y = 2.
    CHECK_FALSE(inside(DiscShape{{0, 1, 0}, {0, 1, 0}, 0.5, 0}, {10, 2.1, 10}, Transform::scale({1, 2, 3})));
    CHECK(inside(DiscShape{{0, 1, 0}, {0, 1, 0}, 0.5, 0}, {10, 1.9, 10}, Transform::scale({1, 2, 3})));
    // A polygon has none.
    CHECK_FALSE(inside(PolygonShape{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {0.2, 0.2, -1}));
    CHECK_FALSE(inside(PolygonShape{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {0.2, 0.2, 1}));
}

TEST_CASE("Primitive::crossings finds every crossing in order", "[shapes][csg]") {
    const Ray ray{{-5, 0.25, 0.25}, {1, 0, 0}};
    const auto count = [&](const Shape& s, double tMin = 0.0, double tMax = kInfinity) {
        return Primitive::make(s, {}).crossings(ray, tMin, tMax).count;
    };
    CHECK(count(SphereShape{{0, 0, 0}, 1}) == 2);
    CHECK(count(SphereShape{{0, 0, 0}, 1}, 5.0) == 1);  // from inside: the far side only
    CHECK(count(BoxShape{{-1, -1, -1}, {1, 1, 1}}) == 2);
    CHECK(count(CylinderShape{{-1, 0, 0}, {1, 0, 0}, 0.5, false}) == 2);  // both caps
    CHECK(count(CylinderShape{{-1, 0, 0}, {1, 0, 0}, 0.5, true}) == 0);   // open: along the tube
    CHECK(count(CylinderShape{{0, -1, 0}, {0, 1, 0}, 0.5, true}) == 2);  // across it
    CHECK(count(ConeShape{{0, -1, 0}, 1, {0, 1, 0}, 0, false}) == 2);
    CHECK(count(PlaneShape{{1, 0, 0}, 0}) == 1);
    CHECK(count(DiscShape{{0, 0, 0}, {1, 0, 0}, 1, 0}) == 1);
    const Crossings c = Primitive::make(SphereShape{{0, 0, 0}, 1}, Transform::scale({2, 1, 1})).crossings(ray, 0, kInfinity);
    REQUIRE(c.count == 2);
    CHECK(c.hits[0].t < c.hits[1].t);
    // x^2/4 + 0.125 = 1 at |x| = sqrt(3.5).
    CHECK(c.hits[0].t == Approx(5.0 - std::sqrt(3.5)));
    CHECK(c.hits[1].t == Approx(5.0 + std::sqrt(3.5)));
}

TEST_CASE("CSG rays: difference, intersection, merge, inverse", "[shapes][csg]") {
    const Ray alongX{{-5, 0, 0}, {1, 0, 0}};
    SECTION("a box minus a sphere: the cut face is the sphere's, seen from inside it") {
        TreeBuilder b;
        const auto root = b.compound(Op::Difference);
        b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
        b.attach(root, b.leaf(SphereShape{{-1, 0, 0}, 0.5}));
        const Primitive box = b.make(0), sphere = b.make(1);
        // The box's face at x = -1 is inside the sphere there: gone; the
        // sphere's far side at x = -0.5 is the cut face.
        CHECK(hitT(box, alongX) == Approx(6.0));  // the back face, seen through the cut
        CHECK(hitT(sphere, alongX) == Approx(4.5));
        // Off the sphere the box is whole.
        const Ray high{{-5, 0.8, 0}, {1, 0, 0}};
        CHECK(hitT(box, high) == Approx(4.0));
        CHECK_FALSE(hitT(sphere, high).has_value());
        // The sphere's near side (outside the box) is never kept.
        const Ray fromLeft{{-5, 0.3, 0}, {1, 0, 0}};
        const auto t = hitT(sphere, fromLeft);
        REQUIRE(t.has_value());
        CHECK(*t > 4.0);
    }
    SECTION("a lens: two spheres' intersection") {
        TreeBuilder b;
        const auto root = b.compound(Op::Intersection);
        b.attach(root, b.leaf(SphereShape{{-0.5, 0, 0}, 1}));
        b.attach(root, b.leaf(SphereShape{{0.5, 0, 0}, 1}));
        const Primitive left = b.make(0), right = b.make(1);
        // Along x the lens runs from -0.5 (the right sphere's near side) to
        // 0.5 (the left sphere's far side).
        CHECK(hitT(right, alongX) == Approx(4.5));
        CHECK(hitT(left, alongX) == Approx(5.5));
        CHECK_FALSE(hitT(left, Ray{{-5, 0, 0.95}, {1, 0, 0}}).has_value());
        CHECK(left.bounded());
        CHECK(left.worldBounds().lo.x >= -0.5 - 1e-9);
        CHECK(left.worldBounds().hi.x <= 0.5 + 1e-9);
    }
    SECTION("a merge drops the surfaces inside the others, a union keeps them") {
        for (const Op op : {Op::Merge, Op::Union}) {
            TreeBuilder b;
            const auto root = b.compound(op);
            b.attach(root, b.leaf(SphereShape{{-0.5, 0, 0}, 1}));
            b.attach(root, b.leaf(SphereShape{{0.5, 0, 0}, 1}));
            const Primitive left = b.make(0), right = b.make(1);
            // The right sphere's near side is inside the left one: a merge
            // shows its far side only.
            CHECK(hitT(left, alongX) == Approx(3.5));
            CHECK(hitT(right, alongX) == Approx(op == Op::Union ? 4.5 : 6.5));
        }
    }
    SECTION("an inverted union in a difference acts as an intersection of its members' outsides") {
        // box - (A u B): A's surface inside B bounds nothing and is dropped.
        TreeBuilder b;
        const auto root = b.compound(Op::Difference);
        b.attach(root, b.leaf(BoxShape{{-2, -2, -2}, {2, 2, 2}}));
        const auto holes = b.compound(Op::Union);
        b.attach(root, holes);
        b.attach(holes, b.leaf(SphereShape{{-0.5, 0, 0}, 1}));
        b.attach(holes, b.leaf(SphereShape{{0.5, 0, 0}, 1}));
        const Primitive a = b.make(1), c = b.make(2);
        const Ray inside{{0, 0, 0}, {1, 0, 0}};  // from the cavity's middle
        // A's far side (x = 0.5) is inside B: not a wall of the cavity.
        CHECK_FALSE(a.intersect(inside, 0.0, kInfinity).has_value());
        CHECK(c.intersect(inside, 0.0, kInfinity)->t == Approx(1.5));
    }
    SECTION("inverse on a member of an intersection is a difference") {
        TreeBuilder b;
        const auto root = b.compound(Op::Intersection);
        b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
        b.attach(root, b.leaf(SphereShape{{-1, 0, 0}, 0.5}, true));
        CHECK(hitT(b.make(1), alongX) == Approx(4.5));
        // Inverted twice (the node and a difference): an intersection again.
        TreeBuilder d;
        const auto r2 = d.compound(Op::Difference);
        d.attach(r2, d.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
        d.attach(r2, d.leaf(SphereShape{{-1, 0, 0}, 0.5}, true));
        CHECK(hitT(d.make(1), alongX) == Approx(4.5));
        CHECK(hitT(d.make(0), alongX) == Approx(4.0));
    }
    SECTION("a plane in an intersection is bounded by the others; a polygon is never inside") {
        TreeBuilder b;
        const auto root = b.compound(Op::Intersection);
        b.attach(root, b.leaf(PlaneShape{{0, 1, 0}, 0}));
        b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
        const Primitive floor = b.make(0);
        CHECK(floor.bounded());
        CHECK(floor.worldBounds().hi.x <= 1.0 + 1e-9);
        CHECK(floor.intersect(Ray{{0.5, 3, 0}, {0, -1, 0}}, 0, kInfinity)->t == Approx(3.0));
        CHECK_FALSE(floor.intersect(Ray{{1.5, 3, 0}, {0, -1, 0}}, 0, kInfinity).has_value());
        TreeBuilder p;
        const auto r = p.compound(Op::Intersection);
        p.attach(r, p.leaf(SphereShape{{0, 0, 0}, 1}));
        p.attach(r, p.leaf(PolygonShape{{{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}}}));
        CHECK_FALSE(hitT(p.make(0), alongX).has_value());
        CHECK(hitT(p.make(1), Ray{{0, 0, -5}, {0, 0, 1}}) == Approx(5.0));
        CHECK_FALSE(hitT(p.make(1), Ray{{1.5, 0, -5}, {0, 0, 1}}).has_value());
    }
    SECTION("transforms apply to the whole, shadow tests agree with hits") {
        TreeBuilder b;
        const auto root = b.compound(Op::Difference);
        b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
        b.attach(root, b.leaf(CylinderShape{{0, 0, -2}, {0, 0, 2}, 0.5, false}));
        const Transform t = Transform::translate({10, 0, 0}) * Transform::scale({2, 2, 2});
        const Primitive wall = b.make(1, t);
        const Ray down{{10, 0, -10}, {0, 0, 1}};  // along the hole's axis: nothing
        CHECK_FALSE(wall.intersectAny(down, 0, kInfinity));
        const Ray across{{5, 0, 0}, {1, 0, 0}};  // across the hole: its walls at x = 9, 11
        CHECK(wall.intersect(across, 0, kInfinity)->t == Approx(4.0));
        CHECK(wall.intersectAny(across, 0, kInfinity));
        CHECK(wall.canShadowItself());
        CHECK_FALSE(wall.convex());
        CHECK_FALSE(wall.translatedSphere().has_value());
    }
}

TEST_CASE("A CSG leaf's cone classification", "[shapes][csg]") {
    TreeBuilder b;
    const auto root = b.compound(Op::Difference);
    b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
    b.attach(root, b.leaf(SphereShape{{0, 0, -1}, 0.5}));
    const Primitive box = b.make(0), sphere = b.make(1);
    // Head-on at the middle of the front face z = -1: the face is cut
    // there, the rays meet the hole's wall (the sphere, at 4.5) and the box's
    // back face (at 6). The sphere decides both, so both are Marginal, with
    // depths that reach the farther crossing.
    const Cone atHole{{0, 0, -5}, {0, 0, 1}, 0.01};
    const ConeClass back = box.classify(atHole), wall = sphere.classify(atHole);
    CHECK(back.coverage == Coverage::Marginal);
    CHECK(back.tFar >= 6.0);
    CHECK(wall.coverage == Coverage::Marginal);
    CHECK(wall.tNear <= 4.5);
    CHECK(wall.tFar >= 4.5);
    // Around a corner the box is whole (Full) and the sphere far (Miss).
    const Cone atCorner{{0.8, 0.8, -5}, {0, 0, 1}, 0.01};
    const ConeClass full = box.classify(atCorner);
    CHECK(full.coverage == Coverage::Full);
    CHECK(full.tNear <= 4.0);
    CHECK(full.tFar >= 4.0);
    CHECK(sphere.classify(atCorner).coverage == Coverage::Miss);
}

TEST_CASE("An oblique cone through a window cut in a wall misses both leaves", "[shapes][csg]") {
    // examples/bench/csg_room.pov's back wall. Over the depths of the wall's
    // (and the cut's) crossings the box around the oblique cone reaches
    // past the cut; its halves and the cut box's exit depths lie within.
    TreeBuilder b;
    const auto root = b.compound(Op::Difference);
    b.attach(root, b.leaf(BoxShape{{-3, 0, 3}, {3, 3, 3.15}}));
    b.attach(root, b.leaf(BoxShape{{-2.2, 1, 2.9}, {-0.8, 2.3, 3.3}}));
    const Primitive wall = b.make(0), cut = b.make(1);
    const Vec3 eye{2.0, 2.1, -2.4};
    const Cone through{eye, Vec3{-1.5, 1.65, 3.075} - eye, 0.003};
    CHECK(wall.classify(through).coverage == Coverage::Miss);
    CHECK(cut.classify(through).coverage == Coverage::Miss);
    // Beside the window the wall is whole.
    const Cone beside{eye, Vec3{0.5, 1.65, 3.0} - eye, 0.003};
    CHECK(wall.classify(beside).coverage == Coverage::Full);
    CHECK(cut.classify(beside).coverage == Coverage::Miss);
}

TEST_CASE("A hole's wall lies behind the face of the box it is cut in", "[shapes][csg]") {
    TreeBuilder b;
    const auto root = b.compound(Op::Difference);
    b.attach(root, b.leaf(BoxShape{{-1, -1, -1}, {1, 1, 1}}));
    b.attach(root, b.leaf(CylinderShape{{-1.5, 0, 0}, {1.5, 0, 0}, 0.3, false}));
    const Primitive box = b.make(0), hole = b.make(1);
    CHECK(hole.keptWithin(box, PreparedCone(Cone{{0.3, 2, -5}, {0, -0.3, 1}, 0.02})));
    CHECK_FALSE(box.keptWithin(hole, PreparedCone(Cone{{0.3, 2, -5}, {0, -0.3, 1}, 0.02})));
    // From inside the box's bounds nothing is claimed.
    CHECK_FALSE(hole.keptWithin(box, PreparedCone(Cone{{0.5, 0.5, 0.5}, {0, 0, 1}, 0.02})));
    // Oblique cones on the face beside the hole: the box is Full, the hole
    // behind it; every ray's kept hit of the hole comes after the box's.
    Rng rng(0xc5600002ull);
    int shown = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3 apex{rng.uniform(-3, 3), rng.uniform(-3, 3), -5.0};
        const Vec3 target{rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), -1.0};
        const Cone cone{apex, target - apex, rng.uniform(0.001, 0.05)};
        const PreparedCone prepared(cone);
        const ConeClass front = box.classify(prepared), back = hole.classify(prepared);
        if (front.coverage != Coverage::Full || back.coverage == Coverage::Miss) continue;
        if (!surelyInFront(box, front, hole, back, prepared)) continue;
        ++shown;
        for (const Vec3& dir : probeDirections(cone)) {
            const Ray ray{apex, dir};
            const auto f = box.intersect(ray, 0.0, kInfinity), h = hole.intersect(ray, 0.0, kInfinity);
            if (f && h) CHECK(f->t <= h->t + 1e-9);
        }
    }
    CHECK(shown > 0);
}

namespace {

// A random leaf shape about the origin, `size` across, and a point of its
// surface.
shapetest::ShapeCase randomLeaf(Rng& rng, double size) {
    using shapetest::ShapeCase;
    const Vec3 c = size * 0.5 * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double r = size * rng.uniform(0.3, 0.8);
    switch (rng.index(7)) {
        case 0: return {SphereShape{c, r}, [=](Rng& g) { return c + r * g.unitVector(); }, size, "sphere"};
        case 1: {
            const Vec3 h(r * rng.uniform(0.4, 1.0), r * rng.uniform(0.4, 1.0), r * rng.uniform(0.4, 1.0));
            return {BoxShape{c - h, c + h},
                    [=](Rng& g) {
                        Vec3 p = c + Vec3(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)) * h;
                        const int axis = g.index(3);
                        p[axis] = c[axis] + (g.chance(0.5) ? h[axis] : -h[axis]);
                        return p;
                    },
                    size, "box"};
        }
        case 2: case 3: {
            const Vec3 axis = rng.unitVector() * size * rng.uniform(0.5, 1.2);
            const bool open = rng.chance(0.3);
            const double rr = r * 0.6;
            return {CylinderShape{c - axis, c + axis, rr, open},
                    [=](Rng& g) {
                        const Mat3 f = frameAroundAxis(glm::normalize(axis));
                        const double a = g.uniform(0, 2 * kPi);
                        return c + g.uniform(-1, 1) * axis + rr * (std::cos(a) * f[0] + std::sin(a) * f[1]);
                    },
                    size, open ? "open cylinder" : "cylinder"};
        }
        case 4: {
            const Vec3 n = rng.unitVector();
            return {PlaneShape{n, glm::dot(n, c)},
                    [=](Rng& g) {
                        const Mat3 f = frameAroundAxis(n);
                        return c + size * (g.uniform(-1, 1) * f[0] + g.uniform(-1, 1) * f[1]);
                    },
                    size, "plane"};
        }
        case 5: {
            const Vec3 n = rng.unitVector();
            return {DiscShape{c, n, r, 0.0},
                    [=](Rng& g) {
                        const Mat3 f = frameAroundAxis(n);
                        const double a = g.uniform(0, 2 * kPi), q = r * std::sqrt(g.uniform());
                        return c + q * (std::cos(a) * f[0] + std::sin(a) * f[1]);
                    },
                    size, "disc"};
        }
        default: {
            const Vec3 p0 = c + size * 0.5 * rng.unitVector(), p1 = c + size * 0.5 * rng.unitVector(),
                       p2 = c + size * 0.5 * rng.unitVector();
            return {PolygonShape{{p0, p1, p2}},
                    [=](Rng& g) {
                        double u = g.uniform(), v = g.uniform();
                        if (u + v > 1) u = 1 - u, v = 1 - v;
                        return p0 + u * (p1 - p0) + v * (p2 - p0);
                    },
                    size, "triangle"};
        }
    }
}

const char* opName(Op op) {
    switch (op) {
        case Op::Union: return "union";
        case Op::Merge: return "merge";
        case Op::Intersection: return "intersection";
        case Op::Difference: return "difference";
        default: return "leaf";
    }
}

// A random tree of two or three members (one of them, at times, a nested
// compound of two), inversions at random; the case is one leaf of it.
shapetest::ShapeCase randomCsg(Rng& rng) {
    const double size = 1.0;
    TreeBuilder b;
    std::vector<shapetest::ShapeCase> leaves;
    std::string text;
    const Op ops[] = {Op::Union, Op::Merge, Op::Intersection, Op::Difference};
    auto addCompound = [&](auto& self, int depth) -> std::uint32_t {
        const Op op = ops[rng.index(4)];
        const auto node = b.compound(op, rng.chance(0.2));
        text += std::string(opName(op)) + (b.tree->nodes[node].inverse ? " inverse" : "") + " { ";
        const int members = 2 + rng.index(2);
        for (int i = 0; i < members; ++i) {
            if (depth == 0 && rng.chance(0.25)) {
                b.attach(node, self(self, depth + 1));
                continue;
            }
            shapetest::ShapeCase leaf = randomLeaf(rng, size);
            const bool inverse = rng.chance(0.15);
            text += leaf.text + (inverse ? " inverse" : "") + " ";
            b.attach(node, b.leaf(leaf.shape, inverse));
            leaves.push_back(std::move(leaf));
        }
        text += "} ";
        return node;
    };
    addCompound(addCompound, 0);
    const auto pick = static_cast<std::uint32_t>(rng.index(static_cast<int>(leaves.size())));
    text += "leaf " + std::to_string(pick);
    return {CsgShape{b.tree, pick}, leaves[pick].surfacePoint, size, text};
}

}  // namespace

TEST_CASE("CSG cone classification is conservative (property)", "[shapes][csg][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("csg", 0xc5600001ull, 20000, randomCsg);
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("A cut's wall seen from its own surface: the exits a clip drops", "[shapes][csg]") {
    // examples/bench/csg_room.pov's window reveal and bowl.
    TreeBuilder b;
    const auto root = b.compound(Op::Difference);
    b.attach(root, b.leaf(BoxShape{{-3, 0, 3}, {3, 3, 3.15}}));
    b.attach(root, b.leaf(BoxShape{{-2.2, 1, 2.9}, {-0.8, 2.3, 3.3}}));
    const Primitive cut = b.make(1);
    const Vec3 light{0.3, 2.8, 0.4};
    for (const Vec3& p : {Vec3{-2.2, 1.5, 3.05}, Vec3{-1.5, 1.0, 3.1}, Vec3{-1.5, 1.0, 3.149}}) {
        Cone cone{p, light - p, 0.18};
        cone.tMin = 1e-3;
        const ConeClass k = cut.classify(PreparedCone(cone));
        INFO(p.x << " " << p.y << " " << p.z << " -> " << int(k.coverage) << " [" << k.tNear << ", " << k.tFar << "]");
        CHECK(k.coverage == Coverage::Miss);
    }
}

TEST_CASE("A CSG leaf seen from within its solid or on its surface is conservative (property)",
          "[shapes][csg][property]") {
    // Cones from a point of the leaf's own surface (a shaded point's shadow
    // beam) or inside its solid, their rays counted from 1e-3 on
    // (Primitive::exitsClass): every probe ray's kept hit agrees.
    Rng rng(0xc5600003ull);
    int misses = 0, cases = 0, failures = 0;
    for (int i = 0; i < 4000; ++i) {
        const shapetest::ShapeCase shape = randomCsg(rng);
        const Primitive prim = Primitive::make(shape.shape, Transform{});
        Vec3 apex = shape.surfacePoint(rng);
        if (rng.chance(0.3)) apex += rng.unitVector() * rng.uniform(0.0, 0.3);
        Cone cone{apex, rng.unitVector(), rng.uniform(0.001, 0.4)};
        cone.tMin = 1e-3;
        const ConeClass k = prim.classify(PreparedCone(cone));
        ++cases;
        if (k.coverage == Coverage::Miss) ++misses;
        for (const Vec3& dir : probeDirections(cone)) {
            const auto hit = prim.intersect(Ray{apex, dir}, cone.tMin, kInfinity);
            const bool wrong = k.coverage == Coverage::Miss ? hit.has_value()
                               : k.coverage == Coverage::Full
                                   ? !hit || hit->t < k.tNear - 1e-9 || hit->t > k.tFar + 1e-9
                                   : hit && (hit->t < k.tNear - 1e-9 || hit->t > k.tFar + 1e-9);
            if (wrong && failures++ < 5)
                FAIL_CHECK("case " << i << ": " << shape.text << "\n  apex " << shapetest::fmt(apex) << " axis "
                                   << shapetest::fmt(cone.axis) << " half-angle " << cone.halfAngle << "\n  answer "
                                   << int(k.coverage) << " [" << k.tNear << ", " << k.tFar << "], the ray along "
                                   << shapetest::fmt(dir) << (hit ? " hits at " + std::to_string(hit->t) : " misses"));
            if (wrong) break;
        }
    }
    CHECK(failures == 0);
    CHECK(misses > cases / 10);
}
