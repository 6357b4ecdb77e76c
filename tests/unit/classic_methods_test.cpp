#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "asos/render/classic_methods.hpp"

using namespace asos;

namespace {

// An orthographic camera whose rays start at (X - W/2, H/2 - Y, 0) for image
// point (X, Y), so that a radiance function can work in image coordinates.
CameraModel imageSpaceCamera(int w, int h) {
    Camera c;
    c.projection = Camera::Projection::Orthographic;
    c.location = {0, 0, 0};
    c.direction = {0, 0, 1};
    c.right = {double(w), 0, 0};
    c.up = {0, double(h), 0};
    return CameraModel(c, w, h);
}

Vec2 imagePoint(const Ray& r, int w, int h) { return {r.origin.x + w / 2.0, h / 2.0 - r.origin.y}; }

// 1 where a X + b Y < c.
struct HalfPlane {
    double a, b, c;
    int w, h;
    Vec3 operator()(const Ray& r) const {
        const Vec2 p = imagePoint(r, w, h);
        return Vec3(a * p.x + b * p.y < c ? 1.0 : 0.0);
    }
    // Exact area of the half-plane within pixel (x, y): clip the unit square.
    double coverage(int x, int y) const {
        std::vector<Vec2> poly{{double(x), double(y)}, {x + 1.0, double(y)}, {x + 1.0, y + 1.0},
                               {double(x), y + 1.0}};
        std::vector<Vec2> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
            const double fp = a * p.x + b * p.y - c, fq = a * q.x + b * q.y - c;
            if (fp < 0) out.push_back(p);
            if ((fp < 0) != (fq < 0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
        }
        double area = 0.0;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Vec2 p = out[i], q = out[(i + 1) % out.size()];
            area += p.x * q.y - q.x * p.y;
        }
        return std::fabs(area) / 2.0;
    }
};

// Edges through pixel (0, 0) of a 1x1 image at many angles and offsets. Over
// a full turn each edge comes with its complement, whose errors cancel.
std::vector<HalfPlane> edgesThroughPixel(int angles = 36) {
    std::vector<HalfPlane> edges;
    for (int k = 0; k < angles; ++k) {
        const double angle = (k * 10.0 + 3.7) * kPi / 180.0;
        const double a = std::cos(angle), b = std::sin(angle);
        for (double t : {0.2, 0.45, 0.7})
            edges.push_back({a, b, a * t + b * (1.0 - t) * 0.9, 1, 1});
    }
    return edges;
}

PixelCorners cornersOf(const HalfPlane& f, const CameraModel& cam, int x, int y) {
    return {f(cam.ray(x, y)), f(cam.ray(x + 1, y)), f(cam.ray(x, y + 1)), f(cam.ray(x + 1, y + 1)),
            ownedCornerRays(x, y, cam.width(), cam.height())};
}

}  // namespace

TEST_CASE("Single sampling shoots one ray through the centre", "[methods]") {
    const CameraModel cam = imageSpaceCamera(8, 6);
    std::vector<Vec2> seen;
    const PixelResult r = estimateSingle(cam, 3, 2, [&](const Ray& ray, const PrimarySample& s) {
        seen.push_back(imagePoint(ray, 8, 6));
        CHECK(s.pixelX == 3);
        CHECK(s.pixelY == 2);
        return Vec3(0.25);
    });
    REQUIRE(seen.size() == 1);
    CHECK(seen[0].x == Approx(3.5));
    CHECK(seen[0].y == Approx(2.5));
    CHECK(r.color == Vec3(0.25));
    CHECK(r.rays == 1);
    CHECK(r.level == 0);
}

