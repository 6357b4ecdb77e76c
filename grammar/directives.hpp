#pragma once
// Directives. POV-Ray lets a directive stand wherever an item of a block may
// stand, so every block body is `entries<Entry>`: its own items mixed with
// directives whose bodies hold the same kind of items.
//
// Naming rule for the whole grammar: a rule that has an error message raises
// wherever it fails (must_if), so such rules are used only where failing is
// an error; a token needed both ways gets two names (`lbrace`, `block_open`).
#include "grammar/expressions.hpp"
#include "grammar/functions.hpp"

namespace asos::grammar {

// Declared values that are blocks; defined in modifiers.hpp and objects.hpp.
struct object_statement;
struct light_source_block;
struct camera_block;
struct pigment_block;
struct finish_block;
struct normal_block;
struct texture_block;
struct interior_block;
struct material_block;
struct colour_map_block;
struct pigment_map_block;
struct sky_sphere_block;
struct fog_block;
struct block_open;
struct unsupported_item;

template <typename Entry>
struct directive;

// A macro call standing as an entry of a block: its body is read as entries of
// that block (the call's node records which kind, parse.hpp's BodyContext).
// Followed by an operator it is an operand of the entry's expression instead.
template <typename Entry>
struct macro_entry : seq<lone_macro_call, macro_call> {};

// A block's body: its items, directives and macro calls, in any order. (The
// not_at spares trying every kind of item at the closing brace.)
template <typename Entry>
struct entries : star<not_at<one<'}'>>, sor<directive<Entry>, macro_entry<Entry>, Entry>> {};

// A directive's body becomes a Sequence node.
struct sequence_start : success {};
template <typename Entry>
struct directive_body : seq<sequence_start, entries<Entry>> {};

struct condition_open : lparen {};
struct condition : if_must<condition_open, logical_expression, rparen> {};

// #if (…) … [#elseif (…) …]… [#else …] #end
struct if_start : seq<hash, kw_if> {};
struct elseif_start : seq<hash, kw_elseif> {};
struct else_start : seq<hash, kw_else> {};
struct if_end : seq<hash, kw_end> {};
template <typename Entry>
struct elseif_part : if_must<elseif_start, condition, directive_body<Entry>> {};
template <typename Entry>
struct else_part : if_must<else_start, directive_body<Entry>> {};
template <typename Entry>
struct if_directive : if_must<if_start, condition, directive_body<Entry>, star<elseif_part<Entry>>,
                              opt<else_part<Entry>>, if_end> {};

// #ifdef (Name) … and #ifndef (Name) …: #if on whether Name is declared.
struct ifdef_start : seq<hash, kw_ifdef> {};
struct ifndef_start : seq<hash, kw_ifndef> {};
struct tested_name : name {};
struct ifdef_condition : seq<condition_open, tested_name, star<subscript>, rparen> {};
template <typename Start, typename Entry>
struct ifdef_family : if_must<Start, ifdef_condition, directive_body<Entry>, star<elseif_part<Entry>>,
                              opt<else_part<Entry>>, if_end> {};
template <typename Entry>
struct ifdef_directive : ifdef_family<ifdef_start, Entry> {};
template <typename Entry>
struct ifndef_directive : ifdef_family<ifndef_start, Entry> {};

// #while (…) … #end
struct while_start : seq<hash, kw_while> {};
struct while_end : seq<hash, kw_end> {};
template <typename Entry>
struct while_directive : if_must<while_start, condition, directive_body<Entry>, while_end> {};

// #for (Name, Start, End [, Step]) … #end
struct for_start : seq<hash, kw_for> {};
struct for_open : lparen {};
struct for_variable : name {};
struct for_comma : comma {};
struct for_value : seq<expression> {};
struct for_step : opt<comma, for_value> {};
struct for_end : seq<hash, kw_end> {};
template <typename Entry>
struct for_directive : if_must<for_start, for_open, for_variable, for_comma, for_value, for_comma,
                               for_value, for_step, rparen, directive_body<Entry>, for_end> {};

// #declare Name = value   and   #local Name = value   (Name may be an array's element: A[i])
struct declare_start : seq<hash, kw_declare> {};
struct local_start : seq<hash, kw_local> {};
struct declared_name : name {};
struct declared_target : seq<declared_name, star<subscript>> {};
// #declare deprecated [once] "message" Name = value: POV-Ray warns with the
// message where the name is used (the first time only, with once).
struct deprecation_once : kw_once {};
struct deprecation_message : seq<expression> {};
struct deprecation : if_must<kw_deprecated, opt<deprecation_once>, deprecation_message> {};
struct declare_equals : equals {};
struct declare_semicolon : semicolon {};
// A declared block followed by textures: POV-Ray's layered texture, each
// one over the one before (the interpreter checks that the first is a
// texture too). The frame opened around the first holds them all.
struct texture_layers_open : success {};
struct layered_texture : seq<at<TAO_PEGTL_KEYWORD("texture")>, texture_layers_open, plus<texture_block>> {};
struct declarable_block : sor<object_statement, light_source_block, camera_block, pigment_block,
                              normal_block, finish_block, texture_block, interior_block, material_block,
                              colour_map_block, pigment_map_block, function_value, sky_sphere_block, fog_block> {};
// POV-Ray wants the ';' after a float, vector or colour, not after a string,
// a block, an array or a macro's value (which may be a block). A string is told
// by how it starts: a literal or a function whose value is a string.
struct string_start
    : sor<one<'"'>, TAO_PEGTL_KEYWORD("concat"), TAO_PEGTL_KEYWORD("str"), TAO_PEGTL_KEYWORD("chr"),
          TAO_PEGTL_KEYWORD("substr"), TAO_PEGTL_KEYWORD("strupr"), TAO_PEGTL_KEYWORD("strlwr"),
          TAO_PEGTL_KEYWORD("vstr")> {};
// A lone name or macro call may be a float, a vector or a colour, which want
// the ';', or anything else, which does not: the interpreter decides, from the
// value, whether a missing ';' (marked in the declaration's flags) is an error.
struct macro_value : seq<lone_macro_call, macro_call> {};
struct lone_name : seq<at<indexed_name, not_at<sor<expression_continues, one<'('>>>>, indexed_name> {};
struct missing_semicolon : success {};
struct declared_value
    : sor<seq<declarable_block, opt<layered_texture>, opt<semicolon>>, seq<array_value, opt<semicolon>>,
          seq<sor<macro_value, lone_name>, sor<semicolon, missing_semicolon>>,
          seq<at<string_start>, expression, opt<semicolon>>, seq<expression, declare_semicolon>> {};
struct declare_directive
    : if_must<declare_start, opt<deprecation>, declared_target, declare_equals, declared_value> {};
struct local_directive : if_must<local_start, opt<deprecation>, declared_target, declare_equals, declared_value> {};

// #undef Name
struct undef_start : seq<hash, kw_undef> {};
struct undefined_name : name {};
struct undef_directive : if_must<undef_start, undefined_name> {};

// #include "file"
struct include_start : seq<hash, kw_include> {};
struct included_file : seq<expression> {};
struct include_directive : if_must<include_start, included_file> {};

// #version 3.7;
struct version_start : seq<hash, kw_version> {};
struct version_value : seq<expression> {};
struct version_directive : if_must<version_start, version_value, opt<semicolon>> {};

// #debug "…"   #warning "…"   #error "…"
struct debug_start : seq<hash, kw_debug> {};
struct warning_start : seq<hash, kw_warning> {};
struct error_start : seq<hash, kw_error> {};
struct message_value : seq<expression> {};
struct debug_directive : if_must<debug_start, message_value> {};
struct warning_directive : if_must<warning_start, message_value> {};
struct error_directive : if_must<error_start, message_value> {};

// #macro Name(P1, P2, …) body #end
// The body is kept as text, read only where the macro is called, as entries of
// the block it is called in (or as a value): POV-Ray's macros are text too. Its
// end is the #end that balances the #if, #ifdef, #ifndef, #switch, #while, #for
// and #macro inside it, strings and comments skipped.
struct macro_start : seq<hash, kw_macro> {};
struct macro_defined_name : name {};
struct macro_parameters_open : lparen {};
struct macro_parameter : name {};
struct macro_parameters_close : rparen {};
struct macro_body_text {
    using rule_t = macro_body_text;
    using subs_t = empty_list;

