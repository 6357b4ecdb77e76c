#pragma once
// The syntax tree of one scene file, as the parser builds it and the
// interpreter walks it. Kept lean because a scene may hold a million objects:
// every node is 24 bytes, children live in contiguous arrays in the tree's
// own arena, identifiers are interned numbers and positions are two integers
// (the file name is held once, by the Ast).
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "asos/lang/words.hpp"

namespace asos::lang {

enum class NodeKind : std::uint8_t {
    // Expressions.
    Number,       // number
    String,       // id: index into Ast::strings
    Name,         // id: interned identifier (NameTable)
    Constant,     // word: x, pi, clock, on, …
    Vector,       // children: 2 to 5 components
    Unary,        // word: OpSub, OpAdd or OpNot; one child
    Binary,       // word: the operator; two children
    Conditional,  // children: condition, then, else
    Call,         // word: the function; children: arguments (defined(): one Name or Index)
    Index,        // children: the array (a Name or an Index), the subscript
    MacroCall,    // children: Name, arguments; flags: the BodyContext of the call (parse.hpp)
    Member,       // word: x, red, gray, …; one child
    Colour,       // flags: 1 when children[0] is a base expression; the rest are ColourItems
    ColourItem,   // word: rgb, rgbf, red, filter, …; one child
    // Block entries and statements.
    Block,     // word: sphere, pigment, camera, …; flags: leading positional children
    Item,      // word: translate, phong, open, area_light, …; children: its arguments
    Sequence,  // entries in order: a file, a directive's body
    Declare,   // children: Name (or Index), value; flags: 1 when a lone name or macro call has no ';', 2 when deprecated (then an Item deprecated, flags 1 for once, comes first)
    Local,     // children: Name (or Index), value; flags: as Declare
    Undef,     // children: Name
    Include,   // children: file name expression
    If,        // children: (condition, Sequence)…, then an optional else Sequence; flags: has else
    While,     // children: condition, Sequence
    For,       // children: Name, start, end, [step,] Sequence; flags: has step
    Version,   // children: expression
    Debug,     // children: message expression
    Warning,
    Error,
    Switch,       // children: value, Case/Range clauses, then an optional else Sequence; flags: has else
    Case,         // children: value, Sequence
    Range,        // children: low, high, Sequence
    Break,        // no children
    Default,      // children: texture, pigment and finish blocks
    Macro,        // children: Name, parameter Names, MacroBody
    MacroBody,    // id: the body's byte offset in its file; count: its length in bytes
    Array,        // children: the sizes, then an optional Initialiser; flags: number of sizes
    Initialiser,  // children: elements, or Initialisers one level down
    // function(…) { … }: children: the parameters (Names, or Constants x y z u
    // v), then the body: an expression, or an Item (word Internal: its number;
    // word Function, flags 1 to 4: a pigment, pattern, transform or spline
    // block, left unread); flags: 1 when a parameter list was written.
    Function,
    Fopen,   // word: Read, Write or Append; children: the handle's Name, the file name expression
    Fclose,  // children: the handle's Name
    Read,    // children: the handle's Name, then the Names read into
    Write,   // children: the handle's Name, then the values written
};

struct Node {
    NodeKind kind = NodeKind::Sequence;
    std::uint8_t flags = 0;
    Word word = Word::None;
    std::uint32_t count = 0;  // number of children
    std::uint32_t line = 0;   // 1-based
    std::uint32_t column = 0; // 1-based, in bytes
    union {
        double number;
        std::uint32_t id;
        const Node* first;  // children[0 .. count)
    };

    Node() : first(nullptr) {}

    std::span<const Node> children() const {
        return hasChildren() ? std::span<const Node>(first, count) : std::span<const Node>();
    }
    const Node& operator[](std::size_t i) const { return first[i]; }
    bool hasChildren() const {
        return kind != NodeKind::Number && kind != NodeKind::String && kind != NodeKind::Name &&
               kind != NodeKind::Constant && kind != NodeKind::MacroBody && count > 0;
    }
};
static_assert(sizeof(Node) == 24, "keep syntax nodes small: a scene may have millions");

// Identifiers, interned once per interpretation so that scopes compare numbers.
class NameTable {
public:
    std::uint32_t intern(std::string_view name);
    const std::string& name(std::uint32_t id) const { return names_[id]; }
    std::size_t size() const { return names_.size(); }

private:
    std::deque<std::string> names_;  // stable addresses for the index's keys
    std::unordered_map<std::string_view, std::uint32_t> index_;
};

// Bump allocation of children arrays; freed all at once with the tree.
class NodeArena {
public:
    Node* allocate(std::size_t n);
    // Forgets every node; keeps the newest (largest) block for reuse.
    void reset();

private:
    struct Block {
        std::unique_ptr<Node[]> nodes;
        std::size_t capacity = 0;
    };
    std::vector<Block> blocks_;
    std::size_t used_ = 0;  // in blocks_.back()
};

struct Ast {
    std::shared_ptr<const std::string> file;  // the file name every position refers to
    Node root;                                // a Sequence (a file) or an expression
    std::vector<std::string> strings;         // string literals, decoded
    NodeArena arena;
};

}  // namespace asos::lang
