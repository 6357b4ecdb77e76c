// Files, scopes and directives. Entries of a block (or of a file) are run in
// order; a directive runs here and hands the entries of the branch it takes
// back to the same handler, so #if and #while work alike in every block.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <new>

#include "asos/lang/parse.hpp"
#include "asos/lang/source_kind.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

constexpr std::size_t kMaxIncludeDepth = 64;
// A diagnostic's context shows this many innermost and outermost steps of a
// longer chain (a runaway recursion has hundreds).
constexpr std::size_t kContextEnds = 5;

// Why `path` cannot be read as a source file, empty when it can.
std::string unreadableReason(const std::filesystem::path& path) {
    const SourceCheck c = checkSource(path);
    switch (c.kind) {
    case SourceKind::Regular: return {};
    case SourceKind::Unreachable: return std::strerror(c.error);
    case SourceKind::Folder: return "it is a folder";
    case SourceKind::Fifo: return "it is a FIFO, not a regular file";
    case SourceKind::Device: return "it is a device, not a regular file";
    case SourceKind::Other: break;
    }
    return "it is not a regular file";
}

std::optional<std::string> readFile(const std::filesystem::path& path) {
    if (!unreadableReason(path).empty()) return std::nullopt;
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const std::streamoff size = in.tellg();
    if (size < 0) return std::nullopt;
    std::string text(static_cast<std::size_t>(size), '\0');
    in.seekg(0);
    if (!in.read(text.data(), size)) return std::nullopt;
    return text;
}

}  // namespace

Transform compose(const Transform& outer, const Transform& inner) {
    // Multiplying by an identity would turn -0 into 0 and is wasted work.
    if (inner.isIdentity()) return outer;
    if (outer.isIdentity()) return inner;
    return outer * inner;
}

bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFinite(const Transform& t) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(t.matrix()[c][r]) || !std::isfinite(t.inverseMatrix()[c][r])) return false;
    return true;
}

Transform Interpreter::composeAt(const Node& at, const Transform& outer, const Transform& inner) {
    Transform t = compose(outer, inner);
    if (!isFinite(t))
        fail(at, "this transform and those before it overflow together: the result is not a finite number");
    return t;
}

Interpreter::Interpreter(const InterpreterOptions& options, Diagnostics& diagnostics)
    : options_(options), diagnostics_(diagnostics) {
    scopes_.emplace_back();
    defaultTexture_ = std::make_shared<const Texture>();
}

Interpreter::Entered::Entered(Interpreter& self, Frame frame, Scope scope)
    : self_(self), file_(self.file_), ast_(self.ast_) {
    self_.frames_.push_back(std::move(frame));
    self_.scopes_.push_back(std::move(scope));
}

Interpreter::Entered::~Entered() {
    self_.scopes_.pop_back();
    self_.frames_.pop_back();
    self_.file_ = file_;
    self_.ast_ = ast_;
}

Interpreter::Nested::Nested(Interpreter& self, const Node& at) : self_(self) {
    if (++self_.depth_ <= kMaxNesting) return;
    self_.error(at, "nested too deep: parentheses, operators, blocks, directives, includes and macro calls "
                    "together go over " + std::to_string(kMaxNesting) + " levels");
    --self_.depth_;
    throw Stop{};
}

std::vector<DiagnosticContext> Interpreter::context() const {
    std::vector<DiagnosticContext> steps;
    const std::size_t n = frames_.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Frame& f = frames_[n - 1 - k];  // innermost first
        if (n > 2 * kContextEnds + 1 && k == kContextEnds) {
            steps.push_back({"... " + std::to_string(n - 2 * kContextEnds) + " more ...", SourceLoc{}});
            k = n - kContextEnds - 1;
            continue;
        }
        steps.push_back({f.what, f.at});
    }
    return steps;
}

