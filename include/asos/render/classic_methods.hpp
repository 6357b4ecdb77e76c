#pragma once
// The classic image-space anti-aliasing methods, as per-pixel estimators over
// a caller-supplied radiance function, so that they share the camera, shading
// and scene with ASOS and differ from it in method only:
//   single    one ray through the pixel centre;
//   grid      N x N rays at the centres of an N x N grid of sub-pixels;
//   jitter    N x N stratified jittered rays, one uniformly in each sub-pixel;
//   adaptive  Whitted's adaptive supersampling as POV-Ray's +AM2 does it:
//             rays at the pixel corners (shared with the neighbours), a square
//             subdivided into four where any two of its corner colours differ
//             by antialias_threshold or more, down to `depth` levels; a square
//             that is not subdivided contributes the mean of its corners.
//   am1       POV-Ray's +AM1, its default: one ray through the pixel centre,
//             and (depth + 1)^2 more on a grid, averaged with it, in the
//             pixels whose first colour differs from their left or upper
//             neighbour's by antialias_threshold or more, and in those
//             neighbours; pixels are compared within a block of POV-Ray's
//             render grid only.
// See docs/rendering.md for the exact rules and their POV-Ray sources.
//
// The radiance function is any callable taking (const Ray&) or
// (const Ray&, const PrimarySample&) and returning a colour; it is called
// directly (a template parameter, no std::function in the loop). It may also
// take many primary rays at once, for a packet search of their hits:
//   radiance.batch(std::span<const Ray> rays, std::span<const PrimarySample> samples,
//                  std::span<Vec3> colors)
// must set colors[k] to radiance(rays[k], samples[k]), the rays being handled
// in order; the grid and jitter estimators then hand it their rays
// kPrimaryBatch at a time and add the colours in the same order as one by
// one, so that the pixel is the same, bit for bit.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/sampling.hpp"
#include "asos/render/stats.hpp"
#include "asos/render/tile_renderer.hpp"

