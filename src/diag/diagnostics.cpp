#include "asos/diag/diagnostics.hpp"

namespace asos {

namespace {
const char* severityName(Severity s) {
    switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    case Severity::Debug: return "debug";
    }
    return "error";
}
}  // namespace

std::string formatLocation(const SourceLoc& loc) {
    std::string out = loc.fileName();
    if (loc.line > 0) {
        out += ':' + std::to_string(loc.line);
        if (loc.column > 0) out += ':' + std::to_string(loc.column);
    }
    return out;
}

std::string formatDiagnostic(const Diagnostic& d) {
    std::string out;
    if (d.loc.file) out += formatLocation(d.loc) + ": ";
    out += severityName(d.severity);
    out += ": ";
    out += d.message;
    out += '\n';
    if (!d.sourceLine.empty()) {
        out += d.sourceLine;
        out += '\n';
        // Keep tabs in the caret line so the caret lines up under the source.
        for (int i = 1; i < d.loc.column && i - 1 < static_cast<int>(d.sourceLine.size()); ++i)
            out += d.sourceLine[i - 1] == '\t' ? '\t' : ' ';
        out += "^\n";
    }
    for (const DiagnosticContext& c : d.context) {
        out += "  ";
        out += c.what;
        if (c.loc.file) out += ' ' + formatLocation(c.loc);
        out += '\n';
    }
    return out;
}

}  // namespace asos
