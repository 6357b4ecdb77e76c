#include "asos/testing/povray_text.hpp"

#include <cctype>
#include <cstddef>

namespace asos {

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of the comment or string that starts at `i`, or `i` when none does.
std::size_t pastCommentOrString(const std::string& t, std::size_t i) {
    const std::size_t n = t.size();
    if (t.compare(i, 2, "//") == 0) {
        while (i < n && t[i] != '\n') ++i;
        return i;
    }
    if (t.compare(i, 2, "/*") == 0) {
        int depth = 0;
        while (i < n) {
            if (t.compare(i, 2, "/*") == 0) {
                ++depth;
                i += 2;
            } else if (t.compare(i, 2, "*/") == 0) {
                i += 2;
                if (--depth == 0) return i;
            } else {
                ++i;
            }
        }
        return n;
    }
    if (t[i] == '"') {
        for (++i; i < n && t[i] != '"'; ++i)
            if (t[i] == '\\' && i + 1 < n) ++i;
        return i < n ? i + 1 : n;
    }
    return i;
}

}  // namespace

std::string withoutAsosBlocks(const std::string& text) {
    std::string out = text;
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        if (const std::size_t past = pastCommentOrString(text, i); past != i) {
            i = past;
            continue;
        }
        const bool keyword = text.compare(i, 4, "asos") == 0 && (i == 0 || !identifierChar(text[i - 1])) &&
                             (i + 4 >= n || !identifierChar(text[i + 4]));
        if (!keyword) {
            ++i;
            continue;
        }
        // Its `{`, past white space and comments.
        std::size_t j = i + 4;
        while (j < n) {
            if (std::isspace(static_cast<unsigned char>(text[j]))) ++j;
            else if (const std::size_t past = pastCommentOrString(text, j); past != j && text[j] != '"') j = past;
            else break;
        }
        if (j >= n || text[j] != '{') {
            i += 4;
            continue;
        }
        // Its matching `}`.
        int depth = 0;
        std::size_t end = j;
        while (end < n) {
            if (const std::size_t past = pastCommentOrString(text, end); past != end) {
                end = past;
                continue;
            }
            if (text[end] == '{') ++depth;
            if (text[end] == '}' && --depth == 0) {
                ++end;
                break;
            }
            ++end;
        }
        for (std::size_t k = i; k < end; ++k)
            if (out[k] != '\n') out[k] = ' ';
        i = end;
    }
    return out;
}

}  // namespace asos
