#pragma once
// A compiled function written back as one POV-Ray function expression (for
// the dump): its callees written out in place, every operation in
// parentheses, numbers as their shortest exact text.
#include <span>
#include <string>

#include "asos/scene/function_program.hpp"

namespace asos {

// `arguments`: the text that stands for each parameter (as many as
// f.parameters()).
std::string functionText(const FunctionProgram& f, std::span<const std::string> arguments);

}  // namespace asos