TEST_CASE("Grid sampling converges on a straight edge within 1/N", "[methods]") {
    const CameraModel cam = imageSpaceCamera(1, 1);
    for (int n : {1, 2, 4, 8, 16, 32}) {
        double worst = 0.0;
        for (const HalfPlane& edge : edgesThroughPixel()) {
            const PixelResult r = estimateGrid(cam, 0, 0, n, edge);
            CHECK(r.rays == std::uint32_t(n * n));
            worst = std::max(worst, std::fabs(r.color.x - edge.coverage(0, 0)));
        }
        INFO("grid " << n << " worst error " << worst);
        CHECK(worst <= 1.0 / n + 1e-12);
    }
    CHECK_THROWS_AS(estimateGrid(cam, 0, 0, 0, HalfPlane{1, 0, 0.5, 1, 1}), std::invalid_argument);
    CHECK_THROWS_AS(estimateGrid(cam, 0, 0, kMaxSamplesPerSide + 1, HalfPlane{1, 0, 0.5, 1, 1}),
                    std::invalid_argument);
    CHECK_THROWS_AS(estimateJitter(cam, 0, 0, -2, PixelRandom(0, 0, 0), HalfPlane{1, 0, 0.5, 1, 1}),
                    std::invalid_argument);
}

TEST_CASE("Grid and jitter sampling measure a disc's area", "[methods]") {
    // A disc of radius 0.3 inside the pixel covers pi 0.09 of it. A grid's
    // error is bounded by the samples within half a cell of the rim: at most
    // about perimeter / N.
    const CameraModel cam = imageSpaceCamera(1, 1);
    const double r = 0.3, exact = kPi * r * r;
    auto disc = [&](const Ray& ray) {
        return Vec3(glm::length(imagePoint(ray, 1, 1) - Vec2(0.52, 0.47)) < r ? 1.0 : 0.0);
    };
    for (int n : {8, 16, 32, 64}) {
        const double gridError = std::fabs(estimateGrid(cam, 0, 0, n, disc).color.x - exact);
        INFO("grid " << n << " error " << gridError);
        CHECK(gridError <= 2.0 * kPi * r / n);
        double jitterSq = 0.0;
        for (int seed = 0; seed < 32; ++seed) {
            const double e = estimateJitter(cam, 0, 0, n, PixelRandom(seed, 0, 0), disc).color.x - exact;
            jitterSq += e * e;
        }
        INFO("jitter " << n << " RMS error " << std::sqrt(jitterSq / 32));
        CHECK(std::sqrt(jitterSq / 32) <= 2.0 * std::sqrt(2.0 * kPi * r) * std::pow(n, -1.5));
    }
}

TEST_CASE("Jittered sampling converges faster than 1/N", "[methods]") {
    const CameraModel cam = imageSpaceCamera(1, 1);
    const auto edges = edgesThroughPixel(18);
    double previousRms = 1.0;
    for (int n : {2, 4, 8, 16}) {
        double sumSq = 0.0;
        int count = 0;
        for (std::uint64_t seed = 0; seed < 16; ++seed)
            for (const HalfPlane& edge : edges) {
                const PixelResult r = estimateJitter(cam, 0, 0, n, PixelRandom(seed, 0, 0), edge);
                const double err = r.color.x - edge.coverage(0, 0);
                sumSq += err * err;
                ++count;
            }
        const double rms = std::sqrt(sumSq / count);
        INFO("jitter " << n << ": RMS error " << rms);
        // Stratified sampling of an edge: error ~ N^-1.5.
        CHECK(rms < 0.6 * std::pow(n, -1.5));
        CHECK(rms < previousRms);
        previousRms = rms;
    }
    // The same pixel and seed give the same samples.
    const HalfPlane e = edges[5];
    CHECK(estimateJitter(cam, 0, 0, 4, PixelRandom(3, 0, 0), e).color ==
          estimateJitter(cam, 0, 0, 4, PixelRandom(3, 0, 0), e).color);
}

