#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "asos/render/sampling.hpp"
#include "asos/render/tile_renderer.hpp"

using namespace asos;

namespace {
// A pixel function with per-pixel random numbers and uneven cost, the way a
// renderer's pixels behave.
PixelResult noisyPixel(int x, int y, RenderCounters& counters) {
    const PixelRandom rng(1234, x, y);
    const int samples = 1 + static_cast<int>(rng.uniform(SampleStream::Test, 0) * 8);
    Vec3 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        const Vec2 u = rng.uniform2(SampleStream::PixelJitter, i);
        sum += Vec3(std::sin(x + u.x), std::cos(y + u.y), u.x * u.y);
    }
    counters.eyeRays += samples;
    counters.countPyray(samples % 3);
    return {sum / double(samples), static_cast<std::uint32_t>(samples),
            static_cast<std::uint32_t>(samples % 3)};
}

// Copies the region `part` of a region render into `assembled`, checking that
// the render left the rest of the image black.
void keepRegion(Image& assembled, const Image& rendered, const PixelRegion& part) {
    for (int y = 0; y < rendered.height(); ++y)
        for (int x = 0; x < rendered.width(); ++x) {
            if (part.contains(x, y))
                assembled.setRgb(x, y, rendered.rgbAt(x, y));
            else
                CHECK(rendered.rgbAt(x, y) == Vec3(0.0));
        }
}
}  // namespace

TEST_CASE("Tiled rendering is identical for any thread count and tile size", "[tiles]") {
    const int w = 53, h = 37;
    TileRenderOptions base;
    base.threads = 1;
    base.tileSize = 16;
    const TileRenderResult reference = renderTiles(w, h, base, noisyPixel);
    CHECK(reference.threads == 1);
    CHECK(reference.counters.pixels == std::uint64_t(w * h));
    for (int threads : {1, 2, 3})
        for (int tile : {1, 7, 16, 64}) {
            TileRenderOptions o;
            o.threads = threads;
            o.tileSize = tile;
            const TileRenderResult r = renderTiles(w, h, o, noisyPixel);
            INFO("threads " << threads << ", tile " << tile);
            CHECK(r.threads == threads);
            CHECK(r.color == reference.color);
            CHECK(r.samples == reference.samples);
            CHECK(r.counters == reference.counters);
        }
}

TEST_CASE("Regions render the same pixels as the whole image", "[tiles]") {
    const int w = 40, h = 30;
    TileRenderOptions o;
    o.threads = 2;
    const TileRenderResult whole = renderTiles(w, h, o, noisyPixel);
    Image assembled = Image::rgb(w, h);
    RenderCounters counters;
    for (const PixelRegion& part : {PixelRegion{0, 0, 40, 13}, PixelRegion{0, 13, 17, 30},
                                    PixelRegion{17, 13, 40, 30}}) {
        o.region = part;
        const TileRenderResult r = renderTiles(w, h, o, noisyPixel);
        keepRegion(assembled, r.color, part);
        counters += r.counters;
    }
    CHECK(assembled == whole.color);
    CHECK(counters == whole.counters);
}

namespace {
// A block function whose pixels tell which block they were rendered in and
// where in it, so that any change of the block grid changes the image.
std::vector<PixelResult> labelledBlock(const PixelRegion& b, RenderCounters& counters) {
    std::vector<PixelResult> out;
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x)
            out.push_back({Vec3(b.x0, b.y0, b.x1 * 100 + b.y1), std::uint32_t(1 + (x + y) % 3), 0});
    counters.eyeRays += std::uint64_t(b.area());
    return out;
}
}  // namespace

