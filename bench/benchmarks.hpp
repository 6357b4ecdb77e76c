#pragma once
// The benchmarks of the `asos-bench` program, each in its own file
// (bench_<name>.cpp), registered by main.cpp with one line. They print
// figures; the unit suite only checks that they run.
#include <filesystem>

#include "cli/common/program.hpp"

namespace asos::bench {

using cli::CommandResult;

// `asos-bench parse`: parse time and peak memory for 10^3 … 10^6 spheres.
void addParseBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench bvh`: BVH build time and nearest-hit rays per second (bench_bvh.cpp).
void addBvhBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench intersect`: ray test vs cone classification (bench_intersect.cpp).
void addIntersectBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench render`: time and rays of every method (bench_render.cpp).
void addRenderBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench lights`: area light shadows, ASOS against the grid (bench_lights.cpp).
void addLightsBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench accuracy`: every method's error against time, charted (bench_accuracy.cpp).
void addAccuracyBenchmark(CLI::App& app, CommandResult& result);

void addStabilityBenchmark(CLI::App& app, CommandResult& result);

void addEpsBenchmark(CLI::App& app, CommandResult& result);

// `asos-bench scale`: time and memory against objects and pixels (bench_scale.cpp).
void addScaleBenchmark(CLI::App& app, CommandResult& result);

// An example scene, `relative` to the examples folder, for a benchmark's
// default: the installed share/asos/examples beside the program when there is
// one, else the source tree's examples/ (example_scene.cpp).
std::filesystem::path exampleScene(const std::filesystem::path& relative);

}  // namespace asos::bench
