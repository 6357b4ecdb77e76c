// The one translation unit that includes PEGTL: grammar/ plus the actions
// that turn matches into syntax nodes. Actions only build data. The grammar
// commits (must) right after the token that starts a construct, so an action
// never fires on a path that is later abandoned.
#include "asos/lang/parse.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>
#include <vector>

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/limit_depth.hpp>

#include "grammar/errors.hpp"

namespace asos::lang {

namespace {

namespace pegtl = tao::pegtl;
namespace g = asos::grammar;

// Thrown by an action: a construct we refuse, with its final message.
struct Rejection {
    std::string message;
    std::size_t line = 0;
    std::size_t column = 0;
};

struct Pos {
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

template <typename Input>
Pos posOf(const Input& in) {
    const auto& it = in.iterator();
    return {static_cast<std::uint32_t>(it.line), static_cast<std::uint32_t>(it.column)};
}

bool isWordChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (c >= '0' && c <= '9');
}

// The identifier a match starts with (tokens carry their trailing space).
std::string_view leadingWord(std::string_view s) {
    std::size_t n = 0;
    while (n < s.size() && isWordChar(s[n])) ++n;
    return s.substr(0, n);
}

// The word after '#' (and any blanks) in a directive's match.
std::string_view directiveWord(std::string_view s) {
    std::size_t i = 1;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return leadingWord(s.substr(i));
}

template <typename Input>
[[noreturn]] void reject(const Input& in, std::string message) {
    const auto& it = in.iterator();
    throw Rejection{std::move(message), it.line, it.column};
}

std::string fillWord(std::string_view pattern, std::string_view word) {
    std::string out(pattern);
    for (auto at = out.find("{}"); at != std::string::npos; at = out.find("{}", at + word.size()))
        out.replace(at, 2, word);
    return out;
}

// Builds the tree bottom-up: finished nodes wait on a stack; a frame marks
// where the children of a construct with a variable number of them begin.
class Builder {
public:
    // `base`: the start of the file's text, which a macro's body is an offset into.
    Builder(Ast& ast, NameTable& names, const char* base) : ast_(ast), names_(names), base_(base) {
        stack_.reserve(1024);
    }

    struct Frame {
        std::size_t start = 0;
        Word word = Word::None;
        int positional = 0;
        bool flag = false;
    };

    void push(const Node& n) { stack_.push_back(n); }

    Node leaf(NodeKind kind, Pos p) const {
        Node n;
        n.kind = kind;
        n.line = p.line;
        n.column = p.column;
        return n;
    }

    void pushNumber(double v, Pos p) {
        Node n = leaf(NodeKind::Number, p);
        n.number = v;
        push(n);
    }
    void pushName(std::string_view name, Pos p) {
        Node n = leaf(NodeKind::Name, p);
        n.id = names_.intern(name);
        push(n);
    }
    void pushString(std::string s, Pos p) {
        Node n = leaf(NodeKind::String, p);
        n.id = static_cast<std::uint32_t>(ast_.strings.size());
        ast_.strings.push_back(std::move(s));
        push(n);
    }
    void pushWord(NodeKind kind, Word w, Pos p) {
        Node n = leaf(kind, p);
        n.word = w;
        push(n);
    }
    void pushSpan(const char* begin, std::size_t length, Pos p) {
        Node n = leaf(NodeKind::MacroBody, p);
        n.id = static_cast<std::uint32_t>(begin - base_);
        n.count = static_cast<std::uint32_t>(length);
        push(n);
    }
    Node& top() { return stack_.back(); }
    Pos topPos() const { return {stack_.back().line, stack_.back().column}; }

    // Replaces the top `count` nodes by one node that owns them.
    void reduce(NodeKind kind, Word w, std::size_t count, Pos p, std::uint8_t flags = 0) {
        push(make(kind, w, stack_.size() - count, p, flags));
    }

    void open(Word w = Word::None) { frames_.push_back({stack_.size(), w, 0, false}); }
    // Opens a frame that holds the last node already made (a colour's base).
    void openAroundLast() { frames_.push_back({stack_.size() - 1, Word::None, 0, true}); }
    Pos frameStart() const {
        const Node& first = stack_[frames_.back().start];
        return {first.line, first.column};
    }
    Frame& frame() { return frames_.back(); }
    std::size_t frameSize() const { return stack_.size() - frames_.back().start; }

    // Closes the innermost frame into one node.
    void close(NodeKind kind, Word w, Pos p, std::uint8_t flags = 0) {
        const std::size_t start = frames_.back().start;
        frames_.pop_back();
        push(make(kind, w, start, p, flags));
    }

    Node takeRoot(Pos p) {
        Node root = make(NodeKind::Sequence, Word::None, 0, p, 0);
        return root;
    }
    Node takeSingle() {
        Node n = stack_.back();
        stack_.pop_back();
        return n;
    }

    Word pendingWord = Word::None;
    bool missingSemicolon = false;  // for the declaration being read
    // For each declaration being read, innermost last: whether it is
    // deprecated (its first child is then the deprecation).
    std::vector<bool> deprecatedDeclarations;
    bool deprecationOnce = false;
    const EntryConsumer* consume = nullptr;  // set: hand over each top-level entry

    // A top-level entry is complete: give it away and forget its nodes.
    void finishTopEntry() {
        if (!consume || stack_.empty()) return;  // a lone '#' leaves no node
        const Node entry = takeSingle();
        (*consume)(ast_, entry);
        ast_.arena.reset();
        ast_.strings.clear();
    }

private:
    Node make(NodeKind kind, Word w, std::size_t start, Pos p, std::uint8_t flags) {
        Node n = leaf(kind, p);
        n.word = w;
        n.flags = flags;
        const std::size_t count = stack_.size() - start;
        n.count = static_cast<std::uint32_t>(count);
        Node* children = ast_.arena.allocate(count);
        std::copy(stack_.begin() + static_cast<std::ptrdiff_t>(start), stack_.end(), children);
        stack_.resize(start);
        n.first = children;
        return n;
    }

