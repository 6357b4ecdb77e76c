#pragma once
#include <string>

namespace asos {

// The shortest text that reads back as `v` ("0.1", "1e+300"; -0 as "0"):
// numbers quoted in messages (the interpreter's, the shapes' validation).
std::string formatNumber(double v);

}  // namespace asos