namespace asos {

// Which primary sample a radiance call is for, so that the radiance function
// can draw its own deterministic random numbers (e.g. area light jitter).
struct PrimarySample {
    Vec2 image{0.0};          // the continuous image point of the ray
    int pixelX = 0, pixelY = 0;
    std::uint32_t index = 0;  // unique within the pixel; kCornerSample for a shared corner
};
// Pixel corners belong to no single pixel: corner (cx, cy) is reported as
// pixel (cx, cy) with this index.
inline constexpr std::uint32_t kCornerSample = 0xffffffffu;

// The largest N of the N x N grid and jitter methods.
inline constexpr int kMaxSamplesPerSide = 1024;

// The most primary rays the grid and jitter estimators hand a batch at once.
inline constexpr int kPrimaryBatch = 64;

namespace detail {
template <class Radiance>
Vec3 callRadiance(Radiance& radiance, const Ray& ray, const PrimarySample& sample) {
    if constexpr (std::is_invocable_v<Radiance&, const Ray&, const PrimarySample&>)
        return Vec3(radiance(ray, sample));
    else
        return Vec3(radiance(ray));
}
inline void requireSampleCount(int n, const char* what) {
    if (n < 1 || n > kMaxSamplesPerSide)
        throw std::invalid_argument(std::string(what) + " must be between 1 and " +
                                    std::to_string(kMaxSamplesPerSide) + ", not " +
                                    std::to_string(n));
}

template <class Radiance>
concept BatchRadiance = requires(Radiance& r, std::span<const Ray> rays,
                                 std::span<const PrimarySample> samples, std::span<Vec3> colors) {
    r.batch(rays, samples, colors);
};

// The summed radiance of a pixel's samples first .. first + count - 1, sample
// k at image point at(k); one by one, or in batches where the radiance
// function takes them.
template <class Radiance, class ImagePoint>
Vec3 sumSamples(const CameraModel& camera, int x, int y, std::uint32_t first, int count,
                Radiance& radiance, ImagePoint&& at) {
    Vec3 sum(0.0);
    if constexpr (BatchRadiance<Radiance>) {
        std::array<Ray, kPrimaryBatch> rays;
        std::array<PrimarySample, kPrimaryBatch> samples;
        std::array<Vec3, kPrimaryBatch> colors;
        for (int start = 0; start < count; start += kPrimaryBatch) {
            const int n = std::min(kPrimaryBatch, count - start);
            for (int k = 0; k < n; ++k) {
                const auto index = first + static_cast<std::uint32_t>(start + k);
                const Vec2 p = at(index);
                rays[k] = camera.ray(p.x, p.y);
                samples[k] = {p, x, y, index};
            }
            const auto m = static_cast<std::size_t>(n);
            radiance.batch(std::span<const Ray>(rays.data(), m),
                           std::span<const PrimarySample>(samples.data(), m),
                           std::span<Vec3>(colors.data(), m));
            for (int k = 0; k < n; ++k) sum += colors[k];
        }
    } else {
        for (int k = 0; k < count; ++k) {
            const auto index = first + static_cast<std::uint32_t>(k);
            const Vec2 p = at(index);
            sum += callRadiance(radiance, camera.ray(p.x, p.y), {p, x, y, index});
        }
    }
    return sum;
}

// The centre of sub-pixel k (row by row) of pixel (x, y)'s n x n grid.
inline Vec2 gridPoint(int x, int y, int n, int k) {
    const int i = k % n, j = k / n;
    return Vec2(x + (i + 0.5) / n, y + (j + 0.5) / n);
}

// The mean radiance of a pixel's samples 0 .. count - 1, sample k at image
// point at(k).
template <class Radiance, class ImagePoint>
PixelResult averageSamples(const CameraModel& camera, int x, int y, int count, Radiance& radiance,
                           ImagePoint&& at) {
    const Vec3 sum = sumSamples(camera, x, y, 0, count, radiance, at);
    return {sum / double(count), static_cast<std::uint32_t>(count), 0};
}
}  // namespace detail

// One ray through the pixel centre.
template <class Radiance>
PixelResult estimateSingle(const CameraModel& camera, int x, int y, Radiance&& radiance) {
    const Vec2 p(x + 0.5, y + 0.5);
    return {detail::callRadiance(radiance, camera.ray(p.x, p.y), {p, x, y, 0}), 1, 0};
}

// n x n rays at the sub-pixel centres (x + (i + 1/2)/n, y + (j + 1/2)/n).
// Throws std::invalid_argument unless 1 <= n <= kMaxSamplesPerSide.
template <class Radiance>
PixelResult estimateGrid(const CameraModel& camera, int x, int y, int n, Radiance&& radiance) {
    detail::requireSampleCount(n, "grid size");
    return detail::averageSamples(camera, x, y, n * n, radiance, [&](std::uint32_t index) {
        return detail::gridPoint(x, y, n, static_cast<int>(index));
    });
}

// n x n stratified jittered rays: one uniform sample in each sub-pixel, its
// position drawn from the pixel's random numbers (SampleStream::PixelJitter).
// Throws std::invalid_argument unless 1 <= n <= kMaxSamplesPerSide.
template <class Radiance>
PixelResult estimateJitter(const CameraModel& camera, int x, int y, int n, const PixelRandom& rng,
                           Radiance&& radiance) {
    detail::requireSampleCount(n, "jitter grid size");
    return detail::averageSamples(camera, x, y, n * n, radiance, [&](std::uint32_t index) {
        const int i = static_cast<int>(index) % n, j = static_cast<int>(index) / n;
        const Vec2 u = rng.uniform2(SampleStream::PixelJitter, index);
        return Vec2(x + (i + u.x) / n, y + (j + u.y) / n);
    });
}

// The parameters of the adaptive and am1 methods (POV-Ray's anti-aliasing
// options), with POV-Ray's defaults.
struct AdaptiveSettings {
    double threshold = 0.3;     // antialias_threshold (+A0.3)
    int depth = 2;              // POV-Ray's +R n is depth n - 1 (+R3: 2): adaptive's
                                // subdivision levels, am1's (depth + 1)^2 sub-samples
    bool jitter = false;        // jitter the sub-samples (never corners or first rays), as +J does
    double jitterAmount = 1.0;  // +J amount
    double gamma = 2.5;         // antialias_gamma: colours are compared after encoding with it
    double assumedGamma = 1.0;  // the scene's working gamma, decoded first
};
inline constexpr int kMaxAdaptiveDepth = 8;

// Empty when the settings are usable; otherwise what is wrong with them
// (depth outside 0..kMaxAdaptiveDepth, a negative or non-finite threshold,
// jitter amount or gamma).
std::string checkAdaptiveSettings(const AdaptiveSettings& settings);

// Whether two colours differ enough to subdivide: POV-Ray's
// ColourDistance(encode(a), encode(b)) >= threshold, the distance being the
// sum of the channels' absolute differences and encode(c) = c^(1/gamma).
bool adaptiveColorsDiffer(const Vec3& a, const Vec3& b, const AdaptiveSettings& settings);

// The colours at a pixel's four corners, and how many of those corner rays
// the pixel is charged with (see ownedCornerRays).
struct PixelCorners {
    Vec3 topLeft{0.0}, topRight{0.0}, bottomLeft{0.0}, bottomRight{0.0};
    std::uint32_t ownedRays = 0;
};

// Corner rays are shared; each is charged to one pixel so that the samples
// AOV sums to the rays traced: a pixel owns its top-left corner, the last
// column also its top-right, the last row its bottom-left, and the
// bottom-right pixel all four.
inline std::uint32_t ownedCornerRays(int x, int y, int width, int height) {
    const bool lastColumn = x == width - 1, lastRow = y == height - 1;
    return 1u + lastColumn + lastRow + (lastColumn && lastRow);
}

// POV-Ray's +AM2 for one pixel, given its corners (POV-Ray's
// TraceTask::SubdivideOnePixel): `rays` is the new sub-samples plus
// corners.ownedRays; `level` the deepest subdivision reached (0: the corners
// alone decided). Sub-sample positions lie on a (2^depth + 1)^2 lattice over
// the pixel and are traced once each; with jitter each moves by up to
// +-jitterAmount / (2 (2^(depth+1) + 1)) pixels, POV-Ray's jitter scale.
// Throws std::invalid_argument for settings checkAdaptiveSettings rejects.
template <class Radiance>
PixelResult estimateAdaptive(const CameraModel& camera, int x, int y, const PixelCorners& corners,
                             const AdaptiveSettings& settings, const PixelRandom& rng,
                             Radiance&& radiance) {
    if (std::string error = checkAdaptiveSettings(settings); !error.empty())
        throw std::invalid_argument(error);
    const int depth = settings.depth;
    const int size = 1 << depth;  // lattice cells per pixel side
    const int side = size + 1;
    const double jitterScale =
        settings.jitter ? settings.jitterAmount / double((1 << (depth + 1)) + 1) : 0.0;

    // The lattice is only needed once the pixel subdivides (edge pixels).
    std::vector<Vec3> lattice;
    std::vector<unsigned char> sampled;
    std::uint32_t rays = corners.ownedRays;
    int deepest = 0;

    auto value = [&](int ix, int iy) -> const Vec3& { return lattice[iy * side + ix]; };
    auto sample = [&](int ix, int iy) {
        const int k = iy * side + ix;
        if (sampled[k]) return;
        Vec2 p(x + double(ix) / size, y + double(iy) / size);
        if (jitterScale > 0.0)
            p += (rng.uniform2(SampleStream::AdaptiveJitter, k) - 0.5) * jitterScale;
        lattice[k] = detail::callRadiance(radiance, camera.ray(p.x, p.y),
                                          {p, x, y, static_cast<std::uint32_t>(k)});
        sampled[k] = 1;
        ++rays;
    };
    auto differ = [&](const Vec3& a, const Vec3& b) { return adaptiveColorsDiffer(a, b, settings); };
    auto anyDiffer = [&](const Vec3& c00, const Vec3& c10, const Vec3& c01, const Vec3& c11) {
        return differ(c00, c01) || differ(c00, c10) || differ(c00, c11) || differ(c01, c10) ||
               differ(c01, c11) || differ(c10, c11);
    };

    if (depth == 0 || !anyDiffer(corners.topLeft, corners.topRight, corners.bottomLeft,
                                 corners.bottomRight))
        return {(corners.topLeft + corners.topRight + corners.bottomLeft + corners.bottomRight) / 4.0,
                rays, 0};

    lattice.assign(std::size_t(side) * side, Vec3(0.0));
    sampled.assign(std::size_t(side) * side, 0);
    lattice[0] = corners.topLeft;
    lattice[size] = corners.topRight;
    lattice[size * side] = corners.bottomLeft;
    lattice[size * side + size] = corners.bottomRight;
    sampled[0] = sampled[size] = sampled[size * side] = sampled[size * side + size] = 1;

    // Recursion over squares of the lattice: (bx, by) top-left, `step` cells wide.
    auto subdivide = [&](auto& self, int bx, int by, int step, int level) -> Vec3 {
        const Vec3 c00 = value(bx, by), c10 = value(bx + step, by);
        const Vec3 c01 = value(bx, by + step), c11 = value(bx + step, by + step);
        if (level >= depth || !anyDiffer(c00, c10, c01, c11)) return (c00 + c10 + c01 + c11) / 4.0;
        const int half = step / 2;
        sample(bx, by + half);
        sample(bx + half, by);
        sample(bx + step, by + half);
        sample(bx + half, by + step);
        sample(bx + half, by + half);
        deepest = std::max(deepest, level + 1);
        return (self(self, bx, by, half, level + 1) + self(self, bx, by + half, half, level + 1) +
                self(self, bx + half, by, half, level + 1) +
                self(self, bx + half, by + half, half, level + 1)) /
               4.0;
    };
    const Vec3 color = subdivide(subdivide, 0, 0, size, 0);
    return {color, rays, static_cast<std::uint32_t>(deepest)};
}

// The colours at the pixel corners of a region, traced in parallel before
// the adaptive pass so that each corner is traced once and shared.
struct CornerGrid {
    PixelRegion pixels;              // corners (cx, cy), x0 <= cx <= x1, y0 <= cy <= y1
    int imageWidth = 0, imageHeight = 0;
    std::vector<Vec3> values;
    RenderCounters counters;         // what tracing the corners cost
    double seconds = 0.0;

