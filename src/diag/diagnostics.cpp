#include "asos/diag/diagnostics.hpp"

#include <algorithm>

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

// Echoed source lines longer than this are cut to a window around the caret:
// a scene written on one 50 MB line must not echo 50 MB per error.
constexpr std::size_t kEchoWidth = 200;

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The part of `line` echoed, "…" marking what is cut, and the caret line.
std::string echoSource(const std::string& line, int column) {
    const std::size_t caret = column > 0 ? std::min<std::size_t>(std::size_t(column) - 1, line.size()) : 0;
    std::size_t start = 0, end = line.size();
    if (line.size() > kEchoWidth) {
        start = caret > kEchoWidth / 2 ? caret - kEchoWidth / 2 : 0;
        end = std::min(line.size(), start + kEchoWidth);
        start = end - kEchoWidth;
        // Whole UTF-8 characters only.
        while (start > 0 && start < line.size() && isContinuationByte(line[start])) --start;
        while (end < line.size() && isContinuationByte(line[end])) ++end;
    }
    std::string out;
    if (start > 0) out += "\u2026";
    out.append(line, start, end - start);
    if (end < line.size()) out += "\u2026";
    out += '\n';
    if (start > 0) out += ' ';
    // Keep tabs in the caret line so the caret lines up under the source.
    for (std::size_t i = start; i < caret && i < end; ++i) out += line[i] == '\t' ? '\t' : ' ';
    out += "^\n";
    return out;
}

// A message quotes words of the scene ("'…' is not declared"); a word longer
// than kEchoWidth keeps its first and last kEchoWidth / 2 bytes around "…",
// so a 50 MB identifier is not echoed in the message either.
std::string clipMessage(const std::string& message) {
    std::string out;
    std::size_t i = 0;
    while (i < message.size()) {
        const std::size_t wordEnd = std::min(message.find_first_of(" \n\t", i), message.size());
        if (wordEnd - i <= kEchoWidth) {
            out.append(message, i, wordEnd - i);
        } else {
            std::size_t headEnd = i + kEchoWidth / 2, tailStart = wordEnd - kEchoWidth / 2;
            while (headEnd > i && isContinuationByte(message[headEnd])) --headEnd;
            while (tailStart < wordEnd && isContinuationByte(message[tailStart])) ++tailStart;
            out.append(message, i, headEnd - i);
            out += "\u2026";
            out.append(message, tailStart, wordEnd - tailStart);
        }
        if (wordEnd < message.size()) out += message[wordEnd];
        i = wordEnd + 1;
    }
    return out;
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
    out += d.message.size() > kEchoWidth ? clipMessage(d.message) : d.message;
    out += '\n';
    if (!d.sourceLine.empty()) out += echoSource(d.sourceLine, d.loc.column);
    for (const DiagnosticContext& c : d.context) {
        out += "  ";
        out += c.what;
        if (c.loc.file) out += ' ' + formatLocation(c.loc);
        out += '\n';
    }
    return out;
}

}  // namespace asos
