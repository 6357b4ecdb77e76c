#include "asos/render/grid_light.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace asos {

namespace {

constexpr double kTolerance = kPovShadowTolerance;

// The random numbers that jitter lattice point (i, j) of the query's light.
Vec2 latticeJitter(const AreaLightQuery& q, int i, int j) {
    const std::uint64_t key = mix64(q.key ^ mix64(0x9e1d0u + q.lightIndex));
    return q.rng.uniform2(SampleStream::LightJitter, mix64(key ^ (std::uint64_t(j) << 32 | std::uint32_t(i))));
}

// A plain shadow ray toward a grid point: through the whole scene, from the
// shadow tolerance to the tolerance before the light.
bool gridRayBlocked(const Scene& scene, const LightModel& model, const BeamRay& ray, RenderCounters& counters) {
    if (model.shadowless || !(ray.distance > 2.0 * kTolerance)) return false;
    ++counters.shadowRays;
    return scene.occluded(ray.ray, kTolerance, ray.distance - kTolerance);
}

// POV-Ray's recursion (trace.cpp, TraceAreaLightSubsetShadowRay) over the
// lattice of area light `form` (the model's) seen from the shaded point: the
// fraction of it that reaches the point.
template <AreaLightForm Form>
double visibleFraction(const Form& form, const Scene& scene, const LightModel& model, const AreaLightQuery& q,
                       AreaLightScratch& s, RenderCounters& counters) {
    const std::optional<typename Form::GridPoints> light = form.gridFrom(q.point);
    if (!light) return 0.0;  // the point is the disc's centre
    const int n1 = std::max(model.count1, 1);
    const int n2 = std::max(model.count2, 1);  // 1 for a segment
    s.gridState.assign(std::size_t(n1) * std::size_t(n2), -1);
    // POV-Ray first tests the object that blocked its last shadow ray, and
    // that test counts hits from MIN_ISECT_DEPTH on rather than from the
    // shadow tolerance (trace.cpp, TracePointLightShadowRay's shadow cache).
    // Near the terminator of a curved object the rays into it are blocked by
    // the object itself, which is then the one cached: the shaded object
    // blocks from kPovMinIsectDepth on (a ray that grazes it leaves it
    // within the tolerance).
    const Primitive& shaded = scene.primitive(q.shadedObject);
    const bool cached = !scene.object(q.shadedObject).noShadow && !scene.transparent(q.shadedObject);
    // Each lattice point traced once; POV-Ray's jitter moves it by up to
    // half a step either way, past the light's edges.
    const auto lit = [&](int i, int j) {
        std::int8_t& state = s.gridState[std::size_t(j) * std::size_t(n1) + std::size_t(i)];
        if (state < 0) {
            const Vec2 xi = model.jitter ? latticeJitter(q, i, j) - 0.5 : Vec2(0.0);
            const BeamRay ray = light->toward(povrayLatticeFraction(i + xi.x, n1), povrayLatticeFraction(j + xi.y, n2));
            const bool hitsCached = cached && ray.distance > kPovMinIsectDepth &&
                                    shaded.intersectAny(ray.ray, kPovMinIsectDepth, ray.distance);
            if (hitsCached) ++counters.shadowRays;
            state = hitsCached || gridRayBlocked(scene, model, ray, counters) ? 0 : 1;
        }
        return state == 1;
    };
    // POV-Ray compares the corners' colours: the light's (faded at its
    // centre's distance and narrowed by a spotlight's cone, neither with
    // area_illumination) or black, more than
    // 0.1 apart in the sum of channels.
    // A spotlight's cone scales that colour too (along the centre's direction).
    const Vec3 toCentre = model.position - q.point;
    const double distance = glm::length(toCentre);
    const double fade = model.areaIllumination ? 1.0
                        : model.fade(distance) *
                              (model.beam && distance > 0.0 ? model.beam->factor(q.point, toCentre / distance) : 1.0);
    const bool compare = (std::abs(model.color.x) + std::abs(model.color.y) + std::abs(model.color.z)) * fade > 0.1;
    const int minLevel = model.adaptive.value_or(kPovrayAdaptiveLevel);
    const auto mean = [&](auto& self, int u1, int v1, int u2, int v2, int level) -> double {
        const bool c[4] = {lit(u1, v1), lit(u2, v1), lit(u1, v2), lit(u2, v2)};
        const bool differ = compare && (c[0] != c[1] || c[1] != c[3] || c[3] != c[2] || c[2] != c[0]);
        if ((u2 - u1 > 1 || v2 - v1 > 1) && (level < minLevel || differ)) {
            const int uLow = (u1 + u2) / 2, uHigh = (u1 + u2 + 1) / 2;
            const int vLow = (v1 + v2) / 2, vHigh = (v1 + v2 + 1) / 2;
            return 0.25 * (self(self, u1, v1, uLow, vLow, level + 1) + self(self, uHigh, v1, u2, vLow, level + 1) +
                           self(self, u1, vHigh, uLow, v2, level + 1) + self(self, uHigh, vHigh, u2, v2, level + 1));
        }
        return 0.25 * (double(c[0]) + double(c[1]) + double(c[2]) + double(c[3]));
    };
    return mean(mean, 0, 0, n1 - 1, n2 - 1, 0);
}

// The samples of area light `form` (the model's), the paper's emitter: its
// grid's points seen from the shaded point.
template <AreaLightForm Form>
void gridSamples(const Form& form, const Scene& scene, const LightModel& model,
                                         const AreaLightQuery& q, AreaLightScratch& s, RenderCounters& counters) {
    const std::optional<typename Form::GridPoints> light = form.gridFrom(q.point);
    if (!light) return;  // the point sees no light (inside a spherical one)
    const int n1 = std::max(model.count1, 1);
    const int n2 = std::max(model.count2, 1);  // 1 for a segment
    auto jitter = [&](int i, int j) { return latticeJitter(q, i, j); };
    auto blocked = [&](const BeamRay& ray) { return gridRayBlocked(scene, model, ray, counters); };
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

double gridVisibleFraction(const Scene& scene, const LightModel& model, const AreaLightQuery& q,
                           AreaLightScratch& s, RenderCounters& counters) {
    double visible = 0.0;
    withAreaForm(model.form, [&](const auto& form) { visible = visibleFraction(form, scene, model, q, s, counters); });
    return visible;
}

std::span<const LightSample> gridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  const AreaLightQuery& q, AreaLightScratch& s,
                                                  RenderCounters& counters) {
    s.samples.clear();
    withAreaForm(model.form, [&](const auto& form) { gridSamples(form, scene, model, q, s, counters); });
    return s.samples;
}

}  // namespace asos