    const Vec3& at(int cx, int cy) const {
        return values[std::size_t(cy - pixels.y0) * (pixels.width() + 1) + (cx - pixels.x0)];
    }
    PixelCorners ofPixel(int x, int y) const {
        return {at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1),
                ownedCornerRays(x, y, imageWidth, imageHeight)};
    }
};

// Traces the corner rays of `pixels` (a region of the camera's image) with
// radiance(const Ray&, const PrimarySample&, RenderCounters&) -> Vec3, or
// radiance(const Ray&, RenderCounters&), using the tile renderer's threads.
// Corner rays pass through the exact corners (POV-Ray does not jitter them).
template <class Radiance>
CornerGrid sampleCorners(const CameraModel& camera, const PixelRegion& pixels,
                         const TileRenderOptions& options, Radiance&& radiance) {
    if (!pixels.within(camera.width(), camera.height()))
        throw std::invalid_argument("render region is empty or not inside the image");
    CornerGrid grid;
    grid.pixels = pixels;
    grid.imageWidth = camera.width();
    grid.imageHeight = camera.height();
    grid.values.assign(std::size_t(pixels.width() + 1) * (pixels.height() + 1), Vec3(0.0));
    const PixelRegion corners{pixels.x0, pixels.y0, pixels.x1 + 1, pixels.y1 + 1};
    TileRenderOptions cornerOptions = options;
    cornerOptions.progress = nullptr;  // progress is the pixels' business
    auto tileFn = [&](const PixelRegion& tile, RenderCounters& counters) {
        for (int cy = tile.y0; cy < tile.y1; ++cy)
            for (int cx = tile.x0; cx < tile.x1; ++cx) {
                const Ray ray = camera.ray(cx, cy);
                const PrimarySample s{Vec2(cx, cy), cx, cy, kCornerSample};
                Vec3 c;
                if constexpr (std::is_invocable_v<Radiance&, const Ray&, const PrimarySample&,
                                                  RenderCounters&>)
                    c = Vec3(radiance(ray, s, counters));
                else
                    c = Vec3(radiance(ray, counters));
                grid.values[std::size_t(cy - pixels.y0) * (pixels.width() + 1) + (cx - pixels.x0)] = c;
            }
    };
    const TileRunResult run = forEachTile(corners, cornerOptions, tileFn);
    grid.counters = run.counters;
    grid.seconds = run.seconds;
    return grid;
}

