#pragma once
// Portable Float Map, the one format asos writes without OpenImageIO: 2.4
// reads PFM (its pnm plugin) but has no writer for it. Private to
// image_io.cpp, which picks it from its table of formats and wraps it in the
// same temporary-file-and-rename as every other format; users write PFM
// through writeImage (asos/image/image_io.hpp). No OpenImageIO here.
#include <filesystem>
#include <span>
#include <string>

namespace asos {

// Writes `samples` (width x height pixels of `channels` interleaved floats,
// top row first) to `file` as PFM: "PF" (3 channels, RGB) or "Pf" (1, grey),
// the size, the scale -1.0 (little-endian), then the float32 rows from bottom
// to top, as the format stores them. Any other channel count is an error, not
// a silent drop (PFM has no alpha). Returns why it failed (every write and
// the close are checked), empty on success; on failure `file` may hold part
// of the image. Throws std::invalid_argument when `samples` is not
// width x height x channels values.
std::string writePfm(const std::filesystem::path& file, int width, int height, int channels,
                     std::span<const float> samples);

}  // namespace asos
