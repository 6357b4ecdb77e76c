#include "asos/render/grid_light.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace asos {

namespace {

constexpr double kTolerance = kPovShadowTolerance;

// The samples of area light `form` (the model's): its grid's points seen
// from the shaded point.
template <AreaLightForm Form>
void gridSamples(const Form& form, const Scene& scene, const LightModel& model,
                                         const AreaLightQuery& q, AreaLightScratch& s, RenderCounters& counters) {
    const std::optional<typename Form::GridPoints> light = form.gridFrom(q.point);
    if (!light) return;  // the point sees no light (inside a spherical one)
    const int n1 = std::max(model.count1, 1);
    const int n2 = std::max(model.count2, 1);  // 1 for a segment
    const std::uint64_t key = mix64(q.key ^ mix64(0x9e1d0u + q.lightIndex));
    auto jitter = [&](int i, int j) {
        return q.rng.uniform2(SampleStream::LightJitter, mix64(key ^ (std::uint64_t(j) << 32 | std::uint32_t(i))));
    };
    auto blocked = [&](const BeamRay& ray) {
        if (model.shadowless || !(ray.distance > 2.0 * kTolerance)) return false;
        ++counters.shadowRays;
        return scene.occluded(ray.ray, kTolerance, ray.distance - kTolerance);
    };
    auto sampleOf = [&](const BeamRay& ray, double weight) {
        return LightSample{ray.ray.dir, ray.distance, model.color * (weight * light->emission(ray.ray.dir))};
    };

    if (!model.adaptive) {
        // Every point of the array, at the centres of equal cells (jittered
        // within them). A point behind the surface would light nothing: no
        // shadow ray is spent on it.
        const double weight = 1.0 / (double(n1) * double(n2));
        for (int j = 0; j < n2; ++j)
            for (int i = 0; i < n1; ++i) {
                const Vec2 xi = model.jitter ? jitter(i, j) : Vec2(0.5);
                const BeamRay ray = light->toward((i + xi.x) / n1, (j + xi.y) / n2);
                if (glm::dot(q.normal, ray.ray.dir) < kPovEpsilon) continue;
                if (!blocked(ray)) s.samples.push_back(sampleOf(ray, weight));
            }
        return;
    }

    // POV-Ray's adaptive scheme over its lattice from edge to edge: each
    // lattice point is traced once (and kept), a rectangle of the lattice is
    // the mean of its four corners unless it is split.
    const std::size_t points = std::size_t(n1) * std::size_t(n2);
    s.gridState.assign(points, -1);
    s.gridWeights.assign(points, 0.0);
    s.gridSamples.resize(points);
    const auto coordinate = [](double index, int n) {
        return n > 1 ? std::clamp(index / (n - 1), 0.0, 1.0) : 0.5;
    };
    const auto lattice = [&](int i, int j) -> std::size_t {
        const std::size_t k = std::size_t(j) * std::size_t(n1) + std::size_t(i);
        if (s.gridState[k] < 0) {
            // POV-Ray moves a point by up to half a lattice step (here kept on
            // the light).
            const Vec2 xi = model.jitter ? jitter(i, j) - 0.5 : Vec2(0.0);
            const BeamRay ray = light->toward(coordinate(i + xi.x, n1), coordinate(j + xi.y, n2));
            s.gridState[k] = blocked(ray) ? 0 : 1;
            s.gridSamples[k] = sampleOf(ray, 1.0);
        }
        return k;
    };
    // POV-Ray compares the corners' colours (the light's colour or black)
    // and splits when two differ by more than 0.1 in the sum of channels.
    const double colourSum = std::abs(model.color.x) + std::abs(model.color.y) + std::abs(model.color.z);
    const int minLevel = *model.adaptive;
    const auto split = [&](auto& self, int u1, int v1, int u2, int v2, int level, double weight) -> void {
        const std::size_t k[4] = {lattice(u1, v1), lattice(u2, v1), lattice(u1, v2), lattice(u2, v2)};
        const auto differ = [&](int a, int b) {
            return s.gridState[k[a]] != s.gridState[k[b]] && colourSum > 0.1;
        };
        if ((u2 - u1 > 1 || v2 - v1 > 1) &&
            (level < minLevel || differ(0, 1) || differ(1, 3) || differ(3, 2) || differ(2, 0))) {
            const int uLow = (u1 + u2) / 2, uHigh = (u1 + u2 + 1) / 2;
            const int vLow = (v1 + v2) / 2, vHigh = (v1 + v2 + 1) / 2;
            self(self, u1, v1, uLow, vLow, level + 1, 0.25 * weight);
            self(self, uHigh, v1, u2, vLow, level + 1, 0.25 * weight);
            self(self, u1, vHigh, uLow, v2, level + 1, 0.25 * weight);
            self(self, uHigh, vHigh, u2, v2, level + 1, 0.25 * weight);
            return;
        }
        for (std::size_t corner : k) s.gridWeights[corner] += 0.25 * weight;
    };
    split(split, 0, 0, n1 - 1, n2 - 1, 0, 1.0);
    for (std::size_t k = 0; k < points; ++k) {
        if (s.gridState[k] != 1 || !(s.gridWeights[k] > 0.0)) continue;
        LightSample sample = s.gridSamples[k];
        if (glm::dot(q.normal, sample.direction) < kPovEpsilon) continue;
        sample.color *= s.gridWeights[k];
        s.samples.push_back(sample);
    }
}

}  // namespace

std::span<const LightSample> gridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  const AreaLightQuery& q, AreaLightScratch& s,
                                                  RenderCounters& counters) {
    s.samples.clear();
    withAreaForm(model.form, [&](const auto& form) { gridSamples(form, scene, model, q, s, counters); });
    return s.samples;
}

}  // namespace asos
