#pragma once
// Deterministic random numbers for rendering. Every number is a pure function
// of (seed, pixel x, pixel y, stream, index): a counter-based generator with
// no state, so a pixel renders the same on any thread, in any tile and in any
// --region (the project's determinism rule). The hash is SplitMix64's
// finaliser applied in a chain, one input word at a time; its avalanche makes
// neighbouring counters give independent-looking outputs.
#include <cstdint>

#include "asos/geometry/vec.hpp"

namespace asos {

// Streams keep the purposes of random numbers apart, so that adding samples of
// one kind never shifts the numbers of another. Callers use `index` for the
// sample or sub-position within the pixel.
enum class SampleStream : std::uint32_t {
    PixelJitter = 1,     // jittered N x N eye samples
    AdaptiveJitter = 2,  // jitter of the adaptive method's sub-samples
    AsosJitter = 3,      // ASOS MAX-pyray jitter
    LightJitter = 4,     // area light sample positions
    ShadowJitter = 5,    // ASOS shadow MAX-pyray jitter
    Am1Jitter = 6,       // jitter of the am1 method's sub-samples
    Grain = 7,           // a finish's crand
    Test = 1000,         // reserved for tests
};

// SplitMix64's output function (Steele, Lea & Flood 2014): a bijection on 64
// bits with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// The 53 high bits as a double in [0, 1).
constexpr double toUnitDouble(std::uint64_t bits) {
    return static_cast<double>(bits >> 11) * (1.0 / 9007199254740992.0);
}

// The index of a K-pyray's random numbers: its level and its position among
// the pixel's 2^K x 2^K squares.
constexpr std::uint64_t subPosition(int level, std::uint32_t ix, std::uint32_t iy) {
    return std::uint64_t(level) << 48 | std::uint64_t(iy) << 24 | ix;
}

// The random numbers of one pixel. Cheap to construct; copyable; no state
// changes when numbers are drawn.
class PixelRandom {
public:
    constexpr PixelRandom(std::uint64_t seed, std::int64_t x, std::int64_t y)
        : key_(mix64(mix64(mix64(seed) ^ static_cast<std::uint64_t>(x)) ^
                     static_cast<std::uint64_t>(y))) {}

    // A uniform number in [0, 1).
    constexpr double uniform(SampleStream stream, std::uint64_t index) const {
        return toUnitDouble(bits(stream, index));
    }
    // Two numbers in [0, 1), drawn at indices 2 index and 2 index + 1.
    constexpr Vec2 uniform2(SampleStream stream, std::uint64_t index) const {
        return {uniform(stream, 2 * index), uniform(stream, 2 * index + 1)};
    }
    constexpr std::uint64_t bits(SampleStream stream, std::uint64_t index) const {
        return mix64(mix64(key_ ^ static_cast<std::uint64_t>(stream)) ^ index);
    }

private:
    std::uint64_t key_;
};

}  // namespace asos