    Ast& ast_;
    NameTable& names_;
    const char* base_;
    std::vector<Node> stack_;
    std::vector<Frame> frames_;
};

Word wordOf(std::string_view text) {
    const WordInfo* w = lookupWord(text);
    return w ? w->word : Word::None;
}

// --- actions ------------------------------------------------------------------------
template <typename Rule>
struct action : pegtl::nothing<Rule> {};

template <>
struct action<g::top_item> {
    static void apply0(Builder& b) { b.finishTopEntry(); }
};

// Nesting guards.
template <>
struct action<g::unary> : pegtl::limit_depth<kMaxNesting> {};
template <>
struct action<g::object_statement> : pegtl::limit_depth<kMaxNesting> {};
template <typename Entry>
struct action<g::directive<Entry>> : pegtl::limit_depth<kMaxNesting> {};
template <>
struct action<g::array_element> : pegtl::limit_depth<kMaxNesting> {};

// Literals and names.
template <>
struct action<g::number_text> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        double v = 0.0;
        const auto r = std::from_chars(in.begin(), in.end(), v);
        if (r.ec != std::errc() || r.ptr != in.end())
            reject(in, "number '" + in.string() + "' is out of range");
        b.pushNumber(v, posOf(in));
    }
};

template <>
struct action<g::string_text> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::string_view raw = in.string_view();
        std::string s = decodeStringBody(raw.substr(1, raw.size() - 2));
        b.pushString(std::move(s), posOf(in));
    }
};

struct PushName {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.pushName(leadingWord(in.string_view()), posOf(in));
    }
};
template <> struct action<g::name_reference> : PushName {};
template <> struct action<g::declared_name> : PushName {};
template <> struct action<g::undefined_name> : PushName {};
template <> struct action<g::for_variable> : PushName {};
template <> struct action<g::tested_name> : PushName {};
template <> struct action<g::macro_name> : PushName {};
template <> struct action<g::macro_defined_name> : PushName {};
template <> struct action<g::macro_parameter> : PushName {};

template <>
struct action<g::constant> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.pushWord(NodeKind::Constant, wordOf(leadingWord(in.string_view())), posOf(in));
    }
};

// Rejections: POV-Ray constructs we do not support, named where they stand.
template <typename Rule>
struct Reject {
    template <typename Input>
    static void apply(const Input& in, Builder&) {
        reject(in, fillWord(g::rejection_message<Rule>, leadingWord(in.string_view())));
    }
};
template <typename Rule>
struct RejectDirective {
    template <typename Input>
    static void apply(const Input& in, Builder&) {
        reject(in, fillWord(g::rejection_message<Rule>, directiveWord(in.string_view())));
    }
};
template <> struct action<g::unsupported_item> : Reject<g::unsupported_item> {};
template <> struct action<g::unsupported_in_expression> : Reject<g::unsupported_in_expression> {};
template <> struct action<g::cylinder_camera> : Reject<g::cylinder_camera> {};
template <> struct action<g::camera_normal> : Reject<g::camera_normal> {};
template <> struct action<g::texture_pattern> : Reject<g::texture_pattern> {};
template <> struct action<g::normal_block_pattern> : Reject<g::normal_block_pattern> {};
template <> struct action<g::normal_pigment_map> : Reject<g::normal_pigment_map> {};
template <> struct action<g::finish_emission> : Reject<g::finish_emission> {};
template <>
struct action<g::texture_layers_open> {
    static void apply0(Builder& b) { b.openAroundLast(); }
};
// A texture block whose children are the layers, lowest first: all of them
// positional (a texture block's own entries are not).
template <>
struct action<g::layered_texture> {
    static void apply0(Builder& b) {
        const auto layers = static_cast<std::uint8_t>(std::min<std::size_t>(b.frameSize(), 255));
        b.close(NodeKind::Block, Word::Texture, b.frameStart(), layers);
    }
};
template <typename Keyword>
struct action<g::pattern_of_textures<Keyword>> : Reject<g::pattern_of_textures<Keyword>> {};
template <> struct action<g::unsupported_directive> : RejectDirective<g::unsupported_directive> {};
template <> struct action<g::unknown_directive> : RejectDirective<g::unknown_directive> {};

// Operators.
template <NodeKind Kind, Word W, std::size_t N>
struct Reduce {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.reduce(Kind, W, N, posOf(in));
    }
};
template <> struct action<g::negation> : Reduce<NodeKind::Unary, Word::OpSub, 1> {};
template <> struct action<g::plus_sign> : Reduce<NodeKind::Unary, Word::OpAdd, 1> {};
template <> struct action<g::logical_not> : Reduce<NodeKind::Unary, Word::OpNot, 1> {};
template <> struct action<g::multiply> : Reduce<NodeKind::Binary, Word::OpMul, 2> {};
template <> struct action<g::divide> : Reduce<NodeKind::Binary, Word::OpDiv, 2> {};
template <> struct action<g::add> : Reduce<NodeKind::Binary, Word::OpAdd, 2> {};
template <> struct action<g::subtract> : Reduce<NodeKind::Binary, Word::OpSub, 2> {};
template <> struct action<g::less> : Reduce<NodeKind::Binary, Word::OpLess, 2> {};
template <> struct action<g::less_equal> : Reduce<NodeKind::Binary, Word::OpLessEqual, 2> {};
template <> struct action<g::greater> : Reduce<NodeKind::Binary, Word::OpGreater, 2> {};
template <> struct action<g::greater_equal> : Reduce<NodeKind::Binary, Word::OpGreaterEqual, 2> {};
template <> struct action<g::equal> : Reduce<NodeKind::Binary, Word::OpEqual, 2> {};
template <> struct action<g::not_equal> : Reduce<NodeKind::Binary, Word::OpNotEqual, 2> {};
template <> struct action<g::conjunction> : Reduce<NodeKind::Binary, Word::OpAnd, 2> {};
template <> struct action<g::disjunction> : Reduce<NodeKind::Binary, Word::OpOr, 2> {};
template <> struct action<g::conditional_tail> : Reduce<NodeKind::Conditional, Word::None, 3> {};
template <> struct action<g::subscript> : Reduce<NodeKind::Index, Word::None, 2> {};

// Arrays: array[N]… { … }.
template <>
struct action<g::array_start> {
    static void apply0(Builder& b) { b.open(); }
};
template <>
struct action<g::array_value> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        std::size_t sizes = b.frameSize();
        if (b.top().kind == NodeKind::Initialiser) --sizes;
        if (sizes > 5) reject(in, "an array has at most 5 dimensions, this one has " + std::to_string(sizes));
        b.close(NodeKind::Array, Word::None, posOf(in), static_cast<std::uint8_t>(sizes));
    }
};
template <>
struct action<g::initialiser_open> {
    static void apply0(Builder& b) { b.open(); }
};
template <>
struct action<g::array_initialiser> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Initialiser, Word::None, posOf(in));
    }
};

