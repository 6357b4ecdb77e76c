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
// A pattern's two colours, either or both left out (POV-Ray's colour list),
// or its two pigments (POV-Ray's pigment list, `checker pigment {…}
// pigment {…}`, the second optional); a list of textures is not ours. Each
// pattern keyword gets its own rules, for its own messages.
struct pigment_block;
template <typename Keyword> struct pattern_colours_start : success {};
template <typename Keyword> struct pattern_of_textures : seq<at<kw_texture>> {};
template <typename Keyword> struct pattern_of_pigments : seq<at<kw_pigment>, pigment_block, opt<comma>, opt<pigment_block>> {};
template <typename Keyword> struct pattern_second_colour : seq<colour_in_place> {};
template <typename Keyword>
struct pattern_colours
    : seq<pattern_colours_start<Keyword>, opt<pattern_of_textures<Keyword>>,
          opt<sor<pattern_of_pigments<Keyword>,
                  seq<colour_in_place, sor<seq<comma, pattern_second_colour<Keyword>>, opt<colour_in_place>>>>>> {};
struct checker_item : if_must<kw_checker, pattern_colours<kw_checker>> {};
struct brick_item : if_must<kw_brick, pattern_colours<kw_brick>> {};
// brick's own modifiers; the interpreter checks that the pattern is brick.
struct brick_size_item : if_must<kw_brick_size, vector_value> {};
struct mortar_item : if_must<kw_mortar, float_value> {};
// The patterns whose value runs over [0, 1] through a colour map.
struct gradient_item : if_must<kw_gradient, vector_value> {};
struct radial_item : kw_radial {};
struct onion_item : kw_onion {};
struct marble_item : kw_marble {};
struct wood_item : kw_wood {};
struct leopard_item : kw_leopard {};
struct bozo_item : kw_bozo {};
struct spotted_item : kw_spotted {};
struct granite_item : kw_granite {};
struct agate_item : kw_agate {};
struct crackle_item : kw_crackle {};
struct map_pattern_item : sor<gradient_item, radial_item, onion_item, marble_item, wood_item, leopard_item,
                              bozo_item, spotted_item, granite_item, agate_item, crackle_item,
                              function_pattern_item> {};
// Their modifiers; the interpreter checks that the pattern takes them.
struct turbulence_item : if_must<kw_turbulence, vector_value> {};  // a float for all three axes
struct octaves_item : if_must<kw_octaves, float_value> {};
struct omega_item : if_must<kw_omega, float_value> {};
struct lambda_item : if_must<kw_lambda, float_value> {};
struct frequency_item : if_must<kw_frequency, float_value> {};
struct phase_item : if_must<kw_phase, float_value> {};
struct agate_turb_item : if_must<kw_agate_turb, float_value> {};
struct noise_generator_item : if_must<kw_noise_generator, float_value> {};
// crackle's own: form <f1, f2, f3>, metric M (a vector, as POV-Ray reads it;
// its x counts), offset F, solid.
struct form_item : if_must<kw_form, vector_value> {};
struct metric_item : if_must<kw_metric, vector_value> {};
struct offset_item : if_must<kw_offset, float_value> {};
struct solid_item : kw_solid {};
struct ramp_wave_item : kw_ramp_wave {};
struct triangle_wave_item : kw_triangle_wave {};
struct sine_wave_item : kw_sine_wave {};
// color_map { [v colour] … }, POV-Ray's older [v1, v2 colour1 colour2], or a
// declared map by name (then entries of its own, if any, replace it).
struct map_entry_value : seq<expression> {};
struct map_entry_colour : seq<colour_in_place> {};
struct map_entry_more : seq<colour_in_place> {};  // the older form's colours: optional, no message
struct map_entry_close : rbracket {};
struct map_entry_start : success {};
struct map_entry
    : if_must<lbracket, map_entry_start, map_entry_value, opt<comma>, map_entry_colour, star<map_entry_more>,
              map_entry_close> {};
struct map_name : indexed_name {};
struct colour_map_end : rbrace {};
struct colour_map_block
    : if_must<kw_colour_map, block_open, opt<map_name>, star<map_entry>, colour_map_end> {};
struct map_modifier
    : sor<turbulence_item, octaves_item, omega_item, lambda_item, frequency_item, phase_item, agate_turb_item,
          noise_generator_item, ramp_wave_item, triangle_wave_item, sine_wave_item, form_item, metric_item,
          offset_item, solid_item, colour_map_block> {};