    static bool opensBody(std::string_view w) {
        return w == "if" || w == "ifdef" || w == "ifndef" || w == "switch" || w == "while" || w == "for" ||
               w == "macro";
    }

    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const char* const begin = in.current();
        const char* const end = in.end();
        auto wordChar = [](char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (c >= '0' && c <= '9');
        };
        int depth = 0;
        const char* p = begin;
        while (p < end) {
            const char c = *p;
            if (c == '"') {  // a string, on one line
                for (++p; p < end && *p != '"' && *p != '\n'; ++p)
                    if (*p == '\\' && p + 1 < end && p[1] != '\n') ++p;
                if (p < end && *p == '"') ++p;
            } else if (c == '/' && p + 1 < end && p[1] == '/') {
                while (p < end && *p != '\n') ++p;
            } else if (c == '/' && p + 1 < end && p[1] == '*') {
                p = blockCommentEnd(p, end);
                if (!p) return false;
            } else if (c == '#') {
                const char* q = p + 1;
                while (q < end && (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\n')) ++q;
                const char* w = q;
                while (q < end && wordChar(*q)) ++q;
                const std::string_view word(w, static_cast<std::size_t>(q - w));
                if (word == "end") {
                    if (depth == 0) {
                        in.bump(static_cast<std::size_t>(p - begin));  // counts the lines
                        return true;
                    }
                    --depth;
                } else if (opensBody(word)) {
                    ++depth;
                }
                p = q;
            } else if (wordChar(c)) {
                while (p < end && wordChar(*p)) ++p;
            } else {
                ++p;
            }
        }
        return false;
    }
};
struct macro_end : seq<hash, kw_end> {};
struct macro_directive
    : if_must<macro_start, macro_defined_name, macro_parameters_open, star<macro_parameter, opt<comma>>,
              macro_parameters_close, macro_body_text, macro_end> {};

// #switch (V)  #case (A) …  #range (Lo, Hi) …  [#else …]  #end, with #break.
// As in POV-Ray, a case that matches runs on into the following ones (and the
// #else) until a #break.
struct switch_start : seq<hash, kw_switch> {};
struct case_start : seq<hash, kw_case> {};
struct range_start : seq<hash, kw_range> {};
struct range_comma : comma {};
struct range_condition : if_must<condition_open, logical_expression, range_comma, logical_expression, rparen> {};
template <typename Entry>
struct case_clause : if_must<case_start, condition, directive_body<Entry>> {};
template <typename Entry>
struct range_clause : if_must<range_start, range_condition, directive_body<Entry>> {};
template <typename Entry>
struct switch_first_clause : sor<case_clause<Entry>, range_clause<Entry>> {};
struct switch_end : seq<hash, kw_end> {};
template <typename Entry>
struct switch_directive
    : if_must<switch_start, condition, switch_first_clause<Entry>, star<sor<case_clause<Entry>, range_clause<Entry>>>,
              opt<else_part<Entry>>, switch_end> {};
// #break: leaves the innermost #switch, #while, #for or macro.
struct break_directive : seq<hash, kw_break> {};

// #default { texture {…} | pigment {…} | normal {…} | finish {…} }; at the top
// of a scene POV-Ray also takes it without the '#'.
struct default_start : seq<hash, kw_default> {};
struct bare_default_start : kw_default {};
struct default_entry : sor<texture_block, pigment_block, normal_block, finish_block, unsupported_item> {};
struct default_end : rbrace {};
struct default_directive : if_must<default_start, block_open, entries<default_entry>, default_end> {};
struct bare_default : if_must<bare_default_start, block_open, entries<default_entry>, default_end> {};

// #fopen Handle "name" read|write|append   #fclose Handle
// #read (Handle, Name, …)   #write (Handle, value, …)
// As POV-Ray, the commas between the parts of #read and #write are optional.
struct fopen_start : seq<hash, kw_fopen> {};
struct opened_handle : name {};
struct opened_file : seq<expression> {};
struct open_mode : sor<kw_read, kw_write, kw_append> {};
struct fopen_directive : if_must<fopen_start, opened_handle, opened_file, open_mode> {};
struct fclose_start : seq<hash, kw_fclose> {};
struct closed_handle : name {};
struct fclose_directive : if_must<fclose_start, closed_handle> {};
struct file_open : lparen {};
struct file_handle : name {};
struct read_start : seq<hash, kw_read> {};
// POV-Ray 3.7 reads into names only, not array elements.
struct read_variable : name {};
struct read_close : rparen {};
struct read_directive
    : if_must<read_start, file_open, file_handle, opt<comma>, star<read_variable, opt<comma>>, read_close> {};
struct write_start : seq<hash, kw_write> {};
// A string is one operand (a literal or a string function), as POV-Ray reads
// it here: `"x" -1` writes "x", then -1.
struct written_value : sor<seq<at<string_start>, primary>, expression> {};
struct write_close : rparen {};
struct write_directive
    : if_must<write_start, file_open, file_handle, opt<comma>, star<written_value, opt<comma>>, write_close> {};

// POV-Ray directives we do not run (#render, #statistics) are named in the error;
// any other word after '#' is not a directive at all. #else, #elseif, #end,
// #case and #range end a body and are left to the directive that owns it.
struct unsupported_directive : seq<hash, word_if<accept_unsupported_directive>> {};
// A '#' with no word after it does nothing, as in POV-Ray.
struct empty_directive : seq<hash, not_at<ascii::identifier_first>> {};
struct unknown_directive
    : seq<hash, not_at<sor<kw_end, kw_else, kw_elseif, kw_case, kw_range>>, word_if<accept_any>> {};

// (The leading at<'#'> spares trying twenty directives at every item.)
template <typename Entry>
struct directive
    : seq<at<one<'#'>>,
          sor<if_directive<Entry>, ifdef_directive<Entry>, ifndef_directive<Entry>,
              while_directive<Entry>, for_directive<Entry>, switch_directive<Entry>, break_directive,
              declare_directive, local_directive, undef_directive, include_directive, macro_directive,
              default_directive, version_directive, debug_directive, warning_directive, error_directive,
              fopen_directive, fclose_directive, read_directive, write_directive, unsupported_directive, empty_directive, unknown_directive>> {};

}  // namespace asos::grammar

namespace tao::pegtl {
template <typename Name>
struct analyze_traits<Name, asos::grammar::macro_body_text> : analyze_opt_traits<> {};
}  // namespace tao::pegtl
