// triangle, smooth_triangle, mesh and mesh2: the faces' hits and cones, and
// the language's meshes (one Object per face).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "asos/shapes/primitive.hpp"
#include "interpret_text.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
TriangleShape flat(Vec3 a, Vec3 b, Vec3 c) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices = {a, b, c};
    mesh->faces.push_back({{0, 1, 2}, {}, false});
    return {mesh, 0};
}
TriangleShape smooth(Vec3 a, Vec3 na, Vec3 b, Vec3 nb, Vec3 c, Vec3 nc) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices = {a, b, c};
    mesh->normals = {glm::normalize(na), glm::normalize(nb), glm::normalize(nc)};
    mesh->faces.push_back({{0, 1, 2}, {0, 1, 2}, true});
    return {mesh, 0};
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Triangle ray hits", "[shapes][triangle]") {
    const Primitive t = Primitive::make(flat({0, 0, 0}, {2, 0, 0}, {0, 2, 0}), {});
    auto hit = t.intersect({{0.5, 0.5, 3}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(std::abs(hit->normal.z) == Approx(1.0));
    CHECK_FALSE(t.intersect({{1.5, 1.5, 3}, {0, 0, -1}}, 0.0, kInfinity));  // past the hypotenuse
    CHECK(t.selfOcclusion() == Primitive::SelfOcclusion::None);
    CHECK(t.convex());
    CHECK_FALSE(t.inside({0.5, 0.5, 0}));  // POV-Ray's triangle has no inside
}

TEST_CASE("Smooth triangle normals are interpolated across the face", "[shapes][triangle]") {
    const Vec3 na = glm::normalize(Vec3(-1, 0, 1)), nb = glm::normalize(Vec3(1, 0, 1)), nc(0, 0, 1);
    const TriangleShape s = smooth({0, 0, 0}, na, {2, 0, 0}, nb, {0, 2, 0}, nc);
    const Primitive p = Primitive::make(s, {});
    // At a corner, its own normal; at the midpoint of a and b, their mean.
    auto hit = p.intersect({{1e-9, 1e-9, 1}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->normal, na, 1e-8));
    hit = p.intersect({{1, 1e-12, 1}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->normal, Vec3(0, 0, 1), 1e-9));
    // Under a non-uniform scale the normals turn as normals do (inverse transpose).
    const Primitive scaled = Primitive::make(s, Transform::scale({1, 1, 3}));
    hit = scaled.intersect({{1e-9, 1e-9, 1}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->normal, glm::normalize(Vec3(-1, 0, 1.0 / 3.0)), 1e-8));
}

TEST_CASE("Degenerate triangles are refused", "[shapes][triangle]") {
    CHECK_THROWS_WITH(Primitive::make(flat({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), {}),
                      "the triangle's corners lie on one line (a degenerate triangle)");
    TriangleShape zero = smooth({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 0, 1});
    auto mesh = std::make_shared<TriangleMesh>(*zero.mesh);
    mesh->normals[2] = Vec3(0.0);
    zero.mesh = mesh;
    CHECK_THROWS_WITH(Primitive::make(zero, {}), "the smooth triangle's normal <0, 0, 0> must be finite and not zero");
}

TEST_CASE("Triangle cone classification is conservative (property)", "[shapes][triangle][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("triangle", 0x7e1a9ull, 8000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 a = rng.unitVector() * rng.uniform(0.2, 1.5), b = rng.unitVector() * rng.uniform(0.2, 1.5),
                   c = rng.unitVector() * rng.uniform(0.2, 1.5);
        const bool isSmooth = rng.uniform(0.0, 1.0) < 0.5;
        sc.shape = isSmooth ? smooth(a, rng.unitVector(), b, rng.unitVector(), c, rng.unitVector()) : flat(a, b, c);
        sc.surfacePoint = [=](Rng& r) {
            double u = r.uniform(0.0, 1.0), v = r.uniform(0.0, 1.0);
            if (u + v > 1.0) {
                u = 1.0 - u;
                v = 1.0 - v;
            }
            return a + u * (b - a) + v * (c - a);
        };
        sc.size = 1.5;
        sc.text = std::string(isSmooth ? "smooth_" : "") + "triangle { " + fmt(a) + ", " + fmt(b) + ", " + fmt(c) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("mesh and mesh2 place one object per face", "[lang][mesh]") {
    using test::ok;
    using test::run;
    {
        const test::Run r = run("mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
                                "  smooth_triangle { <0,0,0>, <0,0,2>, <1,0,0>, z, <0,1,0>, z }\n"
                                "  translate x pigment { rgb 1 } }");
        const auto& scene = ok(r);
        REQUIRE(scene.objects.size() == 2);
        const auto& f0 = std::get<TriangleShape>(scene.objects[0].shape);
        const auto& f1 = std::get<TriangleShape>(scene.objects[1].shape);
        CHECK(f0.mesh == f1.mesh);
        CHECK_FALSE(f0.mesh->faces[f0.face].smooth);
        CHECK(f1.mesh->faces[f1.face].smooth);
        CHECK(f1.mesh->normals[f1.mesh->faces[f1.face].normal[0]] == Vec3(0, 0, 1));  // made unit
        CHECK(scene.objects[1].worldFromObject.point(Vec3(0)) == Vec3(1, 0, 0));
        CHECK(scene.objects[0].texture == scene.objects[1].texture);
    }
    {
        const test::Run r = run("mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
                                "  normal_vectors { 1, z }\n"
                                "  face_indices { 2, <0,1,2>, <0,2,3> }\n"
                                "  normal_indices { 2, <0,0,0>, <0,0,0> } }");
        const auto& scene = ok(r);
        REQUIRE(scene.objects.size() == 2);
        const auto& f = std::get<TriangleShape>(scene.objects[1].shape);
        CHECK(f.mesh->faces[1].vertex == std::array<std::uint32_t, 3>{0, 2, 3});
        CHECK(f.mesh->faces[1].smooth);
    }
    // A degenerate face is left out, with a warning.
    const test::Run degenerate = run("mesh { triangle { 0, x, 2*x } triangle { 0, x, y } }");
    CHECK(ok(degenerate).objects.size() == 1);
    CHECK(degenerate.errors().starts_with("1:8: 1 degenerate triangle(s) of this mesh left out, as POV-Ray does\n"));
    // In a CSG, a mesh is a union of its faces.
    const test::Run csg = run("difference { box { -1, 1 } mesh { triangle { <-2,-2,0>, <2,-2,0>, <0,2,0> } } }");
    CHECK(ok(csg).objects.size() == 2);
}

TEST_CASE("mesh and mesh2 misuse", "[lang][mesh]") {
    using test::run;
    CHECK(run("mesh2 { vertex_vectors { 2, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }").errors() ==
          "1:26: vertex_vectors announces 2 entries but lists 3\n");
    CHECK(run("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }").errors() ==
          "1:75: the index 3 is not one of the 3 vertex_vectors\n");
    CHECK(run("mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 1, 0 } face_indices { 1, <0,1,2> } }").errors() ==
          "1:39: 'uv_vectors' is not supported by asos\n");
    CHECK(run("mesh { triangle { 0, x, y } inside_vector z }").errors() ==
          "1:29: 'inside_vector' is not supported by asos\n");
    CHECK(run("mesh { triangle { 0, x, y } translate x triangle { 0, x, y } }").errors() ==
          "1:41: the triangles of a mesh come before its modifiers\n");
    CHECK(run("mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } }").errors() ==
          "1:27: a mesh's triangles take no modifiers (a texture for each triangle is not supported by asos)\n");
    CHECK(run("triangle { 0, x, 2*x }").errors() ==
          "1:12: the triangle's corners lie on one line (a degenerate triangle)\n");
    CHECK(run("torus { 1, 2 }").errors() ==
          "1:12: a torus whose minor radius 2 exceeds its major radius 1 (POV-Ray's spindle torus) is not supported\n");
    CHECK(run("sphere { 0, 1 sturm }").errors() == "1:15: 'sturm' applies only to a torus, a poly, a quartic, a cubic or a prism here\n");
}
