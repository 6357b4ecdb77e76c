// POV-Ray's file directives: #fopen, #fclose, #read, #write, and file_exists().
//
// A file opened for reading is read whole when it is opened and its values
// are taken from the text as #read asks for them. A file opened for writing
// (or appending) is written whole when it is closed (#fclose, or the end of a
// parse without errors) through a StagedFile, so a parse that stops with an
// error leaves no half-written file, and the file keeps its old contents.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "asos/util/staged_file.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

const char* modeName(UserFile::Mode mode) {
    switch (mode) {
    case UserFile::Mode::Read: return "reading";
    case UserFile::Mode::Write: return "writing";
    case UserFile::Mode::Append: return "appending";
    }
    return "";
}

// POV-Ray writes numbers with C's "%g".
std::string formatG(double v) {
    char buffer[64];
    const int n = std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer, static_cast<std::size_t>(n));
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

// Where a file the scene reads (or asks file_exists about) is found: in the
// folder written files go to, then where #include looks. Empty: not found.
std::filesystem::path Interpreter::findReadable(const std::string& name) const {
    const std::filesystem::path asked(name);
    std::error_code ec;
    auto regular = [&](const std::filesystem::path& p) { return std::filesystem::is_regular_file(p, ec); };
    if (asked.is_absolute()) return regular(asked) ? asked : std::filesystem::path();
    if (regular(writeFolder() / asked)) return writeFolder() / asked;
    for (const auto& dir : searchFolders())
        if (regular(dir / asked)) return dir / asked;
    return {};
}

std::filesystem::path Interpreter::writeFolder() const {
    return options_.writeFolder.empty() ? std::filesystem::path(".") : options_.writeFolder;
}

// The file handle `name` names; an error when it names none.
std::shared_ptr<UserFile> Interpreter::handleOf(const Node& name, const char* directive) {
    const Value* v = lookup(name.id);
    if (!v)
        fail(name, quote(nameOf(name)) + " is not declared: no file is open under that name (a file read to its "
                                        "end is closed, and its handle undeclared, as in POV-Ray)");
    const auto* file = std::get_if<std::shared_ptr<UserFile>>(v);
    if (!file) fail(name, std::string(directive) + " needs a file handle; " + quote(nameOf(name)) + " is " + describe(*v));
    return *file;
}

// The handle is undeclared (POV-Ray's: #fclose, or a file read to its end).
void Interpreter::dropHandle(const UserFile& file) {
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
        for (auto it = scope->begin(); it != scope->end(); ++it) {
            const auto* held = std::get_if<std::shared_ptr<UserFile>>(&it->second.value);
            if (held && held->get() == &file) {
                scope->erase(it);
                return;
            }
        }
    }
}

// Puts a written file in place. Returns why it could not be, empty when it was.
std::string Interpreter::commitFile(UserFile& file) {
    if (!file.open) return {};
    file.open = false;
    if (file.mode == UserFile::Mode::Read) return {};
    std::string bytes;
    if (file.mode == UserFile::Mode::Append) {
        std::error_code ec;
        if (std::filesystem::exists(file.path, ec)) {
            std::ifstream in(file.path, std::ios::binary);
            std::ostringstream old;
            old << in.rdbuf();
            if (!in && !in.eof()) return "it cannot be read to append to it";
            bytes = old.str();
        }
    }
    bytes += file.written;
    file.written.clear();
    file.written.shrink_to_fit();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    StagedResult staged = StagedFile::fromBytes(file.path, std::span<const unsigned char>(data, bytes.size()));
    if (!staged.file) return staged.error;
    return staged.file->commit();
}

void Interpreter::runFopen(const Node& n) {
    const Node& handle = n[0];
    if (const Value* v = lookup(handle.id))
        fail(handle, "#fopen needs a name not in use, as in POV-Ray; " + quote(nameOf(handle)) + " is " +
                         describe(*v) + (std::holds_alternative<std::shared_ptr<UserFile>>(*v)
                                             ? " still open (#fclose it first)"
                                             : ""));
    auto file = std::make_shared<UserFile>();
    file->name = evalString(n[1]);
    file->mode = n.word == Word::Read ? UserFile::Mode::Read
                 : n.word == Word::Write ? UserFile::Mode::Write
                                         : UserFile::Mode::Append;
    if (file->name.empty()) fail(n[1], "#fopen: the file's name is empty");
    if (file->mode == UserFile::Mode::Read) {
        file->path = findReadable(file->name);
        if (file->path.empty()) {
            std::string where = writeFolder().string();
            for (const auto& dir : searchFolders()) where += ", " + dir.string();
            fail(n[1], "cannot find the file '" + file->name + "' to read (looked in " + where + ")");
        }
        std::ifstream in(file->path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in && !in.eof()) fail(n[1], "cannot read the file '" + file->path.string() + "'");
        checkMemory(n, text.str().size(), "the file read");
        SourceFile& source = files_.emplace_back();
        source.name = std::make_shared<const std::string>(file->path.lexically_normal().string());
        source.text = text.str();
        source.path = file->path;
        file->source = &source;
    } else {
        const std::filesystem::path asked(file->name);
        file->path = asked.is_absolute() ? asked : writeFolder() / asked;
        const std::string why = checkWritable(file->path);
        if (!why.empty()) fail(n[1], "cannot open '" + file->name + "' for " + modeName(file->mode) + ": " + why);
    }
    file->openedAt = locOf(n);
    userFiles_.push_back(file);
    slotToAssign(handle.id, false).value = std::move(file);
}