// POV-Ray's render block size (its default +BS32). +AM1 compares pixels
// within one block only, so the block grid is part of the method: it is laid
// from the image's top-left corner, whatever the tiles, threads and region.
inline constexpr int kAm1BlockSize = 32;

// POV-Ray's +AM1 (TraceTask::NonAdaptiveSupersamplingM1) over one block of
// its render grid, the block's pixels row by row: `rays` is what the pixel
// cost (see below), `level` 1 where it was supersampled.
//  - Each pixel's first ray passes through its centre (primary sample index
//    0, as estimateSingle). The row above the block and the column left of it
//    are traced again as first rays (POV-Ray's frame, charged to the block's
//    first row and column); the block compares with them but never
//    supersamples them.
//  - In raster order, a pixel is compared with its left and upper neighbours
//    as they are at that moment (supersampled already, or not): where one
//    differs (adaptiveColorsDiffer), the pixel and that neighbour, unless
//    supersampled already, are supersampled.
//  - Supersampling a pixel averages its first sample with n x n more,
//    n = depth + 1 (POV-Ray's +R n with depth = n - 1, as for adaptive), at
//    the centres of an n x n grid (indices 1 .. n^2); with jitter each moves
//    by up to +-jitterAmount / (2 n) pixels, POV-Ray's jitter scale, from
//    PixelRandom(seed, x, y) (SampleStream::Am1Jitter).
// Throws std::invalid_argument for settings checkAdaptiveSettings rejects.
template <class Radiance>
std::vector<PixelResult> estimateAm1Block(const CameraModel& camera, const PixelRegion& block,
                                          const AdaptiveSettings& settings, std::uint64_t seed,
                                          Radiance&& radiance) {
    if (std::string error = checkAdaptiveSettings(settings); !error.empty())
        throw std::invalid_argument(error);
    const int n = settings.depth + 1;
    const double jitterScale = settings.jitter ? settings.jitterAmount / n : 0.0;

    // The block and its frame; `settled` marks the samples the block must not
    // supersample: those supersampled already, and the frame.
    struct Sample {
        Vec3 color{0.0};
        bool settled = false;
        std::uint32_t rays = 0;
    };
    const int stride = block.width() + 1;
    std::vector<Sample> samples(std::size_t(stride) * (block.height() + 1));
    auto sampleAt = [&](int x, int y) -> Sample& {
        return samples[std::size_t(y - block.y0 + 1) * stride + (x - block.x0 + 1)];
    };
    auto firstSample = [&](int x, int y) -> Sample {
        const Vec2 p(x + 0.5, y + 0.5);
        return {detail::callRadiance(radiance, camera.ray(p.x, p.y), {p, x, y, 0}), false, 1};
    };
    auto supersample = [&](int x, int y) {
        const PixelRandom rng(seed, x, y);
        const Vec3 sum = detail::sumSamples(camera, x, y, 1, n * n, radiance, [&](std::uint32_t index) {
            const int k = static_cast<int>(index) - 1;
            Vec2 p = detail::gridPoint(x, y, n, k);
            if (jitterScale > 0.0)
                p += (rng.uniform2(SampleStream::Am1Jitter, std::uint64_t(k)) - 0.5) * jitterScale;
            return p;
        });
        Sample& s = sampleAt(x, y);
        s.color = (s.color + sum) / double(n * n + 1);
        s.settled = true;
        s.rays += static_cast<std::uint32_t>(n * n);
    };

    auto frame = [&](int x, int y) { (sampleAt(x, y) = firstSample(x, y)).settled = true; };
    for (int x = block.x0; x < block.x1; ++x) frame(x, block.y0 - 1);
    for (int y = block.y0; y < block.y1; ++y) {
        frame(block.x0 - 1, y);
        for (int x = block.x0; x < block.x1; ++x) {
            const Sample& current = sampleAt(x, y) = firstSample(x, y);
            const Sample& left = sampleAt(x - 1, y);
            const Sample& top = sampleAt(x, y - 1);
            const bool leftDiffers = adaptiveColorsDiffer(left.color, current.color, settings);
            const bool topDiffers = adaptiveColorsDiffer(top.color, current.color, settings);
            if (leftDiffers && !left.settled) supersample(x - 1, y);
            if (topDiffers && !top.settled) supersample(x, y - 1);
            if (leftDiffers || topDiffers) supersample(x, y);
        }
    }
    // The frame's rays are charged to the block's first row and column.
    std::vector<PixelResult> results;
    results.reserve(std::size_t(block.area()));
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x) {
            const Sample& s = sampleAt(x, y);
            results.push_back({s.color, s.rays + (x == block.x0) + (y == block.y0), s.rays > 1 ? 1u : 0u});
        }
    return results;
}

}  // namespace asos
