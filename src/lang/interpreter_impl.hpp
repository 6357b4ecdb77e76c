#pragma once
// The interpreter's inside, shared by interpreter.cpp (files, scopes,
// directives), evaluate.cpp (expressions), items.cpp (scene items) and
// user_files.cpp (#fopen, #read, #write).
#include <array>
#include <deque>
#include <filesystem>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <variant>
#include <vector>

#include "asos/scene/truetype_font.hpp"
#include "asos/diag/format_number.hpp"
#include "asos/lang/ast.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/lang/parse.hpp"
#include "asos/scene/pov_tolerances.hpp"  // kPovEpsilon: how the language compares
#include "asos/util/function_ref.hpp"

namespace asos::lang {

// A float (dim 1), a 2- to 5-component vector, or a colour (always five
// components: red, green, blue, filter, transmit).
struct Num {
    std::array<double, 5> v{};
    std::uint8_t dim = 1;
    bool colour = false;

    bool isFloat() const { return dim == 1 && !colour; }
    static Num scalar(double x) {
        Num n;
        n.v[0] = x;
        return n;
    }
    static Num vector(const Vec3& p) {
        Num n;
        n.v = {p.x, p.y, p.z, 0.0, 0.0};
        n.dim = 3;
        return n;
    }
    static Num fromColour(const Color& c) {
        Num n;
        n.v = {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
        n.dim = 5;
        n.colour = true;
        return n;
    }
};

// An object while the scene runs: a shape, a light, or a union, merge,
// intersection or difference of those (Kind::Union, its `op`). Kept as a tree
// until it is placed in the scene, because POV-Ray resolves a union's texture
// for its untextured children only then.
struct ClipLists;

struct ObjectTree {
    enum class Kind : std::uint8_t { Shape, Light, Union };
    Kind kind = Kind::Shape;
    CsgTree::Op op = CsgTree::Op::Union;  // Kind::Union: which combination
    bool inverse = false;                  // POV-Ray's `inverse`, toggled by each
    Shape shape;
    // Kind::Shape: a mesh or mesh2 (its faces; `shape` unused), placed as
    // one Object per face.
    std::shared_ptr<const TriangleMesh> mesh;
    Transform worldFromObject;
    std::shared_ptr<const Light> light;      // Kind::Light (shared: changed by copying)
    std::shared_ptr<const Texture> texture;  // its own; null: inherited or the default
    std::shared_ptr<const Interior> interior;  // its own; null: inherited or the default
    bool noShadow = false;
    bool modified = false;  // a union has had a modifier: no more children
    std::size_t leaves = 1;  // the shapes and lights it holds (a union's, all its children's)
    std::size_t nodes = 1;   // ObjectTrees in it, itself included: what a copy allocates
    AsosOptions asos;
    std::vector<ObjectTree> children;
    // clipped_by's and bounded_by's objects (ClipLists); null: none. Shared
    // by the copies of the object, changed through ownClipping.
    std::shared_ptr<const ClipLists> clipping;
    SourceLoc loc;
};

// An object's clip and bound lists, as POV-Ray keeps them.
struct ClipLists {
    // clipped_by's objects: the object keeps the part of its surface (and of
    // its inside) that is inside every one of them. Placed as a CSG
    // intersection whose clip members make no Objects.
    std::vector<ObjectTree> clips;
    // bounded_by's objects, resolved where the object is placed
    // (object_bounds.hpp). `linked`: bounded_by { clipped_by } or clipped_by
    // { bounded_by } made one list, kept in clips, both.
    std::vector<ObjectTree> bounds;
    bool linked = false;
    SourceLoc boundsLoc;  // the bounded_by written last
};

inline const std::vector<ObjectTree>& clipsOf(const ObjectTree& t) {
    static const std::vector<ObjectTree> none;
    return t.clipping ? t.clipping->clips : none;
}
inline const std::vector<ObjectTree>& boundsOf(const ObjectTree& t) {
    static const std::vector<ObjectTree> none;
    return t.clipping ? t.clipping->bounds : none;
}
// The object's lists to change: a copy of its own, no longer shared.
inline ClipLists& ownClipping(ObjectTree& t) {
    auto own = t.clipping ? std::make_shared<ClipLists>(*t.clipping) : std::make_shared<ClipLists>();
    ClipLists& lists = *own;
    t.clipping = std::move(own);
    return lists;
}

struct CameraValue {
    Camera camera;
    Vec3 sky{0.0, 1.0, 0.0};
    Vec3 lookAt{0.0, 0.0, 1.0};  // POV-Ray's, which sizes an orthographic view
};

struct Poison {};  // the value of a declaration whose right side failed (already reported)
struct Unset {};   // an array's element not given a value yet

// A file read: the scene or an include. Kept to the end of the run, for the
// source lines of errors and for the macros defined in it.
struct SourceFile {
    std::shared_ptr<const std::string> name;
    std::string text;
    std::filesystem::path path;             // canonical when it came from disk; empty for text
    std::vector<std::uint32_t> lineStarts;  // built on the first error
};

struct ArrayValue;
struct MacroDef;
// A declared function (lang/functions.cpp): its program, or, for the kinds
// asos refuses where they are used (internal(N), pigment, pattern,
// transform and spline functions, and functions that call those), why.
struct FunctionValue {
    std::shared_ptr<const FunctionProgram> program;  // null: refused where used
    std::string refusal;                             // the message then
};
// A declared material: POV-Ray's texture and interior together.
struct MaterialValue {
    std::shared_ptr<const Texture> texture;    // null: none given
    std::shared_ptr<const Interior> interior;  // null: none given
};

// A declared color_map.
struct ColourMapValue {
    std::vector<ColourMapEntry> entries;
};

// A file opened by #fopen (lang/user_files.cpp). A file read is read whole
// when opened; what is written is kept until the file is closed, then put in
// place whole.
struct UserFile {
    enum class Mode : std::uint8_t { Read, Write, Append };
    Mode mode = Mode::Read;
    bool open = true;
    std::string name;             // as the scene gave it
    std::filesystem::path path;   // where it is read from or written to
    SourceLoc openedAt;           // the #fopen
    SourceFile* source = nullptr; // Read: its text (kept for the lines of errors)
    std::size_t position = 0;     // Read: where the next value starts
    std::string written;          // Write, Append: what #write gave it so far
};

// A declared pigment_map: its entries, shared with every pigment using it.
struct PigmentMapValue {
    std::shared_ptr<const PigmentMap> entries;
};

using Value = std::variant<Num, std::string, std::shared_ptr<const ObjectTree>,
                           std::shared_ptr<const Pigment>, std::shared_ptr<const Finish>,
                           std::shared_ptr<const Texture>, std::shared_ptr<const CameraValue>,
                           std::shared_ptr<ArrayValue>, std::shared_ptr<const MacroDef>,
                           std::shared_ptr<const ColourMapValue>, std::shared_ptr<const Normal>, Poison, Unset,
                           std::shared_ptr<const FunctionValue>, std::shared_ptr<const Interior>,
                           std::shared_ptr<const MaterialValue>, std::shared_ptr<const SkySphere>,
                           std::shared_ptr<const Fog>, std::shared_ptr<UserFile>,
                           std::shared_ptr<const PigmentMapValue>>;

// A declared array: up to 5 dimensions, its elements all of one kind (the first
// one given sets it, as in POV-Ray). Arrays are values: names share one until
// an element is changed through one of them, which then gets its own copy.
struct ArrayValue {
    std::vector<std::uint32_t> sizes;
    std::vector<Value> elements;  // the last index varies fastest; Unset until given
    int kind = -1;                // kindOf() of the elements; -1 before the first
};

// The kind of a value that an array holds: a float, a vector of each size, a
// colour, a string, an object, …
int kindOf(const Value& v);

// A macro: its parameters and where its body is in its file. The body is read
// (parsed) on the first call from each kind of place (BodyContext) and kept.
inline constexpr std::size_t kBodyContexts = static_cast<std::size_t>(BodyContext::Default) + 1;
struct MacroDef {
    std::uint32_t name = 0;
    std::vector<std::uint32_t> parameters;
    SourceFile* file = nullptr;  // where the body is (and its source lines)
    TextSpan body;
    mutable std::array<std::shared_ptr<const Ast>, kBodyContexts> bodies;
};

// A name's entry in a scope: a value, or, for a macro's parameter given a bare
// identifier, the entry it stands for (POV-Ray passes such an argument by
// reference: assigning to the parameter assigns to it).
struct Slot {
    Value value;
    std::int32_t refScope = -1;  // the scope of the entry it stands for; -1: none
    std::uint32_t refId = 0;
};
using Scope = std::unordered_map<std::uint32_t, Slot>;

// 'word', for messages.
inline std::string quote(std::string_view word) {
    std::string s;
    s.reserve(word.size() + 2);
    s += '\'';
    s += word;
    s += '\'';
    return s;
}

// "1 element", "3 elements": a count with its noun, for messages.
inline std::string countOf(std::size_t n, std::string_view noun) {
    std::string s = std::to_string(n) + ' ';
    s += noun;
    if (n != 1) s += 's';
    return s;
}

// "a float", "a vector", "a string", … for messages.
std::string describe(const Value& v);
std::string describe(const Num& n);
// Every component is a finite number.
bool isFinite(const Num& n);
// "2.5", "<1, nan, 0>": the numbers themselves, for messages.
std::string describeNumbers(const Num& n);

// What a colour carries where it is used, as POV-Ray's Parse_Colour reads
// it: all five components for a pigment's or the background's colour; red,
// green and blue only for a light's, ambient, reflection and ambient_light,
// where a float is a grey (`color 1.5` is rgb 1.5).
enum class ColourChannels : std::uint8_t { Rgbft, Rgb };

// The current statement is dropped; its error has been reported.
struct Abandon {};
// What a body's run ended with: null, or the #break that ended it.
using BreakNode = const Node*;
// Interpretation stops (#error, too many errors, a syntax error in an include).
struct Stop {};

// The entry handler of a block, called for each of its entries.
using EntryHandler = FunctionRef<void(const Node&)>;

// Objects as they arrive. First into a vector reserved for as many objects as
// the scene text can write out (one per '{' at most): reserved memory costs
// address space, not memory, until it is used, and when the guess holds the
// vector becomes the description's as it is. Objects beyond it (made by
// loops, or copies of declared unions) go to 64 MiB chunks, which the
// allocator maps one by one and gives back as soon as they are moved out.
class ObjectStore {
public:
    void reserve(std::size_t count);
    Object& add();
    std::size_t size() const { return main_.size() + overflow_; }
    std::vector<Object> take();

private:
    std::vector<Object> main_;
    std::vector<std::vector<Object>> chunks_;
    std::size_t overflow_ = 0;
};

// Equal textures shared: a scene that writes `pigment { Red }` in a million
// objects stores one texture, not a million (each is 432 bytes).
class TextureInterner {
public:
    std::shared_ptr<const Texture> intern(const std::shared_ptr<const Texture>& texture);

private:
    std::unordered_map<std::uint64_t, std::vector<std::shared_ptr<const Texture>>> byHash_;
    std::shared_ptr<const Texture> lastInput_;  // held, so its address cannot be reused
    std::shared_ptr<const Texture> lastInterned_;
};

class Interpreter {
public:
    Interpreter(const InterpreterOptions& options, Diagnostics& diagnostics);