void Interpreter::report(Severity severity, const Node& at, std::string message, bool withSource) {
    Diagnostic d;
    d.severity = severity;
    d.loc = locOf(at);
    d.message = std::move(message);
    if (withSource && file_) {
        SourceFile& f = *file_;
        if (f.lineStarts.empty()) {
            f.lineStarts.push_back(0);
            for (std::size_t i = 0; i < f.text.size(); ++i)
                if (f.text[i] == '\n') f.lineStarts.push_back(static_cast<std::uint32_t>(i + 1));
        }
        if (at.line >= 1 && at.line <= f.lineStarts.size()) {
            const std::size_t start = f.lineStarts[at.line - 1];
            std::size_t end = f.text.find('\n', start);
            if (end == std::string::npos) end = f.text.size();
            if (end > start && f.text[end - 1] == '\r') --end;
            d.sourceLine = f.text.substr(start, end - start);
        }
    }
    if (severity != Severity::Debug) d.context = context();
    diagnostics_.report(std::move(d));
    if (severity == Severity::Error && ++errorCount_ >= options_.maxErrors) {
        Diagnostic stop;
        stop.severity = Severity::Note;
        stop.loc = locOf(at);
        stop.message = "too many errors (" + std::to_string(errorCount_) + "), stopping here";
        diagnostics_.report(std::move(stop));
        throw Stop{};
    }
}

// Syntax errors of an include or a macro's body, found by a parse of their
// own: reported with the context of the run.
void Interpreter::forwardSyntaxErrors(Diagnostics& syntax) {
    for (Diagnostic d : syntax.all()) {
        d.context = context();
        diagnostics_.report(std::move(d));
        ++errorCount_;
    }
}

std::optional<SceneDescription> Interpreter::runFile(const std::filesystem::path& path) {
    std::error_code ec;
    auto text = readFile(path);
    if (!text) {
        Diagnostic d;
        d.loc.file = std::make_shared<const std::string>(path.string());
        const std::string why = unreadableReason(path);
        d.message = "cannot read the scene file" + (why.empty() ? std::string() : ": " + why);
        diagnostics_.report(std::move(d));
        return std::nullopt;
    }
    const auto canonical = std::filesystem::weakly_canonical(path, ec);
    SourceFile& f = files_.emplace_back();
    f.name = std::make_shared<const std::string>(path.string());
    f.text = std::move(*text);
    f.path = ec ? std::filesystem::absolute(path) : canonical;
    return run(f);
}

std::optional<SceneDescription> Interpreter::runText(std::string text, const std::string& fileName) {
    SourceFile& f = files_.emplace_back();
    f.name = std::make_shared<const std::string>(fileName);
    f.text = std::move(text);
    f.path = std::filesystem::absolute(fileName.empty() ? std::filesystem::path("scene.pov")
                                                        : std::filesystem::path(fileName));
    return run(f);
}

std::optional<SceneDescription> Interpreter::run(SourceFile& f) {
    file_ = &f;
    objects_.reserve(static_cast<std::size_t>(std::count(f.text.begin(), f.text.end(), '{')));
    auto top = [this](const Node& n) { runTopEntry(n); };
    const EntryHandler handler(top);
    try {
        applyDefines();
        // Each top-level entry runs as soon as it is parsed; its tree is then freed.
        const bool parsed = parseSceneEntries(f.text, f.name, names_, diagnostics_,
                                              [&](const Ast& ast, const Node& entry) {
                                                  ast_ = &ast;
                                                  runTopLevel(entry, handler);
                                              });
        if (!parsed) ++errorCount_;
    } catch (const Stop&) {
    }
    return finish();
}

// What the limits (InterpreterOptions) did not foresee: memory runs out
// while this statement runs. The run stops with an error at it rather than an
// uncaught std::bad_alloc.
void Interpreter::runTopLevel(const Node& entry, EntryHandler handler) {
    try {
        runEntries(std::span<const Node>(&entry, 1), handler);
    } catch (const std::bad_alloc&) {
        error(entry, "out of memory while running this statement: it asks for more than this machine has "
                     "(lower what it makes, or --max-memory to stop it sooner)");
        throw Stop{};
    }
}

