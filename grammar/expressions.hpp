#pragma once
// Expressions, as POV-Ray 3.7 parses them. Outside parentheses an expression
// is arithmetic only (so `<` and `>` can delimit vectors and `=` follow
// #declare); comparisons, logic and `?:` live inside parentheses. Precedence
// ladder, loosest first:
//   ?:   |   &   < <= = != >= >   + -   * /   unary - + !   .member   primary
#include "grammar/keywords.hpp"

namespace asos::grammar {

struct expression;
struct logical_expression;

// --- operators ----------------------------------------------------------------
struct op_plus : tok<one<'+'>> {};
struct op_minus : tok<one<'-'>> {};
struct op_times : tok<one<'*'>> {};
struct op_divide : tok<one<'/'>> {};
struct op_not : tok<seq<one<'!'>, not_at<one<'='>>>> {};
struct op_less_equal : tok<string<'<', '='>> {};
struct op_less : tok<one<'<'>> {};
struct op_greater_equal : tok<string<'>', '='>> {};
struct op_greater : tok<one<'>'>> {};
struct op_equal : tok<one<'='>> {};
struct op_not_equal : tok<string<'!', '='>> {};
struct op_and : tok<one<'&'>> {};
struct op_or : tok<one<'|'>> {};
struct op_query : tok<one<'?'>> {};
struct op_colon : tok<one<':'>> {};
// A member dot; `.5` after an expression is a number, not a member.
struct op_dot : tok<seq<one<'.'>, not_at<ascii::digit>>> {};

// --- primaries ------------------------------------------------------------------
struct parenthesized : if_must<lparen, logical_expression, rparen> {};

struct vector_component : seq<expression> {};
// The common case `<1.5, -2, 3e-1>`, numbers and blanks on one line, scanned
// in one go; anything else falls through to vector_literal. (A big scene is
// mostly such vectors.)
struct plain_vector_text {
    using rule_t = plain_vector_text;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* const begin = in.current();
        const char* const end = in.end();
        const char* p = begin;
        auto blanks = [&] {
            while (p < end && (*p == ' ' || *p == '\t')) ++p;
        };
        auto digit = [&](const char* q) { return q < end && *q >= '0' && *q <= '9'; };
        auto number = [&] {
            if (p < end && *p == '-') ++p;
            const char* start = p;
            while (digit(p)) ++p;
            bool any = p != start;
            if (p < end && *p == '.') {
                ++p;
                while (digit(p)) {
                    ++p;
                    any = true;
                }
            }
            if (!any) return false;
            if (p < end && (*p == 'e' || *p == 'E')) {
                const char* q = p + 1;
                if (q < end && (*q == '+' || *q == '-')) ++q;
                if (!digit(q)) return false;
                while (digit(q)) ++q;
                p = q;
            }
            return p == end || !((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || *p == '_' || *p == '.');
        };
        if (p == end || *p != '<') return false;
        ++p;
        int components = 0;
        while (true) {
            blanks();
            if (!number()) return false;
            ++components;
            blanks();
            if (p < end && *p == ',' && components < 5) {
                ++p;
                continue;
            }
            if (p < end && *p == '>' && components >= 2) {
                ++p;
                break;
            }
            return false;
        }
        in.bump_in_this_line(static_cast<std::size_t>(p - begin));
        return true;
    }
};
struct plain_vector : tok<plain_vector_text> {};

// POV-Ray reads the commas between components as optional (woods.inc
// writes `< -1 0 0 >`); without one, the next expression starts a component.
struct vector_next_component : seq<expression> {};  // no message: its failure ends the list
struct vector_components
    : seq<vector_component, star<sor<seq<comma, vector_component>, vector_next_component>>> {};
struct vector_literal : if_must<vector_open, vector_components, vector_close> {};

struct call_argument : seq<expression> {};
struct call_arguments : list_must<call_argument, comma> {};
struct call_open : lparen {};
struct function_call : if_must<function_name, call_open, call_arguments, rparen> {};

// Colours: `rgb <1,0,0>`, `color Red filter 0.5`, `colour red 1 green .5`, …
// An item's operand is a whole arithmetic expression: `rgb <1,1,1>*0.5`.
// As in POV-Ray 3.7, a whole colour (`rgb V`, `rgbf V`, …, or after `color` any
// expression) can only open a colour: once something is read, the next whole
// colour begins the next value, so `checker rgb <1,0,0> rgb <0,0,1>` is two
// colours. Components (`red F`, `filter F`, …) may follow and override.
struct colour_operand : seq<expression> {};
struct colour_component : if_must<colour_component_name, colour_operand> {};
struct colour_whole : if_must<colour_whole_name, colour_operand> {};
struct colour_base : seq<expression> {};
struct colour_components : star<colour_component> {};
struct colour_body : sor<seq<colour_whole, colour_components>, plus<colour_component>> {};
struct colour_after_keyword : sor<colour_body, seq<colour_base, colour_components>> {};
struct colour_keyword_form : if_must<kw_color, colour_after_keyword> {};
struct colour_start : success {};  // opens the colour's node
struct colour_expression
    : seq<at<sor<kw_color, colour_whole_name, colour_component_name>>, colour_start,
          sor<colour_keyword_form, colour_body>> {};

// Where a colour is expected (POV-Ray's Parse_Colour: a pigment's colour,
// `checker`, `ambient`, a light's colour, the background), components may also
// follow a plain expression and override it: `pigment { Red green 1 }`,
// `White * 0.5 green 0`. (Not in `#declare`, where POV-Ray reads a value, not a
// colour: there `color Red green 1` says it.)
struct colour_tail_start : success {};  // makes the expression the colour's base
struct colour_tail : seq<at<colour_component_name>, colour_tail_start, plus<colour_component>> {};
struct colour_in_place : seq<expression, opt<colour_tail>> {};

// --- arrays and macro calls ---------------------------------------------------------
// Values that are blocks (directives.hpp): an object, a light, a camera, a pigment, ….
struct declarable_block;

// A[i][j]: the elements of a declared array. Only after a name: a '[' after any
// other value opens something else (a colour_map's entry).
struct subscript_index : seq<expression> {};
struct subscript_close : rbracket {};
struct subscript : if_must<lbracket, subscript_index, subscript_close> {};
struct name_reference : name {};
struct indexed_name : seq<name_reference, star<subscript>> {};

// array[N][M]… { initialiser }: a declared array's value. The initialiser nests one
// level of braces per dimension; commas between elements are optional (POV-Ray's).
struct array_start : success {};  // opens the array's node
struct array_size : seq<expression> {};
struct array_size_close : rbracket {};
struct array_size_open : lbracket {};
struct array_first_dimension : if_must<array_size_open, array_size, array_size_close> {};
struct array_dimension : if_must<lbracket, array_size, array_size_close> {};
struct array_initialiser;
struct array_element : sor<array_initialiser, declarable_block, expression> {};
struct initialiser_open : lbrace {};
struct initialiser_end : rbrace {};
struct array_initialiser : if_must<initialiser_open, star<array_element, opt<comma>>, initialiser_end> {};
struct array_value
    : if_must<kw_array, array_start, array_first_dimension, star<array_dimension>, opt<array_initialiser>> {};

// Name(arguments): a macro call (POV-Ray has no other `name (`). An argument is
// any value: an expression, a block or an array. The look-ahead keeps the
// name's action from firing for a plain name.
struct macro_name : name {};
struct macro_open : lparen {};
struct macro_first_argument : sor<declarable_block, array_value, expression> {};
struct macro_argument : seq<macro_first_argument> {};  // after a comma: must be there
struct macro_arguments : opt<macro_first_argument, star<comma, macro_argument>> {};
struct macro_close : rparen {};
struct macro_call : seq<at<name, one<'('>>, if_must<macro_name, macro_open, macro_arguments, macro_close>> {};
// What may follow a value to make it part of a longer expression.
struct expression_continues : one<'*', '/', '+', '-', '.'> {};

// A macro call that stands alone: `Name (…)` not followed by an operator that
// would make it an operand (* / + - .). Checked by scanning the text to the
// balancing ')' (strings and comments skipped), not by parsing the arguments:
// a look-ahead runs no actions, so an unsupported keyword among them would go
// unnamed.
struct lone_macro_call {
    using rule_t = lone_macro_call;
    using subs_t = empty_list;

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* p = in.current();
        const char* const end = in.end();
        auto wordChar = [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (c >= '0' && c <= '9');
        };
        auto skipBlanks = [&] {
            while (p < end) {
                if (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == '\f' || *p == '\v') {
                    ++p;
                } else if (*p == '/' && p + 1 < end && p[1] == '/') {
                    while (p < end && *p != '\n') ++p;
                } else if (*p == '/' && p + 1 < end && p[1] == '*') {
                    const char* after = blockCommentEnd(p, end);
                    p = after ? after : end;
                } else {
                    return;
                }
            }
        };
        const char* word = p;
        while (p < end && wordChar(*p)) ++p;
        if (p == word || (*word >= '0' && *word <= '9') || !accept_name::accept(std::string_view(word, static_cast<std::size_t>(p - word))))
            return false;
        skipBlanks();
        if (p == end || *p != '(') return false;
        int depth = 0;
        for (; p < end; ++p) {
            if (*p == '"') {
                for (++p; p < end && *p != '"' && *p != '\n'; ++p)
                    if (*p == '\\' && p + 1 < end) ++p;
            } else if (*p == '/' && p + 1 < end && (p[1] == '/' || p[1] == '*')) {
                skipBlanks();
                --p;
            } else if (*p == '(') {
                ++depth;
            } else if (*p == ')' && --depth == 0) {
                ++p;
                break;
            }
        }
        if (depth != 0) return true;  // unbalanced: let the call's own rules say what is wrong
        skipBlanks();
        return p == end || !(*p == '*' || *p == '/' || *p == '+' || *p == '-' || *p == '.');
    }
};

