#include "src/image/pfm.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace asos {
namespace {

// write(2) may take fewer bytes than asked (a signal, a file size limit
// reached part way): go on until all are written or it fails. Returns why it
// failed, empty on success.
std::string writeAll(int fd, const unsigned char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return std::strerror(errno);
        if (n == 0) return "the file takes no more bytes";
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return {};
}

// Little-endian whatever the machine, so that the file's bytes depend on the
// image only (the header's negative scale says little-endian).
void putLittleEndian(float value, unsigned char* out) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int i = 0; i < 4; ++i) out[i] = static_cast<unsigned char>(bits >> (8 * i));
}

}  // namespace

std::string writePfm(const std::filesystem::path& file, int width, int height, int channels,
                     std::span<const float> samples) {
    if (channels != 1 && channels != 3)
        return "PFM holds 3 channels (RGB) or 1 (grey), not " + std::to_string(channels);
    const std::size_t rowValues = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    if (width <= 0 || height <= 0 || samples.size() != rowValues * static_cast<std::size_t>(height))
        throw std::invalid_argument("writePfm: the samples are not width x height x channels floats");

    const std::string header = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) +
                               " " + std::to_string(height) + "\n-1.0\n";
    std::vector<unsigned char> row(rowValues * 4);

    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) return std::strerror(errno);
    std::string error = writeAll(fd, reinterpret_cast<const unsigned char*>(header.data()), header.size());
    for (int y = height - 1; error.empty() && y >= 0; --y) {
        const float* values = samples.data() + static_cast<std::size_t>(y) * rowValues;
        for (std::size_t i = 0; i < rowValues; ++i) putLittleEndian(values[i], row.data() + 4 * i);
        error = writeAll(fd, row.data(), row.size());
    }
    // close(2) can report a write that failed late (NFS, a full disk): it
    // counts as much as any write.
    if (::close(fd) != 0 && error.empty()) error = std::strerror(errno);
    return error;
}

}  // namespace asos