    std::optional<SceneDescription> runFile(const std::filesystem::path& path);
    std::optional<SceneDescription> runText(std::string text, const std::string& fileName);

    // --- used across the implementation files ---
    SourceLoc locOf(const Node& n) const {
        return SourceLoc{file_->name, static_cast<int>(n.line), static_cast<int>(n.column)};
    }
    void report(Severity severity, const Node& at, std::string message, bool withSource = true);
    void error(const Node& at, std::string message) { report(Severity::Error, at, std::move(message)); }
    [[noreturn]] void fail(const Node& at, std::string message) {
        error(at, std::move(message));
        throw Abandon{};
    }
    const std::string& nameOf(const Node& n) const { return names_.name(n.id); }
    // How a message names a value's expression: 'Name', 'Name[…]', or "this value".
    std::string referenceText(const Node& n) const;

    // evaluate.cpp
    Value eval(const Node& n);
    Value call(const Node& n);
    Num binaryStep(const Node& n, const Num& acc);
    Num operand(Word op, const Node& n);
    int toInt(double v, const Node& at, const char* what);
    Num evalNum(const Node& n);
    double evalFloat(const Node& n);
    int evalInt(const Node& n, int min);
    bool evalBool(const Node& n);
    Vec3 evalVector(const Node& n);
    Color evalColour(const Node& n, ColourChannels channels = ColourChannels::Rgbft);
    Color toColour(const Num& value, const Node& at, ColourChannels channels = ColourChannels::Rgbft);
    Num evalColourNode(const Node& n, ColourChannels channels);
    Vec3 evalRgb(const Node& n, std::string_view usedAs);
    void evalReflection(const Node& block, Finish& f);
    double positiveExponent(const Node& n);
    std::shared_ptr<const Texture> withTopLayerItem(const Texture& base, const Node& n);
    std::string evalString(const Node& n);
    std::vector<std::filesystem::path> searchFolders() const;
    const Value* lookup(std::uint32_t id) const;
    Value evalMacroValue(const Node& call);
    bool isDefined(const Node& n);
    Value arrayElement(const Node& index);

