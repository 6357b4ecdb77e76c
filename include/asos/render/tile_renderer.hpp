#pragma once
// Parallel rendering over square tiles with TBB. Each pixel's value comes from
// a caller-supplied function of the pixel alone (its random numbers included,
// see sampling.hpp), so the image is identical for any thread count, tile
// size or --region split. Counters are kept per thread (tbb::combinable) and
// summed once at the end: no shared counter is touched while tracing. The
// library never prints: progress goes to a callback that the command line
// turns into a bar.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

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

// Renders every pixel of options.region (default: the whole image) with
// pixel(int x, int y, RenderCounters& counters) -> PixelResult.
// Throws std::invalid_argument when the region is not inside the image.
template <class PixelFn>
TileRenderResult renderTiles(int width, int height, const TileRenderOptions& options, PixelFn&& pixel) {
    const PixelRegion region = options.region.value_or(PixelRegion::whole(width, height));
    if (!region.within(width, height))
        throw std::invalid_argument("render region is empty or not inside the image");
    TileRenderResult out{Image::rgb(width, height), Image(width, height, {"rays", "level"}), {}, 0.0, 0};
    // Each pixel is written by exactly one tile: no two threads share an element.
    auto tileFn = [&](const PixelRegion& tile, RenderCounters& counters) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const PixelResult r = pixel(x, y, counters);
                out.color.setRgb(x, y, r.color);
                out.samples.at(x, y, 0) = static_cast<float>(r.rays);
                out.samples.at(x, y, 1) = static_cast<float>(r.level);
                ++counters.pixels;
            }
    };
    const TileRunResult run = forEachTile(region, options, tileFn);
    out.counters = run.counters;
    out.seconds = run.seconds;
    out.threads = run.threads;
    return out;
}

}  // namespace asos
