#include "asos/testing/image_error.hpp"

#include <stdexcept>

#include "asos/image/encoding.hpp"
#include "asos/testing/image_comparison.hpp"

namespace asos {

namespace {

Image displayValues(const Image& image, std::optional<double> assumedGamma) {
    Image out = Image::rgb(image.width(), image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = static_cast<float>(workingToSrgb(image.at(x, y, c), assumedGamma));
    return out;
}

}  // namespace

ImageError imageError(const Image& image, const Image& reference, std::optional<double> assumedGamma) {
    if (image.width() != reference.width() || image.height() != reference.height() || image.channels() < 3 ||
        reference.channels() < 3)
        throw std::invalid_argument("imageError: two RGB images of one size");
    CompareThresholds t;
    t.failValue = kOffByValue;
    const ImageComparison c =
        compareImages(displayValues(image, assumedGamma), displayValues(reference, assumedGamma), t);
    ImageError e;
    e.rmse = c.rmsError;
    e.maxError = c.maxError;
    e.offShare = c.pixels > 0 ? double(c.failPixels) / double(c.pixels) : 0.0;
    return e;
}

}  // namespace asos
