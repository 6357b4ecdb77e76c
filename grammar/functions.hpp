#pragma once
// User-defined functions, POV-Ray 3.7's `function`:
//   function { expr }                 parameters x, y, z (u and v are x and y)
//   function(a, b, c) { expr }        its own parameters
//   function { internal(N) }          POV-Ray's built-in functions (functions.inc)
//   function { pigment {…} }, { pattern {…} }, { transform {…} }, { spline {…} }
// Inside the braces the whole expression ladder holds (comparisons, & | and
// ?: without parentheses), as in POV-Ray's function parser. The four block
// forms are kept as text, unread: asos refuses them where such a function is
// used (lang/functions.cpp), so that an include that merely declares them
// (functions.inc) still reads.
#include "grammar/expressions.hpp"

namespace asos::grammar {

struct kw_function : tok<TAO_PEGTL_KEYWORD("function")> {};
struct kw_internal : tok<TAO_PEGTL_KEYWORD("internal")> {};

// `{ … }` with what is inside unread: braces balanced, strings and comments
// skipped.
struct skipped_block_text {
    using rule_t = skipped_block_text;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* p = in.current();
        const char* const end = in.end();
        if (p == end || *p != '{') return false;
        int depth = 0;
        while (p < end) {
            if (*p == '"') {
                for (++p; p < end && *p != '"' && *p != '\n'; ++p)
                    if (*p == '\\' && p + 1 < end) ++p;
                if (p < end) ++p;
                continue;
            }
            if (*p == '/' && p + 1 < end && p[1] == '/') {
                while (p < end && *p != '\n') ++p;
                continue;
            }
            if (*p == '/' && p + 1 < end && p[1] == '*') {
                const char* after = blockCommentEnd(p, end);
                if (!after) return false;
                p = after;
                continue;
            }
            if (*p == '{') ++depth;
            if (*p == '}' && --depth == 0) {
                in.bump(static_cast<std::size_t>(p + 1 - in.current()));
                return true;
            }
            ++p;
        }
        return false;
    }
};
struct skipped_block : tok<skipped_block_text> {};

struct function_block_word
    : tok<sor<TAO_PEGTL_KEYWORD("pigment"), TAO_PEGTL_KEYWORD("pattern"), TAO_PEGTL_KEYWORD("transform"),
              TAO_PEGTL_KEYWORD("spline")>> {};
struct function_block : seq<at<function_block_word, one<'{'>>, function_block_word, skipped_block> {};
struct internal_number : seq<expression> {};
struct internal_open : lparen {};
struct function_internal : if_must<kw_internal, internal_open, internal_number, rparen> {};
struct function_expression : seq<logical_expression> {};
struct function_body : sor<function_block, function_internal, function_expression> {};

struct function_parameter_name : name {};
struct function_parameter : sor<constant, function_parameter_name> {};
struct function_parameters_open : lparen {};
struct function_parameter_list : list_must<function_parameter, comma> {};
struct function_parameters : if_must<function_parameters_open, function_parameter_list, rparen> {};
struct function_start : success {};  // opens the function's node
struct function_open : lbrace {};
struct function_close : rbrace {};
struct function_value
    : if_must<kw_function, function_start, opt<function_parameters>, function_open, function_body, function_close> {};

// pigment { function { expr } … }, normal { function { expr } … }: the
// function pattern, its body a function of x, y, z.
struct function_pattern_open : lbrace {};
struct function_pattern_item : if_must<kw_function, function_pattern_open, function_expression, function_close> {};

}  // namespace asos::grammar

namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, asos::grammar::skipped_block_text> : analyze_any_traits<> {};
}  // namespace tao::pegtl
