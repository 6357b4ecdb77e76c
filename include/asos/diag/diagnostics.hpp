#pragma once
// Diagnostics: library code reports here and never prints. The command line
// decides how to show them and which exit code follows.
#include <string>
#include <vector>

#include "asos/diag/source_loc.hpp"

namespace asos {

enum class Severity { Error, Warning, Note, Debug };

// One step of the way to where a diagnostic was found, innermost first:
// "in macro Foo called at" or "included from", and where; a step without a
// location stands for steps left out of a long chain.
struct DiagnosticContext {
    std::string what;
    SourceLoc loc;
};

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;
    std::string sourceLine;  // the text of loc.line, for the caret display; may be empty
    std::vector<DiagnosticContext> context;
};

class Diagnostics {
public:
    void report(Diagnostic d) { all_.push_back(std::move(d)); }
    void error(SourceLoc loc, std::string message, std::string sourceLine = {}) {
        report({Severity::Error, std::move(loc), std::move(message), std::move(sourceLine), {}});
    }
    void warning(SourceLoc loc, std::string message, std::string sourceLine = {}) {
        report({Severity::Warning, std::move(loc), std::move(message), std::move(sourceLine), {}});
    }
    bool hasErrors() const {
        for (const auto& d : all_)
            if (d.severity == Severity::Error) return true;
        return false;
    }
    const std::vector<Diagnostic>& all() const { return all_; }
    void clear() { all_.clear(); }

private:
    std::vector<Diagnostic> all_;
};

// "file:line:col: error: message\n<source line>\n<spaces>^\n", then a line
// per step of its context: "  in macro Foo called at file:line:col\n". A
// source line over 200 bytes is cut to 200 around the caret, "…" at each cut.
std::string formatDiagnostic(const Diagnostic& d);

// "file:line:col" (as much of it as is known).
std::string formatLocation(const SourceLoc& loc);

}  // namespace asos
