#pragma once
// The samples AOV (--aov samples=FILE): per pixel, the rays (or pyrays) it
// cost and the deepest subdivision level it reached, so that a picture shows
// where the work went. Written as OpenEXR with float channels "rays" and
// "level", or, for any other extension, as a colour-mapped heat map of the
// rays (docs/rendering.md, "Samples AOV").
#include <filesystem>

#include "asos/geometry/vec.hpp"
#include "asos/image/image_io.hpp"
#include "asos/image/image.hpp"

namespace asos {

// The heat map's colour for t in [0, 1] (clamped): piecewise linear through
// black (0), purple (0.25), red (0.5), orange (0.75) and white (1). The
// values are display values, written without encoding.
Vec3 heatMapColor(double t);

// t = log2(rays) / log2(maxRays): 1 ray (or none) is black, maxRays white.
// maxRays <= 0 uses the image's largest count. `samples` needs a "rays"
// channel (std::invalid_argument otherwise).
Image samplesHeatMap(const Image& samples, double maxRays = 0.0);

// .exr: the channels as they are; anything else: the heat map. Staged as
// stageImage stages an image, to be committed by the caller.
StagedResult stageSamplesAov(const Image& samples, const std::filesystem::path& path, double maxRays = 0.0);

// stageSamplesAov, then commit.
IoStatus writeSamplesAov(const Image& samples, const std::filesystem::path& path, double maxRays = 0.0);

}  // namespace asos
