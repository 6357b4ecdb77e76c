#pragma once
// The interpreter's limits for fuzz_scene (fuzz/fuzz_scene.cpp), here so that
// the unit tests check that the limit scenes among its seeds stop early.
// Small enough that a loop, an array or a doubling union the fuzzer writes
// ends at a located error in milliseconds, and that what passes them stays
// far below the fuzzer's -rss_limit_mb (2048, scripts/fuzz.sh) with
// AddressSanitizer's overhead: with the defaults (8 GiB, 50 million
// objects) tests/golden/errors/limit_union_doubling.pov doubles a union
// until its copies fill gigabytes, a minute per input in Release.
#include "asos/lang/interpreter.hpp"

namespace asos {

inline lang::InterpreterOptions fuzzSceneOptions() {
    lang::InterpreterOptions options;
    options.maxLoopIterations = 20'000;
    options.maxArrayElements = 20'000;
    options.maxObjects = 100'000;
    options.maxStringLength = 1'000'000;
    options.maxMemoryMiB = 64;
    options.maxErrors = 10;
    return options;
}

}  // namespace asos
