#pragma once
// A float image buffer: width x height pixels of named channels, stored
// interleaved by scanline, top row first. Rendered colour is linear RGB
// (channels R, G, B); AOVs use their own channel names.
#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "asos/geometry/vec.hpp"

namespace asos {

class Image {
public:
    Image() = default;
    // Zero-filled. Throws std::invalid_argument for a negative size or no channels.
    Image(int width, int height, std::vector<std::string> channelNames)
        : width_(width), height_(height), names_(std::move(channelNames)) {
        if (width < 0 || height < 0 || names_.empty())
            throw std::invalid_argument("image needs a non-negative size and at least one channel");
        data_.assign(static_cast<std::size_t>(width) * height * names_.size(), 0.0f);
    }
    static Image rgb(int width, int height) { return Image(width, height, {"R", "G", "B"}); }

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return static_cast<int>(names_.size()); }
    const std::vector<std::string>& channelNames() const { return names_; }
    bool empty() const { return data_.empty(); }
    // The index of the channel called `name`, or -1. (Files may reorder
    // channels: OpenEXR stores them sorted by name.)
    int channelIndex(const std::string& name) const {
        for (std::size_t c = 0; c < names_.size(); ++c)
            if (names_[c] == name) return static_cast<int>(c);
        return -1;
    }

    float& at(int x, int y, int c) { return data_[index(x, y) + c]; }
    float at(int x, int y, int c) const { return data_[index(x, y) + c]; }
    std::span<float> pixel(int x, int y) { return {data_.data() + index(x, y), names_.size()}; }
    std::span<const float> pixel(int x, int y) const {
        return {data_.data() + index(x, y), names_.size()};
    }

    // The first three channels as a colour.
    Vec3 rgbAt(int x, int y) const {
        const float* p = data_.data() + index(x, y);
        return {p[0], p[1], p[2]};
    }
    void setRgb(int x, int y, const Vec3& c) {
        float* p = data_.data() + index(x, y);
        p[0] = static_cast<float>(c.x);
        p[1] = static_cast<float>(c.y);
        p[2] = static_cast<float>(c.z);
    }

    // The pixels [x0, x1) x [y0, y1) as a new image (a rendered --region
    // without the unrendered surround). Throws std::invalid_argument when the
    // rectangle is empty or not inside the image.
    Image cropped(int x0, int y0, int x1, int y1) const {
        if (x0 < 0 || y0 < 0 || x1 > width_ || y1 > height_ || x1 <= x0 || y1 <= y0)
            throw std::invalid_argument("crop rectangle is empty or not inside the image");
        Image out(x1 - x0, y1 - y0, names_);
        const std::size_t rowValues = static_cast<std::size_t>(x1 - x0) * names_.size();
        for (int y = y0; y < y1; ++y)
            std::copy_n(data_.begin() + index(x0, y), rowValues, out.data_.begin() + out.index(0, y - y0));
        return out;
    }

    const std::vector<float>& data() const { return data_; }
    std::vector<float>& data() { return data_; }

    bool operator==(const Image&) const = default;

private:
    std::size_t index(int x, int y) const {
        return (static_cast<std::size_t>(y) * width_ + x) * names_.size();
    }

    int width_ = 0, height_ = 0;
    std::vector<std::string> names_;
    std::vector<float> data_;
};

}  // namespace asos
