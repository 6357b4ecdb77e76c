#pragma once
// Lexical rules of the scene language: white space, comments, numbers,
// strings, identifiers and punctuation.
//
// Padding convention, followed by every file in grammar/: a token eats the
// white space and comments that FOLLOW it (tok<…>); the top rule eats those
// before the first token. So every rule starts at a token and a failure
// points at the first character of the offending token.
#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

#include "asos/lang/words.hpp"

namespace asos::grammar {

using namespace tao::pegtl;

// --- white space and comments ---------------------------------------------
// Blanks and // comments, scanned by hand: they follow every token, so this is
// the hottest rule of a big scene.
struct blank_run {
    using rule_t = blank_run;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* const begin = in.current();
        const char* const end = in.end();
        const char* p = begin;
        while (p < end) {
            const char c = *p;
            if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++p;
            } else if (c == '/' && p + 1 < end && p[1] == '/') {
                while (p < end && *p != '\n') ++p;
            } else {
                break;
            }
        }
        in.bump(static_cast<std::size_t>(p - begin));  // counts the lines
        return true;
    }
};
// Block comments nest, as in POV-Ray: the end of the comment that opens at
// `p` ("/*"), or null when none closes it. (Shared with the rules that scan
// text by hand: a macro's body, the look-ahead for a lone macro call.)
inline const char* blockCommentEnd(const char* p, const char* end) {
    int depth = 0;
    for (; p + 1 < end; ++p) {
        if (p[0] == '/' && p[1] == '*') {
            ++depth;
            ++p;
        } else if (p[0] == '*' && p[1] == '/') {
            ++p;
            if (--depth == 0) return p + 1;
        }
    }
    return nullptr;
}

// An unterminated block comment is reported where it starts, not at the end
// of the file.
struct unterminated_comment {
    using rule_t = unterminated_comment;
    using subs_t = empty_list;
    template <typename ParseInput>
    static bool match(ParseInput&) {
        return false;
    }
};
struct block_comment {
    using rule_t = block_comment;
    using subs_t = empty_list;

    template <apply_mode, rewind_mode, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&&... st) {
        const char* const begin = in.current();
        const char* const end = in.end();
        if (end - begin < 2 || begin[0] != '/' || begin[1] != '*') return false;
        if (const char* after = blockCommentEnd(begin, end)) {
            in.bump(static_cast<std::size_t>(after - begin));  // counts the lines
            return true;
        }
        Control<unterminated_comment>::raise(static_cast<const ParseInput&>(in), st...);
    }
};
struct skip : seq<blank_run, star<block_comment, blank_run>> {};
struct byte_order_mark : string<'\xEF', '\xBB', '\xBF'> {};

template <typename Rule>
struct tok : seq<Rule, skip> {};

// --- numbers: 1  1.  .5  1e-3  2.5E+10 (the sign is an operator) -----------
// Scanned by hand, like blanks: a big scene is mostly numbers.
struct number_text {
    using rule_t = number_text;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* const begin = in.current();
        const char* const end = in.end();
        auto digit = [&](const char* q) { return q < end && *q >= '0' && *q <= '9'; };
        const char* p = begin;
        while (digit(p)) ++p;
        const bool whole = p != begin;
        bool fraction = false;
        if (p < end && *p == '.' && (whole || digit(p + 1))) {
            ++p;
            while (digit(p)) {
                ++p;
                fraction = true;
            }
        }
        if (!whole && !fraction) return false;
        if (p < end && (*p == 'e' || *p == 'E')) {
            const char* q = p + 1;
            if (q < end && (*q == '+' || *q == '-')) ++q;
            if (digit(q)) {
                while (digit(q)) ++q;
                p = q;
            }
        }
        in.bump_in_this_line(static_cast<std::size_t>(p - begin));
        return true;
    }
};
struct number_literal : tok<number_text> {};

// --- strings: "…" with C escapes, on one line --------------------------------
struct escaped_char : seq<one<'\\'>, any> {};
struct string_char : sor<escaped_char, not_one<'"', '\r', '\n'>> {};
struct string_body : until<one<'"'>, string_char> {};
struct string_text : if_must<one<'"'>, string_body> {};
struct string_literal : tok<string_text> {};

// --- identifiers ------------------------------------------------------------
// An identifier-shaped word, checked against a word table by `Accept`. Written
// as a custom rule so that hundreds of keywords cost one table look-up rather
// than hundreds of string comparisons.
template <typename Accept>
struct word_if {
    using rule_t = word_if;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const std::size_t n = in.size(0);  // memory inputs: all that is left
        if (n == 0) return false;
        const char* p = in.current();
        auto first = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
        auto other = [&](char c) { return first(c) || (c >= '0' && c <= '9'); };
        if (!first(p[0])) return false;
        std::size_t len = 1;
        while (len < n && other(p[len])) ++len;
        if (!Accept::accept(std::string_view(p, len))) return false;
        in.bump_in_this_line(len);
        return true;
    }
};

struct accept_name {
    static bool accept(std::string_view s) { return !lang::isReservedWord(s); }
};
template <std::uint8_t Classes>
struct accept_class {
    static bool accept(std::string_view s) {
        const lang::WordInfo* w = lang::lookupWord(s);
        return w && (w->classes & Classes);
    }
};
struct accept_unsupported {
    static bool accept(std::string_view s) { return lang::isUnsupportedKeyword(s); }
};
struct accept_unsupported_directive {
    static bool accept(std::string_view s) { return lang::isUnsupportedDirective(s); }
};
struct accept_any {
    static bool accept(std::string_view) { return true; }
};

// A user identifier: any word that is not reserved by POV-Ray or by us.
struct name_text : word_if<accept_name> {};
struct name : tok<name_text> {};

// --- punctuation ------------------------------------------------------------
struct lbrace : tok<one<'{'>> {};
struct rbrace : tok<one<'}'>> {};
struct lparen : tok<one<'('>> {};
struct rparen : tok<one<')'>> {};
struct lbracket : tok<one<'['>> {};
struct rbracket : tok<one<']'>> {};
struct vector_open : tok<one<'<'>> {};
struct vector_close : tok<one<'>'>> {};
struct comma : tok<one<','>> {};
struct semicolon : tok<one<';'>> {};
struct equals : tok<one<'='>> {};
struct hash : tok<one<'#'>> {};
// Commas between an object's leading arguments are optional in POV-Ray.
struct opt_comma : opt<comma> {};

}  // namespace asos::grammar

namespace tao::pegtl {
template <typename Name, typename Accept>
struct analyze_traits<Name, asos::grammar::word_if<Accept>> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, asos::grammar::number_text> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, asos::grammar::blank_run> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, asos::grammar::block_comment> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, asos::grammar::unterminated_comment> : analyze_any_traits<> {};
}  // namespace tao::pegtl