struct unsupported_in_expression : unsupported_keyword {};

struct primary : sor<number_literal, string_literal, parenthesized, plain_vector, vector_literal, function_call,
                     colour_expression, constant, macro_call, indexed_name, unsupported_in_expression> {};

// --- operators, tightest first -------------------------------------------------------
struct unary;
struct member_access : if_must<op_dot, member_name> {};
struct postfix : seq<primary, star<member_access>> {};
struct unary_operand : seq<unary> {};
struct negation : if_must<op_minus, unary_operand> {};
struct plus_sign : if_must<op_plus, unary_operand> {};
struct logical_not : if_must<op_not, unary_operand> {};
// (The at<> guards spare failed attempts at every operand.)
struct unary : sor<seq<at<one<'-', '+', '!'>>, sor<negation, plus_sign, logical_not>>, postfix> {};

struct factor_operand : seq<unary> {};
struct multiply : if_must<op_times, factor_operand> {};
struct divide : if_must<op_divide, factor_operand> {};
struct product : seq<unary, star<at<one<'*', '/'>>, sor<multiply, divide>>> {};

struct term_operand : seq<product> {};
struct add : if_must<op_plus, term_operand> {};
struct subtract : if_must<op_minus, term_operand> {};
// An arithmetic expression: what POV-Ray accepts without parentheses.
struct expression : seq<product, star<at<one<'+', '-'>>, sor<add, subtract>>> {};

