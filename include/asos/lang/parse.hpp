#pragma once
// Scene text → syntax tree. Syntax errors (including every POV-Ray construct
// asos does not support, named at its keyword) go to the diagnostics sink;
// parsing stops at the first one.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/ast.hpp"

namespace asos::lang {

// Parses a scene file and hands each top-level entry (an item or a directive,
// with all it contains) to `consume` as soon as it is complete, so that a huge
// file never has its whole tree in memory; the entry's nodes live until
// `consume` returns. Returns false after a syntax error (reported).
// Exceptions thrown by `consume` pass through.
using EntryConsumer = std::function<void(const Ast& ast, const Node& entry)>;
bool parseSceneEntries(std::string_view text, std::shared_ptr<const std::string> file,
                       NameTable& names, Diagnostics& diagnostics, const EntryConsumer& consume);

// A whole scene file as one tree. `file` names it in every position.
std::optional<Ast> parseScene(std::string_view text, std::shared_ptr<const std::string> file,
                              NameTable& names, Diagnostics& diagnostics);

// One expression and nothing else (a -D value); the tree's root is the expression.
std::optional<Ast> parseExpression(std::string_view text, std::shared_ptr<const std::string> file,
                                   NameTable& names, Diagnostics& diagnostics);

// The text of line `line` (1-based) of `text`, without its end of line.
std::string_view sourceLine(std::string_view text, int line);

}  // namespace asos::lang