TEST_CASE("Jittered sampling is unbiased", "[methods]") {
    // For a fixed edge, independent pixels (seeds) average to the exact
    // coverage within four standard errors.
    const CameraModel cam = imageSpaceCamera(1, 1);
    const auto edges = edgesThroughPixel(18);
    for (std::size_t k = 0; k < edges.size(); k += 9) {
        const HalfPlane& edge = edges[k];
        const double exact = edge.coverage(0, 0);
        const int seeds = 400;
        double sum = 0.0, sumSq = 0.0;
        for (int seed = 0; seed < seeds; ++seed) {
            const double err = estimateJitter(cam, 0, 0, 4, PixelRandom(seed, 0, 0), edge).color.x - exact;
            sum += err;
            sumSq += err * err;
        }
        const double mean = sum / seeds, sd = std::sqrt(sumSq / seeds - mean * mean);
        INFO("edge " << k << ": mean error " << mean << ", sd " << sd);
        CHECK(std::fabs(mean) < 4.0 * sd / std::sqrt(double(seeds)));
    }
}

TEST_CASE("Adaptive sampling takes one owned ray where the corners agree", "[methods]") {
    const CameraModel cam = imageSpaceCamera(4, 4);
    const HalfPlane everywhere{1, 0, 100, 4, 4};
    int calls = 0;
    auto counted = [&](const Ray& r) {
        ++calls;
        return everywhere(r);
    };
    const PixelResult r =
        estimateAdaptive(cam, 1, 1, cornersOf(everywhere, cam, 1, 1), {}, PixelRandom(0, 1, 1), counted);
    CHECK(calls == 0);
    CHECK(r.color == Vec3(1.0));
    CHECK(r.rays == 1);
    CHECK(r.level == 0);
    CHECK(ownedCornerRays(3, 1, 4, 4) == 2);
    CHECK(ownedCornerRays(1, 3, 4, 4) == 2);
    CHECK(ownedCornerRays(3, 3, 4, 4) == 4);
}

TEST_CASE("Adaptive sampling subdivides a contrasting edge to its depth", "[methods]") {
    const CameraModel cam = imageSpaceCamera(1, 1);
    for (int depth : {1, 2, 3, 4}) {
        AdaptiveSettings s;
        s.depth = depth;
        double worst = 0.0;
        int subdividedToDepth = 0, edgePixels = 0;
        for (const HalfPlane& edge : edgesThroughPixel()) {
            const PixelCorners corners = cornersOf(edge, cam, 0, 0);
            const PixelResult r = estimateAdaptive(cam, 0, 0, corners, s, PixelRandom(0, 0, 0), edge);
            const double exact = edge.coverage(0, 0);
            worst = std::max(worst, std::fabs(r.color.x - exact));
            CHECK(r.rays <= corners.ownedRays + std::uint32_t((1 << depth) + 1) * ((1 << depth) + 1) - 4);
            if (corners.topLeft != corners.topRight || corners.topLeft != corners.bottomLeft ||
                corners.topLeft != corners.bottomRight) {
                ++edgePixels;
                subdividedToDepth += r.level == std::uint32_t(depth);
            }
        }
        INFO("depth " << depth << " worst error " << worst);
        // A square that straddles the edge is off by at most half its area;
        // one straight edge crosses at most 2^(depth+1) squares of the finest level.
        CHECK(worst <= 0.5 * std::pow(2.0, depth + 1) / std::pow(4.0, depth) + 1e-12);
        CHECK(subdividedToDepth == edgePixels);
    }
}

TEST_CASE("Adaptive settings outside their range are rejected", "[methods]") {
    CHECK(checkAdaptiveSettings({}).empty());
    AdaptiveSettings s;
    s.depth = kMaxAdaptiveDepth + 1;
    CHECK_THAT(checkAdaptiveSettings(s), Catch::Contains("depth"));
    s.depth = -1;
    CHECK_FALSE(checkAdaptiveSettings(s).empty());
    s = {};
    s.threshold = -0.1;
    CHECK_THAT(checkAdaptiveSettings(s), Catch::Contains("threshold"));
    s = {};
    s.jitterAmount = std::nan("");
    CHECK_FALSE(checkAdaptiveSettings(s).empty());
    s.jitterAmount = 1.0;
    s.depth = 99;
    const CameraModel cam = imageSpaceCamera(1, 1);
    CHECK_THROWS_AS(estimateAdaptive(cam, 0, 0, PixelCorners{}, s, PixelRandom(0, 0, 0),
                                     [](const Ray&) { return Vec3(0.0); }),
                    std::invalid_argument);
}