// Inside parentheses only.
struct comparison_operand : seq<expression> {};
struct less_equal : if_must<op_less_equal, comparison_operand> {};
struct less : if_must<op_less, comparison_operand> {};
struct greater_equal : if_must<op_greater_equal, comparison_operand> {};
struct greater : if_must<op_greater, comparison_operand> {};
struct equal : if_must<op_equal, comparison_operand> {};
struct not_equal : if_must<op_not_equal, comparison_operand> {};
struct comparison
    : seq<expression, star<sor<less_equal, less, greater_equal, greater, not_equal, equal>>> {};
struct conjunction_operand : seq<comparison> {};
struct conjunction : if_must<op_and, conjunction_operand> {};
struct logical_and : seq<comparison, star<conjunction>> {};
struct disjunction_operand : seq<logical_and> {};
struct disjunction : if_must<op_or, disjunction_operand> {};
struct logical_or : seq<logical_and, star<disjunction>> {};
struct conditional_tail : if_must<op_query, logical_expression, op_colon, logical_expression> {};
struct logical_expression : seq<logical_or, opt<conditional_tail>> {};

}  // namespace asos::grammar

namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, asos::grammar::plain_vector_text> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, asos::grammar::lone_macro_call> : analyze_opt_traits<> {};
}  // namespace tao::pegtl