// Macro calls: Name(arguments); an entry's call records the block it stands in.
template <>
struct action<g::macro_open> {
    static void apply0(Builder& b) { b.openAroundLast(); }
};
template <>
struct action<g::macro_call> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::MacroCall, Word::None, posOf(in));
    }
};
template <typename Entry>
struct action<g::macro_entry<Entry>> {
    static void apply0(Builder& b) {
        b.top().flags = static_cast<std::uint8_t>(g::body_context<Entry>::value);
    }
};

template <>
struct action<g::member_word> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.pendingWord = wordOf(in.string_view());
    }
};
template <>
struct action<g::member_access> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.reduce(NodeKind::Member, b.pendingWord, 1, posOf(in));
    }
};

// Vectors: <a, b [, c [, d [, e]]]>.
template <>
struct action<g::vector_open> {
    static void apply0(Builder& b) { b.open(); }
};
template <>
struct action<g::vector_literal> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::size_t n = b.frameSize();
        if (n < 2 || n > 5)
            reject(in, "a vector has 2 to 5 components, this one has " + std::to_string(n));
        b.close(NodeKind::Vector, Word::None, posOf(in));
    }
};

// `<1, -2.5, 3>` in one go: Number children (a leading '-' folded in).
template <>
struct action<g::plain_vector_text> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const Pos start = posOf(in);
        const char* const begin = in.begin();
        const char* const end = in.end();
        b.open();
        const char* p = begin + 1;
        while (p < end) {
            while (*p == ' ' || *p == '\t' || *p == ',') ++p;
            if (*p == '>') break;
            const char* numberBegin = p;
            const bool negative = *p == '-';
            if (negative) ++p;
            double v = 0.0;
            const auto r = std::from_chars(p, end, v);
            if (r.ec != std::errc())
                reject(in, "number '" + std::string(numberBegin, r.ptr) + "' is out of range");
            b.pushNumber(negative ? -v : v,
                         {start.line, start.column + static_cast<std::uint32_t>(numberBegin - begin)});
            p = r.ptr;
        }
        b.close(NodeKind::Vector, Word::None, start);
    }
};

// Function calls, with their number of arguments checked here.
template <>
struct action<g::function_word> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.open(wordOf(in.string_view()));
    }
};

struct Arity {
    int min;
    int max;  // -1: any
};
Arity arityOf(Word w) {
    switch (w) {
    case Word::Pow: case Word::Atan2: case Word::Mod: case Word::Div: case Word::Vcross:
    case Word::Vdot: case Word::Vrotate: case Word::Strcmp: case Word::DimensionSize:
        return {2, 2};
    case Word::VaxisRotate: case Word::Substr:
        return {3, 3};
    case Word::Sum: case Word::Prod:
        return {4, 4};
    case Word::Vstr:
        return {5, 5};
    case Word::Select:
        return {3, 4};
    case Word::Min: case Word::Max:
        return {1, -1};
    case Word::Concat:
        return {1, -1};
    case Word::Str:
        return {3, 3};
    default:
        return {1, 1};
    }
}

template <>
struct action<g::function_call> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const Word w = b.frame().word;
        const int n = static_cast<int>(b.frameSize());
        const Arity a = arityOf(w);
        if (n < a.min || (a.max >= 0 && n > a.max)) {
            std::string message = "'";
            message += wordText(w);
            message += "' takes ";
            if (a.max < 0) message += "at least ";
            message += std::to_string(a.min);
            if (a.max > a.min) message += " or " + std::to_string(a.max);
            message += a.min == 1 && a.max == 1 ? " argument, not " : " arguments, not ";
            message += std::to_string(n);
            reject(in, std::move(message));
        }
        b.close(NodeKind::Call, w, posOf(in));
    }
};

// User-defined functions (grammar/functions.hpp).
template <>
struct action<g::function_start> {
    static void apply0(Builder& b) { b.open(Word::Function); }
};
template <>
struct action<g::function_parameters> {
    static void apply0(Builder& b) { b.frame().flag = true; }
};
template <> struct action<g::function_parameter_name> : PushName {};
template <>
struct action<g::function_block> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::string_view word = leadingWord(in.string_view());
        b.pushWord(NodeKind::Item, Word::Function, posOf(in));
        b.top().flags = word == "pigment" ? 1 : word == "pattern" ? 2 : word == "transform" ? 3 : 4;
    }
};
template <> struct action<g::function_internal> : Reduce<NodeKind::Item, Word::Internal, 1> {};
template <>
struct action<g::function_value> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::uint8_t flags = b.frame().flag ? 1 : 0;
        b.close(NodeKind::Function, Word::Function, posOf(in), flags);
    }
};
template <> struct action<g::function_pattern_item> : Reduce<NodeKind::Item, Word::Function, 1> {};

// Colours.
template <>
struct action<g::colour_start> {
    static void apply0(Builder& b) { b.open(); }
};
template <>
struct action<g::colour_base> {
    static void apply0(Builder& b) { b.frame().flag = true; }
};
struct colour_item_action {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.reduce(NodeKind::ColourItem, wordOf(leadingWord(in.string_view())), 1, posOf(in));
    }
};
template <>
struct action<g::colour_whole> : colour_item_action {};
template <>
struct action<g::colour_component> : colour_item_action {};
template <>
struct action<g::colour_expression> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::uint8_t flags = b.frame().flag ? 1 : 0;
        b.close(NodeKind::Colour, Word::None, posOf(in), flags);
    }
};

template <>
struct action<g::colour_tail_start> {
    static void apply0(Builder& b) { b.openAroundLast(); }
};
template <>
struct action<g::colour_tail> {
    static void apply0(Builder& b) { b.close(NodeKind::Colour, Word::None, b.frameStart(), 1); }
};

