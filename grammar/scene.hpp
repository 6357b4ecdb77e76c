#pragma once
// The top rules: a scene file, and a lone expression (a -D value).
#include "grammar/objects.hpp"

namespace asos::grammar {

struct top_entry : sor<camera_block, light_source_block, object_statement, global_settings_block,
                       background_block, unsupported_item> {};
// One entry of the file; the parser may hand each to the interpreter as soon
// as it is complete.
struct top_item : sor<directive<top_entry>, top_entry> {};
struct end_of_file : eof {};
struct scene_file : must<opt<byte_order_mark>, skip, star<top_item>, end_of_file> {};

struct lone_expression : seq<expression> {};
struct end_of_expression : eof {};
struct expression_text : must<skip, lone_expression, end_of_expression> {};

}  // namespace asos::grammar
