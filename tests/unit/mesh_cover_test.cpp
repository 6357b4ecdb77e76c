// MeshCover: the faces of one mesh that a cone meets, joined into a sheet
// that covers it, with known answers (a flat quad, its boundary, a fold) and
// a property: where it finds a sheet, every ray of the cone meets the sheet
// first.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "asos/geometry/frame.hpp"
#include "asos/render/mesh_cover.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/testing/rng.hpp"

using namespace asos;

namespace {

// A scene of one mesh, a face an object, as the interpreter makes it.
SceneDescription meshScene(std::shared_ptr<TriangleMesh> mesh) {
    SceneDescription d;
    for (std::uint32_t f = 0; f < mesh->faces.size(); ++f) {
        Object o;
        o.shape = TriangleShape{mesh, f};
        d.objects.push_back(o);
    }
    return d;
}

MeshCover coverOf(const SceneDescription& d) {
    return MeshCover(d, std::vector<std::uint8_t>(d.objects.size(), 1));
}

// The objects the cone may meet, as the tracer lists them.
std::vector<MeshCandidate> candidates(const SceneDescription& d, const PreparedCone& cone) {
    std::vector<MeshCandidate> out;
    for (std::uint32_t i = 0; i < d.objects.size(); ++i) {
        const ConeClass k = Primitive::make(d.objects[i].shape, d.objects[i].worldFromObject).classify(cone);
        if (k.coverage != Coverage::Miss) out.push_back({i, k.tNear, k.tFar});
    }
    return out;
}

PreparedCone downCone(Vec3 apex, double halfAngle) {
    return PreparedCone(Cone{apex, Vec3(0, 0, -1), halfAngle, 0.0, kInfinity}, true);
}

// The square [-1, 1]^2 at z = 0 as two triangles over its diagonal.
std::shared_ptr<TriangleMesh> quad() {
    auto m = std::make_shared<TriangleMesh>();
    m->vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    m->faces = {{{0, 1, 2}, {}, false}, {{0, 2, 3}, {}, false}};
    return m;
}

// Two faces over the edge x = 0, z = 0; the second's far corner at (x, 0, z).
std::shared_ptr<TriangleMesh> hinge(double x, double z) {
    auto m = std::make_shared<TriangleMesh>();
    m->vertices = {{0, -1, 0}, {0, 1, 0}, {1, 0, 0}, {x, 0, z}};
    m->faces = {{{0, 1, 2}, {}, false}, {{1, 0, 3}, {}, false}};
    return m;
}

}  // namespace

TEST_CASE("A cone inside a flat quad of two triangles is covered", "[mesh_cover]") {
    const SceneDescription d = meshScene(quad());
    const MeshCover cover = coverOf(d);
    // Over the diagonal: Marginal on both faces, Full on the mesh.
    const PreparedCone cone = downCone({0.1, 0.1, 5}, 0.05);
    const auto list = candidates(d, cone);
    REQUIRE(list.size() == 2);
    const auto sheet = cover.cover(d, cone, list);
    REQUIRE(sheet);
    CHECK(sheet->member == std::vector<std::uint8_t>{1, 1});
    CHECK(sheet->normalJump == 0.0);  // coplanar: no crease
    CHECK(sheet->tNear <= 5.0);
    CHECK(sheet->tFar >= 5.0);
}

TEST_CASE("A cone over a mesh's boundary edge is not covered", "[mesh_cover]") {
    const SceneDescription d = meshScene(quad());
    const MeshCover cover = coverOf(d);
    const PreparedCone cone = downCone({0.98, 0.0, 5}, 0.05);
    CHECK_FALSE(cover.cover(d, cone, candidates(d, cone)));
    // Near the corner, over the diagonal's end.
    const PreparedCone corner = downCone({0.99, 0.99, 5}, 0.05);
    CHECK_FALSE(cover.cover(d, corner, candidates(d, corner)));
}

TEST_CASE("A cone over a silhouette edge is not covered, over a crease it is", "[mesh_cover]") {
    const PreparedCone cone = downCone({0.0, 0.0, 5}, 0.05);
    {
        // Folded back over the first face: seen from above, both lie on the
        // same side of the edge, which is a silhouette.
        const SceneDescription d = meshScene(hinge(1.0, 0.5));
        CHECK_FALSE(coverOf(d).cover(d, cone, candidates(d, cone)));
    }
    {
        // Opened out, a roof: a crease, whose normals jump.
        const SceneDescription d = meshScene(hinge(-1.0, 0.5));
        const auto sheet = coverOf(d).cover(d, cone, candidates(d, cone));
        REQUIRE(sheet);
        const Vec3 n0(0, 0, 1), n1 = glm::normalize(Vec3(0.5, 0, 1));
        CHECK(sheet->normalJump == Approx(glm::length(n0 - n1)));
    }
    {
        // The same roof with its second face wound the other way: the same.
        auto m = hinge(-1.0, 0.5);
        m->faces[1] = {{0, 1, 3}, {}, false};
        const SceneDescription d = meshScene(m);
        CHECK(coverOf(d).cover(d, cone, candidates(d, cone)));
    }
}

