#include "src/image/pfm.hpp"

#include <bit>
#include <cstdint>
#include <stdexcept>

namespace asos {
namespace {

// Little-endian whatever the machine, so that the file's bytes depend on the
// image only (the header's negative scale says little-endian).
void putLittleEndian(float value, unsigned char* out) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int i = 0; i < 4; ++i) out[i] = static_cast<unsigned char>(bits >> (8 * i));
}

}  // namespace

PfmBytes encodePfm(int width, int height, int channels, std::span<const float> samples) {
    if (channels != 1 && channels != 3)
        return {{}, "PFM holds 3 channels (RGB) or 1 (grey), not " + std::to_string(channels)};
    const std::size_t rowValues = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    if (width <= 0 || height <= 0 || samples.size() != rowValues * static_cast<std::size_t>(height))
        throw std::invalid_argument("encodePfm: the samples are not width x height x channels floats");

    const std::string header = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) +
                               " " + std::to_string(height) + "\n-1.0\n";
    PfmBytes out;
    out.bytes.reserve(header.size() + samples.size() * 4);
    out.bytes.assign(header.begin(), header.end());
    std::size_t at = out.bytes.size();
    out.bytes.resize(at + samples.size() * 4);
    for (int y = height - 1; y >= 0; --y) {
        const float* values = samples.data() + static_cast<std::size_t>(y) * rowValues;
        for (std::size_t i = 0; i < rowValues; ++i, at += 4) putLittleEndian(values[i], out.bytes.data() + at);
    }
    return out;
}

}  // namespace asos