struct pigment_colour : seq<colour_in_place> {};  // a colour, or a declared pigment
// The normal patterns, in a pigment as map patterns of their own values.
struct bumps_item : kw_bumps {};
struct dents_item : kw_dents {};
struct wrinkles_item : kw_wrinkles {};
struct ripples_item : kw_ripples {};
struct waves_item : kw_waves {};
struct pigment_normal_pattern : sor<bumps_item, dents_item, wrinkles_item, ripples_item, waves_item> {};
// POV-Ray's average: the weighted mean of its pigment map's pigments.
struct average_item : kw_average {};
// pigment_map { [value pigment-body] … }: each entry a pigment's own items
// (a colour, a declared pigment, a pattern with its modifiers, transforms),
// written without braces; under `average` the value is an optional weight
// (POV-Ray's Allow_Float), so it is marked as written or not
// (pigment_map_value_end) and the interpreter decides.
struct pigment_entry;
struct pigment_map_entry_start : success {};
struct pigment_map_value : seq<expression> {};
struct pigment_map_value_end : success {};
struct pigment_map_entry_close : rbracket {};
struct pigment_map_entry
    : if_must<lbracket, pigment_map_entry_start, opt<pigment_map_value, opt<comma>>, pigment_map_value_end,
              entries<pigment_entry>, pigment_map_entry_close> {};
struct pigment_map_end : rbrace {};
// A declared map by name first, if any (then entries of its own replace it).
struct pigment_map_block
    : if_must<kw_pigment_map, block_open, opt<map_name>, star<pigment_map_entry>, pigment_map_end> {};
struct pigment_entry : sor<checker_item, brick_item, map_pattern_item, average_item, transform_item, brick_size_item,
                           mortar_item, map_modifier, pigment_map_block, pigment_normal_pattern, pigment_colour,
                           unsupported_item> {};
struct pigment_end : rbrace {};
struct pigment_block : if_must<kw_pigment, block_open, entries<pigment_entry>, pigment_end> {};

// --- normal { Name  pattern [bump size]  bump_size F  accuracy F  modifiers } -------
// The five normal-only patterns, or a map pattern tilting the normal by its
// slope. The bump size written right after the pattern (`bumps 0.4`,
// `granite, -0.1`) is read where a number plainly follows (a digit, a sign,
// a point, a parenthesis or a name), as POV-Ray's optional float there.
struct bump_amount_value : seq<expression> {};
struct bump_amount : seq<opt<comma>, at<sor<ascii::digit, one<'.', '-', '+', '('>, name>>, bump_amount_value> {};
struct normal_pattern_item
    : seq<sor<bumps_item, dents_item, wrinkles_item, ripples_item, waves_item, map_pattern_item>, opt<bump_amount>> {};
// checker and brick tilt the normal with normals of their own: not ours.
struct normal_block_pattern : sor<kw_checker, kw_brick, kw_average> {};
// A pigment's map in a normal: POV-Ray's "can only be used in a pigment".
struct normal_pigment_map : kw_pigment_map {};
struct bump_size_item : if_must<kw_bump_size, float_value> {};
struct accuracy_item : if_must<kw_accuracy, float_value> {};
struct normal_name : indexed_name {};  // a declared normal
struct normal_entry : sor<normal_pattern_item, normal_block_pattern, normal_pigment_map, transform_item, bump_size_item, accuracy_item,
                          map_modifier, normal_name, unsupported_item> {};
struct normal_end : rbrace {};
struct normal_block : if_must<kw_normal, block_open, entries<normal_entry>, normal_end> {};

// --- finish { Name  ambient C  diffuse F  … } ---------------------------------------
// An optional number after a keyword (`metallic`, `fresnel`): taken only
// where one plainly follows (a constant, a declared name, a number, a sign
// or a parenthesis), as POV-Ray reads an optional float there.
struct arguments_end;  // grammar/objects.hpp
struct optional_number : seq<at<sor<constant, name, ascii::digit, one<'(', '!', '-', '+', '.'>>>, expression> {};
// reflection C, or reflection { [C_min,] C_max  fresnel [B]  falloff F
// exponent F  metallic [F] }
struct reflection_option_word : sor<kw_fresnel, kw_falloff, kw_exponent, kw_metallic> {};
struct fresnel_start : success {};
struct fresnel_item : seq<kw_fresnel, fresnel_start, opt<optional_number>> {};
struct falloff_item : if_must<kw_falloff, float_value> {};
struct exponent_item : if_must<kw_exponent, float_value> {};
struct metallic_start : success {};
struct metallic_item : seq<kw_metallic, metallic_start, opt<optional_number>> {};
struct reflection_option : sor<fresnel_item, falloff_item, exponent_item, metallic_item> {};
struct reflection_colours
    : seq<colour_value, opt<comma>, opt<not_at<sor<reflection_option_word, rbrace>>, colour_value>> {};
struct reflection_block_end : rbrace {};
struct reflection_open : lbrace {};
struct reflection_block
    : if_must<reflection_open, reflection_colours, arguments_end, star<reflection_option>, reflection_block_end> {};
