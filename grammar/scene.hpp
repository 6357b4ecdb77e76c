#pragma once
// The top rules: a scene file, a macro's body, and a lone expression (a -D value).
#include "grammar/objects.hpp"

namespace asos::grammar {

struct top_entry : sor<camera_block, light_source_block, object_statement, global_settings_block,
                       background_block, sky_sphere_block, fog_block, bare_default, unsupported_item> {};
// One entry of the file; the parser may hand each to the interpreter as soon
// as it is complete.
struct top_item : sor<directive<top_entry>, macro_entry<top_entry>, top_entry> {};
struct end_of_file : eof {};
struct scene_file : must<opt<byte_order_mark>, skip, star<top_item>, end_of_file> {};

// A macro's body where the macro's value is wanted (`#declare A = M(1);`,
// `M(1) * 2`, an argument): what may follow `#declare A =`.
struct value_entry : sor<declarable_block, array_value, expression> {};
// A macro's body, read as entries of the block the macro is called in
// (top_entry, object_modifier, …) or of value_entry.
template <typename Entry>
struct macro_body_end : eof {};
template <typename Entry>
struct macro_body : must<skip, entries<Entry>, macro_body_end<Entry>> {};

struct lone_expression : seq<expression> {};
struct end_of_expression : eof {};
struct expression_text : must<skip, lone_expression, end_of_expression> {};

}  // namespace asos::grammar
