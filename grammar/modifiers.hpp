#pragma once
// Modifiers: transforms, pigment, finish, texture, our `asos { … }` block,
// and the modifiers an object accepts.
#include "grammar/directives.hpp"

namespace asos::grammar {

// Values after a keyword; each name carries its own error message.
struct float_value : seq<expression> {};
struct vector_value : seq<expression> {};
struct colour_value : seq<colour_in_place> {};
struct block_open : lbrace {};

// A POV-Ray keyword we do not support, met where an item may stand.
struct unsupported_item : unsupported_keyword {};

// --- transforms ---------------------------------------------------------------
struct translate_item : if_must<kw_translate, vector_value> {};
struct rotate_item : if_must<kw_rotate, vector_value> {};
struct scale_item : if_must<kw_scale, vector_value> {};  // a float scales uniformly
// matrix <m00, m01, m02,  m10, m11, m12,  m20, m21, m22,  m30, m31, m32>
struct matrix_value : seq<expression> {};
struct matrix_components : list_must<matrix_value, comma> {};
struct matrix_close : vector_close {};
struct matrix_values : if_must<vector_open, matrix_components, matrix_close> {};
struct matrix_item : if_must<kw_matrix, matrix_values> {};
struct transform_item : sor<translate_item, rotate_item, scale_item, matrix_item> {};

// --- asos { eps E  max M  jitter on|off  emitter povray|panel } -------------------
// `emitter` is a light's (the interpreter refuses it elsewhere).
struct eps_item : if_must<kw_eps, float_value> {};
struct max_item : if_must<kw_max, float_value> {};
struct asos_jitter_item : if_must<kw_jitter, float_value> {};
struct emitter_povray : kw_povray {};
struct emitter_panel : kw_panel {};
struct emitter_kind : sor<emitter_povray, emitter_panel> {};
struct emitter_item : if_must<kw_emitter, emitter_kind> {};
struct asos_highlights_item : if_must<kw_highlights, float_value> {};
struct asos_entry : sor<eps_item, max_item, asos_jitter_item, asos_highlights_item, emitter_item> {};
struct asos_end : rbrace {};
struct asos_block : if_must<kw_asos, block_open, entries<asos_entry>, asos_end> {};

// --- pigment { colour | checker c1, c2 | brick c1, c2 | Name  modifiers } --------
// A pattern's two colours, either or both left out (POV-Ray's colour list);
// `checker pigment {…} pigment {…}` (pigments rather than colours) is not
// ours. Each pattern keyword gets its own rules, for its own messages.
template <typename Keyword> struct pattern_colours_start : success {};
template <typename Keyword> struct pattern_of_blocks : seq<at<sor<kw_pigment, kw_texture>>> {};
template <typename Keyword> struct pattern_second_colour : seq<colour_in_place> {};
template <typename Keyword>
struct pattern_colours
    : seq<pattern_colours_start<Keyword>, opt<pattern_of_blocks<Keyword>>,
          opt<colour_in_place, sor<seq<comma, pattern_second_colour<Keyword>>, opt<colour_in_place>>>> {};
struct checker_item : if_must<kw_checker, pattern_colours<kw_checker>> {};
struct brick_item : if_must<kw_brick, pattern_colours<kw_brick>> {};
// brick's own modifiers; the interpreter checks that the pattern is brick.
struct brick_size_item : if_must<kw_brick_size, vector_value> {};
struct mortar_item : if_must<kw_mortar, float_value> {};
struct pigment_colour : seq<colour_in_place> {};  // a colour, or a declared pigment
struct pigment_entry : sor<checker_item, brick_item, transform_item, brick_size_item, mortar_item, pigment_colour,
                           unsupported_item> {};
struct pigment_end : rbrace {};
struct pigment_block : if_must<kw_pigment, block_open, entries<pigment_entry>, pigment_end> {};

// --- finish { Name  ambient C  diffuse F  … } ---------------------------------------
// `reflection { … }` (POV-Ray's block form) is not ours; `reflection C` is.
struct reflection_block : at<one<'{'>> {};
struct reflection_value : sor<reflection_block, seq<expression>> {};
struct ambient_item : if_must<kw_ambient, colour_value> {};
struct diffuse_item : if_must<kw_diffuse, float_value> {};
struct brilliance_item : if_must<kw_brilliance, float_value> {};
struct phong_item : if_must<kw_phong, float_value> {};
struct phong_size_item : if_must<kw_phong_size, float_value> {};
struct specular_item : if_must<kw_specular, float_value> {};
struct roughness_item : if_must<kw_roughness, float_value> {};
struct reflection_item : if_must<kw_reflection, reflection_value> {};
struct finish_name : indexed_name {};  // a declared finish
struct finish_entry
    : sor<ambient_item, diffuse_item, brilliance_item, phong_item, phong_size_item, specular_item,
          roughness_item, reflection_item, finish_name, unsupported_item> {};
struct finish_end : rbrace {};
struct finish_block : if_must<kw_finish, block_open, entries<finish_entry>, finish_end> {};

// --- texture { Name  pigment {…}  finish {…}  transforms } ------------------------
// A pattern of textures (`texture { checker texture {…} … }`) is not ours.
struct texture_pattern : sor<kw_checker, kw_brick> {};
struct texture_name : indexed_name {};  // a declared texture
struct texture_entry
    : sor<pigment_block, finish_block, transform_item, texture_pattern, texture_name, unsupported_item> {};
struct texture_end : rbrace {};
struct texture_block : if_must<kw_texture, block_open, entries<texture_entry>, texture_end> {};

// --- what an object accepts ------------------------------------------------------
struct open_item : kw_open {};  // cones and cylinders only; the interpreter checks
struct no_shadow_item : kw_no_shadow {};
struct object_modifier : sor<pigment_block, finish_block, texture_block, transform_item, no_shadow_item,
                             open_item, asos_block, unsupported_item> {};

}  // namespace asos::grammar