struct reflection_simple : seq<expression> {};
struct reflection_value : sor<reflection_block, reflection_simple> {};
struct ambient_item : if_must<kw_ambient, colour_value> {};
struct diffuse_item : if_must<kw_diffuse, float_value> {};
struct brilliance_item : if_must<kw_brilliance, float_value> {};
struct phong_item : if_must<kw_phong, float_value> {};
struct phong_size_item : if_must<kw_phong_size, float_value> {};
struct specular_item : if_must<kw_specular, float_value> {};
struct roughness_item : if_must<kw_roughness, float_value> {};
struct crand_item : if_must<kw_crand, float_value> {};
struct reflection_item : if_must<kw_reflection, reflection_value> {};
struct reflection_exponent_item : if_must<kw_reflection_exponent, float_value> {};
struct conserve_energy_item : kw_conserve_energy {};
// POV-Ray 3.0's ior, caustics and refraction in a finish: read, and refused
// where a finish holding one is made (a scene keeps them in #if (version <
// 3.1) branches that are never taken).
struct legacy_ior_item : if_must<kw_ior, float_value> {};
struct legacy_caustics_item : if_must<kw_caustics, float_value> {};
struct legacy_refraction_item : if_must<kw_refraction, float_value> {};
struct finish_name : indexed_name {};  // a declared finish
struct finish_emission : kw_emission {};  // a finish's emission: not ours
struct finish_entry
    : sor<finish_emission, ambient_item, diffuse_item, brilliance_item, phong_item, phong_size_item, specular_item,
          roughness_item, crand_item, reflection_item, reflection_exponent_item, metallic_item, conserve_energy_item,
          legacy_ior_item, legacy_caustics_item, legacy_refraction_item, finish_name, unsupported_item> {};
struct finish_end : rbrace {};
struct finish_block : if_must<kw_finish, block_open, entries<finish_entry>, finish_end> {};

// --- texture { Name  pigment {…}  finish {…}  transforms } ------------------------
// A pattern of textures (`texture { checker texture {…} … }`) is not ours.
struct texture_pattern : sor<kw_checker, kw_brick, kw_gradient, kw_radial, kw_onion, kw_marble, kw_wood, kw_leopard,
                             kw_bozo, kw_spotted, kw_granite, kw_agate, kw_crackle, kw_average> {};
struct texture_name : indexed_name {};  // a declared texture
struct texture_entry
    : sor<pigment_block, normal_block, finish_block, transform_item, texture_pattern, texture_name, unsupported_item> {};
struct texture_end : rbrace {};
struct texture_block : if_must<kw_texture, block_open, entries<texture_entry>, texture_end> {};

// --- interior { Name  ior F  caustics F  fade_distance F  fade_power F  fade_color C } ---
struct ior_item : if_must<kw_ior, float_value> {};
struct caustics_item : if_must<kw_caustics, float_value> {};
struct dispersion_item : if_must<kw_dispersion, float_value> {};
struct dispersion_samples_item : if_must<kw_dispersion_samples, float_value> {};
struct interior_fade_distance_item : if_must<kw_fade_distance, float_value> {};
struct interior_fade_power_item : if_must<kw_fade_power, float_value> {};
struct fade_colour_item : if_must<sor<kw_fade_color, kw_fade_colour>, colour_value> {};
struct interior_name : indexed_name {};  // a declared interior
struct interior_entry : sor<ior_item, caustics_item, dispersion_item, dispersion_samples_item, interior_fade_distance_item, interior_fade_power_item,
                            fade_colour_item, interior_name, unsupported_item> {};
struct interior_end : rbrace {};
struct interior_block : if_must<kw_interior, block_open, entries<interior_entry>, interior_end> {};

// --- material { Name  texture {…}  interior {…}  transforms } ---------------------
struct material_name : indexed_name {};  // a declared material
struct material_entry : sor<texture_block, interior_block, transform_item, material_name, unsupported_item> {};
struct material_end : rbrace {};
struct material_block : if_must<kw_material, block_open, entries<material_entry>, material_end> {};

// --- what an object accepts ------------------------------------------------------
struct open_item : kw_open {};  // cones and cylinders only; the interpreter checks
struct no_shadow_item : kw_no_shadow {};
// hollow [on|off]: a boolean only where one plainly follows (a constant, a
// number or a parenthesis), as POV-Ray reads an optional float there.
struct hollow_start : success {};
struct hollow_value : seq<at<sor<constant, ascii::digit, one<'(', '!'>>>, expression> {};
struct hollow_item : seq<kw_hollow, hollow_start, opt<hollow_value>> {};
struct inverse_item : kw_inverse {};
struct sturm_item : kw_sturm {};  // a torus or a poly only; the interpreter checks
struct clipped_by_block;  // objects.hpp: they hold objects
struct bounded_by_block;
struct object_modifier : sor<pigment_block, normal_block, finish_block, texture_block, interior_block, material_block,
                             transform_item, no_shadow_item, open_item, hollow_item, inverse_item, sturm_item,
                             clipped_by_block, bounded_by_block, asos_block, unsupported_item> {};

}  // namespace asos::grammar