void Interpreter::applyDefines() {
    // A value is an expression (a number, a vector, a quoted string), as
    // POV-Ray's Declare=NAME=VALUE: one that does not parse or evaluate is an
    // error located in the value (file "-D NAME"), and the scene is not run.
    SourceFile* const scene = file_;
    for (const Define& define : options_.defines) {
        SourceFile& f = files_.emplace_back();
        f.name = std::make_shared<const std::string>("-D " + define.name);
        f.text = define.value;
        f.path = scene->path;
        file_ = &f;
        Diagnostics syntax;
        auto expr = parseExpression(define.value, f.name, names_, syntax);
        if (!expr) {
            forwardSyntaxErrors(syntax);
            continue;
        }
        const Ast* saved = ast_;
        ast_ = &*expr;
        try {
            scopes_[0][names_.intern(define.name)] = Slot{eval(expr->root)};
        } catch (const Abandon&) {
        }
        ast_ = saved;
    }
    file_ = scene;
    if (errorCount_ > 0) throw Stop{};
}

std::optional<SceneDescription> Interpreter::finish() {
    closeUserFiles();
    if (errorCount_ > 0) return std::nullopt;
    applyVersionRules();
    scene_.objects = objects_.take();
    // A pigment that names no noise generator uses the scene's, which
    // global_settings may set anywhere in the file.
    if (scene_.globals.noiseGenerator != GlobalSettings{}.noiseGenerator) {
        std::map<const Texture*, std::shared_ptr<const Texture>> moved;
        auto usesScenes = [](const Pigment& pigment) {
            return pigment.noiseGenerator == 0 && pigment.kind != Pigment::Kind::Solid &&
                   pigment.kind != Pigment::Kind::Checker && pigment.kind != Pigment::Kind::Brick;
        };
        // A normal's noise: dents' and its map pattern's.
        auto normalUsesScenes = [&](const TextureLayer& layer) {
            return layer.normal && (layer.normal->kind == Normal::Kind::Dents
                                        ? layer.normal->pattern.noiseGenerator == 0
                                        : usesScenes(layer.normal->pattern));
        };
        auto layerUsesScenes = [&](const TextureLayer& layer) {
            return usesScenes(layer.pigment) || normalUsesScenes(layer);
        };
        auto setScenes = [&](TextureLayer& layer) {
            if (usesScenes(layer.pigment)) layer.pigment.noiseGenerator = scene_.globals.noiseGenerator;
            if (normalUsesScenes(layer)) layer.normal->pattern.noiseGenerator = scene_.globals.noiseGenerator;
        };
        for (Object& o : scene_.objects) {
            const Texture& texture = *o.texture;
            bool any = layerUsesScenes(texture);
            for (const TextureLayer& layer : texture.above) any = any || layerUsesScenes(layer);
            if (!any) continue;
            auto& copy = moved[o.texture.get()];
            if (!copy) {
                auto t = std::make_shared<Texture>(texture);
                setScenes(*t);
                for (TextureLayer& layer : t->above) setScenes(layer);
                copy = std::move(t);
            }
            o.texture = copy;
        }
    }
    return std::move(scene_);
}

// POV-Ray 3.7's rules once the scene is read (its Parser::Run): the version
// the scene ends with decides, and one without #version is read as 3.62.
// Without assumed_gamma a scene older than 3.7 has gamma correction off and a
// 3.7 scene gets assumed_gamma 1.0; POV-Ray warns of both, and of a scene
// without #version.
void Interpreter::applyVersionRules() {
    const int version = versionSet_ ? versionHundredths_ : 362;
    scene_.version = version / 100.0;
    const SourceLoc scene{files_.front().name, 0, 0};
    const std::string versionText =
        versionSet_ ? "#version " + formatNumber(scene_.version) : "no #version, read as 3.62";
    if (!assumedGammaSet_ && version < 370) {
        scene_.globals.assumedGamma = std::nullopt;
        diagnostics_.warning(scene, "assumed_gamma not specified, so gamma correction is turned off for "
                                    "this scene older than POV-Ray 3.7 (" + versionText +
                                    "), as POV-Ray does: its colours go to the image file as they are; "
                                    "set assumed_gamma in global_settings to turn it on");
    } else if (!assumedGammaSet_) {
        scene_.globals.assumedGamma = 1.0;
        diagnostics_.warning(scene, "assumed_gamma not specified in this POV-Ray 3.7 scene: it is 1.0, "
                                    "as in POV-Ray, which may make this an error in future versions; "
                                    "write 'assumed_gamma 1.0' in global_settings");
    }
    if (version < 350)
        diagnostics_.warning(scene, "the scene ends with #version " + formatNumber(scene_.version) +
                                        ": like POV-Ray 3.7, asos does not reproduce the defects of "
                                        "POV-Ray 3.1 and earlier");
    if (!versionSet_)
        diagnostics_.warning(scene, "this scene has no #version directive: like POV-Ray 3.7, asos reads it "
                                    "as a scene older than 3.7; start it with '#version 3.7;'");
}