    // functions.cpp
    // function(…) { … } compiled (parameters and body as the Function node's).
    Value makeFunction(const Node& fn);
    // A function of x, y, z from an expression (the function pattern's body).
    std::shared_ptr<const FunctionProgram> compileFunctionOfPoint(const Node& body);
    // F(…) where F is a function: its value, the arguments evaluated as floats.
    Num callFunction(const Node& call, const FunctionValue& f);

    // items.cpp
    void runTopEntry(const Node& n);
    ObjectTree evalObject(const Node& block);
    std::shared_ptr<const Pigment> evalPigment(const Node& block, const Pigment& start);
    std::shared_ptr<const Pigment> evalPigmentEntries(std::span<const Node> entries, const Pigment& start,
                                                      const Node& where);
    std::shared_ptr<const PigmentMap> evalPigmentMap(const Node& block, bool average);
    bool patternOfPigments(const Node& item, Pigment& p, const Color& first, const Color& second);
    std::shared_ptr<const Finish> evalFinish(const Node& block, const Finish& start);
    std::shared_ptr<const Interior> evalInterior(const Node& block, const Interior& start);
    std::shared_ptr<const MaterialValue> evalMaterial(const Node& block);
    std::shared_ptr<const ColourMapValue> evalColourMap(const Node& block);
    void applyMapModifier(const Node& n, Pigment& p);
    void setMapModifier(const Node& n, Pigment& p);
    void startMapPattern(const Node& n, Pigment& p);
    std::shared_ptr<const Normal> evalNormal(const Node& block, const std::optional<Normal>& start);
    int evalNoiseGenerator(const Node& n);
    std::shared_ptr<const Texture> evalTexture(const Node& block);
    CameraValue evalCamera(const Node& block);
    Value evalDeclarable(const Node& n);