// Blocks: '{' opens the children; the block's rule closes them. The
// other rules that open a frame for a rule closing it later take it too.
struct OpenFrame {
    static void apply0(Builder& b) { b.open(); }
};
template <> struct action<g::block_open> : OpenFrame {};
template <> struct action<g::reflection_open> : OpenFrame {};
template <>
struct action<g::arguments_end> {
    static void apply0(Builder& b) { b.frame().positional = static_cast<int>(b.frameSize()); }
};
template <Word W>
struct CloseBlock {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const auto positional = static_cast<std::uint8_t>(b.frame().positional);
        b.close(NodeKind::Block, W, posOf(in), positional);
    }
};
template <> struct action<g::sphere_block> : CloseBlock<Word::Sphere> {};
template <> struct action<g::box_block> : CloseBlock<Word::Box> {};
template <> struct action<g::cone_block> : CloseBlock<Word::Cone> {};
template <> struct action<g::cylinder_block> : CloseBlock<Word::Cylinder> {};
template <> struct action<g::disc_block> : CloseBlock<Word::Disc> {};
template <> struct action<g::polygon_block> : CloseBlock<Word::Polygon> {};
template <> struct action<g::plane_block> : CloseBlock<Word::Plane> {};
template <> struct action<g::quadric_block> : CloseBlock<Word::Quadric> {};
template <> struct action<g::torus_block> : CloseBlock<Word::Torus> {};
template <> struct action<g::poly_block> : CloseBlock<Word::Poly> {};
template <> struct action<g::quartic_block> : CloseBlock<Word::Quartic> {};
template <> struct action<g::cubic_block> : CloseBlock<Word::Cubic> {};
template <> struct action<g::text_block> : CloseBlock<Word::Text> {};
template <> struct action<g::prism_block> : CloseBlock<Word::Prism> {};
template <> struct action<g::triangle_block> : CloseBlock<Word::Triangle> {};
template <> struct action<g::smooth_triangle_block> : CloseBlock<Word::SmoothTriangle> {};
template <> struct action<g::mesh_block> : CloseBlock<Word::Mesh> {};
template <> struct action<g::mesh2_block> : CloseBlock<Word::Mesh2> {};
template <> struct action<g::vertex_vectors_block> : CloseBlock<Word::VertexVectors> {};
template <> struct action<g::normal_vectors_block> : CloseBlock<Word::NormalVectors> {};
template <> struct action<g::face_indices_block> : CloseBlock<Word::FaceIndices> {};
template <> struct action<g::normal_indices_block> : CloseBlock<Word::NormalIndices> {};
template <> struct action<g::union_block> : CloseBlock<Word::Union> {};
template <> struct action<g::difference_block> : CloseBlock<Word::Difference> {};
template <> struct action<g::intersection_block> : CloseBlock<Word::Intersection> {};
template <> struct action<g::merge_block> : CloseBlock<Word::Merge> {};
template <> struct action<g::object_block> : CloseBlock<Word::Object> {};
template <> struct action<g::clipped_by_block> : CloseBlock<Word::ClippedBy> {};
template <> struct action<g::bounded_by_block> : CloseBlock<Word::BoundedBy> {};
template <> struct action<g::light_source_block> : CloseBlock<Word::LightSource> {};
template <> struct action<g::camera_block> : CloseBlock<Word::Camera> {};
template <> struct action<g::global_settings_block> : CloseBlock<Word::GlobalSettings> {};
template <> struct action<g::background_block> : CloseBlock<Word::Background> {};
template <> struct action<g::sky_sphere_block> : CloseBlock<Word::SkySphere> {};
template <> struct action<g::fog_block> : CloseBlock<Word::Fog> {};
template <> struct action<g::pigment_block> : CloseBlock<Word::Pigment> {};
template <> struct action<g::normal_block> : CloseBlock<Word::Normal> {};
template <> struct action<g::finish_block> : CloseBlock<Word::Finish> {};
template <> struct action<g::texture_block> : CloseBlock<Word::Texture> {};
template <> struct action<g::interior_block> : CloseBlock<Word::Interior> {};
template <> struct action<g::material_block> : CloseBlock<Word::Material> {};
template <> struct action<g::asos_block> : CloseBlock<Word::Asos> {};
template <> struct action<g::colour_map_block> : CloseBlock<Word::ColorMap> {};
template <> struct action<g::pigment_map_block> : CloseBlock<Word::PigmentMap> {};
// A pigment map's entry: an Item whose flags say whether its first child is
// the value as written (1) or the entry starts with the pigment's items (0).
template <> struct action<g::pigment_map_entry_start> : OpenFrame {};
template <> struct action<g::pigment_map_value_end> {
    static void apply0(Builder& b) { b.frame().positional = static_cast<int>(b.frameSize()); }
};
template <>
struct action<g::pigment_map_entry> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const auto written = static_cast<std::uint8_t>(b.frame().positional);
        b.close(NodeKind::Item, Word::PigmentMap, posOf(in), written);
    }
};

// Sequences: directive bodies and a polygon's points.
template <>
struct action<g::sequence_start> {
    static void apply0(Builder& b) { b.open(); }
};
template <typename Entry>
struct action<g::directive_body<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Sequence, Word::None, posOf(in));
    }
};
template <>
struct action<g::prism_options> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Sequence, Word::None, posOf(in));
    }
};
template <>
struct action<g::prism_points> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Sequence, Word::None, posOf(in));
    }
};
template <>
struct action<g::polygon_points> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Sequence, Word::None, posOf(in));
    }
};
// A poly's coefficients: vector_open opened the frame.
template <>
struct action<g::poly_coefficients> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Sequence, Word::None, posOf(in));
    }
};

