#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "asos/scene/truetype_font.hpp"
#include "asos/shapes/extrusion.hpp"
#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
OutlinePiece line(double x0, double z0, double x1, double z1) {
    OutlinePiece p;
    p.degree = 1;
    p.p = {x0, z0, x1, z1, 0, 0, 0, 0};
    return p;
}
OutlineContour square(double h) {
    return {{line(-h, -h, h, -h), line(h, -h, h, h), line(h, h, -h, h), line(-h, h, -h, -h)}};
}
Primitive extrusion(std::vector<OutlineContour> contours, double y0, double y1, const Transform& t = {}) {
    return Primitive::make(
        ExtrusionShape{std::make_shared<const std::vector<OutlineContour>>(std::move(contours)), y0, y1, "prism"}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-9) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Extrusion: a ray down the middle of a square prism", "[shapes][extrusion]") {
    const Primitive p = extrusion({square(1.0)}, 0.0, 2.0);
    auto hit = p.intersect(Ray{{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(near(hit->normal, {0, 1, 0}));
    // From the side, and from inside out.
    hit = p.intersect(Ray{{-5, 1, 0.25}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {-1, 0, 0}));
    hit = p.intersect(Ray{{0, 1, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0));
    CHECK(near(hit->normal, {1, 0, 0}));
    CHECK(p.inside({0.5, 1.0, -0.5}));
    CHECK_FALSE(p.inside({0.5, 2.5, -0.5}));
    CHECK_FALSE(p.inside({1.5, 1.0, 0.0}));
    // Past the caps' height, beside the prism: nothing.
    CHECK_FALSE(p.intersect(Ray{{-5, 2.5, 0}, {1, 0, 0}}, 0.0, kInfinity));
    CHECK_FALSE(p.intersect(Ray{{3, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
}

TEST_CASE("Extrusion: an open prism has no caps", "[shapes][extrusion][prism]") {
    ExtrusionShape record{std::make_shared<const std::vector<OutlineContour>>(std::vector<OutlineContour>{square(1.0)}),
                          0.0, 2.0, "prism"};
    record.open = true;
    const Primitive p = Primitive::make(record, Transform{});
    // Down the middle: no cap to meet, and the sides run along the ray.
    CHECK_FALSE(p.intersect(Ray{{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    // Slanted: through the open top onto the inner side.
    auto hit = p.intersect(Ray{{0, 2.5, 0}, glm::normalize(Vec3(1, -1, 0))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {1, 1.5, 0}));
    // From the side: the outer side, as when closed; the inside is the closed prism's.
    hit = p.intersect(Ray{{-5, 1, 0.25}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(p.inside({0.5, 1.0, -0.5}));
}

TEST_CASE("Extrusion: the even-odd rule makes a hole", "[shapes][extrusion]") {
    const Primitive p = extrusion({square(2.0), square(1.0)}, 0.0, 1.0);
    CHECK_FALSE(p.intersect(Ray{{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    CHECK(p.intersect(Ray{{1.5, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    CHECK_FALSE(p.inside({0, 0.5, 0}));
    CHECK(p.inside({1.5, 0.5, 0}));
    const Crossings all = p.crossings(Ray{{-5, 0.5, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(all.count == 4);
    const double xs[4] = {-2, -1, 1, 2}, nx[4] = {-1, 1, -1, 1};
    for (int i = 0; i < 4; ++i) {
        CHECK(all.hits[i].point.x == Approx(xs[i]));
        CHECK(glm::normalize(all.hits[i].normal).x == Approx(nx[i]));
    }
}

TEST_CASE("Extrusion: a quadratic side", "[shapes][extrusion]") {
    // A line along z = 0 from x = 1 to -1... and back over the arch
    // z = 4 s (1 - s), x = 1 - 2 s, whose top is (0, 1).
    OutlinePiece arch;
    arch.degree = 2;
    arch.p = {1, 0, 0, 2, -1, 0, 0, 0};
    const Primitive p = extrusion({{{line(-1, 0, 1, 0), arch}}}, 0.0, 1.0);
    auto hit = p.intersect(Ray{{0, 0.5, 5}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(glm::normalize(hit->normal), {0, 0, 1}));
    // x = 0.5 at s = 1/4, z = 3/4.
    hit = p.intersect(Ray{{0.5, 0.5, 5}, {0, 0, -1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.z == Approx(0.75));
    CHECK(p.inside({0, 0.5, 0.9}));
    CHECK_FALSE(p.inside({0, 0.5, 1.1}));
}

TEST_CASE("Extrusion: records refused", "[shapes][extrusion]") {
    CHECK_THROWS_WITH(extrusion({square(1.0)}, 1.0, 1.0), "the heights of a prism must be finite and differ, not 1 and 1");
    CHECK_THROWS_WITH(extrusion({{{line(0, 0, 1, 0), line(1, 0, 1, 1)}}}, 0.0, 1.0),
                      "an outline of a prism is not closed");
}

TEST_CASE("Extrusion: a ray through the hole of a glyph 'O'", "[shapes][extrusion][text]") {
    std::ifstream in("/usr/share/povray-3.7/include/timrom.ttf", std::ios::binary);
    REQUIRE(in);
    const TrueTypeFont font =
        TrueTypeFont::read(std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {}));
    const Glyph o = font.glyph(font.glyphIndex('O'), false);
    std::vector<OutlineContour> contours;
    for (const auto& c : o.contours) {
        OutlineContour out;
        for (const OutlineSegment& s : contourSegments(c)) {
            OutlinePiece p;
            p.degree = 2;
            p.p = {s.x0, s.y0, s.cx, s.cy, s.x2, s.y2, 0, 0};
            out.pieces.push_back(p);
        }
        contours.push_back(std::move(out));
    }
    const Primitive p = extrusion(contours, 0.0, 0.1);
    const double u = 1.0 / font.unitsPerEm();
    const double cx = 0.5 * (o.xMin + o.xMax) * u, cz = 0.5 * (o.yMin + o.yMax) * u;
    CHECK_FALSE(p.intersect(Ray{{cx, 1, cz}, {0, -1, 0}}, 0.0, kInfinity));
    // Through the ring, just inside the left edge.
    const double ring = o.xMin * u + 0.02;
    auto hit = p.intersect(Ray{{ring, 1, cz}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(0.9));
    // Along x through the middle: out, in, out, in: four sides.
    const Crossings all = p.crossings(Ray{{-1, 0.05, cz}, {1, 0, 0}}, 0.0, kInfinity);
    CHECK(all.count == 4);
}

TEST_CASE("Extrusion cone classification is conservative (property)", "[shapes][extrusion][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("extrusion", 0xe7e5ull, 5000, [](Rng& rng) {
        ShapeCase sc;
        // A star-ish closed contour of quadratic pieces about the origin.
        const int n = 3 + static_cast<int>(rng.uniform(0.0, 5.0));
        std::vector<double> xs, zs;
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * kPi * i / n, r = rng.uniform(0.5, 1.5);
            xs.push_back(r * std::cos(a));
            zs.push_back(r * std::sin(a));
        }
        OutlineContour c;
        for (int i = 0; i < n; ++i) {
            const int j = (i + 1) % n;
            OutlinePiece p;
            p.degree = 2;
            const double k = rng.uniform(0.2, 1.6);
            p.p = {xs[i], zs[i], k * 0.5 * (xs[i] + xs[j]), k * 0.5 * (zs[i] + zs[j]), xs[j], zs[j], 0, 0};
            c.pieces.push_back(p);
        }
        const double y0 = rng.uniform(-1.0, 0.0), y1 = y0 + rng.uniform(0.1, 2.0);
        auto outline = std::make_shared<const std::vector<OutlineContour>>(std::vector<OutlineContour>{c});
        sc.shape = ExtrusionShape{outline, y0, y1, "prism"};
        sc.surfacePoint = [outline, y0, y1](Rng& r) {
            const auto& pieces = (*outline)[0].pieces;
            const auto& p = pieces[static_cast<std::size_t>(r.uniform(0.0, double(pieces.size()) - 1e-9))];
            const double s = r.uniform(0.0, 1.0);
            const double x = (1 - s) * (1 - s) * p.p[0] + 2 * s * (1 - s) * p.p[2] + s * s * p.p[4];
            const double z = (1 - s) * (1 - s) * p.p[1] + 2 * s * (1 - s) * p.p[3] + s * s * p.p[5];
            return Vec3(x, r.uniform(y0, y1), z);
        };
        sc.size = 1.5;
        sc.text = "prism of " + std::to_string(n) + " quadratic pieces";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
