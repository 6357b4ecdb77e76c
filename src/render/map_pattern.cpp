#include "asos/render/map_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "asos/render/crackle_pattern.hpp"
#include "asos/render/normal_pattern.hpp"
#include "asos/render/pov_noise.hpp"

namespace asos {

namespace {

constexpr Color rgb(double r, double g, double b) { return Color{Vec3(r, g, b), 0.0, 0.0}; }

// POV-Ray's default colour maps (core/material/pattern.cpp).
const ColourMapEntry kGrayMap[] = {{0.0, rgb(0.0, 0.0, 0.0)}, {1.0, rgb(1.0, 1.0, 1.0)}};
const ColourMapEntry kAgateMap[] = {{0.0, rgb(1.0, 1.0, 1.0)}, {0.5, rgb(0.95, 0.75, 0.5)},
                                    {0.5, rgb(0.9, 0.7, 0.5)}, {0.6, rgb(0.9, 0.7, 0.4)},
                                    {0.6, rgb(1.0, 0.7, 0.4)}, {1.0, rgb(0.6, 0.3, 0.0)}};
const ColourMapEntry kBozoMap[] = {{0.4, rgb(1.0, 1.0, 1.0)}, {0.4, rgb(0.0, 1.0, 0.0)},
                                   {0.6, rgb(0.0, 1.0, 0.0)}, {0.6, rgb(0.0, 0.0, 1.0)},
                                   {0.8, rgb(0.0, 0.0, 1.0)}, {0.8, rgb(1.0, 0.0, 0.0)}};
const ColourMapEntry kMarbleMap[] = {
    {0.0, rgb(0.9, 0.8, 0.8)}, {0.9, rgb(0.9, 0.08, 0.08)}, {0.9, rgb(0.0, 0.0, 0.0)}};
const ColourMapEntry kRadialMap[] = {{0.0, rgb(0.0, 1.0, 1.0)}, {0.333, rgb(1.0, 1.0, 0.0)},
                                     {0.666, rgb(1.0, 0.0, 1.0)}, {1.0, rgb(0.0, 1.0, 1.0)}};
const ColourMapEntry kWoodMap[] = {{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.066)}};

int generatorOf(const Pigment& p) { return p.noiseGenerator != 0 ? p.noiseGenerator : 2; }

// The pattern's own value before the wave (POV-Ray's EvaluateRaw).
double rawValue(const Pigment& p, const Vec3& q) {
    const PovNoise& noise = PovNoise::tables();
    switch (p.kind) {
        case Pigment::Kind::Gradient: {
            const double r = glm::dot(q, p.gradient);
            return r > 1.0 ? std::fmod(r, 1.0) : r;
        }
        case Pigment::Kind::Radial:
            if (std::fabs(q.x) < 0.001 && std::fabs(q.z) < 0.001) return 0.25;
            return 0.25 + (std::atan2(q.x, q.z) + std::numbers::pi) / (2.0 * std::numbers::pi);
        case Pigment::Kind::Onion: return std::fmod(glm::length(q), 1.0);
        case Pigment::Kind::Marble: {
            const double turb = p.turbulence.x != 0.0
                                    ? p.turbulence.x * noise.turbulence(q, p.octaves, p.omega, p.lambda, generatorOf(p))
                                    : 0.0;
            return q.x + turb;
        }
        case Pigment::Kind::Wood: {
            double x = 0.0, y = 0.0;
            if (p.turbulence != Vec3(0.0)) {
                const Vec3 t = noise.dturbulence(q, p.octaves, p.omega, p.lambda);
                x = PovNoise::cycloidal((q.x + t.x) * p.turbulence.x);
                y = PovNoise::cycloidal((q.y + t.y) * p.turbulence.y);
            }
            x += q.x;
            y += q.y;
            return std::sqrt(x * x + y * y);
        }
        case Pigment::Kind::Leopard: {
            const double s = (std::sin(q.x) + std::sin(q.y) + std::sin(q.z)) / 3.0;
            return s * s;
        }
        case Pigment::Kind::Bozo:
        case Pigment::Kind::Spotted:
        case Pigment::Kind::Bumps: return noise.noise(q, generatorOf(p));
        case Pigment::Kind::Dents: {
            const double n = noise.noise(q, generatorOf(p));
            return n * n * n;
        }
        case Pigment::Kind::Wrinkles: {
            // Ten octaves of the noise, halved; under generators 2 and 3
            // each octave stretched to 2 n - 0.5 and clipped to [0, 1].
            const int generator = generatorOf(p);
            auto octave = [&](const Vec3& at) {
                const double n = noise.noise(at, generator);
                return generator > 1 ? std::clamp(2.0 * n - 0.5, 0.0, 1.0) : n;
            };
            double value = octave(q), lambda = 2.0, omega = 0.5;
            for (int i = 1; i < 10; ++i, lambda *= 2.0, omega *= 0.5) value += omega * octave(q * lambda);
            return value / 2.0;
        }
        case Pigment::Kind::Ripples:
        case Pigment::Kind::Waves: {
            // POV-Ray's ten wave sources, each a cycloid of the distance to
            // it (waves: at its own frequency, weighted by its inverse);
            // the pattern's frequency and phase inside, and again as the
            // wave after (as POV-Ray applies them).
            const WaveSources& waves = WaveSources::tables();
            double sum = 0.0;
            for (int i = 0; i < WaveSources::kCount; ++i) {
                double length = glm::length(q - waves.sources[static_cast<std::size_t>(i)]);
                if (length == 0.0) length = 1.0;
                if (p.kind == Pigment::Kind::Ripples) {
                    sum += PovNoise::cycloidal(length * p.frequency + p.phase);
                } else {
                    const double f = waves.frequencies[static_cast<std::size_t>(i)];
                    sum += PovNoise::cycloidal(length * p.frequency * f + p.phase) / f;
                }
            }
            sum /= WaveSources::kCount;
            return p.kind == Pigment::Kind::Ripples ? 0.5 * (1.0 + sum) : 0.2 * (2.5 + sum);
        }
        case Pigment::Kind::Granite: {
            const int generator = generatorOf(p);
            double sum = 0.0, freq = 1.0;
            const Vec3 base = q * 4.0;
            for (int i = 0; i < 6; ++i, freq *= 2.0) {
                const double n = noise.noise(base * freq, generator);
                const double t = generator == 1 ? std::fabs(0.5 - n) : std::min(std::fabs(1.0 - 2.0 * n), 0.5);
                sum += t / freq;
            }
            return sum;
        }
        case Pigment::Kind::Agate: {
            const double turb =
                p.agateTurb * noise.turbulence(q, p.octaves, p.omega, p.lambda, generatorOf(p));
            const double v = 0.5 * (PovNoise::cycloidal(1.3 * turb + 1.1 * q.z) + 1.0);
            return v < 0.0 ? 0.0 : std::pow(std::min(1.0, v), 0.77);
        }
        case Pigment::Kind::Crackle: return CracklePattern::tables().value(p, q, generatorOf(p));
        case Pigment::Kind::Function: {
            // POV-Ray's FunctionPattern: the function of the point, above 1
            // wrapped as gradient's; NaN (sqrt(-1) …) reads as 0 here.
            const double point[3] = {q.x, q.y, q.z};
            const double v = p.function->evaluate(point);
            if (std::isnan(v)) return 0.0;
            return v > 1.0 ? std::fmod(v, 1.0) : v;
        }
        case Pigment::Kind::Solid:
        case Pigment::Kind::Checker:
        case Pigment::Kind::Brick:
        case Pigment::Kind::Average: break;
    }
    return 0.0;
}

}  // namespace