// --- entries and directives -----------------------------------------------------------

BreakNode Interpreter::runBody(std::span<const Node> entries, EntryHandler handle) {
    if (entries.empty()) return nullptr;
    const Nested nested(*this, entries.front());
    for (const Node& n : entries) {
        if (n.kind != NodeKind::Version) statementRun_ = true;
        try {
            switch (n.kind) {
            case NodeKind::If: case NodeKind::While: case NodeKind::For: case NodeKind::Switch:
            case NodeKind::Declare: case NodeKind::Local: case NodeKind::Undef: case NodeKind::Include:
            case NodeKind::Macro: case NodeKind::Default: case NodeKind::Version: case NodeKind::Debug:
            case NodeKind::Warning: case NodeKind::Error: case NodeKind::Fopen: case NodeKind::Fclose:
            case NodeKind::Read: case NodeKind::Write:
                if (const BreakNode b = runDirective(n, handle)) return b;
                break;
            case NodeKind::Break:
                return &n;
            case NodeKind::MacroCall:
                invokeMacro(n, static_cast<BodyContext>(n.flags), handle);
                break;
            default:
                handle(n);
            }
        } catch (const Abandon&) {
            // Reported; go on with the next entry so that every error is found.
        }
    }
    return nullptr;
}

void Interpreter::runEntries(std::span<const Node> entries, EntryHandler handle) {
    if (const BreakNode b = runBody(entries, handle))
        error(*b, "#break outside a #switch, a #while, a #for or a macro");
}

BreakNode Interpreter::runSequence(const Node& seq, EntryHandler handle) {
    return runBody(seq.children(), handle);
}

// Where a relative file name is looked for, in order, each folder once:
// beside the current file, beside the scene, in each -L folder, then in
// POV-Ray's library folders.
std::vector<std::filesystem::path> Interpreter::searchFolders() const {
    std::vector<std::filesystem::path> folders;
    auto add = [&](const std::filesystem::path& dir) {
        if (std::find(folders.begin(), folders.end(), dir) == folders.end()) folders.push_back(dir);
    };
    add(file_->path.parent_path());
    add(files_.front().path.parent_path());
    for (const auto& dir : options_.includePaths) add(dir);
    for (const auto& dir : options_.libraryPaths) add(dir);
    return folders;
}

bool Interpreter::truth(const Node& condition) {
    return std::abs(evalFloat(condition)) > kPovEpsilon;
}

void Interpreter::countIteration(const Node& at) {
    if (++iterations_ > options_.maxLoopIterations) {
        error(at, "more than " + std::to_string(options_.maxLoopIterations) +
                      " loop iterations: is this loop endless?");
        throw Stop{};
    }
}

