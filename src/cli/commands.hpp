#pragma once
// The subcommands of the `asos` program, each in its own file
// (cmd_<name>.cpp), registered by main.cpp with one line.
#include "cli/common/program.hpp"

namespace asos::cli {

// `asos render SCENE -o OUT …`: renders a scene to an image (cmd_render.cpp).
void addRenderCommand(CLI::App& app, CommandResult& result);

// `asos parse SCENE`: prints the canonical dump of the scene description.
void addParseCommand(CLI::App& app, CommandResult& result);

// `asos reference SCENE -o REF.exr`: a brute-force reference image, cached (cmd_reference.cpp).
void addReferenceCommand(CLI::App& app, CommandResult& result);

}  // namespace asos::cli