TEST_CASE("Adaptive thresholds compare antialias_gamma-encoded colours like POV-Ray", "[methods]") {
    AdaptiveSettings s;  // threshold 0.3, gamma 2.5
    // 0.05^(1/2.5) = 0.3017 >= 0.3, 0.04^(1/2.5) = 0.2759 < 0.3.
    CHECK(adaptiveColorsDiffer(Vec3(0.0), Vec3(0.05, 0, 0), s));
    CHECK_FALSE(adaptiveColorsDiffer(Vec3(0.0), Vec3(0.04, 0, 0), s));
    // Channel differences add up.
    CHECK(adaptiveColorsDiffer(Vec3(0.0), Vec3(0.02, 0.02, 0.0), s));
    s.threshold = 1.0;
    CHECK_FALSE(adaptiveColorsDiffer(Vec3(0.0), Vec3(0.5, 0.0, 0.0), s));  // 0.758
    CHECK(adaptiveColorsDiffer(Vec3(0.0), Vec3(1.0, 0.0, 0.0), s));  // 1 >= 1
}

TEST_CASE("Adaptive sampling misses a small object between its samples", "[methods]") {
    // The weakness the paper starts from: image-space sampling decides from
    // the samples alone, so a 0.2-pixel disc away from the lattice points is
    // not seen at all, whatever the depth.
    const CameraModel cam = imageSpaceCamera(1, 1);
    auto disc = [&](const Ray& r) {
        const Vec2 p = imagePoint(r, 1, 1);
        return Vec3(glm::length(p - Vec2(0.43, 0.61)) < 0.1 ? 1.0 : 0.0);
    };
    AdaptiveSettings s;
    s.depth = 4;
    const PixelCorners corners{disc(cam.ray(0, 0)), disc(cam.ray(1, 0)), disc(cam.ray(0, 1)),
                               disc(cam.ray(1, 1)), 1};
    const PixelResult r = estimateAdaptive(cam, 0, 0, corners, s, PixelRandom(0, 0, 0), disc);
    CHECK(r.color == Vec3(0.0));  // the disc covers 3.1% of the pixel
    CHECK(r.rays == 1);
}

TEST_CASE("Adaptive jitter moves sub-samples only and stays deterministic", "[methods]") {
    const CameraModel cam = imageSpaceCamera(1, 1);
    const HalfPlane edge{1, 0.3, 0.6, 1, 1};
    AdaptiveSettings s;
    s.depth = 3;
    s.jitter = true;
    std::vector<Vec2> points;
    auto record = [&](const Ray& r) {
        points.push_back(imagePoint(r, 1, 1));
        return edge(r);
    };
    const PixelCorners corners = cornersOf(edge, cam, 0, 0);
    const PixelResult a = estimateAdaptive(cam, 0, 0, corners, s, PixelRandom(9, 0, 0), record);
    const std::vector<Vec2> first = points;
    points.clear();
    const PixelResult b = estimateAdaptive(cam, 0, 0, corners, s, PixelRandom(9, 0, 0), record);
    CHECK(a.color == b.color);
    CHECK(points == first);
    const double maxOffset = 0.5 / ((1 << 4) + 1);
    bool moved = false;
    for (const Vec2& p : first) {
        const Vec2 lattice = glm::round(p * 8.0) / 8.0;
        CHECK(std::fabs(p.x - lattice.x) <= maxOffset + 1e-12);
        CHECK(std::fabs(p.y - lattice.y) <= maxOffset + 1e-12);
        moved = moved || p != lattice;
    }
    CHECK(moved);
}

