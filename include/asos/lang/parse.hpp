#pragma once
// Scene text → syntax tree. Syntax errors (including every POV-Ray construct
// asos does not support, named at its keyword) go to the diagnostics sink;
// parsing stops at the first one.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "asos/diag/diagnostics.hpp"
#include "asos/lang/ast.hpp"

namespace asos::lang {

// How deep parentheses, operators, blocks, directives, includes and macro
// calls may nest, all together: past it, a located error rather than the end
// of the stack. A parse that starts inside others (an include, a macro's body)
// starts at their depth.
inline constexpr std::size_t kMaxNesting = 1000;

// Where a macro is called, which says how its body is read: as a value (in an
// expression, an argument, `#declare A = M();`, `object { M() }`), or as
// entries of the block the call stands in, as if written there.
enum class BodyContext : std::uint8_t {
    Value,
    Top,
    ObjectModifier,
    Union,
    Light,
    Camera,
    Pigment,
    Normal,
    Finish,
    Texture,
    GlobalSettings,
    Asos,
    Default,
    Mesh,
    Mesh2List,
    SkySphere,
    Fog,
    Interior,
    Material,
    Clip,
};

// Parses a scene file and hands each top-level entry (an item or a directive,
// with all it contains) to `consume` as soon as it is complete, so that a huge
// file never has its whole tree in memory; the entry's nodes live until
// `consume` returns. Returns false after a syntax error (reported).
// Exceptions thrown by `consume` pass through.
using EntryConsumer = std::function<void(const Ast& ast, const Node& entry)>;
bool parseSceneEntries(std::string_view text, std::shared_ptr<const std::string> file,
                       NameTable& names, Diagnostics& diagnostics, const EntryConsumer& consume,
                       std::size_t startDepth = 0);

// A whole scene file as one tree. `file` names it in every position.
std::optional<Ast> parseScene(std::string_view text, std::shared_ptr<const std::string> file,
                              NameTable& names, Diagnostics& diagnostics);

// The body of a macro, `length` bytes at `offset` of its file's text (a
// MacroBody node's), starting at `line`:`column`, read for `context`. The
// tree's root is a Sequence of its entries.
struct TextSpan {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    std::uint32_t line = 1;
    std::uint32_t column = 1;
};
std::optional<Ast> parseMacroBody(std::string_view fileText, TextSpan body, std::shared_ptr<const std::string> file,
                                  BodyContext context, std::size_t startDepth, NameTable& names,
                                  Diagnostics& diagnostics);

// One expression and nothing else (a -D value); the tree's root is the expression.
std::optional<Ast> parseExpression(std::string_view text, std::shared_ptr<const std::string> file,
                                   NameTable& names, Diagnostics& diagnostics);

// A string literal's text between its quotes, its escapes (\n, \t, \", …)
// decoded as POV-Ray decodes them.
std::string decodeStringBody(std::string_view body);

// The text of line `line` (1-based) of `text`, without its end of line.
std::string_view sourceLine(std::string_view text, int line);

}  // namespace asos::lang
