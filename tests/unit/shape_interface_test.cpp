// The shapes' one interface: what the concepts accept and refuse, one
// validate per record used by both the interpreter and Primitive::make, and
// the answers the shadow tests ask of each shape.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/shapes/primitive_shape.hpp"
#include "asos/shapes/shape_issue.hpp"

using namespace asos;

namespace {

// A sphere that leaves one answer out: no longer a PrimitiveShape.
struct SphereWithoutSelfShadow : Sphere {
    using Sphere::Sphere;
    bool canShadowItself() const = delete;
};
struct SphereWithoutRaysLeave : Sphere {
    using Sphere::Sphere;
    bool raysLeave(const LocalRays&) const = delete;
};

static_assert(PrimitiveShape<Sphere> && PrimitiveShape<Box> && PrimitiveShape<Cylinder> &&
              PrimitiveShape<TruncatedCone> && PrimitiveShape<Disc> && PrimitiveShape<EllipticDisc> &&
              PrimitiveShape<Polygon> && PrimitiveShape<Plane> && PrimitiveShape<Quadric> && PrimitiveShape<Torus> &&
              PrimitiveShape<SmoothTriangle> && PrimitiveShape<Poly>);
static_assert(!PrimitiveShape<SphereWithoutSelfShadow>, "a missing answer is a compile error");
static_assert(!PrimitiveShape<SphereWithoutRaysLeave>, "a missing answer is a compile error");
static_assert(!PrimitiveShape<int>);
static_assert(ShapeRecord<SphereShape> && ShapeRecord<PolygonShape> && ShapeRecord<DiscShape> &&
              ShapeRecord<TorusShape> && ShapeRecord<TriangleShape> && ShapeRecord<PolyShape>);
static_assert(!ShapeRecord<int>, "a record without validate and place is refused");
static_assert(kEveryAlternativeShapeRecord<Shape>);
static_assert(!kEveryAlternativePrimitiveShape<std::variant<Sphere, SphereWithoutSelfShadow>>);

// The interpreter's first error on `text`, without its location.
std::string interpreterError(const std::string& text) {
    Diagnostics diagnostics;
    (void)lang::interpretText(text, "t.pov", {}, diagnostics);
    REQUIRE_FALSE(diagnostics.all().empty());
    return diagnostics.all().front().message;
}

std::string makeError(const Shape& record) {
    try {
        (void)Primitive::make(record, Transform{});
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST_CASE("One validate per record: the interpreter and Primitive::make say the same", "[shapes]") {
    struct Case {
        const char* scene;
        Shape record;
    };
    const Case cases[] = {
        {"sphere { <0, 1, 0>, -2 }", SphereShape{{0, 1, 0}, -2}},
        {"cylinder { <0, 0, 0>, <0, 0, 0>, 1 }", CylinderShape{{0, 0, 0}, {0, 0, 0}, 1, false}},
        {"cylinder { <0, 0, 0>, <0, 1, 0>, 0 }", CylinderShape{{0, 0, 0}, {0, 1, 0}, 0, false}},
        {"cone { <0, 0, 0>, -1, <0, 1, 0>, 0.5 }", ConeShape{{0, 0, 0}, -1, {0, 1, 0}, 0.5, false}},
        {"cone { <0, 0, 0>, 0, <0, 1, 0>, 0 }", ConeShape{{0, 0, 0}, 0, {0, 1, 0}, 0, false}},
        {"disc { <0, 0, 0>, <0, 0, 0>, 1 }", DiscShape{{0, 0, 0}, {0, 0, 0}, 1, 0}},
        {"disc { <0, 0, 0>, y, 1, 2 }", DiscShape{{0, 0, 0}, {0, 1, 0}, 1, 2}},
        {"plane { <0, 0, 0>, 1 }", PlaneShape{{0, 0, 0}, 1}},
        {"quadric { <0, 0, 0>, <0, 0, 0>, <0, 0, 0>, 1 }", QuadricShape{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1}},
        {"torus { 1, 0 }", TorusShape{1, 0, false}},
        {"torus { 1, 2 }", TorusShape{1, 2, false}},
        {"polygon { 3, <0, 0, 0>, <1, 0, 0>, <2, 0, 0> }", PolygonShape{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}},
        {"polygon { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 1> }",
         PolygonShape{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}}}},
    };
    for (const Case& c : cases) {
        INFO(c.scene);
        const std::vector<ShapeIssue> issues = shapeIssues(c.record);
        REQUIRE_FALSE(issues.empty());
        CHECK(interpreterError(c.scene) == issues.front().message);
        CHECK(makeError(c.record) == issues.front().message);
    }
    // Sound records have no issue, and make places them.
    CHECK(shapeIssues(SphereShape{{0, 1, 0}, 2}).empty());
    CHECK(shapeIssues(DiscShape{{0, 0, 0}, {0, 1, 0}, 2, 1}).empty());
    CHECK(makeError(BoxShape{{0, 0, 0}, {1, 1, 1}}) == "(accepted)");
}

TEST_CASE("Each shape says whether it can shadow itself: only open tubes do", "[shapes]") {
    const Transform none;
    CHECK(Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, true}, none).canShadowItself());
    CHECK(Primitive::make(ConeShape{{0, 0, 0}, 1.0, {0, 1, 0}, 0.5, true}, none).canShadowItself());
    // An open cone whose radii are equal is placed as a cylinder, and still a tube.
    CHECK(Primitive::make(ConeShape{{0, 0, 0}, 0.5, {0, 1, 0}, 0.5, true}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, false}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(ConeShape{{0, 0, 0}, 1.0, {0, 1, 0}, 0.5, false}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(SphereShape{{0, 0, 0}, 1}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(BoxShape{{0, 0, 0}, {1, 1, 1}}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1, 0.5}, none).canShadowItself());
    CHECK_FALSE(Primitive::make(PlaneShape{{0, 1, 0}, 0}, none).canShadowItself());
    CHECK_FALSE(
        Primitive::make(PolygonShape{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}}}, none).canShadowItself());
    // Under a non-uniform scale the disc becomes an ellipse: still flat.
    CHECK_FALSE(Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1, 0}, Transform::scale({2, 1, 1}))
                    .canShadowItself());
}