// Items with a fixed number of arguments.
template <Word W, std::size_t N>
struct ItemAction : Reduce<NodeKind::Item, W, N> {};
template <> struct action<g::translate_item> : ItemAction<Word::Translate, 1> {};
template <> struct action<g::rotate_item> : ItemAction<Word::Rotate, 1> {};
template <> struct action<g::scale_item> : ItemAction<Word::Scale, 1> {};
template <> struct action<g::eps_item> : ItemAction<Word::Eps, 1> {};
template <> struct action<g::max_item> : ItemAction<Word::Max, 1> {};
template <> struct action<g::asos_jitter_item> : ItemAction<Word::Jitter, 1> {};
template <> struct action<g::emitter_povray> : ItemAction<Word::Povray, 0> {};
template <> struct action<g::emitter_panel> : ItemAction<Word::Panel, 0> {};
template <> struct action<g::emitter_item> : ItemAction<Word::Emitter, 1> {};
template <> struct action<g::asos_highlights_item> : ItemAction<Word::Highlights, 1> {};
template <> struct action<g::ambient_item> : ItemAction<Word::Ambient, 1> {};
template <> struct action<g::diffuse_item> : ItemAction<Word::Diffuse, 1> {};
template <> struct action<g::brilliance_item> : ItemAction<Word::Brilliance, 1> {};
template <> struct action<g::phong_item> : ItemAction<Word::Phong, 1> {};
template <> struct action<g::phong_size_item> : ItemAction<Word::PhongSize, 1> {};
template <> struct action<g::specular_item> : ItemAction<Word::Specular, 1> {};
template <> struct action<g::roughness_item> : ItemAction<Word::Roughness, 1> {};
template <> struct action<g::reflection_simple> : ItemAction<Word::Reflection, 1> {};
template <> struct action<g::reflection_block> : CloseBlock<Word::Reflection> {};
template <> struct action<g::falloff_item> : ItemAction<Word::Falloff, 1> {};
template <> struct action<g::exponent_item> : ItemAction<Word::Exponent, 1> {};
template <> struct action<g::reflection_exponent_item> : ItemAction<Word::ReflectionExponent, 1> {};
template <> struct action<g::conserve_energy_item> : ItemAction<Word::ConserveEnergy, 0> {};
template <> struct action<g::legacy_ior_item> : ItemAction<Word::Ior, 1> {};
template <> struct action<g::legacy_caustics_item> : ItemAction<Word::Caustics, 1> {};
template <> struct action<g::legacy_refraction_item> : ItemAction<Word::Refraction, 1> {};
template <> struct action<g::ior_item> : ItemAction<Word::Ior, 1> {};
template <> struct action<g::caustics_item> : ItemAction<Word::Caustics, 1> {};
template <> struct action<g::dispersion_item> : ItemAction<Word::Dispersion, 1> {};
template <> struct action<g::dispersion_samples_item> : ItemAction<Word::DispersionSamples, 1> {};
template <> struct action<g::interior_fade_distance_item> : ItemAction<Word::FadeDistance, 1> {};
template <> struct action<g::interior_fade_power_item> : ItemAction<Word::FadePower, 1> {};
template <> struct action<g::fade_colour_item> : ItemAction<Word::FadeColor, 1> {};
template <> struct action<g::crand_item> : ItemAction<Word::Crand, 1> {};
template <> struct action<g::emission_item> : ItemAction<Word::Emission, 1> {};
template <> struct action<g::fog_type_item> : ItemAction<Word::FogType, 1> {};
template <> struct action<g::distance_item> : ItemAction<Word::Distance, 1> {};
template <> struct action<g::fog_offset_item> : ItemAction<Word::FogOffset, 1> {};
template <> struct action<g::fog_alt_item> : ItemAction<Word::FogAlt, 1> {};
template <> struct action<g::turb_depth_item> : ItemAction<Word::TurbDepth, 1> {};
template <> struct action<g::bumps_item> : ItemAction<Word::Bumps, 0> {};
template <> struct action<g::dents_item> : ItemAction<Word::Dents, 0> {};
template <> struct action<g::wrinkles_item> : ItemAction<Word::Wrinkles, 0> {};
template <> struct action<g::ripples_item> : ItemAction<Word::Ripples, 0> {};
template <> struct action<g::waves_item> : ItemAction<Word::Waves, 0> {};
template <> struct action<g::bump_amount> : ItemAction<Word::BumpSize, 1> {};
template <> struct action<g::bump_size_item> : ItemAction<Word::BumpSize, 1> {};
template <> struct action<g::accuracy_item> : ItemAction<Word::Accuracy, 1> {};
template <> struct action<g::brick_size_item> : ItemAction<Word::BrickSize, 1> {};
template <> struct action<g::mortar_item> : ItemAction<Word::Mortar, 1> {};
template <> struct action<g::gradient_item> : ItemAction<Word::Gradient, 1> {};
template <> struct action<g::radial_item> : ItemAction<Word::Radial, 0> {};
template <> struct action<g::onion_item> : ItemAction<Word::Onion, 0> {};
template <> struct action<g::marble_item> : ItemAction<Word::Marble, 0> {};
template <> struct action<g::wood_item> : ItemAction<Word::Wood, 0> {};
template <> struct action<g::leopard_item> : ItemAction<Word::Leopard, 0> {};
template <> struct action<g::bozo_item> : ItemAction<Word::Bozo, 0> {};
template <> struct action<g::spotted_item> : ItemAction<Word::Spotted, 0> {};
template <> struct action<g::granite_item> : ItemAction<Word::Granite, 0> {};
template <> struct action<g::agate_item> : ItemAction<Word::Agate, 0> {};
template <> struct action<g::crackle_item> : ItemAction<Word::Crackle, 0> {};
template <> struct action<g::average_item> : ItemAction<Word::Average, 0> {};
template <> struct action<g::form_item> : ItemAction<Word::Form, 1> {};
template <> struct action<g::metric_item> : ItemAction<Word::Metric, 1> {};
template <> struct action<g::offset_item> : ItemAction<Word::Offset, 1> {};
template <> struct action<g::solid_item> : ItemAction<Word::Solid, 0> {};
template <> struct action<g::turbulence_item> : ItemAction<Word::Turbulence, 1> {};
template <> struct action<g::octaves_item> : ItemAction<Word::Octaves, 1> {};
template <> struct action<g::omega_item> : ItemAction<Word::Omega, 1> {};
template <> struct action<g::lambda_item> : ItemAction<Word::Lambda, 1> {};
template <> struct action<g::frequency_item> : ItemAction<Word::Frequency, 1> {};
template <> struct action<g::phase_item> : ItemAction<Word::Phase, 1> {};
template <> struct action<g::agate_turb_item> : ItemAction<Word::AgateTurb, 1> {};
template <> struct action<g::noise_generator_item> : ItemAction<Word::NoiseGenerator, 1> {};
template <> struct action<g::ramp_wave_item> : ItemAction<Word::RampWave, 0> {};
template <> struct action<g::triangle_wave_item> : ItemAction<Word::TriangleWave, 0> {};
template <> struct action<g::sine_wave_item> : ItemAction<Word::SineWave, 0> {};
template <> struct action<g::open_item> : ItemAction<Word::Open, 0> {};
template <> struct action<g::sturm_item> : ItemAction<Word::Sturm, 0> {};
template <> struct action<g::no_shadow_item> : ItemAction<Word::NoShadow, 0> {};
template <> struct action<g::inverse_item> : ItemAction<Word::Inverse, 0> {};
template <> struct action<g::clip_link> : ItemAction<Word::BoundedBy, 0> {};
template <> struct action<g::bound_link> : ItemAction<Word::ClippedBy, 0> {};
template <> struct action<g::area_light_item> : ItemAction<Word::AreaLight, 4> {};
template <> struct action<g::adaptive_item> : ItemAction<Word::Adaptive, 1> {};
template <> struct action<g::jitter_item> : ItemAction<Word::Jitter, 0> {};
template <> struct action<g::circular_item> : ItemAction<Word::Circular, 0> {};
template <> struct action<g::orient_item> : ItemAction<Word::Orient, 0> {};
template <> struct action<g::fade_distance_item> : ItemAction<Word::FadeDistance, 1> {};
template <> struct action<g::fade_power_item> : ItemAction<Word::FadePower, 1> {};
template <> struct action<g::shadowless_item> : ItemAction<Word::Shadowless, 0> {};
template <> struct action<g::spotlight_item> : ItemAction<Word::Spotlight, 0> {};
template <> struct action<g::prism_linear_sweep> : ItemAction<Word::LinearSweep, 0> {};
template <> struct action<g::prism_conic_sweep> : ItemAction<Word::ConicSweep, 0> {};
template <> struct action<g::prism_linear_spline> : ItemAction<Word::LinearSpline, 0> {};
template <> struct action<g::prism_quadratic_spline> : ItemAction<Word::QuadraticSpline, 0> {};
template <> struct action<g::prism_cubic_spline> : ItemAction<Word::CubicSpline, 0> {};
template <> struct action<g::prism_bezier_spline> : ItemAction<Word::BezierSpline, 0> {};
template <> struct action<g::cylinder_light> : ItemAction<Word::Cylinder, 0> {};
template <> struct action<g::parallel_item> : ItemAction<Word::Parallel, 0> {};
template <> struct action<g::point_at_item> : ItemAction<Word::PointAt, 1> {};
template <> struct action<g::light_radius_item> : ItemAction<Word::Radius, 1> {};
template <> struct action<g::light_falloff_item> : ItemAction<Word::Falloff, 1> {};
template <> struct action<g::tightness_item> : ItemAction<Word::Tightness, 1> {};
// area_illumination with or without its value.
template <>
struct action<g::area_illumination_start> {
    static void apply0(Builder& b) { b.open(); }
};
template <>
struct action<g::area_illumination_item> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Item, Word::AreaIllumination, posOf(in));
    }
};
template <> struct action<g::perspective_item> : ItemAction<Word::Perspective, 0> {};
template <> struct action<g::orthographic_item> : ItemAction<Word::Orthographic, 0> {};
template <> struct action<g::location_item> : ItemAction<Word::Location, 1> {};
template <> struct action<g::look_at_item> : ItemAction<Word::LookAt, 1> {};
template <> struct action<g::angle_item> : ItemAction<Word::Angle, 1> {};
template <> struct action<g::right_item> : ItemAction<Word::Right, 1> {};
template <> struct action<g::up_item> : ItemAction<Word::Up, 1> {};
template <> struct action<g::direction_item> : ItemAction<Word::Direction, 1> {};
template <> struct action<g::sky_item> : ItemAction<Word::Sky, 1> {};
template <> struct action<g::assumed_gamma_item> : ItemAction<Word::AssumedGamma, 1> {};
template <> struct action<g::max_trace_level_item> : ItemAction<Word::MaxTraceLevel, 1> {};
template <> struct action<g::ambient_light_item> : ItemAction<Word::AmbientLight, 1> {};

