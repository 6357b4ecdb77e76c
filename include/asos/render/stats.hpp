#pragma once
// Render statistics: counters gathered per thread while tracing and summed
// afterwards, timings, and two ways to show them (a JSON document for
// --stats-json and a table for --stats). Nothing here prints.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace asos {

// Levels 0..kStatLevels-1 are counted apart; deeper ones go to the last slot.
inline constexpr int kStatLevels = 16;

struct RenderCounters {
    std::uint64_t pixels = 0;
    std::uint64_t eyeRays = 0;        // rays shaded for the image (central rays of pyrays, samples)
    std::uint64_t reflectedRays = 0;  // mirror rays
    std::uint64_t shadowRays = 0;     // plain shadow rays (central rays of shadow pyrays included)
    std::uint64_t coneTests = 0;      // cone-object classifications
    std::uint64_t rayTests = 0;       // ray-object intersection tests
    std::array<std::uint64_t, kStatLevels> pyraysByLevel{};        // eye pyrays
    std::array<std::uint64_t, kStatLevels> shadowPyraysByLevel{};  // shadow pyrays and cones

    void countPyray(int level) { ++pyraysByLevel[slot(level)]; }
    void countShadowPyray(int level) { ++shadowPyraysByLevel[slot(level)]; }
    void countShadowPyrays(int level, std::uint64_t n) { shadowPyraysByLevel[slot(level)] += n; }
    std::uint64_t rays() const { return eyeRays + reflectedRays; }
    std::uint64_t allRays() const { return eyeRays + reflectedRays + shadowRays; }

    RenderCounters& operator+=(const RenderCounters& o);
    bool operator==(const RenderCounters&) const = default;

private:
    static std::size_t slot(int level) {
        return static_cast<std::size_t>(std::clamp(level, 0, kStatLevels - 1));
    }
};

struct RenderTimes {
    double parseSeconds = 0.0;
    double buildSeconds = 0.0;
    double renderSeconds = 0.0;
    double total() const { return parseSeconds + buildSeconds + renderSeconds; }
};

struct RenderStats {
    std::string method;  // "asos", "single", "grid", "jitter", "adaptive", "am1"
    int width = 0, height = 0;
    int threads = 0;
    RenderCounters counters;
    RenderTimes times;

    // All rays (eye, reflected, shadow) per second of render time; 0 when no
    // time was measured.
    double raysPerSecond() const;
};

// A JSON object (keys in snake_case, documented in docs/rendering.md).
std::string statsToJson(const RenderStats& stats);
// A human-readable table, one quantity per line, ending in a newline.
std::string formatStatsTable(const RenderStats& stats);

}  // namespace asos