TEST_CASE("Blocks are laid from the image corner for any thread count, tile size and region", "[tiles]") {
    const int w = 53, h = 37, size = 16;
    TileRenderOptions o;
    o.threads = 1;
    const TileRenderResult whole = renderBlocks(w, h, size, o, labelledBlock);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int x0 = x / size * size, y0 = y / size * size;
            CHECK(whole.color.rgbAt(x, y) ==
                  Vec3(x0, y0, std::min(x0 + size, w) * 100 + std::min(y0 + size, h)));
        }
    CHECK(whole.counters.pixels == std::uint64_t(w * h));
    CHECK(whole.counters.eyeRays == std::uint64_t(w * h));
    for (int threads : {1, 2, 3})
        for (int tile : {1, 7, 64}) {
            INFO("threads " << threads << ", tile " << tile);
            o.threads = threads;
            o.tileSize = tile;
            const TileRenderResult r = renderBlocks(w, h, size, o, labelledBlock);
            CHECK(r.color == whole.color);
            CHECK(r.samples == whole.samples);
            CHECK(r.counters == whole.counters);
        }
    // A region renders the blocks it meets whole, and keeps its own pixels.
    Image assembled = Image::rgb(w, h);
    for (const PixelRegion& part : {PixelRegion{0, 0, 53, 13}, PixelRegion{0, 13, 20, 37},
                                    PixelRegion{20, 13, 53, 37}}) {
        o.region = part;
        const TileRenderResult r = renderBlocks(w, h, size, o, labelledBlock);
        CHECK(r.counters.pixels == std::uint64_t(part.area()));
        keepRegion(assembled, r.color, part);
    }
    CHECK(assembled == whole.color);
    o.region = PixelRegion{20, 13, 21, 14};
    CHECK(renderBlocks(w, h, size, o, labelledBlock).counters.eyeRays == std::uint64_t(size * size));

    o.region.reset();
    CHECK_THROWS_AS(renderBlocks(w, h, 0, o, labelledBlock), std::invalid_argument);
    auto wrongSize = [](const PixelRegion&, RenderCounters&) { return std::vector<PixelResult>(3); };
    CHECK_THROWS_AS(renderBlocks(w, h, size, o, wrongSize), std::logic_error);
}

TEST_CASE("Progress is reported once per tile in order", "[tiles]") {
    std::vector<TileProgress> calls;
    TileRenderOptions o;
    o.threads = 2;
    o.tileSize = 8;
    o.region = PixelRegion{3, 2, 30, 20};  // 27 x 18 pixels: 4 x 3 tiles
    o.progress = [&](const TileProgress& p) { calls.push_back(p); };
    renderTiles(32, 24, o, noisyPixel);
    REQUIRE(calls.size() == 12);
    for (std::size_t i = 0; i < calls.size(); ++i) {
        CHECK(calls[i].tilesDone == i + 1);
        CHECK(calls[i].tilesTotal == 12);
        CHECK(calls[i].pixelsTotal == 27 * 18);
    }
    CHECK(calls.back().pixelsDone == 27 * 18);
}

TEST_CASE("Tile rendering rejects bad options and passes exceptions on", "[tiles]") {
    TileRenderOptions o;
    o.tileSize = 0;
    CHECK_THROWS_AS(renderTiles(8, 8, o, noisyPixel), std::invalid_argument);
    o.tileSize = 4;
    o.threads = -1;
    CHECK_THROWS_AS(renderTiles(8, 8, o, noisyPixel), std::invalid_argument);
    o.threads = 2;
    o.region = PixelRegion{0, 0, 9, 8};
    CHECK_THROWS_AS(renderTiles(8, 8, o, noisyPixel), std::invalid_argument);
    o.region.reset();
    auto failing = [](int x, int y, RenderCounters&) -> PixelResult {
        if (x == 5 && y == 6) throw std::runtime_error("pixel failed");
        return {};
    };
    CHECK_THROWS_WITH(renderTiles(8, 8, o, failing), "pixel failed");
}

TEST_CASE("Regions parse from x0,y0,x1,y1", "[tiles]") {
    const RegionParse ok = parseRegion("0, 0,320,240", 640, 480);
    REQUIRE(ok.region);
    CHECK(*ok.region == PixelRegion{0, 0, 320, 240});
    CHECK(parseRegion("10,20,11,21", 640, 480).region);
    for (const char* bad : {"", "1,2,3", "1,2,3,4,5", "a,b,c,d", "1;2;3;4", "5,5,5,9",
                            "0,0,641,10", "-1,0,10,10", "10,10,5,20", "0,0,10,10x"}) {
        const RegionParse r = parseRegion(bad, 640, 480);
        INFO(bad);
        CHECK_FALSE(r.region);
        CHECK_FALSE(r.error.empty());
    }
}
