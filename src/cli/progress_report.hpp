#pragma once
// The progress of `asos render` on stderr: on a terminal, a bar redrawn at
// most ten times a second (one line per frame of an animation); elsewhere
// (a log, a pipe, a farm's job), lines as POV-Ray prints them: a still's
// "Rendered N of M pixels (P%)" at every tenth, an animation's one line per
// frame written.
#include <chrono>
#include <string>

#include "asos/render/tile_renderer.hpp"

namespace asos::cli {

class ProgressReport {
public:
    enum class Mode { None, Bar, Lines };
    // The mode for stderr: None with --quiet, else Bar on a terminal, Lines elsewhere.
    static Mode modeForStderr(bool quiet);

    ProgressReport(Mode mode, bool animation) : mode_(mode), animation_(animation) {}

    bool wanted() const { return mode_ != Mode::None; }

    // A frame (or the still) starts; `label` ("frame 3 (3 of 48) ") goes before the bar.
    void start(std::string label);
    void update(const TileProgress& p);
    // An animation's frame is written: `line` says which, as Lines shows it.
    void frameWritten(const std::string& line);
    // Ends a bar left half drawn, so that an error starts on a line of its own.
    void interrupt();

    // Seconds since start().
    double seconds() const;

private:
    Mode mode_;
    bool animation_;
    std::string label_;
    bool lineOpen_ = false;
    int nextTenth_ = 1;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point lastDraw_{};
};

}  // namespace asos::cli
