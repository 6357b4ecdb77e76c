#include "asos/render/tile_renderer.hpp"

#include <charconv>
#include <chrono>
#include <mutex>
#include <optional>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace asos {

RegionParse parseRegion(std::string_view text, int width, int height) {
    RegionParse result;
    int v[4];
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < 4; ++i) {
        while (p < end && *p == ' ') ++p;
        const auto r = std::from_chars(p, end, v[i]);
        if (r.ec != std::errc()) {
            result.error = "region '" + std::string(text) +
                           "' is not four integers x0,y0,x1,y1";
            return result;
        }
        p = r.ptr;
        while (p < end && *p == ' ') ++p;
        if (i < 3) {
            if (p == end || *p != ',') {
                result.error = "region '" + std::string(text) +
                               "' is not four integers x0,y0,x1,y1";
                return result;
            }
            ++p;
        }
    }
    if (p != end) {
        result.error = "region '" + std::string(text) + "' has extra text after x0,y0,x1,y1";
        return result;
    }
    const PixelRegion region{v[0], v[1], v[2], v[3]};
    if (region.empty()) {
        result.error = "region '" + std::string(text) + "' is empty (need x0 < x1 and y0 < y1)";
        return result;
    }
    if (!region.within(width, height)) {
        result.error = "region '" + std::string(text) + "' is not inside the " +
                       std::to_string(width) + "x" + std::to_string(height) + " image";
        return result;
    }
    result.region = region;
    return result;
}

TileRunResult forEachTile(const PixelRegion& region, const TileRenderOptions& options,
                          FunctionRef<void(const PixelRegion&, RenderCounters&)> tileFn) {
    if (options.tileSize < 1) throw std::invalid_argument("tile size must be at least 1");
    if (options.threads < 0) throw std::invalid_argument("thread count must not be negative");

    std::vector<PixelRegion> tiles;
    if (!region.empty()) {
        for (int y = region.y0; y < region.y1; y += options.tileSize)
            for (int x = region.x0; x < region.x1; x += options.tileSize)
                tiles.push_back({x, y, std::min(x + options.tileSize, region.x1),
                                 std::min(y + options.tileSize, region.y1)});
    }

    // An explicit thread count must be honoured even above the number of
    // cores (TBB otherwise caps its workers there, and says so on stderr):
    // the scoped global_control lifts the cap for this run only.
    std::optional<tbb::global_control> allowThreads;
    if (options.threads > 0)
        allowThreads.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<std::size_t>(options.threads));
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    tbb::combinable<RenderCounters> perThread;
    std::mutex progressMutex;
    TileProgress progress{0, tiles.size(), 0, region.area()};

    const auto start = std::chrono::steady_clock::now();
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    tileFn(tiles[i], perThread.local());
                    if (options.progress) {
                        const std::lock_guard lock(progressMutex);
                        ++progress.tilesDone;
                        progress.pixelsDone += tiles[i].area();
                        options.progress(progress);
                    }
                }
            },
            tbb::simple_partitioner());
    });
    const auto stop = std::chrono::steady_clock::now();

    TileRunResult result;
    perThread.combine_each([&](const RenderCounters& c) { result.counters += c; });
    result.seconds = std::chrono::duration<double>(stop - start).count();
    result.threads = arena.max_concurrency();
    return result;
}

}  // namespace asos