TEST_CASE("Shared corners and the adaptive pass render deterministically", "[methods]") {
    const int w = 24, h = 18;
    const CameraModel cam = imageSpaceCamera(w, h);
    const HalfPlane edge{0.8, 0.6, 14.3, w, h};
    AdaptiveSettings s;
    s.depth = 3;
    s.jitter = true;
    std::vector<Image> images;
    for (int threads : {1, 2}) {
        TileRenderOptions o;
        o.threads = threads;
        o.tileSize = threads == 1 ? 5 : 16;
        const CornerGrid corners = sampleCorners(cam, PixelRegion::whole(w, h), o,
                                                 [&](const Ray& r, RenderCounters& c) {
                                                     ++c.eyeRays;
                                                     return edge(r);
                                                 });
        CHECK(corners.counters.eyeRays == std::uint64_t((w + 1) * (h + 1)));
        const TileRenderResult r = renderTiles(w, h, o, [&](int x, int y, RenderCounters& c) {
            return estimateAdaptive(cam, x, y, corners.ofPixel(x, y), s, PixelRandom(1, x, y),
                                    [&](const Ray& ray) {
                                        ++c.eyeRays;
                                        return edge(ray);
                                    });
        });
        // The samples AOV adds up to every ray traced, corners once each.
        double aovRays = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) aovRays += r.samples.at(x, y, 0);
        CHECK(aovRays == double(corners.counters.eyeRays + r.counters.eyeRays));
        // Each pixel equals the estimator run on its own, and the image the
        // edge's exact coverage within the method's error.
        double worst = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const PixelResult alone = estimateAdaptive(cam, x, y, cornersOf(edge, cam, x, y), s,
                                                           PixelRandom(1, x, y), edge);
                CHECK(r.color.rgbAt(x, y).x == Approx(alone.color.x).margin(1e-6));
                worst = std::max(worst, std::fabs(r.color.rgbAt(x, y).x - edge.coverage(x, y)));
            }
        CHECK(worst < 0.2);
        images.push_back(r.color);
    }
    CHECK(images[0] == images[1]);
}

namespace {

// A radiance function that also takes batches (as the renderer's eye
// radiance does, to search a pixel's hits as one packet): the estimators
// must give the same pixel, bit for bit, as from one ray at a time.
struct Wavy {
    int w, h;
    Vec3 operator()(const Ray& r, const PrimarySample& s) const {
        const Vec2 p = imagePoint(r, w, h);
        return Vec3(std::sin(3.1 * p.x + 0.7 * p.y), std::cos(1.3 * p.x * p.y), 0.01 * s.index);
    }
};
struct BatchedWavy {
    Wavy f;
    int batches = 0, rays = 0;
    std::uint32_t nextIndex = 0;
    Vec3 operator()(const Ray&, const PrimarySample&) const {
        FAIL("the estimators must use the batches");
        return Vec3(0.0);
    }
    void batch(std::span<const Ray> r, std::span<const PrimarySample> s, std::span<Vec3> colors) {
        REQUIRE(r.size() == s.size());
        REQUIRE(r.size() == colors.size());
        REQUIRE(r.size() <= std::size_t(kPrimaryBatch));
        ++batches;
        for (std::size_t k = 0; k < r.size(); ++k) {
            CHECK(s[k].index == nextIndex++);  // in order, each once
            colors[k] = f(r[k], s[k]);
            ++rays;
        }
    }
};

}  // namespace

