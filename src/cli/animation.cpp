#include "cli/animation.hpp"

#include <cmath>
#include <filesystem>

#include "cli/common/arguments.hpp"

namespace asos::cli {

namespace {

// Frame numbers as POV-Ray takes them: whole, not negative (it clamps a
// negative first frame to 0; asos refuses it), below a billion.
constexpr std::uint64_t kFrameLimit = 999'999'999;

std::optional<int> parseFrame(std::string_view text) {
    const std::optional<std::uint64_t> n = parseUnsigned(text);
    if (!n || *n > kFrameLimit) return std::nullopt;
    return static_cast<int>(*n);
}

struct FrameSpan {
    int first = 0, last = 0;
};

// "A-B" with A <= B; `single` also takes "N" for N-N.
std::optional<FrameSpan> parseSpan(const std::string& text, bool single) {
    const auto dash = text.find('-');
    if (dash == std::string::npos) {
        if (!single) return std::nullopt;
        const std::optional<int> n = parseFrame(text);
        if (!n) return std::nullopt;
        return FrameSpan{*n, *n};
    }
    const std::optional<int> a = parseFrame(std::string_view(text).substr(0, dash));
    const std::optional<int> b = parseFrame(std::string_view(text).substr(dash + 1));
    if (!a || !b) return std::nullopt;
    return FrameSpan{*a, *b};
}

int digitsOf(int n) {
    int digits = 1;
    for (; n >= 10; n /= 10) ++digits;
    return digits;
}

// Where the run of '#' of the file name (not its folders) starts, and how
// long it is; a second run makes `runs` 2.
struct HashRun {
    std::size_t start = std::string::npos, length = 0;
    int runs = 0;
};

HashRun findHashRun(const std::string& pattern) {
    const std::size_t slash = pattern.find_last_of('/');
    HashRun run;
    for (std::size_t i = slash == std::string::npos ? 0 : slash + 1; i < pattern.size(); ++i) {
        if (pattern[i] != '#') continue;
        ++run.runs;
        if (run.runs > 1) break;
        run.start = i;
        while (i < pattern.size() && pattern[i] == '#') ++i;
        run.length = i - run.start;
    }
    return run;
}

}  // namespace

Animation::Parse Animation::parse(const AnimationArgs& args) {
    Parse result;
    auto& problems = result.problems;
    if (!args.frames) {
        for (const auto& [given, name] : {std::pair{args.subset.has_value(), "--subset"},
                                          std::pair{args.clockFrom.has_value(), "--clock-from"},
                                          std::pair{args.clockTo.has_value(), "--clock-to"}})
            if (given) problems.push_back(std::string(name) + " needs --frames A-B, the frames of the animation");
        return result;
    }
    Animation a;
    bool ok = true;
    if (const std::optional<FrameSpan> frames = parseSpan(*args.frames, false)) {
        if (frames->first > frames->last) {
            problems.push_back("--frames " + *args.frames + ": the first frame comes after the last");
            ok = false;
        }
        a.initialFrame_ = a.firstFrame_ = frames->first;
        a.finalFrame_ = a.lastFrame_ = frames->last;
    } else {
        problems.push_back("--frames wants A-B, the first and last frame numbers (whole numbers 0 to 999999999), "
                           "not '" + *args.frames + "'");
        ok = false;
    }
    if (args.subset) {
        const std::optional<FrameSpan> subset = parseSpan(*args.subset, true);
        if (!subset) {
            problems.push_back("--subset wants C-D or N, frame numbers within --frames, not '" + *args.subset + "'");
            ok = false;
        } else if (subset->first > subset->last) {
            problems.push_back("--subset " + *args.subset + ": the first frame comes after the last");
            ok = false;
        } else if (ok && (subset->first < a.initialFrame_ || subset->last > a.finalFrame_)) {
            problems.push_back("--subset " + *args.subset + " is not within --frames " + *args.frames);
            ok = false;
        } else {
            a.firstFrame_ = subset->first;
            a.lastFrame_ = subset->last;
        }
    }
    auto clock = [&](const std::optional<std::string>& text, const char* name, double& value) {
        if (!text) return;
        const std::optional<double> v = parseNumber(*text);
        if (!v || !std::isfinite(*v)) {
            problems.push_back(std::string(name) + " wants a finite number, not '" + *text + "'");
            ok = false;
        } else {
            value = *v;
        }
    };
    clock(args.clockFrom, "--clock-from", a.initialClock_);
    clock(args.clockTo, "--clock-to", a.finalClock_);
    if (ok) result.animation = a;
    return result;
}

double Animation::clockDelta() const {
    if (finalFrame_ == initialFrame_) return 0.0;
    return (finalClock_ - initialClock_) / double(finalFrame_ - initialFrame_);
}

double Animation::clockAt(int frame) const {
    // POV-Ray's order of operations, so that the clocks are its clocks to the bit.
    return clockDelta() * double(frame - initialFrame_) + initialClock_;
}

lang::InterpreterOptions Animation::frameOptions(lang::InterpreterOptions options, int frame) const {
    options.clock = clockAt(frame);
    options.clockOn = true;
    options.frameNumber = frame;
    options.initialFrame = initialFrame_;
    options.finalFrame = finalFrame_;
    options.initialClock = initialClock_;
    options.finalClock = finalClock_;
    options.clockDelta = clockDelta();
    return options;
}

std::string Animation::fileName(const std::string& pattern, int frame) const {
    const HashRun run = findHashRun(pattern);
    if (run.runs == 0) return pattern;
    std::string number = std::to_string(frame);
    const std::size_t width = std::max<std::size_t>(run.length, std::size_t(digitsOf(finalFrame_)));
    number.insert(0, width - std::min(width, number.size()), '0');
    return pattern.substr(0, run.start) + number + pattern.substr(run.start + run.length);
}

std::string frameNameProblem(const std::string& option, const std::string& pattern, const Animation& animation) {
    const HashRun run = findHashRun(pattern);
    if (run.runs > 1)
        return option + " '" + pattern + "' has two runs of '#' in its file name: one takes the frame number";
    if (run.runs == 0 && animation.frameCount() > 1)
        return option + " '" + pattern + "' names one file for " + std::to_string(animation.frameCount()) +
               " frames: put a run of '#' in its name for the frame number";
    return {};
}

}  // namespace asos::cli
