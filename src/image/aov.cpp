#include "asos/image/aov.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>

namespace asos {

Vec3 heatMapColor(double t) {
    static constexpr std::array<Vec3, 5> kStops{Vec3(0.0, 0.0, 0.0), Vec3(0.33, 0.0, 0.55),
                                                Vec3(0.85, 0.15, 0.25), Vec3(1.0, 0.65, 0.0),
                                                Vec3(1.0, 1.0, 1.0)};
    if (!(t > 0.0)) return kStops.front();
    if (t >= 1.0) return kStops.back();
    const double s = t * (kStops.size() - 1);
    const auto i = static_cast<std::size_t>(s);
    return glm::mix(kStops[i], kStops[i + 1], s - double(i));
}

Image samplesHeatMap(const Image& samples, double maxRays) {
    const int rays = samples.channelIndex("rays");
    if (rays < 0) throw std::invalid_argument("samples image has no \"rays\" channel");
    if (!(maxRays > 0.0)) {
        maxRays = 0.0;
        for (int y = 0; y < samples.height(); ++y)
            for (int x = 0; x < samples.width(); ++x)
                maxRays = std::max(maxRays, double(samples.at(x, y, rays)));
    }
    const double scale = maxRays > 1.0 ? 1.0 / std::log2(maxRays) : 0.0;
    Image heat = Image::rgb(samples.width(), samples.height());
    for (int y = 0; y < samples.height(); ++y)
        for (int x = 0; x < samples.width(); ++x) {
            const double n = samples.at(x, y, rays);
            heat.setRgb(x, y, heatMapColor(n > 1.0 ? std::log2(n) * scale : 0.0));
        }
    return heat;
}

StagedResult stageSamplesAov(const Image& samples, const std::filesystem::path& path, double maxRays) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".exr") return stageImage(samples, path);
    if (samples.channelIndex("rays") < 0)
        return {std::nullopt, "cannot write the samples AOV to '" + path.string() + "': no \"rays\" channel"};
    return stageImage(samplesHeatMap(samples, maxRays), path, {.transfer = Transfer::Raw});
}

IoStatus writeSamplesAov(const Image& samples, const std::filesystem::path& path, double maxRays) {
    StagedResult staged = stageSamplesAov(samples, path, maxRays);
    if (!staged.file) return {staged.error};
    return {staged.file->commit()};
}

}  // namespace asos