void Interpreter::runFclose(const Node& n) {
    const Value* v = lookup(n[0].id);
    if (!v) return;  // POV-Ray: a handle already closed (a file read to its end) is no error
    const auto* file = std::get_if<std::shared_ptr<UserFile>>(v);
    if (!file) {
        report(Severity::Warning, n[0],
               "#fclose of " + quote(nameOf(n[0])) + ", which is " + describe(*v) + ", not a file handle: nothing is closed");
        return;
    }
    const std::shared_ptr<UserFile> held = *file;
    dropHandle(*held);
    const std::string why = commitFile(*held);
    if (!why.empty()) fail(n, "cannot write the file '" + held->name + "': " + why);
}

// POV-Ray's data: floats, vectors of 2 to 5 floats in < >, and strings in
// double quotes, with commas between them; white space and comments between.
void Interpreter::runRead(const Node& n) {
    const auto parts = n.children();
    const std::shared_ptr<UserFile> file = handleOf(parts[0], "#read");
    if (file->mode != UserFile::Mode::Read)
        fail(parts[0], "cannot read from '" + file->name + "': it is open for " + modeName(file->mode));
    const std::string& text = file->source->text;
    std::size_t& p = file->position;

    // A data error: at its place in the file, in the context of the #read.
    auto dataError = [&](std::size_t at, const std::string& message) {
        if (at == text.size() && at > 0 && text[at - 1] == '\n') --at;  // the end of the last line
        std::size_t lineStart = text.rfind('\n', at == 0 ? 0 : at - 1);
        lineStart = lineStart == std::string::npos || at == 0 ? 0 : lineStart + 1;
        std::size_t lineEnd = text.find('\n', lineStart);
        if (lineEnd == std::string::npos) lineEnd = text.size();
        if (lineEnd > lineStart && text[lineEnd - 1] == '\r') --lineEnd;
        Diagnostic d;
        d.loc = SourceLoc{file->source->name,
                          static_cast<int>(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(lineStart), '\n')),
                          static_cast<int>(at - lineStart + 1)};
        d.message = message;
        d.sourceLine = text.substr(lineStart, lineEnd - lineStart);
        d.context = context();
        d.context.insert(d.context.begin(), DiagnosticContext{"read by #read at", locOf(n)});
        diagnostics_.report(std::move(d));
        if (++errorCount_ >= options_.maxErrors) throw Stop{};
        throw Abandon{};
    };
    auto skipBlanks = [&] {
        while (p < text.size()) {
            const char c = text[p];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
                ++p;
            } else if (c == '/' && p + 1 < text.size() && text[p + 1] == '/') {
                while (p < text.size() && text[p] != '\n') ++p;
            } else if (c == '/' && p + 1 < text.size() && text[p + 1] == '*') {
                const std::size_t end = text.find("*/", p + 2);
                if (end == std::string::npos) dataError(p, "unterminated comment: no '*/' closes this '/*'");
                p = end + 2;
            } else {
                return;
            }
        }
    };
    auto readNumber = [&](const char* what) {
        skipBlanks();
        const std::size_t start = p;
        bool negative = false;
        if (p < text.size() && (text[p] == '-' || text[p] == '+')) negative = text[p++] == '-';
        const std::size_t digits = p;
        while (p < text.size() && (isDigit(text[p]) || text[p] == '.')) ++p;
        if (p == digits || (p == digits + 1 && text[digits] == '.')) {
            p = start;
            dataError(start, std::string("expected ") + what);
        }
        if (p < text.size() && (text[p] == 'e' || text[p] == 'E')) {
            std::size_t q = p + 1;
            if (q < text.size() && (text[q] == '+' || text[q] == '-')) ++q;
            if (q < text.size() && isDigit(text[q])) {
                p = q;
                while (p < text.size() && isDigit(text[p])) ++p;
            }
        }
        double v = 0.0;
        const auto r = std::from_chars(text.data() + digits, text.data() + p, v);
        if (r.ec == std::errc::result_out_of_range)
            dataError(start, "the number '" + text.substr(start, p - start) + "' is out of range");
        if (r.ec != std::errc() || r.ptr != text.data() + p)
            dataError(start, "'" + text.substr(start, p - start) + "' is not a number");
        if (p < text.size() && (std::isalnum(static_cast<unsigned char>(text[p])) || text[p] == '_' || text[p] == '.'))
            dataError(start, "'" + text.substr(start, p - start + 1) + "…' is not a number");
        return negative ? -v : v;
    };
    auto readValue = [&]() -> Value {
        const std::size_t start = p;
        const char c = text[p];
        if (c == '"') {
            std::size_t q = p + 1;
            while (q < text.size() && text[q] != '"' && text[q] != '\n') q += text[q] == '\\' && q + 1 < text.size() && text[q + 1] != '\n' ? 2 : 1;
            if (q >= text.size() || text[q] != '"') dataError(start, "unterminated string: expected '\"' before the end of the line");
            std::string s = decodeStringBody(std::string_view(text).substr(p + 1, q - p - 1));
            p = q + 1;
            return s;
        }
        if (c == '<') {
            ++p;
            Num v;
            v.dim = 0;
            while (true) {
                if (v.dim == 5) dataError(start, "a vector has at most 5 components");
                const double component = readNumber("a vector component");
                v.v[v.dim++] = component;
                skipBlanks();
                if (p < text.size() && text[p] == ',') {
                    ++p;
                    continue;
                }
                if (p < text.size() && text[p] == '>') {
                    ++p;
                    break;
                }
                dataError(p, p >= text.size() ? "expected ',' or '>' to close the vector, found the end of the file"
                                              : "expected ',' or '>' to close the vector");
            }
            if (v.dim < 2) dataError(start, "a vector has at least 2 components");
            return v;
        }
        if (c == '-' || c == '+' || c == '.' || isDigit(c)) return Num::scalar(readNumber("a number"));
        std::size_t end = p;
        while (end < text.size() && end - p < 20 && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
        dataError(start, "expected a float, a vector or a string in double quotes, found '" +
                             (end > p ? text.substr(p, end - p) : text.substr(p, 1)) + "'");
        return Poison{};  // not reached: dataError throws
    };

    for (std::size_t i = 1; i < parts.size(); ++i) {
        skipBlanks();
        if (p >= text.size()) {
            // Read to its end: closed, its handle undeclared; the names left
            // keep what they had (POV-Ray's).
            dropHandle(*file);
            file->open = false;
            return;
        }
        Value value = readValue();
        slotToAssign(parts[i].id, false).value = std::move(value);
        skipBlanks();
        if (p >= text.size()) {
            dropHandle(*file);
            file->open = false;
            return;
        }
        if (text[p] != ',') dataError(p, "expected ',' after the value read");
        ++p;
    }
}