// Items with a variable number of arguments.
template <typename Keyword>
struct action<g::pattern_colours_start<Keyword>> {
    static void apply0(Builder& b) { b.open(); }
};
template <Word W>
struct ClosePattern {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Item, W, posOf(in));
    }
};
template <> struct action<g::checker_item> : ClosePattern<Word::Checker> {};
// A colour map's entry: its value and one colour, or POV-Ray's older two
// values and two colours.
template <> struct action<g::map_entry_start> : OpenFrame {};
template <> struct action<g::map_entry> : ClosePattern<Word::ColorMap> {};
template <> struct action<g::hollow_start> : OpenFrame {};
template <> struct action<g::hollow_item> : ClosePattern<Word::Hollow> {};
template <> struct action<g::fresnel_start> : OpenFrame {};
template <> struct action<g::fresnel_item> : ClosePattern<Word::Fresnel> {};
template <> struct action<g::metallic_start> : OpenFrame {};
template <> struct action<g::metallic_item> : ClosePattern<Word::Metallic> {};
template <> struct action<g::brick_item> : ClosePattern<Word::Brick> {};
template <>
struct action<g::matrix_item> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::size_t n = b.frameSize();
        if (n != 12) reject(in, "a matrix has 12 numbers, this one has " + std::to_string(n));
        b.close(NodeKind::Item, Word::Matrix, posOf(in));
    }
};

// Directives.
template <Word W>
struct OpenDirective {
    static void apply0(Builder& b) { b.open(W); }
};
template <> struct action<g::if_start> : OpenDirective<Word::If> {};
template <> struct action<g::ifdef_start> : OpenDirective<Word::Ifdef> {};
template <> struct action<g::ifndef_start> : OpenDirective<Word::Ifndef> {};
template <> struct action<g::while_start> : OpenDirective<Word::While> {};
template <> struct action<g::for_start> : OpenDirective<Word::For> {};

struct CloseIf {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        // Condition/body pairs, then the else body if the count is odd.
        const std::uint8_t hasElse = b.frameSize() % 2 == 1 ? 1 : 0;
        b.close(NodeKind::If, Word::None, posOf(in), hasElse);
    }
};
template <typename Entry> struct action<g::if_directive<Entry>> : CloseIf {};
template <typename Entry> struct action<g::ifdef_directive<Entry>> : CloseIf {};
template <typename Entry> struct action<g::ifndef_directive<Entry>> : CloseIf {};

// #ifdef (N) is #if (defined(N)); #ifndef (N) is #if (!defined(N)).
template <>
struct action<g::ifdef_condition> {
    static void apply0(Builder& b) {
        const Pos p = b.topPos();
        b.reduce(NodeKind::Call, Word::Defined, 1, p);
        if (b.frame().word == Word::Ifndef) b.reduce(NodeKind::Unary, Word::OpNot, 1, p);
    }
};