    // interpreter.cpp
    // Runs the entries of a block; a #break among them (outside a loop, a
    // #switch or a macro) is an error.
    void runEntries(std::span<const Node> entries, EntryHandler handle);
    // Interpretation that nests (a block, a directive's body, an operand, an
    // include, a macro call) holds one of these: past kMaxNesting levels all
    // together, a located error ends the run.
    class Nested {
    public:
        Nested(Interpreter& self, const Node& at);
        ~Nested() { --self_.depth_; }
        Nested(const Nested&) = delete;
        Nested& operator=(const Nested&) = delete;

    private:
        Interpreter& self_;
    };

private:
    std::optional<SceneDescription> run(SourceFile& file);
    void runTopLevel(const Node& entry, EntryHandler handler);
    BreakNode runBody(std::span<const Node> entries, EntryHandler handle);
    BreakNode runDirective(const Node& n, EntryHandler handle);
    BreakNode runSequence(const Node& seq, EntryHandler handle);
    BreakNode runSwitch(const Node& n, EntryHandler handle);
    void runInclude(const Node& n, EntryHandler handle);
    void runDefault(const Node& n);
    void defineMacro(const Node& n);
    void invokeMacro(const Node& call, BodyContext context, EntryHandler handle);
    const Ast& macroBody(const MacroDef& macro, BodyContext context);
    void forwardSyntaxErrors(Diagnostics& syntax);
    std::vector<DiagnosticContext> context() const;
    void declare(const Node& target, Value value, bool local);
    Slot* resolve(Slot& slot);
    const Slot* findSlot(std::uint32_t id, std::size_t* scope) const;
    Slot& slotToAssign(std::uint32_t id, bool local);
    // A[i][j]: the array's name, and the subscripts (evaluated) outermost first.
    struct ElementRef {
        const Node* name = nullptr;
        std::array<const Node*, 5> subscripts{};
        std::array<double, 5> values{};
        std::size_t count = 0;
    };
    ElementRef elementRef(const Node& index);
    std::size_t elementOffset(const ArrayValue& array, const ElementRef& ref, const Node& at);
    void assignElement(const Node& index, Value value);
    void storeElement(ArrayValue& array, std::size_t offset, Value value, const Node& at);
    void fillArray(ArrayValue& array, const Node& initialiser, std::size_t dimension, std::size_t offset);
    Value makeArray(const Node& n);
    void applyDefines();
    bool truth(const Node& condition);
    void countIteration(const Node& at);
    std::optional<SceneDescription> finish();
    void applyVersionRules();

