#pragma once
// The interpreter's inside, shared by interpreter.cpp (files, scopes,
// directives), evaluate.cpp (expressions) and items.cpp (scene items).
#include <array>
#include <deque>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "asos/diag/format_number.hpp"
#include "asos/lang/ast.hpp"
#include "asos/lang/interpreter.hpp"
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

// An object while the scene runs: a shape, a light, or a union of those. Kept
// as a tree until it is placed in the scene, because POV-Ray resolves a
// union's texture for its untextured children only then.
struct ObjectTree {
    enum class Kind : std::uint8_t { Shape, Light, Union };
    Kind kind = Kind::Shape;
    Shape shape;
    Transform worldFromObject;
    std::shared_ptr<const Light> light;      // Kind::Light (shared: changed by copying)
    std::shared_ptr<const Texture> texture;  // its own; null: inherited or the default
    bool noShadow = false;
    bool modified = false;  // a union has had a modifier: no more children
    AsosOptions asos;
    std::vector<ObjectTree> children;
    SourceLoc loc;
};

struct CameraValue {
    Camera camera;
    Vec3 sky{0.0, 1.0, 0.0};
};

struct Poison {};  // the value of a declaration whose right side failed (already reported)

using Value = std::variant<Num, std::string, std::shared_ptr<const ObjectTree>,
                           std::shared_ptr<const Pigment>, std::shared_ptr<const Finish>,
                           std::shared_ptr<const Texture>, std::shared_ptr<const CameraValue>, Poison>;

// 'word', for messages.
inline std::string quote(std::string_view word) {
    std::string s;
    s.reserve(word.size() + 2);
    s += '\'';
    s += word;
    s += '\'';
    return s;
}

// "a float", "a vector", "a string", … for messages.
std::string describe(const Value& v);
std::string describe(const Num& n);

// What a colour carries where it is used, as POV-Ray's Parse_Colour reads
// it: all five components for a pigment's or the background's colour; red,
// green and blue only for a light's, ambient, reflection and ambient_light,
// where a float is a grey (`color 1.5` is rgb 1.5).
enum class ColourChannels : std::uint8_t { Rgbft, Rgb };

// The current statement is dropped; its error has been reported.
struct Abandon {};
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
    struct SourceFile {
        std::shared_ptr<const std::string> name;
        std::string text;
        std::filesystem::path path;  // canonical when it came from disk; empty for text
        std::vector<std::uint32_t> lineStarts;  // built on the first error
    };

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

    // evaluate.cpp
    Value eval(const Node& n);
    Num evalNum(const Node& n);
    double evalFloat(const Node& n);
    int evalInt(const Node& n, int min);
    bool evalBool(const Node& n);
    Vec3 evalVector(const Node& n);
    Color evalColour(const Node& n, ColourChannels channels = ColourChannels::Rgbft);
    Color toColour(const Num& value, const Node& at, ColourChannels channels = ColourChannels::Rgbft);
    Num evalColourNode(const Node& n, ColourChannels channels);
    Vec3 evalRgb(const Node& n, std::string_view usedAs);
    Color checkOpaque(const Color& c, const Node& at);
    std::string evalString(const Node& n);
    const Value* lookup(std::uint32_t id) const;

    // items.cpp
    void runTopEntry(const Node& n);
    ObjectTree evalObject(const Node& block);
    std::shared_ptr<const Pigment> evalPigment(const Node& block, const Pigment& start);
    std::shared_ptr<const Finish> evalFinish(const Node& block, const Finish& start);
    std::shared_ptr<const Texture> evalTexture(const Node& block);
    CameraValue evalCamera(const Node& block);
    Value evalDeclarable(const Node& n);

    // interpreter.cpp
    void runEntries(std::span<const Node> entries, EntryHandler handle);

private:
    std::optional<SceneDescription> run(SourceFile& file);
    void runDirective(const Node& n, EntryHandler handle);
    void runSequence(const Node& seq, EntryHandler handle);
    void runInclude(const Node& n, EntryHandler handle);
    void declare(const Node& nameNode, Value value, bool local);
    void applyDefines();
    bool truth(const Node& condition);
    void countIteration(const Node& at);
    std::optional<SceneDescription> finish();
    void applyVersionRules();

    // items.cpp
    void placeObject(ObjectTree&& tree);
    void flatten(ObjectTree& node, const std::shared_ptr<const Texture>& inherited,
                 bool inheritedNoShadow, const AsosOptions& inheritedAsos);
    void applyObjectModifier(ObjectTree& tree, const Node& n, bool isShape);
    void applyTransform(ObjectTree& tree, const Transform& m);
    Light evalLight(const Node& block);
    void applyGlobalSettings(const Node& block);
    AsosOptions evalAsos(const Node& block, AsosOptions start);
    Transform evalTransformItem(const Node& item);

    const InterpreterOptions& options_;
    Diagnostics& diagnostics_;
    std::size_t errorCount_ = 0;
    bool quiet_ = false;  // evaluating a -D value: failures mean "a string", not errors
    std::size_t iterations_ = 0;

    NameTable names_;
    // scopes_[0] is global; each #include adds one for its #local names.
    std::vector<std::unordered_map<std::uint32_t, Value>> scopes_;
    // POV-Ray's language version, in hundredths as it keeps it. `version`
    // reads 3.7 until a #version sets it; a scene without one is read as 3.62.
    int versionHundredths_ = 370;
    bool versionSet_ = false;
    bool statementRun_ = false;    // something ran before: a #version now is late
    bool assumedGammaSet_ = false;

    std::deque<SourceFile> files_;  // every file read, kept for error lines
    std::unordered_map<std::string, SourceFile*> filesByPath_;  // included files, by canonical path
    SourceFile* file_ = nullptr;    // the file being run
    const Ast* ast_ = nullptr;      // its tree (for string literals)
    std::vector<std::filesystem::path> includeStack_;

    SceneDescription scene_;
    ObjectStore objects_;
    TextureInterner textures_;
    std::shared_ptr<const Texture> defaultTexture_;
    bool cameraSeen_ = false;
};

// Transforms: compose without touching exact values when one side is the identity.
Transform compose(const Transform& outer, const Transform& inner);

}  // namespace asos::lang
