#pragma once
// Parallel rendering over square tiles with TBB. Each pixel's value comes from
// a caller-supplied function of the pixel alone (its random numbers included,
// see sampling.hpp), so the image is identical for any thread count, tile
// size or --region split. Counters are kept per thread (tbb::combinable) and
// summed once at the end: no shared counter is touched while tracing. The
// library never prints: progress goes to a callback that the command line
// turns into a bar.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "asos/geometry/vec.hpp"
#include "asos/image/image.hpp"
#include "asos/render/stats.hpp"
#include "asos/util/function_ref.hpp"

namespace asos {

// The pixels [x0, x1) x [y0, y1).
struct PixelRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    static PixelRegion whole(int width, int height) { return {0, 0, width, height}; }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    std::int64_t area() const { return empty() ? 0 : std::int64_t(width()) * height(); }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool within(int imageWidth, int imageHeight) const {
        return x0 >= 0 && y0 >= 0 && x1 <= imageWidth && y1 <= imageHeight && !empty();
    }
    bool operator==(const PixelRegion&) const = default;
};

struct RegionParse {
    std::optional<PixelRegion> region;
    std::string error;  // set when region is empty
};

// Parses --region "x0,y0,x1,y1": pixel columns x0..x1-1 and rows y0..y1-1 of
// a width x height image (so "0,0,320,240" is the top-left quarter of
// 640x480). Rejects malformed text, empty regions and regions outside the image.
RegionParse parseRegion(std::string_view text, int width, int height);

// What a pixel function returns: the pixel's linear colour, the number of
// rays (or pyrays) it cost and the deepest subdivision level it reached.
struct PixelResult {
    Vec3 color{0.0};
    std::uint32_t rays = 0;
    std::uint32_t level = 0;
};

struct TileProgress {
    std::size_t tilesDone = 0, tilesTotal = 0;
    std::int64_t pixelsDone = 0, pixelsTotal = 0;
};

struct TileRenderOptions {
    int tileSize = 16;                  // pixels per tile side, >= 1
    int threads = 0;                    // worker threads; 0: all cores
    std::optional<PixelRegion> region;  // default: the whole image
    // Called after each finished tile, from whichever worker finished it, but
    // never by two threads at once and with tilesDone increasing by one.
    std::function<void(const TileProgress&)> progress;
};

struct TileRunResult {
    RenderCounters counters;  // summed over the threads
    double seconds = 0.0;     // wall-clock time of the run
    int threads = 0;          // worker threads the run could use
};

// Calls tileFn once for every tile of `region` (tiles of options.tileSize
// pixels, the last row and column clipped), in parallel. tileFn gets the
// calling thread's counters. Throws std::invalid_argument for tileSize < 1 or
// threads < 0; an exception thrown by tileFn stops the run and propagates.
TileRunResult forEachTile(const PixelRegion& region, const TileRenderOptions& options,
                          FunctionRef<void(const PixelRegion& tile, RenderCounters& counters)> tileFn);

struct TileRenderResult {
    Image color;    // width x height linear RGB; pixels outside the region stay 0
    Image samples;  // width x height, channels "rays" and "level" (the samples AOV)
    RenderCounters counters;  // counters.pixels = pixels rendered
    double seconds = 0.0;
    int threads = 0;
};

namespace detail {
// The region of options (default: the whole image), checked.
inline PixelRegion renderRegion(int width, int height, const TileRenderOptions& options) {
    const PixelRegion region = options.region.value_or(PixelRegion::whole(width, height));
    if (!region.within(width, height))
        throw std::invalid_argument("render region is empty or not inside the image");
    return region;
}
inline TileRenderResult blankRender(int width, int height) {
    return {Image::rgb(width, height), Image(width, height, {"rays", "level"}), {}, 0.0, 0};
}
inline void storePixel(TileRenderResult& out, int x, int y, const PixelResult& r, RenderCounters& counters) {
    out.color.setRgb(x, y, r.color);
    out.samples.at(x, y, 0) = static_cast<float>(r.rays);
    out.samples.at(x, y, 1) = static_cast<float>(r.level);
    ++counters.pixels;
}
inline void finishRender(TileRenderResult& out, const TileRunResult& run) {
    out.counters = run.counters;
    out.seconds = run.seconds;
    out.threads = run.threads;
}
}  // namespace detail

// Renders every pixel of options.region (default: the whole image) with
// pixel(int x, int y, RenderCounters& counters) -> PixelResult.
// Throws std::invalid_argument when the region is not inside the image.
template <class PixelFn>
TileRenderResult renderTiles(int width, int height, const TileRenderOptions& options, PixelFn&& pixel) {
    const PixelRegion region = detail::renderRegion(width, height, options);
    TileRenderResult out = detail::blankRender(width, height);
    // Each pixel is written by exactly one tile: no two threads share an element.
    auto tileFn = [&](const PixelRegion& tile, RenderCounters& counters) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                detail::storePixel(out, x, y, pixel(x, y, counters), counters);
    };
    detail::finishRender(out, forEachTile(region, options, tileFn));
    return out;
}

// Renders options.region like renderTiles, for a method whose pixels depend
// on their neighbours within a block of a fixed grid (POV-Ray's +AM1):
// block(const PixelRegion& block, RenderCounters&) -> std::vector<PixelResult>
// gives the whole block's pixels, row by row. The blocks are blockSize pixels
// square, laid from the image's top-left corner (options.tileSize is not
// used); every block that meets the region is rendered whole and its pixels
// outside the region are dropped, so that a pixel is the same for any thread
// count, tile size or region. Throws std::invalid_argument when the region is
// not inside the image or blockSize < 1, std::logic_error when a block gives
// the wrong number of pixels.
template <class BlockFn>
TileRenderResult renderBlocks(int width, int height, int blockSize, const TileRenderOptions& options,
                              BlockFn&& block) {
    const PixelRegion region = detail::renderRegion(width, height, options);
    if (blockSize < 1) throw std::invalid_argument("block size must be at least 1");
    auto down = [&](int v) { return v / blockSize * blockSize; };
    auto up = [&](int v, int limit) { return std::min(down(v + blockSize - 1), limit); };
    const PixelRegion blocks{down(region.x0), down(region.y0), up(region.x1, width), up(region.y1, height)};
    TileRenderOptions blockOptions = options;
    blockOptions.tileSize = blockSize;
    TileRenderResult out = detail::blankRender(width, height);
    auto tileFn = [&](const PixelRegion& b, RenderCounters& counters) {
        const std::vector<PixelResult> results = block(b, counters);
        if (results.size() != static_cast<std::size_t>(b.area()))
            throw std::logic_error("a block gave " + std::to_string(results.size()) + " pixels, not " +
                                   std::to_string(b.area()));
        for (int y = std::max(b.y0, region.y0); y < std::min(b.y1, region.y1); ++y)
            for (int x = std::max(b.x0, region.x0); x < std::min(b.x1, region.x1); ++x) {
                const std::size_t k = std::size_t(y - b.y0) * b.width() + (x - b.x0);
                detail::storePixel(out, x, y, results[k], counters);
            }
    };
    detail::finishRender(out, forEachTile(blocks, blockOptions, tileFn));
    return out;
}

}  // namespace asos