BreakNode Interpreter::runDirective(const Node& n, EntryHandler handle) {
    switch (n.kind) {
    case NodeKind::If: {
        const auto parts = n.children();
        const std::size_t pairs = parts.size() / 2;
        for (std::size_t i = 0; i < pairs; ++i) {
            if (truth(parts[2 * i])) return runSequence(parts[2 * i + 1], handle);
        }
        if (n.flags) return runSequence(parts.back(), handle);
        return nullptr;
    }
    case NodeKind::While: {
        while (truth(n[0])) {
            countIteration(n);
            if (runSequence(n[1], handle)) break;
        }
        return nullptr;
    }
    case NodeKind::For: {
        // POV-Ray re-reads the variable each time round (the body may change
        // it), and compares with its epsilon: #for (I, 0, 0.3, 0.1) runs 4 times.
        const Node& var = n[0];
        const double end = evalFloat(n[2]);
        const double step = n.flags ? evalFloat(n[3]) : 1.0;
        if (step == 0.0) fail(n[3], "the step of #for is zero: the loop would never end");
        slotToAssign(var.id, true).value = Num::scalar(evalFloat(n[1]));
        const Node& body = n.children().back();
        auto current = [&] {
            const Value* v = lookup(var.id);
            if (!v || !std::holds_alternative<Num>(*v) || !std::get<Num>(*v).isFloat())
                fail(var, "the #for variable '" + nameOf(var) + "' is no longer a float");
            return std::get<Num>(*v).v[0];
        };
        while (true) {
            const double i = current();
            if (step > 0 ? i > end + kPovEpsilon : i < end - kPovEpsilon) break;
            countIteration(n);
            if (runSequence(body, handle)) break;
            slotToAssign(var.id, true).value = Num::scalar(current() + step);
        }
        return nullptr;
    }
    case NodeKind::Switch:
        return runSwitch(n, handle);
    case NodeKind::Declare:
    case NodeKind::Local: {
        // A deprecated declaration's deprecation comes first.
        const bool deprecated = (n.flags & 2) != 0;
        const Node& target = n[deprecated ? 1 : 0];
        const Node& declared = n[deprecated ? 2 : 1];
        Value value = Poison{};
        const std::uint32_t outerDeclaring = declaring_;
        declaring_ = target.kind == NodeKind::Name ? target.id : kNoName;
        try {
            value = evalDeclarable(declared);
            declaring_ = outerDeclaring;
            if ((n.flags & 1) && std::holds_alternative<Num>(value))
                fail(declared, "expected ';' after the declared value: POV-Ray wants one after a float, a vector "
                               "or a colour, and this is " + describe(value));
        } catch (const Abandon&) {
            declaring_ = outerDeclaring;
            // Declared anyway, as poison, so that its uses do not each report
            // "not declared" after the real error.
            if (target.kind != NodeKind::Name) throw;
        }
        declare(target, std::move(value), n.kind == NodeKind::Local);
        if (target.kind == NodeKind::Name) {
            if (deprecated)
                deprecations_[target.id] = {evalString(n[0][0]), (n[0].flags & 1) != 0, false};
            else if (!deprecations_.empty())
                deprecations_.erase(target.id);
        }
        return nullptr;
    }
    case NodeKind::Undef: {
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
            if (scope->erase(n[0].id)) return nullptr;
        report(Severity::Warning, n[0], "#undef of '" + nameOf(n[0]) + "', which is not declared");
        return nullptr;
    }
    case NodeKind::Include:
        runInclude(n, handle);
        return nullptr;
    case NodeKind::Macro:
        defineMacro(n);
        return nullptr;
    case NodeKind::Default:
        runDefault(n);
        return nullptr;
    case NodeKind::Fopen:
        runFopen(n);
        return nullptr;
    case NodeKind::Fclose:
        runFclose(n);
        return nullptr;
    case NodeKind::Read:
        runRead(n);
        return nullptr;
    case NodeKind::Write:
        runWrite(n);
        return nullptr;
    case NodeKind::Version: {
        // POV-Ray 3.7 expects #version first; one after anything else (an
        // #include that holds it included) is late, and it says so.
        const bool late = !versionSet_ && statementRun_;
        statementRun_ = true;
        const double v = evalFloat(n[0]);
        // POV-Ray keeps the version in hundredths, rounded: 3.704 is 3.7.
        const double hundredths = std::floor(v * 100.0 + 0.5);
        if (hundredths > 370)
            fail(n[0], "#version " + formatNumber(v) + " is newer than POV-Ray 3.7, which asos follows");
        if (v < 1.0) fail(n[0], "#version " + formatNumber(v) + " is not a POV-Ray version");
        versionHundredths_ = static_cast<int>(hundredths);
        versionSet_ = true;
        if (late)
            report(Severity::Warning, n,
                   "other statements come before the first #version: POV-Ray 3.7 expects #version "
                   "as the first statement of a scene");
        return nullptr;
    }
    case NodeKind::Debug:
    case NodeKind::Warning:
    case NodeKind::Error: {
        std::string message = evalString(n[0]);
        while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
        if (n.kind == NodeKind::Debug) {
            report(Severity::Debug, n, std::move(message), false);
        } else if (n.kind == NodeKind::Warning) {
            report(Severity::Warning, n, std::move(message), false);
        } else {
            report(Severity::Error, n, "#error: " + message);
            throw Stop{};
        }
        return nullptr;
    }
    default:
        handle(n);
        return nullptr;
    }
}

