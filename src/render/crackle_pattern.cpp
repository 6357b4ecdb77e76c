#include "asos/render/crackle_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "asos/render/pov_noise.hpp"
#include "asos/scene/description.hpp"
#include "asos/scene/pov_tolerances.hpp"

namespace asos {

const CracklePattern& CracklePattern::tables() {
    static const CracklePattern instance;
    return instance;
}

CracklePattern::CracklePattern() {
    // std::mt19937 default-seeded is Boost's; Boost's uniform_real over a
    // 32-bit engine divides its number by 2^32.
    std::mt19937 engine;
    for (double& r : randoms_) r = static_cast<double>(engine()) / 4294967296.0;
    std::size_t i = 0;
    for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz)
                if ((std::abs(dx) == 2) + (std::abs(dy) == 2) + (std::abs(dz) == 2) <= 1) cubes_[i++] = {dx, dy, dz};
}

Vec3 CracklePattern::pointInCube(int x, int y, int z) const {
    const auto seed = static_cast<std::size_t>(PovNoise::tables().hash3d(x, y, z));
    return Vec3(x + randoms_[seed], y + randoms_[seed + 1], z + randoms_[seed + 2]);
}

double CracklePattern::value(const Pigment& p, const Vec3& q, int generator) const {
    const double metric = p.crackleMetric;
    const bool square = metric == 2.0, unity = metric == 1.0;
    // The metric's sum over the axes, without its root.
    auto distance = [&](const Vec3& d) {
        if (square) return d.x * d.x + d.y * d.y + d.z * d.z;
        if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
    };
    // floor, not truncation, so the cells do not mirror about 0.
    const int cx = static_cast<int>(std::floor(q.x - kPovEpsilon));
    const int cy = static_cast<int>(std::floor(q.y - kPovEpsilon));
    const int cz = static_cast<int>(std::floor(q.z - kPovEpsilon));

    // The nearest three, d1 <= d2 <= d3, and the nearest point: the first
    // three cubes' points sorted as POV-Ray sorts them, then the others in its
    // order (on a tie the earlier cube stays nearer).
    auto pointAt = [&](std::size_t i) { return pointInCube(cx + cubes_[i][0], cy + cubes_[i][1], cz + cubes_[i][2]); };
    const Vec3 first = pointAt(0), second = pointAt(1), third = pointAt(2);
    double d1 = distance(first - q), d2 = distance(second - q), d3 = distance(third - q);
    Vec3 nearest = first;
    if (d2 < d1) {
        std::swap(d1, d2);
        nearest = second;
    }
    if (d3 < d1) {
        std::swap(d1, d3);
        nearest = third;
    }
    if (d3 < d2) std::swap(d2, d3);
    for (std::size_t i = 3; i < cubes_.size(); ++i) {
        const Vec3 point = pointAt(i);
        const double d = distance(point - q);
        if (d < d1) {
            d3 = d2;
            d2 = d1;
            d1 = d;
            nearest = point;
        } else if (d < d2) {
            d3 = d2;
            d2 = d;
        } else if (d < d3) {
            d3 = d;
        }
    }

    const double offset = p.crackleOffset;
    if (offset != 0.0) {
        const double add = square ? offset * offset : unity ? offset : std::pow(offset, metric);
        d1 += add;
        d2 += add;
        d3 += add;
    }

    double v;
    if (p.crackleSolid) {
        v = PovNoise::tables().noise(nearest, generator);
    } else if (square) {
        v = p.crackleForm.x * std::sqrt(d1) + p.crackleForm.y * std::sqrt(d2) + p.crackleForm.z * std::sqrt(d3);
    } else if (unity) {
        v = p.crackleForm.x * d1 + p.crackleForm.y * d2 + p.crackleForm.z * d3;
    } else {
        const double root = 1.0 / metric;
        v = p.crackleForm.x * std::pow(d1, root) + p.crackleForm.y * std::pow(d2, root) +
            p.crackleForm.z * std::pow(d3, root);
    }
    return std::max(std::min(v, 1.0), 0.0);
}

}  // namespace asos