TEST_CASE("Grid and jitter give the same pixel from batches as one ray at a time", "[classic]") {
    const CameraModel cam = imageSpaceCamera(16, 16);
    const Wavy f{16, 16};
    for (int n : {1, 3, 8, 9, 20}) {
        for (int x : {0, 7}) {
            BatchedWavy g{f};
            const PixelResult a = estimateGrid(cam, x, 5, n, f);
            const PixelResult b = estimateGrid(cam, x, 5, n, g);
            CHECK(a.color == b.color);
            CHECK(a.rays == b.rays);
            CHECK(g.rays == n * n);
            CHECK(g.batches == (n * n + kPrimaryBatch - 1) / kPrimaryBatch);
            BatchedWavy j{f};
            const PixelRandom rng(11, x, 5);
            const PixelResult c = estimateJitter(cam, x, 5, n, rng, f);
            const PixelResult e = estimateJitter(cam, x, 5, n, rng, j);
            CHECK(c.color == e.color);
            CHECK(c.rays == e.rays);
            CHECK(j.rays == n * n);
        }
    }
}

namespace {

// A w x h image by am1 over POV-Ray's render blocks, each ray counted.
template <class Radiance>
TileRenderResult renderAm1(const CameraModel& cam, const AdaptiveSettings& s, const Radiance& f,
                           const TileRenderOptions& options = {}) {
    return renderBlocks(cam.width(), cam.height(), kAm1BlockSize, options,
                        [&](const PixelRegion& block, RenderCounters& c) {
                            return estimateAm1Block(cam, block, s, 5, [&](const Ray& r) {
                                ++c.eyeRays;
                                return f(r);
                            });
                        });
}

double aovRays(const TileRenderResult& r) {
    double sum = 0.0;
    for (int y = 0; y < r.samples.height(); ++y)
        for (int x = 0; x < r.samples.width(); ++x) sum += r.samples.at(x, y, 0);
    return sum;
}

}  // namespace

TEST_CASE("Am1 never supersamples a flat colour", "[methods]") {
    const int w = 40, h = 35;  // 2 x 2 blocks: 32 + 8 by 32 + 3
    const CameraModel cam = imageSpaceCamera(w, h);
    const Vec3 flat(0.25, 0.5, 0.75);
    const TileRenderResult r = renderAm1(cam, {}, [&](const Ray&) { return flat; });
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            INFO(x << ", " << y);
            CHECK(r.color.rgbAt(x, y) == flat);
            CHECK(r.samples.at(x, y, 1) == 0.0f);
            // Its first ray, and the frame rays of the row above or the column
            // left of its block that it is charged with.
            CHECK(r.samples.at(x, y, 0) == float(1 + (x % kAm1BlockSize == 0) + (y % kAm1BlockSize == 0)));
        }
    // Each block row traces a frame row, each block column a frame column.
    CHECK(r.counters.eyeRays == std::uint64_t(w * h + 2 * w + 2 * h));
    CHECK(aovRays(r) == double(r.counters.eyeRays));
}

TEST_CASE("Am1 supersamples an edge's pixels as POV-Ray does", "[methods]") {
    const int w = 24, h = 6;
    const CameraModel cam = imageSpaceCamera(w, h);
    struct Case {
        double edge;               // 1 left of x = edge, 0 right of it
        std::vector<int> columns;  // the columns supersampled
        std::vector<double> values;
    };
    // Pixels 9 and 10 differ at 10.3 and both are supersampled; pixel 10's
    // colour becomes (0 + 3 x 1 + 6 x 0) / 10 = 0.3, which still differs from
    // pixel 11's first colour, so that pixel 11 is supersampled too (POV-Ray
    // compares with a neighbour as it is by then). At 10.9 pixel 10's
    // supersampled colour is 1, and only pixels 10 and 11 are supersampled.
    for (const auto& [edge, columns, values] :
         {Case{10.3, {9, 10, 11}, {1.0, 0.3, 0.0}}, Case{10.9, {10, 11}, {1.0, 0.0}}}) {
        INFO("edge at x = " << edge);
        const HalfPlane f{1, 0, edge, w, h};
        const TileRenderResult r = renderAm1(cam, {}, f);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                INFO(x << ", " << y);
                const auto it = std::find(columns.begin(), columns.end(), x);
                const bool supersampled = it != columns.end();
                CHECK(r.samples.at(x, y, 1) == float(supersampled));
                const double expected = supersampled ? values[std::size_t(it - columns.begin())]
                                                     : f(cam.ray(x + 0.5, y + 0.5)).x;
                CHECK(r.color.rgbAt(x, y).x == Approx(expected).margin(1e-7));
            }
        CHECK(aovRays(r) == double(r.counters.eyeRays));
        CHECK(r.counters.eyeRays == std::uint64_t(w * h + w + h + h * 9 * columns.size()));
    }
}