// As POV-Ray: the first #case (|V - A| < epsilon) or #range (Lo <= V <= Hi)
// that holds starts the run, which goes on through the following clauses and
// the #else until a #break; with none holding, the #else runs.
BreakNode Interpreter::runSwitch(const Node& n, EntryHandler handle) {
    const double value = evalFloat(n[0]);
    const auto parts = n.children();
    const std::size_t clauses = parts.size() - 1 - (n.flags ? 1 : 0);
    bool running = false;
    for (std::size_t i = 1; i <= clauses; ++i) {
        const Node& clause = parts[i];
        if (!running) {
            if (clause.kind == NodeKind::Case)
                running = std::abs(value - evalFloat(clause[0])) < kPovEpsilon;
            else
                running = value >= evalFloat(clause[0]) && value <= evalFloat(clause[1]);
        }
        if (running && runSequence(clause.children().back(), handle)) return nullptr;
    }
    if (n.flags) runSequence(parts.back(), handle);
    return nullptr;
}

// #default { texture {…} pigment {…} normal {…} finish {…} }: what later
// textures, pigments, normals and finishes start from, and the texture of
// objects without one.
void Interpreter::runDefault(const Node& n) {
    auto entry = [&](const Node& e) {
        switch (e.word) {
        case Word::Texture:
            defaultTexture_ = evalTexture(e);
            break;
        case Word::Pigment: case Word::Normal: case Word::Finish:
            defaultTexture_ = withTopLayerItem(*defaultTexture_, e);
            break;
        default:
            fail(e, "#default takes texture, pigment, normal and finish");
        }
    };
    runEntries(n.children(), EntryHandler(entry));
}

// --- names and scopes ---------------------------------------------------------------------

Slot* Interpreter::resolve(Slot& slot) {
    if (slot.refScope < 0) return &slot;
    auto& scope = scopes_[static_cast<std::size_t>(slot.refScope)];
    auto it = scope.find(slot.refId);
    return it == scope.end() ? nullptr : &it->second;
}

// The innermost entry of `id` (a parameter's own entry, not what it stands for).
const Slot* Interpreter::findSlot(std::uint32_t id, std::size_t* scope) const {
    for (std::size_t i = scopes_.size(); i-- > 0;) {
        if (auto it = scopes_[i].find(id); it != scopes_[i].end()) {
            if (scope) *scope = i;
            return &it->second;
        }
    }
    return nullptr;
}

// Where `#declare` (local: `#local`) puts a value, as POV-Ray: `#declare` into
// the innermost entry of the name, wherever it is (global when there is none);
// `#local` into the current scope's. A parameter that stands for an entry
// passes the value on to it.
Slot& Interpreter::slotToAssign(std::uint32_t id, bool local) {
    Slot* slot = nullptr;
    if (local) {
        auto it = scopes_.back().find(id);
        if (it != scopes_.back().end()) slot = &it->second;
    } else {
        std::size_t scope = 0;
        slot = const_cast<Slot*>(findSlot(id, &scope));
    }
    if (!slot) return (local ? scopes_.back() : scopes_.front())[id];
    if (slot->refScope >= 0) {
        Slot& own = *slot;
        if (Slot* target = resolve(own)) return *target;
        own = Slot{};  // what it stood for is gone (#undef): it is a name of its own again
    }
    return *slot;
}

void Interpreter::declare(const Node& target, Value value, bool local) {
    if (target.kind == NodeKind::Name) {
        slotToAssign(target.id, local).value = std::move(value);
        return;
    }
    assignElement(target, std::move(value));  // #local or #declare: the array wherever it is
}

