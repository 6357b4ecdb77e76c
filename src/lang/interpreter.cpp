// Files, scopes and directives. Entries of a block (or of a file) are run in
// order; a directive runs here and hands the entries of the branch it takes
// back to the same handler, so #if and #while work alike in every block.
#include <algorithm>
#include <cmath>
#include <fstream>

#include "asos/lang/parse.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

constexpr std::size_t kMaxIncludeDepth = 64;

std::optional<std::string> readFile(const std::filesystem::path& path) {
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

Interpreter::Interpreter(const InterpreterOptions& options, Diagnostics& diagnostics)
    : options_(options), diagnostics_(diagnostics) {
    scopes_.emplace_back();
    defaultTexture_ = std::make_shared<const Texture>();
}

void Interpreter::report(Severity severity, const Node& at, std::string message, bool withSource) {
    if (quiet_) return;
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

std::optional<SceneDescription> Interpreter::runFile(const std::filesystem::path& path) {
    std::error_code ec;
    auto text = std::filesystem::is_directory(path, ec) ? std::nullopt : readFile(path);
    if (!text) {
        Diagnostic d;
        d.loc.file = std::make_shared<const std::string>(path.string());
        d.message = "cannot read the scene file";
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
    includeStack_.push_back(f.path);
    auto top = [this](const Node& n) { runTopEntry(n); };
    const EntryHandler handler(top);
    try {
        applyDefines();
        // Each top-level entry runs as soon as it is parsed; its tree is then freed.
        const bool parsed = parseSceneEntries(f.text, f.name, names_, diagnostics_,
                                              [&](const Ast& ast, const Node& entry) {
                                                  ast_ = &ast;
                                                  runEntries(std::span<const Node>(&entry, 1), handler);
                                              });
        if (!parsed) ++errorCount_;
    } catch (const Stop&) {
    }
    return finish();
}

void Interpreter::applyDefines() {
    for (const Define& define : options_.defines) {
        // A value that parses and evaluates as an expression is one; anything
        // else is a string, as with POV-Ray's Declare=NAME=VALUE.
        Value value = define.value;
        Diagnostics ignored;
        const auto file = std::make_shared<const std::string>("-D " + define.name);
        if (auto expr = parseExpression(define.value, file, names_, ignored)) {
            const Ast* saved = ast_;
            ast_ = &*expr;
            quiet_ = true;
            try {
                value = eval(expr->root);
            } catch (const Abandon&) {
            }
            quiet_ = false;
            ast_ = saved;
        }
        scopes_[0][names_.intern(define.name)] = std::move(value);
    }
}

std::optional<SceneDescription> Interpreter::finish() {
    if (errorCount_ > 0) return std::nullopt;
    applyVersionRules();
    scene_.objects = objects_.take();
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

void Interpreter::runEntries(std::span<const Node> entries, EntryHandler handle) {
    for (const Node& n : entries) {
        if (n.kind != NodeKind::Version) statementRun_ = true;
        try {
            switch (n.kind) {
            case NodeKind::If: case NodeKind::While: case NodeKind::For: case NodeKind::Declare:
            case NodeKind::Local: case NodeKind::Undef: case NodeKind::Include:
            case NodeKind::Version: case NodeKind::Debug: case NodeKind::Warning:
            case NodeKind::Error:
                runDirective(n, handle);
                break;
            default:
                handle(n);
            }
        } catch (const Abandon&) {
            // Reported; go on with the next entry so that every error is found.
        }
    }
}

void Interpreter::runSequence(const Node& seq, EntryHandler handle) {
    runEntries(seq.children(), handle);
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

void Interpreter::declare(const Node& nameNode, Value value, bool local) {
    auto& scope = local ? scopes_.back() : scopes_.front();
    scope[nameNode.id] = std::move(value);
}

void Interpreter::runDirective(const Node& n, EntryHandler handle) {
    switch (n.kind) {
    case NodeKind::If: {
        const auto parts = n.children();
        const std::size_t pairs = parts.size() / 2;
        for (std::size_t i = 0; i < pairs; ++i) {
            if (truth(parts[2 * i])) {
                runSequence(parts[2 * i + 1], handle);
                return;
            }
        }
        if (n.flags) runSequence(parts.back(), handle);
        return;
    }
    case NodeKind::While: {
        while (truth(n[0])) {
            countIteration(n);
            runSequence(n[1], handle);
        }
        return;
    }
    case NodeKind::For: {
        // POV-Ray re-reads the variable each time round: the body may change it.
        const Node& var = n[0];
        const double end = evalFloat(n[2]);
        const double step = n.flags ? evalFloat(n[3]) : 1.0;
        if (step == 0.0) fail(n[3], "the step of #for is zero: the loop would never end");
        declare(var, Num::scalar(evalFloat(n[1])), true);
        const Node& body = n.children().back();
        while (true) {
            const Value* v = lookup(var.id);
            if (!v || !std::holds_alternative<Num>(*v) || !std::get<Num>(*v).isFloat())
                fail(var, "the #for variable '" + nameOf(var) + "' is no longer a float");
            const double i = std::get<Num>(*v).v[0];
            if (step > 0 ? i > end : i < end) break;
            countIteration(n);
            runSequence(body, handle);
            const Value* after = lookup(var.id);
            if (!after || !std::holds_alternative<Num>(*after) || !std::get<Num>(*after).isFloat())
                fail(var, "the #for variable '" + nameOf(var) + "' is no longer a float");
            declare(var, Num::scalar(std::get<Num>(*after).v[0] + step), true);
        }
        return;
    }
    case NodeKind::Declare:
    case NodeKind::Local: {
        Value value = Poison{};
        try {
            value = evalDeclarable(n[1]);
        } catch (const Abandon&) {
            // Declared anyway, as poison, so that its uses do not each report
            // "not declared" after the real error.
        }
        declare(n[0], std::move(value), n.kind == NodeKind::Local);
        return;
    }
    case NodeKind::Undef: {
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
            if (scope->erase(n[0].id)) return;
        report(Severity::Warning, n[0], "#undef of '" + nameOf(n[0]) + "', which is not declared");
        return;
    }
    case NodeKind::Include:
        runInclude(n, handle);
        return;
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
        return;
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
        return;
    }
    default:
        handle(n);
    }
}

void Interpreter::runInclude(const Node& n, EntryHandler handle) {
    const std::string name = evalString(n[0]);
    // A file that cannot be included is fatal: what follows depends on it.
    auto fatal = [&](const Node& at, std::string message) {
        error(at, std::move(message));
        throw Stop{};
    };
    if (includeStack_.size() > kMaxIncludeDepth)
        fatal(n, "#include nested more than " + std::to_string(kMaxIncludeDepth) + " deep");

    // Beside the including file first, then each -L folder in order.
    std::vector<std::filesystem::path> candidates;
    const std::filesystem::path asked(name);
    if (asked.is_absolute()) {
        candidates.push_back(asked);
    } else {
        candidates.push_back(file_->path.parent_path() / asked);
        for (const auto& dir : options_.includePaths) candidates.push_back(dir / asked);
    }
    std::filesystem::path found;
    std::error_code ec;
    for (const auto& c : candidates) {
        if (std::filesystem::is_regular_file(c, ec)) {
            found = std::filesystem::weakly_canonical(c, ec);
            if (ec) found = c;
            break;
        }
    }
    if (found.empty()) {
        std::string where;
        for (const auto& c : candidates) where += (where.empty() ? "" : ", ") + c.parent_path().string();
        fatal(n[0], "cannot find include file '" + name + "' (looked in " + where + ")");
    }
    if (std::find(includeStack_.begin(), includeStack_.end(), found) != includeStack_.end()) {
        std::string chain;
        for (const auto& p : includeStack_) chain += p.filename().string() + " -> ";
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

    SourceFile* const savedFile = file_;
    const Ast* const savedAst = ast_;
    file_ = &f;
    includeStack_.push_back(found);
    scopes_.emplace_back();
    struct Restore {
        Interpreter& self;
        SourceFile* file;
        const Ast* ast;
        ~Restore() {
            self.scopes_.pop_back();
            self.includeStack_.pop_back();
            self.file_ = file;
            self.ast_ = ast;
        }
    } restore{*this, savedFile, savedAst};
    const bool parsed = parseSceneEntries(f.text, f.name, names_, diagnostics_,
                                          [&](const Ast& ast, const Node& entry) {
                                              ast_ = &ast;
                                              runEntries(std::span<const Node>(&entry, 1), handle);
                                          });
    if (!parsed) {
        ++errorCount_;
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
