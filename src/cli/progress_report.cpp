#include "cli/progress_report.hpp"

#include <unistd.h>

#include <cstdio>

namespace asos::cli {

namespace {
constexpr int kBarWidth = 40;
}  // namespace

ProgressReport::Mode ProgressReport::modeForStderr(bool quiet) {
    if (quiet) return Mode::None;
    return isatty(STDERR_FILENO) ? Mode::Bar : Mode::Lines;
}

void ProgressReport::start(std::string label) {
    label_ = std::move(label);
    start_ = std::chrono::steady_clock::now();
    lastDraw_ = {};
    nextTenth_ = 1;
}

void ProgressReport::update(const TileProgress& p) {
    const auto now = std::chrono::steady_clock::now();
    const bool done = p.tilesDone == p.tilesTotal;
    const double fraction = p.pixelsTotal > 0 ? double(p.pixelsDone) / double(p.pixelsTotal) : 1.0;
    if (mode_ == Mode::Lines) {
        if (animation_) return;  // a line per frame instead
        // Every tenth passed since the last line; a tile may pass several.
        const int tenths = static_cast<int>(fraction * 10.0 + 1e-9);
        if (tenths < nextTenth_) return;
        nextTenth_ = tenths + 1;
        std::fprintf(stderr, "Rendered %lld of %lld pixels (%d%%)\n", static_cast<long long>(p.pixelsDone),
                     static_cast<long long>(p.pixelsTotal), static_cast<int>(fraction * 100.0));
        std::fflush(stderr);
        return;
    }
    if (mode_ != Mode::Bar) return;
    if (!done && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kBarWidth, ' ');
    std::fprintf(stderr, "\r%s[%s] %3d%%  %.1f s", label_.c_str(), bar.c_str(), static_cast<int>(fraction * 100.0),
                 seconds());
    lineOpen_ = !done;
    if (done) std::fputc('\n', stderr);
    std::fflush(stderr);
}

void ProgressReport::frameWritten(const std::string& line) {
    if (mode_ != Mode::Lines) return;
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
}

void ProgressReport::interrupt() {
    if (!lineOpen_) return;
    std::fputc('\n', stderr);
    lineOpen_ = false;
}

double ProgressReport::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace asos::cli
