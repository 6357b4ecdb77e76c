// The docs as code: every ```pov snippet of docs/*.md and docs/manual/ is
// read by the interpreter, and every scene of examples/ opens with a comment
// that names the command rendering it and renders at 64 x 48 without an
// error. The rule that wraps a snippet is docs/goldens.md's
// ("Snippets in the docs"): the fence's word after `pov` says what it is.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "asos/lang/interpreter.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

const fs::path kSource = ASOS_SOURCE_DIR;

struct Snippet {
    std::string where;  // docs/language.md:144, the fence's line
    std::string kind;   // the fence's word after `pov`: "", "in-object", "colours", "refused"
    std::string text;
};

std::vector<fs::path> markdownFiles() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(kSource / "docs"))
        if (e.path().extension() == ".md") files.push_back(e.path());
    if (fs::exists(kSource / "docs" / "manual"))
        for (const auto& e : fs::recursive_directory_iterator(kSource / "docs" / "manual"))
            if (e.path().extension() == ".md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<Snippet> snippetsOf(const fs::path& file) {
    std::vector<Snippet> snippets;
    std::ifstream in(file);
    std::string line;
    int number = 0;
    Snippet* open = nullptr;
    while (std::getline(in, line)) {
        ++number;
        if (open) {
            if (line.starts_with("```")) open = nullptr;
            else open->text += line + '\n';
        } else if (line.starts_with("```pov")) {
            std::string kind = line.substr(6);
            kind.erase(0, kind.find_first_not_of(' '));
            snippets.push_back({fs::relative(file, kSource).string() + ":" + std::to_string(number), kind, {}});
            open = &snippets.back();
        }
    }
    return snippets;
}

// "…" stands for what a snippet leaves out: it is left out.
std::string withoutEllipses(const std::string& text) {
    static constexpr std::string_view kEllipsis = "…";
    std::string out;
    for (std::size_t from = 0;;) {
        const std::size_t at = text.find(kEllipsis, from);
        out.append(text, from, at == std::string::npos ? std::string::npos : at - from);
        if (at == std::string::npos) return out;
        out += ' ';
        from = at + kEllipsis.size();
    }
}

// The scene texts a snippet is read as; the prelude goes on the snippet's
// first line, so that an error's line is the snippet's.
std::vector<std::string> scenesOf(const Snippet& s) {
    const std::string prelude = "#include \"" + (kSource / "tests/golden/docs/prelude.inc").string() + "\" ";
    const std::string text = withoutEllipses(s.text);
    if (s.kind == "in-object") return {prelude + "sphere { 0, 1 " + text + "}\n"};
    if (s.kind == "colours") {
        std::vector<std::string> scenes;
        std::istringstream lines(text);
        std::string line;
        while (std::getline(lines, line))
            if (line.find_first_not_of(' ') != std::string::npos) scenes.push_back(prelude + "#declare C = " + line + ";\n");
        return scenes;
    }
    return {prelude + text};
}

std::string errorsOf(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.all())
        if (d.severity == Severity::Error) out += formatDiagnostic(d);
    return out;
}

}  // namespace

TEST_CASE("every pov snippet of the docs is read as the fence says", "[docs]") {
    std::vector<Snippet> snippets;
    for (const fs::path& file : markdownFiles()) {
        std::vector<Snippet> more = snippetsOf(file);
        snippets.insert(snippets.end(), more.begin(), more.end());
    }
    REQUIRE(snippets.size() >= 20);
    for (const Snippet& s : snippets) {
        INFO(s.where << " (```pov " << s.kind << "):\n" << s.text);
        const bool known = s.kind.empty() || s.kind == "in-object" || s.kind == "colours" || s.kind == "refused";
        CHECK(known);
        if (!known) continue;
        for (const std::string& scene : scenesOf(s)) {
            Diagnostics diagnostics;
            lang::InterpreterOptions options;
            options.libraryPaths = lang::povrayLibraryPaths();
            const bool read = lang::interpretText(scene, s.where, options, diagnostics).has_value();
            INFO(errorsOf(diagnostics));
            if (s.kind == "refused") CHECK_FALSE(read);  // it shows an error on purpose
            else CHECK(read);
        }
    }
}

TEST_CASE("every example renders at 64 x 48 without an error", "[docs][examples]") {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::recursive_directory_iterator(kSource / "examples"))
        if (e.path().extension() == ".pov") scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    REQUIRE(scenes.size() >= 10);
    const fs::path dir = asos::test::testCaseDir("docs", "examples");
    for (const fs::path& scene : scenes) {
        const std::string name = fs::relative(scene, kSource / "examples").string();
        std::string png = name;
        std::replace(png.begin(), png.end(), '/', '_');
        png.replace(png.size() - 4, 4, ".png");
        const asos::test::ProgramResult r =
            asos::test::runAsos(dir, {"render", scene.string(), "-o", png, "-W", "64", "-H", "48", "--quiet"});
        INFO(name << ":\n" << r.err);
        // It opens with a comment saying what it shows and the command that renders it.
        std::ifstream in(scene);
        std::string opening, line;
        while (std::getline(in, line) && line.starts_with("//")) opening += line + '\n';
        CHECK(opening.find("asos render ") != std::string::npos);
        CHECK(r.exitCode == 0);
        CHECK(r.err.find(": error:") == std::string::npos);
        CHECK(fs::exists(dir / png));
    }
}