TEST_CASE("A smooth mesh's shared normals make no crease", "[mesh_cover]") {
    auto m = hinge(-1.0, 0.5);
    m->normals = {{0, 0, 1}, {0, 0, 1}, glm::normalize(Vec3(-0.2, 0, 1)), glm::normalize(Vec3(0.2, 0, 1))};
    m->faces[0] = {{0, 1, 2}, {0, 1, 2}, true};
    m->faces[1] = {{1, 0, 3}, {1, 0, 3}, true};
    const SceneDescription d = meshScene(m);
    const PreparedCone cone = downCone({0.0, 0.0, 5}, 0.05);
    const auto sheet = coverOf(d).cover(d, cone, candidates(d, cone));
    REQUIRE(sheet);
    CHECK(sheet->normalJump == Approx(0.0).margin(1e-12));
}

TEST_CASE("Another object in front of the sheet, or overlapping it, gives nothing", "[mesh_cover]") {
    SceneDescription d = meshScene(quad());
    auto other = std::make_shared<TriangleMesh>();
    other->vertices = {{-2, -2, 1}, {2, -2, 1}, {0, 2, 1}};
    other->faces = {{{0, 1, 2}, {}, false}};
    Object o;
    o.shape = TriangleShape{other, 0};
    d.objects.push_back(o);
    const PreparedCone cone = downCone({0.1, 0.1, 5}, 0.05);
    CHECK_FALSE(coverOf(d).cover(d, cone, candidates(d, cone)));
    // Behind the quad instead: the quad's faces cover the cone in front of it.
    d.objects.back().worldFromObject = Transform::translate({0, 0, -3});
    const auto sheet = coverOf(d).cover(d, cone, candidates(d, cone));
    REQUIRE(sheet);
    CHECK(sheet->member == std::vector<std::uint8_t>{1, 1, 0});
}

TEST_CASE("A sheet covers its cone in front of everything else (property)", "[mesh_cover][property]") {
    Rng rng(0x5eedull);
    int sheets = 0, failures = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        // A crumpled grid of n x n squares, each as two triangles, seen from a
        // random point: folds, boundaries and silhouettes all occur.
        const int n = 2 + rng.index(5);
        const double rough = rng.logUniform(-2.0, 0.3);
        auto m = std::make_shared<TriangleMesh>();
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                m->vertices.push_back({double(i) / n * 2 - 1, double(j) / n * 2 - 1, rng.uniform(-rough, rough)});
        const auto at = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const bool flip = rng.chance(0.3);  // windings need not agree
                m->faces.push_back({{at(i, j), flip ? at(i + 1, j + 1) : at(i + 1, j),
                                     flip ? at(i + 1, j) : at(i + 1, j + 1)}, {}, false});
                m->faces.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}, {}, false});
            }
        const SceneDescription d = meshScene(m);
        const Vec3 apex = rng.unitVector() * rng.uniform(1.5, 6.0);
        const Vec3 target(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), 0.0);
        const double half = rng.logUniform(-3.0, -0.7);
        const Cone raw{apex, glm::normalize(target - apex), half, 0.0, kInfinity};
        const PreparedCone cone(raw, true);
        const auto list = candidates(d, cone);
        const auto sheet = coverOf(d).cover(d, cone, list);
        if (!sheet) continue;
        std::vector<Primitive> prims;
        for (const Object& o : d.objects) prims.push_back(Primitive::make(o.shape, o.worldFromObject));
        const auto nearest = [&](const Ray& ray, int& object) {
            std::optional<SurfaceHit> best;
            for (std::size_t k = 0; k < prims.size(); ++k)
                if (auto h = prims[k].intersect(ray, 0.0, kInfinity); h && (!best || h->t < best->t)) {
                    best = h;
                    object = int(k);
                }
            return best;
        };
        // As the tracer asks: the axis must hit a face of the sheet.
        int axisObject = -1;
        if (!nearest({apex, raw.axis}, axisObject)) continue;
        bool axisOnSheet = false;
        for (std::size_t c = 0; c < list.size(); ++c)
            axisOnSheet |= sheet->member[c] && int(list[c].object) == axisObject;
        if (!axisOnSheet) continue;
        ++sheets;
        const Mat3 basis = frameAroundAxis(raw.axis);
        for (int r = 0; r < 64; ++r) {
            const double a = rng.uniform(0.0, 2.0 * kPi), s = half * std::sqrt(rng.uniform());
            const Vec3 dir = glm::normalize(std::cos(s) * raw.axis +
                                            std::sin(s) * (std::cos(a) * basis[0] + std::sin(a) * basis[1]));
            int object = -1;
            const auto hit = nearest({apex, dir}, object);
            bool onSheet = false;
            for (std::size_t c = 0; hit && c < list.size(); ++c)
                onSheet |= sheet->member[c] && int(list[c].object) == object;
            if (!onSheet && failures++ < 5)
                FAIL_CHECK("trial " << trial << ": a ray of the cone " << (hit ? "meets another face first" : "misses the mesh"));
            if (hit && onSheet) {
                CHECK(hit->t >= sheet->tNear - 1e-9);
                CHECK(hit->t <= sheet->tFar + 1e-9);
            }
        }
    }
    CHECK(failures == 0);
    INFO("sheets found: " << sheets);
    CHECK(sheets > 100);  // the property was exercised
}
