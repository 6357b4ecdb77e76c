#pragma once
// ASOS's three knobs (paper: EPS, MAX and jittering of MAX-rays), and
// whether highlights inside covered pyrays are bounded (beyond the paper), as
// they apply to one object or light. Sources, strongest first: the object's or
// light's own `asos { … }` block, the command line, global_settings' block,
// the built-in defaults (EPS 1/64, MAX 4, jitter off, highlights on). Where a pyray involves
// several objects, the finest setting among them wins (docs/algorithm.md,
// "Per-object settings").
#include <algorithm>
#include <string>

#include "asos/scene/description.hpp"

namespace asos {

// The deepest MAX accepted: 4^10 leaves per pixel is already a million rays.
inline constexpr int kMaxAsosLevel = 10;

struct AsosSettings {
    double eps = 1.0 / 64.0;
    int maxLevel = 4;
    bool jitter = false;
    // An object: subdivide a pyray it covers where its highlights may vary
    // by more than EPS (docs/algorithm.md, "Highlights inside covered
    // pixels"). A light: count its highlights there.
    bool highlights = true;

    bool operator==(const AsosSettings&) const = default;

    // Fields set in `options` replace these.
    AsosSettings refinedBy(const AsosOptions& options) const {
        AsosSettings s = *this;
        if (options.eps) s.eps = *options.eps;
        if (options.maxLevel) s.maxLevel = *options.maxLevel;
        if (options.jitter) s.jitter = *options.jitter;
        if (options.highlights) s.highlights = *options.highlights;
        return s;
    }
    // The finer of two settings, field by field: the smaller EPS, the deeper
    // MAX, jitter and highlights if either asks for them.
    AsosSettings finest(const AsosSettings& o) const {
        return {std::min(eps, o.eps), std::max(maxLevel, o.maxLevel), jitter || o.jitter,
                highlights || o.highlights};
    }
    // The identity of finest(): coarser than any valid setting.
    static AsosSettings coarsest() { return {kInfinity, 0, false, false}; }
};

// The scene-wide setting: built-in defaults, refined by global_settings'
// asos block, then by the command line's options.
inline AsosSettings sceneAsosSettings(const GlobalSettings& globals, const AsosOptions& commandLine) {
    return AsosSettings{}.refinedBy(globals.asos).refinedBy(commandLine);
}

// The largest EPS accepted: a pixel's change is measured on colours in
// [0, 1], so an EPS above 1 could only mean "never subdivide" by mistake.
inline constexpr double kMaxAsosEps = 1.0;

// Empty when `eps` is usable: a finite number above 0 and at most
// kMaxAsosEps; otherwise what is wrong ("eps must be positive, not 0"). The
// one rule for asos { eps }, global_settings and --eps.
std::string epsProblem(double eps);

// Empty when the options are usable; otherwise what is wrong (epsProblem, MAX outside 0..kMaxAsosLevel). `what` names their source in the
// message ("--eps", "global_settings asos", ...).
std::string checkAsosOptions(const AsosOptions& options, const std::string& what);

}  // namespace asos