// --- includes ----------------------------------------------------------------------------

void Interpreter::runInclude(const Node& n, EntryHandler handle) {
    const std::string name = evalString(n[0]);
    // A file that cannot be included is fatal: what follows depends on it.
    auto fatal = [&](const Node& at, std::string message) {
        error(at, std::move(message));
        throw Stop{};
    };
    // The files being included, the scene first.
    std::vector<std::filesystem::path> includes{files_.front().path};
    for (const Frame& frame : frames_)
        if (!frame.include.empty()) includes.push_back(frame.include);
    if (includes.size() > kMaxIncludeDepth)
        fatal(n, "#include nested more than " + std::to_string(kMaxIncludeDepth) + " deep");

    // Beside the including file, beside the scene, in each -L folder, then in
    // POV-Ray's library folders.
    const std::filesystem::path asked(name);
    std::vector<std::filesystem::path> folders;
    if (!asked.is_absolute()) folders = searchFolders();
    std::filesystem::path found;
    std::filesystem::path notAFile;  // the first match that is a folder or a device (/dev/zero)
    std::error_code ec;
    auto tryPath = [&](const std::filesystem::path& candidate) {
        if (!std::filesystem::is_regular_file(candidate, ec)) {
            if (notAFile.empty() && std::filesystem::exists(candidate, ec)) notAFile = candidate;
            return false;
        }
        found = std::filesystem::weakly_canonical(candidate, ec);
        if (ec) found = candidate;
        return true;
    };
    if (asked.is_absolute()) {
        tryPath(asked);
    } else {
        for (const auto& dir : folders)
            if (tryPath(dir / asked)) break;
    }
    if (found.empty() && !notAFile.empty())
        fatal(n[0], "cannot include '" + name + "': " + notAFile.lexically_normal().string() + " is " +
                        (checkSource(notAFile).kind == SourceKind::Folder ? "a folder" : "not a regular file"));
    if (found.empty()) {
        std::string where;
        for (const auto& dir : folders) where += (where.empty() ? "" : ", ") + dir.string();
        fatal(n[0], "cannot find include file '" + name + "'" + (where.empty() ? "" : " (looked in " + where + ")"));
    }
    if (std::find(includes.begin(), includes.end(), found) != includes.end()) {
        std::string chain;
        for (const auto& p : includes) chain += p.filename().string() + " -> ";
        fatal(n, "#include cycle: " + chain + found.filename().string());
    }
    // A file included again (say, in a loop) is read once.
    SourceFile*& cached = filesByPath_[found.string()];
    if (!cached) {
        auto text = readFile(found);
        if (!text) fatal(n[0], "cannot read include file '" + found.string() + "'");
        SourceFile& added = files_.emplace_back();
        added.name = std::make_shared<const std::string>(found.string());
        added.text = std::move(*text);
        added.path = found;
        cached = &added;
    }
    SourceFile& f = *cached;

    const Nested nested(*this, n);
    const Entered entered(*this, Frame{"included from", locOf(n), found}, Scope{});
    file_ = &f;
    Diagnostics syntax;
    const bool parsed = parseSceneEntries(
        f.text, f.name, names_, syntax,
        [&](const Ast& ast, const Node& entry) {
            ast_ = &ast;
            runEntries(std::span<const Node>(&entry, 1), handle);
        },
        depth_);
    if (!parsed) {
        forwardSyntaxErrors(syntax);
        throw Stop{};  // a syntax error: what follows cannot be trusted
    }
}

// --- entry points ---------------------------------------------------------------------

std::optional<SceneDescription> interpretFile(const std::filesystem::path& scene,
                                              const InterpreterOptions& options,
                                              Diagnostics& diagnostics) {
    Interpreter interpreter(options, diagnostics);
    return interpreter.runFile(scene);
}

std::optional<SceneDescription> interpretText(std::string text, const std::string& fileName,
                                              const InterpreterOptions& options,
                                              Diagnostics& diagnostics) {
    Interpreter interpreter(options, diagnostics);
    return interpreter.runText(std::move(text), fileName);
}

}  // namespace asos::lang
