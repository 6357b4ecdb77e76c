#include "asos/render/stats.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace asos {

RenderCounters& RenderCounters::operator+=(const RenderCounters& o) {
    pixels += o.pixels;
    eyeRays += o.eyeRays;
    reflectedRays += o.reflectedRays;
    shadowRays += o.shadowRays;
    coneTests += o.coneTests;
    rayTests += o.rayTests;
    for (int i = 0; i < kStatLevels; ++i) {
        pyraysByLevel[i] += o.pyraysByLevel[i];
        shadowPyraysByLevel[i] += o.shadowPyraysByLevel[i];
    }
    return *this;
}

double RenderStats::raysPerSecond() const {
    if (!(times.renderSeconds > 0.0)) return 0.0;
    return static_cast<double>(counters.allRays()) / times.renderSeconds;
}

namespace {

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += static_cast<char>(c);
                }
        }
    }
    return out + "\"";
}

// Levels up to the deepest non-zero one.
int usedLevels(const std::array<std::uint64_t, kStatLevels>& levels) {
    int n = kStatLevels;
    while (n > 0 && levels[n - 1] == 0) --n;
    return n;
}

std::string jsonArray(const std::array<std::uint64_t, kStatLevels>& levels) {
    std::string out = "[";
    const int n = usedLevels(levels);
    for (int i = 0; i < n; ++i) {
        if (i) out += ", ";
        out += std::to_string(levels[i]);
    }
    return out + "]";
}

}  // namespace

std::string statsToJson(const RenderStats& s) {
    const RenderCounters& c = s.counters;
    std::string j = "{\n";
    j += "  \"method\": " + jsonString(s.method) + ",\n";
    j += "  \"width\": " + std::to_string(s.width) + ",\n";
    j += "  \"height\": " + std::to_string(s.height) + ",\n";
    j += "  \"threads\": " + std::to_string(s.threads) + ",\n";
    j += "  \"pixels\": " + std::to_string(c.pixels) + ",\n";
    j += "  \"rays\": {\"eye\": " + std::to_string(c.eyeRays) +
         ", \"reflected\": " + std::to_string(c.reflectedRays) +
         ", \"shadow\": " + std::to_string(c.shadowRays) +
         ", \"total\": " + std::to_string(c.allRays()) + "},\n";
    j += "  \"pyrays_by_level\": " + jsonArray(c.pyraysByLevel) + ",\n";
    j += "  \"shadow_pyrays_by_level\": " + jsonArray(c.shadowPyraysByLevel) + ",\n";
    j += "  \"cone_tests\": " + std::to_string(c.coneTests) + ",\n";
    j += "  \"ray_tests\": " + std::to_string(c.rayTests) + ",\n";
    j += "  \"times\": {\"parse\": " + jsonNumber(s.times.parseSeconds) +
         ", \"build\": " + jsonNumber(s.times.buildSeconds) +
         ", \"render\": " + jsonNumber(s.times.renderSeconds) +
         ", \"total\": " + jsonNumber(s.times.total()) + "},\n";
    j += "  \"rays_per_second\": " + jsonNumber(s.raysPerSecond()) + "\n";
    j += "}\n";
    return j;
}

std::string formatStatsTable(const RenderStats& s) {
    const RenderCounters& c = s.counters;
    std::string t;
    auto line = [&](const char* label, const std::string& value) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "  %-24s %s\n", label, value.c_str());
        t += buf;
    };
    auto count = [](std::uint64_t v) { return std::to_string(v); };
    auto seconds = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3f s", v);
        return std::string(buf);
    };
    auto levels = [&](const char* label, const std::array<std::uint64_t, kStatLevels>& a) {
        const int n = usedLevels(a);
        if (n == 0) {
            line(label, "0");
            return;
        }
        for (int i = 0; i < n; ++i) {
            char name[64];
            std::snprintf(name, sizeof name, "%s level %d%s", label, i,
                          i == kStatLevels - 1 ? "+" : "");
            line(name, count(a[i]));
        }
    };
    t += "Render statistics\n";
    line("method", s.method);
    line("image", std::to_string(s.width) + " x " + std::to_string(s.height));
    line("threads", std::to_string(s.threads));
    line("pixels", count(c.pixels));
    line("eye rays", count(c.eyeRays));
    line("reflected rays", count(c.reflectedRays));
    line("shadow rays", count(c.shadowRays));
    line("all rays", count(c.allRays()));
    levels("pyrays", c.pyraysByLevel);
    levels("shadow pyrays", c.shadowPyraysByLevel);
    line("cone tests", count(c.coneTests));
    line("ray tests", count(c.rayTests));
    line("parse time", seconds(s.times.parseSeconds));
    line("build time", seconds(s.times.buildSeconds));
    line("render time", seconds(s.times.renderSeconds));
    line("total time", seconds(s.times.total()));
    char rps[32];
    std::snprintf(rps, sizeof rps, "%.0f", s.raysPerSecond());
    line("rays per second", rps);
    return t;
}

}  // namespace asos
