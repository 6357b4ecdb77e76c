#pragma once
// Each subcommand of the `asos` program lives in its own file (cmd_<name>.cpp)
// and is registered by main.cpp with one line. A command sets
// `result.exitCode` from its callback; only the command line prints and
// decides the exit code.
#include <CLI/CLI.hpp>

namespace asos::cli {

struct CommandResult {
    int exitCode = 0;
};

// `asos render SCENE -o OUT …`: renders a scene to an image (cmd_render.cpp).
void addRenderCommand(CLI::App& app, CommandResult& result);

// `asos bench …`: programs that print figures. Each benchmark registers under
// the `bench` subcommand returned by addBenchCommand.
CLI::App* addBenchCommand(CLI::App& app);

// `asos parse SCENE`: prints the canonical dump of the scene description.
void addParseCommand(CLI::App& app, CommandResult& result);

// `asos bench parse`: parse time and peak memory for 10^3 … 10^6 spheres.
void addBenchParseCommand(CLI::App& bench, CommandResult& result);

// `asos bench render`: time and rays of every method (bench_render.cpp).
void addBenchRenderCommand(CLI::App& bench, CommandResult& result);

// `asos bench bvh` (bench_bvh.cpp).
void addBenchBvhCommand(CLI::App& bench, CommandResult& result);

// `asos bench intersect` (bench_intersect.cpp).
void addBenchIntersectCommand(CLI::App& bench, CommandResult& result);

// `asos bench lights`: area light shadows, ASOS against the grid (bench_lights.cpp).
void addBenchLightsCommand(CLI::App& bench, CommandResult& result);

}  // namespace asos::cli
