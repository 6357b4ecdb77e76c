#pragma once
// Portable Float Map, the one format asos writes without OpenImageIO: 2.4
// reads PFM (its pnm plugin) but has no writer for it. Private to
// image_io.cpp, which picks it from its table of formats and wraps it in the
// same staged file (asos/util/staged_file.hpp) as every other format; users write PFM
// through writeImage (asos/image/image_io.hpp). No OpenImageIO here.
#include <span>
#include <string>
#include <vector>

namespace asos {

struct PfmBytes {
    std::vector<unsigned char> bytes;
    std::string error;  // why the image cannot be PFM, empty on success
};

// `samples` (width x height pixels of `channels` interleaved floats, top row
// first) as a PFM file's bytes: "PF" (3 channels, RGB) or "Pf" (1, grey),
// the size, the scale -1.0 (little-endian), then the float32 rows from bottom
// to top, as the format stores them. Any other channel count is an error, not
// a silent drop (PFM has no alpha). Throws std::invalid_argument when
// `samples` is not width x height x channels values.
PfmBytes encodePfm(int width, int height, int channels, std::span<const float> samples);

}  // namespace asos