TEST_CASE("Am1 compares pixels within a render block only, as POV-Ray", "[methods]") {
    const int w = 64, h = 8;
    const CameraModel cam = imageSpaceCamera(w, h);
    auto supersampledColumns = [&](const TileRenderResult& r) {
        std::vector<int> columns;
        for (int x = 0; x < w; ++x) {
            for (int y = 0; y < h; ++y) CHECK(r.samples.at(x, y, 1) == r.samples.at(x, 0, 1));
            if (r.samples.at(x, 0, 1) == 1.0f) columns.push_back(x);
        }
        return columns;
    };
    // Inside a block both sides of an edge are supersampled.
    CHECK(supersampledColumns(renderAm1(cam, {}, HalfPlane{1, 0, 16, w, h})) == std::vector<int>{15, 16});
    // On the border of two blocks the right one compares its first column with
    // the left one's last (its frame, traced again, never supersampled) and the
    // left block never sees the edge: one side only.
    CHECK(supersampledColumns(renderAm1(cam, {}, HalfPlane{1, 0, 32, w, h})) == std::vector<int>{32});
    // The first row is compared with the row above the image, traced too.
    const TileRenderResult above = renderAm1(cam, {}, HalfPlane{0, 1, 0, w, h});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) CHECK(above.samples.at(x, y, 1) == float(y == 0));
}

TEST_CASE("Am1 averages the first ray with a (depth + 1)^2 grid, jittered at +J's scale", "[methods]") {
    const CameraModel cam = imageSpaceCamera(2, 1);
    // Pixels 0 and 1 differ in red and are both supersampled; the faint
    // gradients in green and blue make every sample's colour its own.
    auto colour = [](Vec2 p) { return Vec3(p.x >= 1.0 ? 1.0 : 0.0, 0.001 * (p.x + 2), 0.001 * (p.y + 2)); };
    for (bool jitter : {false, true})
        for (int depth : {0, 1, 2, 3}) {
            INFO("depth " << depth << (jitter ? ", jittered" : ""));
            AdaptiveSettings s;
            s.depth = depth;
            s.jitter = jitter;
            const int n = depth + 1;
            std::vector<std::pair<Vec2, PrimarySample>> seen;
            const PixelRegion block{0, 0, 2, 1};
            const std::vector<PixelResult> r =
                estimateAm1Block(cam, block, s, 7, [&](const Ray& ray, const PrimarySample& p) {
                    const Vec2 at = imagePoint(ray, 2, 1);
                    CHECK(glm::length(at - p.image) < 1e-12);
                    seen.emplace_back(at, p);
                    return colour(at);
                });
            REQUIRE(r.size() == 2);
            // The frame (3 rays), the two first rays, then n^2 per pixel.
            REQUIRE(seen.size() == std::size_t(5 + 2 * n * n));
            for (int x : {0, 1}) {
                Vec3 sum = colour(Vec2(x + 0.5, 0.5));
                std::vector<std::uint32_t> indices;
                bool moved = false;
                for (const auto& [at, sample] : seen) {
                    if (sample.pixelX != x || sample.pixelY != 0 || sample.index == 0) {
                        if (sample.pixelX == x && sample.pixelY == 0)
                            CHECK(glm::length(at - Vec2(x + 0.5, 0.5)) < 1e-12);
                        continue;
                    }
                    indices.push_back(sample.index);
                    const int k = int(sample.index) - 1;
                    const Vec2 grid(x + (k % n + 0.5) / n, (k / n + 0.5) / n);
                    CHECK(std::fabs(at.x - grid.x) <= 0.5 / n + 1e-12);
                    CHECK(std::fabs(at.y - grid.y) <= 0.5 / n + 1e-12);
                    if (!jitter) CHECK(glm::length(at - grid) < 1e-12);
                    moved = moved || glm::length(at - grid) > 1e-9;
                    sum += colour(at);
                }
                CHECK(moved == jitter);
                CHECK(indices.size() == std::size_t(n * n));
                for (std::size_t i = 0; i < indices.size(); ++i) CHECK(indices[i] == i + 1);
                CHECK(r[std::size_t(x)].level == 1);
                // Pixel 0 is charged with the frame rays above it and left of it.
                CHECK(r[std::size_t(x)].rays == std::uint32_t(3 + n * n) - std::uint32_t(x));
                CHECK(glm::length(r[std::size_t(x)].color - sum / double(n * n + 1)) < 1e-15);
            }
            // The same seed gives the same samples.
            auto plain = [&](const Ray& ray) { return colour(imagePoint(ray, 2, 1)); };
            const std::vector<PixelResult> again = estimateAm1Block(cam, block, s, 7, plain);
            CHECK(again[0].color == r[0].color);
            CHECK(again[1].color == r[1].color);
        }
}