template <typename Entry>
struct action<g::while_directive<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::While, Word::None, posOf(in));
    }
};
template <typename Entry>
struct action<g::for_directive<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::uint8_t hasStep = b.frameSize() == 5 ? 1 : 0;
        b.close(NodeKind::For, Word::None, posOf(in), hasStep);
    }
};
template <> struct action<g::switch_start> : OpenDirective<Word::Switch> {};
template <> struct action<g::case_start> : OpenDirective<Word::Case> {};
template <> struct action<g::range_start> : OpenDirective<Word::Range> {};
template <typename Entry>
struct action<g::case_clause<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Case, Word::Case, posOf(in));
    }
};
template <typename Entry>
struct action<g::range_clause<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Range, Word::Range, posOf(in));
    }
};
template <typename Entry>
struct action<g::switch_directive<Entry>> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const std::uint8_t hasElse = b.top().kind == NodeKind::Sequence ? 1 : 0;
        b.close(NodeKind::Switch, Word::Switch, posOf(in), hasElse);
    }
};
template <>
struct action<g::break_directive> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.pushWord(NodeKind::Break, Word::Break, posOf(in));
    }
};
template <> struct action<g::default_start> : OpenDirective<Word::Default> {};
template <> struct action<g::bare_default_start> : OpenDirective<Word::Default> {};
struct CloseDefault {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Default, Word::Default, posOf(in));
    }
};
template <> struct action<g::default_directive> : CloseDefault {};
template <> struct action<g::bare_default> : CloseDefault {};
template <> struct action<g::macro_start> : OpenDirective<Word::Macro> {};
template <>
struct action<g::macro_body_text> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.pushSpan(in.begin(), in.size(), posOf(in));
    }
};
template <>
struct action<g::macro_directive> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Macro, Word::Macro, posOf(in));
    }
};
template <>
struct action<g::missing_semicolon> {
    static void apply0(Builder& b) { b.missingSemicolon = true; }
};
// flags: 1 when a lone name or macro call was declared without its ';'.
template <NodeKind Kind, Word W>
struct CloseDeclare {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const bool deprecated = !b.deprecatedDeclarations.empty() && b.deprecatedDeclarations.back();
        if (!b.deprecatedDeclarations.empty()) b.deprecatedDeclarations.pop_back();
        b.reduce(Kind, W, deprecated ? 3 : 2, posOf(in),
                 static_cast<std::uint8_t>((b.missingSemicolon ? 1 : 0) | (deprecated ? 2 : 0)));
        b.missingSemicolon = false;
    }
};
template <>
struct action<g::declare_start> {
    static void apply0(Builder& b) { b.deprecatedDeclarations.push_back(false); }
};
template <>
struct action<g::local_start> {
    static void apply0(Builder& b) { b.deprecatedDeclarations.push_back(false); }
};
template <>
struct action<g::deprecation_once> {
    static void apply0(Builder& b) { b.deprecationOnce = true; }
};
template <>
struct action<g::deprecation> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.reduce(NodeKind::Item, Word::Deprecated, 1, posOf(in), b.deprecationOnce ? 1 : 0);
        b.deprecationOnce = false;
        if (!b.deprecatedDeclarations.empty()) b.deprecatedDeclarations.back() = true;
    }
};
template <> struct action<g::declare_directive> : CloseDeclare<NodeKind::Declare, Word::Declare> {};
template <> struct action<g::local_directive> : CloseDeclare<NodeKind::Local, Word::Local> {};
template <> struct action<g::undef_directive> : Reduce<NodeKind::Undef, Word::Undef, 1> {};
template <> struct action<g::include_directive> : Reduce<NodeKind::Include, Word::Include, 1> {};
template <> struct action<g::version_directive> : Reduce<NodeKind::Version, Word::Version, 1> {};
template <> struct action<g::debug_directive> : Reduce<NodeKind::Debug, Word::Debug, 1> {};
template <> struct action<g::warning_directive> : Reduce<NodeKind::Warning, Word::Warning, 1> {};
template <> struct action<g::error_directive> : Reduce<NodeKind::Error, Word::Error, 1> {};

// #fopen, #fclose, #read, #write.
template <> struct action<g::fopen_start> : OpenDirective<Word::Fopen> {};
template <> struct action<g::opened_handle> : PushName {};
template <>
struct action<g::open_mode> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.frame().word = wordOf(leadingWord(in.string_view()));
    }
};
template <>
struct action<g::fopen_directive> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        const Word mode = b.frame().word;
        b.close(NodeKind::Fopen, mode, posOf(in));
    }
};
template <> struct action<g::closed_handle> : PushName {};
template <> struct action<g::fclose_directive> : Reduce<NodeKind::Fclose, Word::Fclose, 1> {};
template <> struct action<g::read_start> : OpenDirective<Word::Read> {};
template <> struct action<g::write_start> : OpenDirective<Word::Write> {};
template <> struct action<g::file_handle> : PushName {};
template <> struct action<g::read_variable> : PushName {};
template <>
struct action<g::read_directive> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Read, Word::Read, posOf(in));
    }
};
template <>
struct action<g::write_directive> {
    template <typename Input>
    static void apply(const Input& in, Builder& b) {
        b.close(NodeKind::Write, Word::Write, posOf(in));
    }
};

// --- errors ---------------------------------------------------------------------------

// What stands at `byte`, quoted for a message: a word, a number, a string,
// a directive or one character.
std::string foundAt(std::string_view text, std::size_t byte) {
    if (byte >= text.size()) return "the end of the file";
    const std::string_view rest = text.substr(byte);
    const char c = rest[0];
    std::size_t n = 1;
    if (isWordChar(c) || (c == '.' && rest.size() > 1 && rest[1] >= '0' && rest[1] <= '9')) {
        while (n < rest.size() && (isWordChar(rest[n]) || rest[n] == '.')) ++n;
    } else if (c == '#') {
        while (n < rest.size() && (rest[n] == ' ' || rest[n] == '\t')) ++n;
        while (n < rest.size() && isWordChar(rest[n])) ++n;
    } else if (c == '"') {
        while (n < rest.size() && rest[n] != '"' && rest[n] != '\n' && n < 40) ++n;
        if (n < rest.size() && rest[n] == '"') ++n;
    } else if (static_cast<unsigned char>(c) < 0x20) {
        return c == '\n' || c == '\r' ? "the end of the line" : "a control character";
    }
    std::string quoted = "'";
    quoted += rest.substr(0, n);
    quoted += '\'';
    return quoted;
}

Diagnostic makeError(const std::shared_ptr<const std::string>& file, std::string_view fileText,
                     std::size_t line, std::size_t column, std::string message) {
    Diagnostic d;
    d.severity = Severity::Error;
    d.loc = SourceLoc{file, static_cast<int>(line), static_cast<int>(column)};
    d.message = std::move(message);
    d.sourceLine = std::string(sourceLine(fileText, static_cast<int>(line)));
    return d;
}

// What a parse reads: `span` of a file's text (all of it, or a macro's body).
struct Source {
    std::string_view fileText;
    TextSpan span;

    std::string_view text() const { return fileText.substr(span.offset, span.length); }
};

Source wholeText(std::string_view text) {
    return {text, TextSpan{0, static_cast<std::uint32_t>(text.size()), 1, 1}};
}