void Interpreter::runWrite(const Node& n) {
    const auto parts = n.children();
    const std::shared_ptr<UserFile> file = handleOf(parts[0], "#write");
    if (file->mode == UserFile::Mode::Read)
        fail(parts[0], "cannot write to '" + file->name + "': it is open for reading");
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const Value v = eval(parts[i]);
        std::string text;
        if (const auto* s = std::get_if<std::string>(&v)) {
            text = *s;
        } else if (const auto* num = std::get_if<Num>(&v); num && !num->colour) {
            // POV-Ray: a float as %g, a vector as <%g,…> and a space.
            if (num->dim == 1) {
                text = formatG(num->v[0]);
            } else {
                text = "<";
                for (std::size_t k = 0; k < num->dim; ++k) {
                    if (k > 0) text += ',';
                    text += formatG(num->v[k]);
                }
                text += "> ";
            }
        } else {
            fail(parts[i], "#write writes strings, floats and vectors, as POV-Ray; this is " + describe(v));
        }
        checkMemory(parts[i], file->written.size() + text.size(), "the file written");
        file->written += text;
    }
}

// The end of the parse: what is still open is closed, written files put in
// place; after an error they are left unwritten.
void Interpreter::closeUserFiles() {
    for (const auto& file : userFiles_) {
        if (!file->open) continue;
        if (errorCount_ > 0) {
            file->open = false;
            continue;
        }
        const std::string why = commitFile(*file);
        if (why.empty()) continue;
        ++errorCount_;
        diagnostics_.error(file->openedAt, "cannot write the file '" + file->name + "', opened here and closed at "
                                               "the end of the scene: " + why);
    }
    userFiles_.clear();
}

}  // namespace asos::lang