TEST_CASE("Am1 renders the same for any thread count, tile size and region", "[methods]") {
    const int w = 45, h = 40;
    const CameraModel cam = imageSpaceCamera(w, h);
    const HalfPlane edge{0.8, 0.6, 27.3, w, h};
    AdaptiveSettings s;
    s.jitter = true;
    TileRenderOptions o;
    o.threads = 1;
    const TileRenderResult reference = renderAm1(cam, s, edge, o);
    for (int threads : {1, 2, 3})
        for (int tile : {1, 7, 16, 64}) {
            INFO("threads " << threads << ", tile " << tile);
            o.threads = threads;
            o.tileSize = tile;
            const TileRenderResult r = renderAm1(cam, s, edge, o);
            CHECK(r.color == reference.color);
            CHECK(r.samples == reference.samples);
            CHECK(r.counters == reference.counters);
        }
    // Regions whose borders are not the blocks' give the pixels of the whole.
    Image assembled = Image::rgb(w, h);
    Image samples(w, h, {"rays", "level"});
    for (const PixelRegion& part :
         {PixelRegion{0, 0, 45, 13}, PixelRegion{0, 13, 33, 40}, PixelRegion{33, 13, 45, 40}}) {
        o.region = part;
        const TileRenderResult r = renderAm1(cam, s, edge, o);
        CHECK(r.counters.pixels == std::uint64_t(part.area()));
        for (int y = part.y0; y < part.y1; ++y)
            for (int x = part.x0; x < part.x1; ++x) {
                assembled.setRgb(x, y, r.color.rgbAt(x, y));
                for (int c : {0, 1}) samples.at(x, y, c) = r.samples.at(x, y, c);
            }
    }
    CHECK(assembled == reference.color);
    CHECK(samples == reference.samples);
}

TEST_CASE("Am1 settings outside their range are rejected", "[methods]") {
    const CameraModel cam = imageSpaceCamera(1, 1);
    AdaptiveSettings s;
    s.depth = kMaxAdaptiveDepth + 1;
    auto black = [](const Ray&) { return Vec3(0.0); };
    CHECK_THROWS_AS(estimateAm1Block(cam, PixelRegion{0, 0, 1, 1}, s, 0, black), std::invalid_argument);
}