bool isMapPattern(Pigment::Kind kind) {
    return kind != Pigment::Kind::Solid && kind != Pigment::Kind::Checker && kind != Pigment::Kind::Brick;
}

Vec3 turbulatedPoint(const Pigment& p, const Vec3& patternPoint) {
    // Classic turbulence moves the point, except for the patterns that use it
    // in their own way.
    if (p.kind == Pigment::Kind::Marble || p.kind == Pigment::Kind::Wood || p.turbulence == Vec3(0.0))
        return patternPoint;
    return patternPoint + PovNoise::tables().dturbulence(patternPoint, p.octaves, p.omega, p.lambda) * p.turbulence;
}

double mapPatternValue(const Pigment& p, const Vec3& patternPoint) {
    return mapPatternValueAt(p, turbulatedPoint(p, patternPoint));
}

double mapPatternValueAt(const Pigment& p, const Vec3& q) {
    double v = rawValue(p, q);
    // POV-Ray's wave (ContinuousPattern::Evaluate), with its 1.00001.
    if (p.frequency != 0.0) v = std::fmod(v * p.frequency + p.phase, 1.00001);
    if (v < 0.0) v -= std::floor(v);
    switch (p.wave) {
        case Pigment::Wave::Ramp: break;
        case Pigment::Wave::Sine: v = (1.0 + PovNoise::cycloidal(v)) * 0.5; break;
        case Pigment::Wave::Triangle: v = triangleWave(v); break;
    }
    return v;
}

std::span<const ColourMapEntry> colourMapOf(const Pigment& p) {
    if (!p.colourMap.empty()) return p.colourMap;
    switch (p.kind) {
        case Pigment::Kind::Agate: return kAgateMap;
        case Pigment::Kind::Bozo: return kBozoMap;
        case Pigment::Kind::Marble: return kMarbleMap;
        case Pigment::Kind::Radial: return kRadialMap;
        case Pigment::Kind::Wood: return kWoodMap;
        default: return kGrayMap;
    }
}

Color colourMapAt(std::span<const ColourMapEntry> map, double value) {
    if (value <= map.front().value) return map.front().color;
    if (value >= map.back().value) return map.back().color;
    std::size_t i = 1;
    while (value > map[i].value) ++i;
    const ColourMapEntry& a = map[i - 1];
    const ColourMapEntry& b = map[i];
    const double f = (value - a.value) / (b.value - a.value);
    return Color{a.color.rgb + f * (b.color.rgb - a.color.rgb), a.color.filter + f * (b.color.filter - a.color.filter),
                 a.color.transmit + f * (b.color.transmit - a.color.transmit)};
}

}  // namespace asos
