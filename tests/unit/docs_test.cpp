// The docs as code: every ```pov snippet of docs/*.md and docs/manual/ is
// read by the interpreter, every scene of examples/ opens with a comment
// that names the command rendering it and renders at 64 x 48 without an
// error, the manual's keyword index lists exactly the words the language
// accepts, and every link of the manual (pictures included) leads somewhere. The rule that wraps a snippet is docs/goldens.md's
// ("Snippets in the docs"): the fence's word after `pov` says what it is.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "asos/lang/interpreter.hpp"
#include "asos/lang/words.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

const fs::path kSource = ASOS_SOURCE_DIR;

struct Snippet {
    std::string where;  // docs/manual/objects.md:144, the fence's line
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
    // What the snippets write (#fopen … write) goes to a temporary folder.
    const fs::path writes = fs::temp_directory_path() / ("asos-docs-writes-" + std::to_string(getpid()));
    fs::create_directories(writes);
    for (const Snippet& s : snippets) {
        INFO(s.where << " (```pov " << s.kind << "):\n" << s.text);
        const bool known = s.kind.empty() || s.kind == "in-object" || s.kind == "colours" || s.kind == "refused";
        CHECK(known);
        if (!known) continue;
        for (const std::string& scene : scenesOf(s)) {
            Diagnostics diagnostics;
            lang::InterpreterOptions options;
            options.libraryPaths = lang::povrayLibraryPaths();
            options.writeFolder = writes;
            const bool read = lang::interpretText(scene, s.where, options, diagnostics).has_value();
            INFO(errorsOf(diagnostics));
            if (s.kind == "refused") CHECK_FALSE(read);  // it shows an error on purpose
            else CHECK(read);
        }
    }
    fs::remove_all(writes);
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

namespace {

std::string fileText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// GitHub's anchor of a heading: lower case, punctuation dropped but for `-`
// and `_`, spaces made `-`.
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '-' || c == '_') anchor += static_cast<char>(std::tolower(u));
        else if (c == ' ') anchor += '-';
    }
    return anchor;
}

std::set<std::string> anchorsOf(const fs::path& file) {
    std::set<std::string> anchors;
    std::istringstream lines(fileText(file));
    std::string line;
    bool fenced = false;
    while (std::getline(lines, line)) {
        if (line.starts_with("```")) fenced = !fenced;
        if (fenced || !line.starts_with("#")) continue;
        const std::size_t text = line.find_first_not_of('#');
        if (text != std::string::npos && line[text] == ' ') anchors.insert(anchorOf(line.substr(text + 1)));
    }
    return anchors;
}

}  // namespace

TEST_CASE("the manual's keyword index lists every word the language accepts, and no other", "[docs]") {
    // Accepted words are the word table's identifiers (operators aside).
    std::set<std::string> accepted;
    for (int w = 1; w < static_cast<int>(lang::Word::Count); ++w) {
        const std::string_view text = lang::wordText(static_cast<lang::Word>(w));
        if (std::isalpha(static_cast<unsigned char>(text.front())) || text.front() == '_') accepted.emplace(text);
    }
    REQUIRE(accepted.size() > 200);
    // The index's rows: "| `word` |" or "| `#word` |".
    std::set<std::string> indexed;
    const std::regex row(R"(^\| `#?([a-z_0-9]+)` \|)");
    std::istringstream lines(fileText(kSource / "docs/manual/keywords.md"));
    std::string line;
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_search(line, m, row)) indexed.insert(m[1]);
    for (const std::string& w : accepted) {
        INFO("accepted by the language, missing from docs/manual/keywords.md: " << w);
        CHECK(indexed.count(w) == 1);
    }
    for (const std::string& w : indexed) {
        INFO("in docs/manual/keywords.md, not accepted by the language: " << w);
        CHECK(accepted.count(w) == 1);
    }
}

TEST_CASE("every link of the manual leads to a file, and to a heading there", "[docs]") {
    std::vector<fs::path> pages;
    for (const auto& e : fs::recursive_directory_iterator(kSource / "docs" / "manual"))
        if (e.path().extension() == ".md") pages.push_back(e.path());
    pages.push_back(kSource / "README.md");
    const std::regex link(R"(\]\(([^)#\s]*)(#[^)\s]*)?\))");
    int pictures = 0;
    for (const fs::path& page : pages) {
        const std::string text = fileText(page);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1];
            const std::string anchor = (*it)[2].matched ? std::string((*it)[2]).substr(1) : "";
            if (target.find("://") != std::string::npos) continue;
            const fs::path file = target.empty() ? page : page.parent_path() / target;
            INFO(fs::relative(page, kSource).string() << ": link to " << target << (anchor.empty() ? "" : "#" + anchor));
            CHECK(fs::exists(file));
            if (file.extension() == ".png") ++pictures;
            if (!anchor.empty() && fs::exists(file) && file.extension() == ".md") CHECK(anchorsOf(file).count(anchor) == 1);
        }
    }
    CHECK(pictures >= 20);
}
