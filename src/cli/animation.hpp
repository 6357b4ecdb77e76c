#pragma once
// `asos render --frames A-B [--subset C-D] [--clock-from F --clock-to T]`:
// an animation as POV-Ray 3.7 runs one (+KFI A +KFF B +SF C +EF D +KI F
// +KF T): frame N's clock is F + (N - A) * (T - F) / (B - A), and the scene
// reads its frame's `frame_number`, `clock_delta`, ... (docs/cli.md,
// "Animation"). Output names carry the frame number in their run of '#'.
#include <optional>
#include <string>
#include <vector>

#include "asos/lang/interpreter.hpp"

namespace asos::cli {

// The options as given, each a text still to check.
struct AnimationArgs {
    std::optional<std::string> frames;     // "A-B"
    std::optional<std::string> subset;     // "C-D" or "N"
    std::optional<std::string> clockFrom;  // POV-Ray's Initial_Clock, default 0
    std::optional<std::string> clockTo;    // POV-Ray's Final_Clock, default 1
};

class Animation {
public:
    // The frames the options name, or what is wrong with them ("--frames
    // wants ..."), every problem; nothing and no problem without --frames.
    struct Parse;
    static Parse parse(const AnimationArgs& args);

    int initialFrame() const { return initialFrame_; }
    int finalFrame() const { return finalFrame_; }
    int firstFrame() const { return firstFrame_; }  // the first rendered (--subset)
    int lastFrame() const { return lastFrame_; }
    int frameCount() const { return lastFrame_ - firstFrame_ + 1; }

    // POV-Ray's clock_delta: 0 for a range of one frame (where POV-Ray's is
    // infinite and its clock not a number).
    double clockDelta() const;
    double clockAt(int frame) const;

    // The interpreter's options for `frame`: its clock, `clock_on` 1 and the
    // range's values.
    lang::InterpreterOptions frameOptions(lang::InterpreterOptions options, int frame) const;

    // `pattern` with the run of '#' in its file name replaced by `frame`,
    // zero-padded to the run's length or to the final frame's digits, which
    // ever is more (so that the names of one run sort by frame, as
    // POV-Ray's do); `pattern` itself when it has no '#'.
    std::string fileName(const std::string& pattern, int frame) const;

private:
    int initialFrame_ = 1, finalFrame_ = 1, firstFrame_ = 1, lastFrame_ = 1;
    double initialClock_ = 0.0, finalClock_ = 1.0;
};

struct Animation::Parse {
    std::optional<Animation> animation;
    std::vector<std::string> problems;
};

// What is wrong with an output name for the frames: a file name with two
// runs of '#', or none while several frames are rendered ("" when fine).
// `option` names it in the message ("-o").
std::string frameNameProblem(const std::string& option, const std::string& pattern, const Animation& animation);

}  // namespace asos::cli
