#pragma once
// Directives. POV-Ray lets a directive stand wherever an item of a block may
// stand, so every block body is `entries<Entry>`: its own items mixed with
// directives whose bodies hold the same kind of items.
//
// Naming rule for the whole grammar: a rule that has an error message raises
// wherever it fails (must_if), so such rules are used only where failing is
// an error; a token needed both ways gets two names (`lbrace`, `block_open`).
#include "grammar/expressions.hpp"

namespace asos::grammar {

// Declared values that are blocks; defined in modifiers.hpp and objects.hpp.
struct object_statement;
struct light_source_block;
struct camera_block;
struct pigment_block;
struct finish_block;
struct texture_block;

template <typename Entry>
struct directive;

// A block's body: its items and directives, in any order. (The not_at spares
// trying every kind of item at the closing brace.)
template <typename Entry>
struct entries : star<not_at<one<'}'>>, sor<directive<Entry>, Entry>> {};

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
struct ifdef_condition : seq<condition_open, tested_name, rparen> {};
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

// #declare Name = value   and   #local Name = value
struct declare_start : seq<hash, kw_declare> {};
struct local_start : seq<hash, kw_local> {};
struct declared_name : name {};
struct declare_equals : equals {};
struct declare_semicolon : semicolon {};
struct declarable_block : sor<object_statement, light_source_block, camera_block, pigment_block,
                              finish_block, texture_block> {};
// POV-Ray wants the ';' after a float, vector or colour, not after a string
// or a block. A string is told by how it starts: a literal, concat, str, chr.
struct string_start : sor<one<'"'>, TAO_PEGTL_KEYWORD("concat"), TAO_PEGTL_KEYWORD("str"),
                          TAO_PEGTL_KEYWORD("chr")> {};
struct declared_value
    : sor<seq<declarable_block, opt<semicolon>>, seq<at<string_start>, expression, opt<semicolon>>,
          seq<expression, declare_semicolon>> {};
struct declare_directive : if_must<declare_start, declared_name, declare_equals, declared_value> {};
struct local_directive : if_must<local_start, declared_name, declare_equals, declared_value> {};

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

// POV-Ray directives we do not run (#macro, #switch, …) are named in the
// error; any other word after '#' is not a directive at all. #else, #elseif
// and #end end a body and are left to the directive that owns it.
struct unsupported_directive : seq<hash, word_if<accept_unsupported_directive>> {};
// A '#' with no word after it does nothing, as in POV-Ray.
struct empty_directive : seq<hash, not_at<ascii::identifier_first>> {};
struct unknown_directive
    : seq<hash, not_at<sor<kw_end, kw_else, kw_elseif>>, word_if<accept_any>> {};

// (The leading at<'#'> spares trying fifteen directives at every item.)
template <typename Entry>
struct directive
    : seq<at<one<'#'>>,
          sor<if_directive<Entry>, ifdef_directive<Entry>, ifndef_directive<Entry>,
              while_directive<Entry>, for_directive<Entry>, declare_directive, local_directive,
              undef_directive, include_directive, version_directive, debug_directive,
              warning_directive, error_directive, unsupported_directive, empty_directive,
              unknown_directive>> {};

}  // namespace asos::grammar