    // user_files.cpp
    std::filesystem::path writeFolder() const;
    std::filesystem::path findReadable(const std::string& name) const;
    std::shared_ptr<UserFile> handleOf(const Node& name, const char* directive);
    void dropHandle(const UserFile& file);
    std::string commitFile(UserFile& file);
    void runFopen(const Node& n);
    void runFclose(const Node& n);
    void runRead(const Node& n);
    void runWrite(const Node& n);
    void closeUserFiles();

    // items.cpp
    void placeObject(ObjectTree&& tree, const Node& at);
    // Moves every layer of `t` by `m` (a transform written at `at`).
    void moveLayers(const Node& at, Texture& t, const Transform& m);
    // The limits of InterpreterOptions: a request for `count` more objects
    // (leaves of `tree`s), or for `bytes` (estimated) on top of the objects
    // made so far, refused at `at` past its limit.
    void checkObjects(const Node& at, std::size_t count, const char* what);
    void checkMemory(const Node& at, std::size_t bytes, const char* what);
    // A CSG object (or an inverted union) as one Object per leaf.
    void placeCsg(ObjectTree& node, const std::shared_ptr<const Texture>& inherited, bool inheritedNoShadow,
                  const AsosOptions& inheritedAsos, const std::shared_ptr<const Interior>& inheritedInterior);
    // `placed`: the node stands alone in the scene (POV-Ray's Link_To_Frame),
    // not inside another object.
    void flatten(ObjectTree& node, const std::shared_ptr<const Texture>& inherited,
                 bool inheritedNoShadow, const AsosOptions& inheritedAsos,
                 const std::shared_ptr<const Interior>& inheritedInterior, bool placed);
    void applyObjectModifier(ObjectTree& tree, const Node& n, bool isShape);
    void applyClipOrBound(ObjectTree& tree, const Node& n);
    // Resolves node.bounds (object_bounds.hpp): dropped, or moved into its
    // clips, with a warning where POV-Ray's image may differ.
    // `placed`: the object stands alone in the scene, not inside another.
    void settleBounds(ObjectTree& node, bool placed);

    // meshes.cpp
    // A triangle or smooth_triangle block's face, its corners added to `mesh`.
    void addTriangle(TriangleMesh& mesh, const Node& block);
    // A mesh or mesh2 block (its faces and modifiers) into `t`.
    void evalMesh(const Node& block, ObjectTree& t);
    void evalMesh2(const Node& block, ObjectTree& t);
    // prism { … }: an ExtrusionShape, its spline's segments as Bezier pieces
    // (lang/prism.cpp).
    void evalPrism(const Node& block, ObjectTree& t);
    // text { ttf … }: a union of its glyphs, each an ExtrusionShape (lang/text.cpp).
    void evalText(const Node& block, ObjectTree& t);
    // `at`: the transform item, named when the result would not be finite.
    void applyTransform(ObjectTree& tree, const Transform& m, const Node& at);
    // compose(outer, inner), refused at `at` (the item that added `outer`)
    // when the product overflows.
    Transform composeAt(const Node& at, const Transform& outer, const Transform& inner);
    Light evalLight(const Node& block);
    void applyGlobalSettings(const Node& block);
    SkySphere evalSkySphere(const Node& block);
    Fog evalFog(const Node& block);
    // `forLight`: the block is a light's, where `emitter` belongs.
    AsosOptions evalAsos(const Node& block, AsosOptions start, bool forLight = false);
    Transform evalTransformItem(const Node& item);

