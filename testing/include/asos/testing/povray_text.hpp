#pragma once
// What POV-Ray is given of our scenes: the text with every `asos { ... }`
// block (our extension, docs/language.md) blanked out, so that the
// benchmarks can render the same file with POV-Ray 3.7 (the issue's "our
// asos {} blocks stripped").
#include <string>

namespace asos {

// `text` with each `asos` keyword that opens a block (white space and
// comments may stand between it and its `{`) blanked to its matching `}`:
// every character of the block a space, its line breaks kept, so that
// POV-Ray's line numbers stay the scene's. Comments (POV-Ray's block
// comments nest) and strings are read past, not searched; an identifier
// that merely contains `asos` is kept. A block left open runs to the end.
std::string withoutAsosBlocks(const std::string& text);

}  // namespace asos