// Parses with TopRule; `root` says what the tree's root is. Returns false after
// a syntax error, which it reports. The nesting limit counts from `startDepth`.
enum class Root { File, Expression };
template <typename TopRule>
bool parseWith(Ast& ast, const Source& source, NameTable& names, Diagnostics& diagnostics, Root root,
               const EntryConsumer* consume, std::size_t startDepth) {
    const std::string_view text = source.text();
    Builder builder(ast, names, source.fileText.data());
    builder.consume = consume;
    pegtl::memory_input<pegtl::tracking_mode::eager> in(text.data(), text.data() + text.size(),
                                                        ast.file ? *ast.file : std::string(), 0,
                                                        source.span.line, source.span.column);
    in.private_depth = startDepth;
    try {
        if (root == Root::File) builder.open();
        pegtl::parse<TopRule, action, g::control>(in, builder);
        ast.root = root == Root::File ? builder.takeRoot({source.span.line, source.span.column}) : builder.takeSingle();
        return true;
    } catch (const pegtl::parse_error& e) {
        const pegtl::position& p = e.positions().front();
        std::string message(e.message());
        if (message.rfind("expected", 0) == 0) message += ", found " + foundAt(text, p.byte);
        if (message == "maximum parser rule nesting depth exceeded")  // limit_depth's words
            message = "nested too deep: parentheses, operators, blocks, directives, includes and macro calls "
                      "together go over " + std::to_string(kMaxNesting) + " levels";
        std::size_t line = p.line;
        std::size_t column = p.column;
        if (p.byte >= text.size()) {
            // At the end of the text: point just after the last token, on a
            // line that can be shown.
            std::size_t end = text.size();
            while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
            const std::size_t lineStart = end == 0 ? std::string_view::npos : text.rfind('\n', end - 1);
            line = source.span.line +
                   static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
            column = lineStart == std::string_view::npos ? source.span.column + end : end - lineStart;
        }
        diagnostics.report(makeError(ast.file, source.fileText, line, column, std::move(message)));
    } catch (const Rejection& r) {
        diagnostics.report(makeError(ast.file, source.fileText, r.line, r.column, r.message));
    }
    return false;
}

// The body of a macro read as entries of Entry.
template <typename Entry>
std::optional<Ast> parseBody(const Source& source, std::shared_ptr<const std::string> file, std::size_t startDepth,
                             NameTable& names, Diagnostics& diagnostics) {
    Ast ast;
    ast.file = std::move(file);
    if (!parseWith<g::macro_body<Entry>>(ast, source, names, diagnostics, Root::File, nullptr, startDepth))
        return std::nullopt;
    return ast;
}

}  // namespace

std::string decodeStringBody(std::string_view body) {
    std::string s;
    s.reserve(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) {
        char c = body[i];
        if (c == '\\' && i + 1 < body.size()) {
            const char e = body[++i];
            switch (e) {
            case 'n': c = '\n'; break;
            case 't': c = '\t'; break;
            case 'r': c = '\r'; break;
            case 'a': c = '\a'; break;
            case 'b': c = '\b'; break;
            case 'f': c = '\f'; break;
            case 'v': c = '\v'; break;
            case '\\': case '"': case '\'': c = e; break;
            default: s += '\\'; c = e; break;  // kept as written, like POV-Ray
            }
        }
        s += c;
    }
    return s;
}

std::string_view sourceLine(std::string_view text, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return text.substr(start, end - start);
}

bool parseSceneEntries(std::string_view text, std::shared_ptr<const std::string> file, NameTable& names,
                       Diagnostics& diagnostics, const EntryConsumer& consume, std::size_t startDepth) {
    Ast ast;
    ast.file = std::move(file);
    return parseWith<g::scene_file>(ast, wholeText(text), names, diagnostics, Root::File, &consume, startDepth);
}

std::optional<Ast> parseScene(std::string_view text, std::shared_ptr<const std::string> file,
                              NameTable& names, Diagnostics& diagnostics) {
    Ast ast;
    ast.file = std::move(file);
    if (!parseWith<g::scene_file>(ast, wholeText(text), names, diagnostics, Root::File, nullptr, 0))
        return std::nullopt;
    return ast;
}

std::optional<Ast> parseMacroBody(std::string_view fileText, TextSpan body, std::shared_ptr<const std::string> file,
                                  BodyContext context, std::size_t startDepth, NameTable& names,
                                  Diagnostics& diagnostics) {
    const Source source{fileText, body};
    auto parse = [&]<typename Entry>(Entry*) {
        return parseBody<Entry>(source, std::move(file), startDepth, names, diagnostics);
    };
    switch (context) {
    case BodyContext::Value: return parse(static_cast<g::value_entry*>(nullptr));
    case BodyContext::Top: return parse(static_cast<g::top_entry*>(nullptr));
    case BodyContext::ObjectModifier: return parse(static_cast<g::object_modifier*>(nullptr));
    case BodyContext::Union: return parse(static_cast<g::union_entry*>(nullptr));
    case BodyContext::Clip: return parse(static_cast<g::clip_entry*>(nullptr));
    case BodyContext::Light: return parse(static_cast<g::light_entry*>(nullptr));
    case BodyContext::Camera: return parse(static_cast<g::camera_entry*>(nullptr));
    case BodyContext::Pigment: return parse(static_cast<g::pigment_entry*>(nullptr));
    case BodyContext::Normal: return parse(static_cast<g::normal_entry*>(nullptr));
    case BodyContext::Finish: return parse(static_cast<g::finish_entry*>(nullptr));
    case BodyContext::Interior: return parse(static_cast<g::interior_entry*>(nullptr));
    case BodyContext::Material: return parse(static_cast<g::material_entry*>(nullptr));
    case BodyContext::Texture: return parse(static_cast<g::texture_entry*>(nullptr));
    case BodyContext::GlobalSettings: return parse(static_cast<g::global_entry*>(nullptr));
    case BodyContext::Asos: return parse(static_cast<g::asos_entry*>(nullptr));
    case BodyContext::Default: return parse(static_cast<g::default_entry*>(nullptr));
    case BodyContext::Mesh: return parse(static_cast<g::mesh_entry*>(nullptr));
    case BodyContext::Mesh2List: return parse(static_cast<g::mesh2_item*>(nullptr));
    case BodyContext::SkySphere: return parse(static_cast<g::sky_sphere_entry*>(nullptr));
    case BodyContext::Fog: return parse(static_cast<g::fog_entry*>(nullptr));
    }
    return std::nullopt;
}

std::optional<Ast> parseExpression(std::string_view text, std::shared_ptr<const std::string> file,
                                   NameTable& names, Diagnostics& diagnostics) {
    Ast ast;
    ast.file = std::move(file);
    if (!parseWith<g::expression_text>(ast, wholeText(text), names, diagnostics, Root::Expression, nullptr, 0))
        return std::nullopt;
    return ast;
}

}  // namespace asos::lang