    const InterpreterOptions& options_;
    Diagnostics& diagnostics_;
    std::size_t errorCount_ = 0;
    std::size_t iterations_ = 0;

    NameTable names_;
    // scopes_[0] is global; each #include and each macro call adds one for its
    // #local names. A name is looked up from the innermost scope out (POV-Ray's
    // scopes are dynamic: a macro sees its caller's locals).
    std::vector<Scope> scopes_;
    // POV-Ray's language version, in hundredths as it keeps it. `version`
    // reads 3.7 until a #version sets it; a scene without one is read as 3.62.
    int versionHundredths_ = 370;
    bool versionSet_ = false;
    bool statementRun_ = false;    // something ran before: a #version now is late
    bool assumedGammaSet_ = false;

    std::deque<SourceFile> files_;  // every file read, kept for error lines and macros
    std::unordered_map<std::string, SourceFile*> filesByPath_;  // included files, by canonical path
    std::unordered_map<std::string, std::shared_ptr<const TrueTypeFont>> fonts_;  // text's fonts, by path
    SourceFile* file_ = nullptr;    // the file being run
    const Ast* ast_ = nullptr;      // its tree (for string literals)

    // The includes and macro calls the run is inside, outermost first: the
    // context of every diagnostic, and the chain of includes.
    struct Frame {
        std::string what;  // "included from", "in macro Foo called at"
        SourceLoc at;
        std::filesystem::path include;  // the file an include entered; empty for a macro
    };
    std::vector<Frame> frames_;
    // Holds an include's or a macro call's frame, scope, file and tree while
    // its body runs, and puts back the caller's when it is left.
    class Entered {
    public:
        Entered(Interpreter& self, Frame frame, Scope scope);
        ~Entered();
        Entered(const Entered&) = delete;
        Entered& operator=(const Entered&) = delete;

    private:
        Interpreter& self_;
        SourceFile* file_;
        const Ast* ast_;
    };
    std::size_t depth_ = 0;  // nesting, for Nested
    // The tree nodes held by the unions being built, for checkMemory.
    std::size_t unionNodes_ = 0;
    // The bounded_by places already warned of (file, line, column).
    std::set<std::tuple<const std::string*, int, int>> warnedBounds_;
    class HeldNodes {
    public:
        HeldNodes(Interpreter& self, const ObjectTree& tree) : self_(self), tree_(tree) {}
        ~HeldNodes() { self_.unionNodes_ -= tree_.nodes - 1; }
        HeldNodes(const HeldNodes&) = delete;
        HeldNodes& operator=(const HeldNodes&) = delete;

    private:
        Interpreter& self_;
        const ObjectTree& tree_;
    };
    // The name a #declare or #local is giving a value to (a function may not
    // call it: POV-Ray's functions are not recursive); kNoName: none.
    static constexpr std::uint32_t kNoName = 0xffffffffu;
    std::uint32_t declaring_ = kNoName;
    // Names declared deprecated: the message their uses are warned with
    // (only the first, with once).
    struct Deprecation {
        std::string message;
        bool once = false;
        bool warned = false;
    };
    std::unordered_map<std::uint32_t, Deprecation> deprecations_;
    std::vector<std::uint32_t> randomStreams_;
    std::vector<std::shared_ptr<UserFile>> userFiles_;  // every file #fopen opened, in order  // seed(): POV-Ray's generators, by number

    SceneDescription scene_;
    ObjectStore objects_;
    TextureInterner textures_;
    std::shared_ptr<const Texture> defaultTexture_;
    bool cameraSeen_ = false;
};

// Transforms: compose without touching exact values when one side is the identity.
Transform compose(const Transform& outer, const Transform& inner);
// Every entry of the transform and of its inverse is a finite number.
bool isFinite(const Transform& t);
bool isFinite(const Vec3& v);

// A transform moves every layer's pattern (POV-Ray's Transform_Textures).

// `upper`'s layers, bottom first, over `t`'s.
inline void layerOver(Texture& t, const Texture& upper) {
    t.above.push_back(static_cast<const TextureLayer&>(upper));
    t.above.insert(t.above.end(), upper.above.begin(), upper.above.end());
}

inline TextureLayer& topLayer(Texture& t) { return t.above.empty() ? t : t.above.back(); }

}  // namespace asos::lang
