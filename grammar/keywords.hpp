#pragma once
// Keywords. A keyword never matches the front of a longer identifier
// (`spheres` is not `sphere`), and no keyword — ours or POV-Ray's — can be
// declared as an identifier. Big families (functions, constants, member
// names, colour items, unsupported POV-Ray words) are matched through the
// word table in asos/lang/words.hpp.
#include "grammar/lexical.hpp"

namespace asos::grammar {

#define ASOS_KEYWORD(rule, text) \
    struct rule : tok<TAO_PEGTL_KEYWORD(text)> {};

// scene items and objects
ASOS_KEYWORD(kw_camera, "camera")
ASOS_KEYWORD(kw_light_source, "light_source")
ASOS_KEYWORD(kw_sphere, "sphere")
ASOS_KEYWORD(kw_box, "box")
ASOS_KEYWORD(kw_cone, "cone")
ASOS_KEYWORD(kw_cylinder, "cylinder")
ASOS_KEYWORD(kw_disc, "disc")
ASOS_KEYWORD(kw_polygon, "polygon")
ASOS_KEYWORD(kw_plane, "plane")
ASOS_KEYWORD(kw_quadric, "quadric")
ASOS_KEYWORD(kw_torus, "torus")
ASOS_KEYWORD(kw_text, "text")
ASOS_KEYWORD(kw_ttf, "ttf")
ASOS_KEYWORD(kw_triangle, "triangle")
ASOS_KEYWORD(kw_smooth_triangle, "smooth_triangle")
ASOS_KEYWORD(kw_mesh, "mesh")
ASOS_KEYWORD(kw_mesh2, "mesh2")
ASOS_KEYWORD(kw_vertex_vectors, "vertex_vectors")
ASOS_KEYWORD(kw_normal_vectors, "normal_vectors")
ASOS_KEYWORD(kw_face_indices, "face_indices")
ASOS_KEYWORD(kw_normal_indices, "normal_indices")
ASOS_KEYWORD(kw_union, "union")
ASOS_KEYWORD(kw_difference, "difference")
ASOS_KEYWORD(kw_intersection, "intersection")
ASOS_KEYWORD(kw_merge, "merge")
ASOS_KEYWORD(kw_object, "object")
ASOS_KEYWORD(kw_global_settings, "global_settings")
ASOS_KEYWORD(kw_background, "background")
ASOS_KEYWORD(kw_sky_sphere, "sky_sphere")
ASOS_KEYWORD(kw_emission, "emission")
ASOS_KEYWORD(kw_fog, "fog")
ASOS_KEYWORD(kw_fog_type, "fog_type")
ASOS_KEYWORD(kw_distance, "distance")
ASOS_KEYWORD(kw_fog_offset, "fog_offset")
ASOS_KEYWORD(kw_fog_alt, "fog_alt")
ASOS_KEYWORD(kw_turb_depth, "turb_depth")
// camera
ASOS_KEYWORD(kw_perspective, "perspective")
ASOS_KEYWORD(kw_orthographic, "orthographic")
ASOS_KEYWORD(kw_location, "location")
ASOS_KEYWORD(kw_look_at, "look_at")
ASOS_KEYWORD(kw_angle, "angle")
ASOS_KEYWORD(kw_right, "right")
ASOS_KEYWORD(kw_up, "up")
ASOS_KEYWORD(kw_direction, "direction")
ASOS_KEYWORD(kw_sky, "sky")
// lights
ASOS_KEYWORD(kw_area_light, "area_light")
ASOS_KEYWORD(kw_adaptive, "adaptive")
ASOS_KEYWORD(kw_jitter, "jitter")
ASOS_KEYWORD(kw_circular, "circular")
ASOS_KEYWORD(kw_orient, "orient")
ASOS_KEYWORD(kw_fade_distance, "fade_distance")
ASOS_KEYWORD(kw_fade_power, "fade_power")
ASOS_KEYWORD(kw_fade_color, "fade_color")
ASOS_KEYWORD(kw_fade_colour, "fade_colour")
ASOS_KEYWORD(kw_interior, "interior")
ASOS_KEYWORD(kw_ior, "ior")
ASOS_KEYWORD(kw_metallic, "metallic")
ASOS_KEYWORD(kw_fresnel, "fresnel")
ASOS_KEYWORD(kw_falloff, "falloff")
ASOS_KEYWORD(kw_exponent, "exponent")
ASOS_KEYWORD(kw_reflection_exponent, "reflection_exponent")
ASOS_KEYWORD(kw_conserve_energy, "conserve_energy")
ASOS_KEYWORD(kw_refraction, "refraction")
ASOS_KEYWORD(kw_dispersion, "dispersion")
ASOS_KEYWORD(kw_deprecated, "deprecated")
ASOS_KEYWORD(kw_once, "once")
ASOS_KEYWORD(kw_dispersion_samples, "dispersion_samples")
ASOS_KEYWORD(kw_caustics, "caustics")
ASOS_KEYWORD(kw_material, "material")
ASOS_KEYWORD(kw_shadowless, "shadowless")
ASOS_KEYWORD(kw_area_illumination, "area_illumination")
ASOS_KEYWORD(kw_spotlight, "spotlight")
ASOS_KEYWORD(kw_parallel, "parallel")
ASOS_KEYWORD(kw_point_at, "point_at")
ASOS_KEYWORD(kw_radius, "radius")
ASOS_KEYWORD(kw_tightness, "tightness")
// modifiers
ASOS_KEYWORD(kw_open, "open")
ASOS_KEYWORD(kw_pigment, "pigment")
ASOS_KEYWORD(kw_finish, "finish")
ASOS_KEYWORD(kw_texture, "texture")
ASOS_KEYWORD(kw_translate, "translate")
ASOS_KEYWORD(kw_rotate, "rotate")
ASOS_KEYWORD(kw_scale, "scale")
ASOS_KEYWORD(kw_matrix, "matrix")
ASOS_KEYWORD(kw_no_shadow, "no_shadow")
ASOS_KEYWORD(kw_checker, "checker")
ASOS_KEYWORD(kw_brick, "brick")
ASOS_KEYWORD(kw_brick_size, "brick_size")
ASOS_KEYWORD(kw_mortar, "mortar")
ASOS_KEYWORD(kw_hollow, "hollow")
ASOS_KEYWORD(kw_sturm, "sturm")
ASOS_KEYWORD(kw_inverse, "inverse")
ASOS_KEYWORD(kw_gradient, "gradient")
ASOS_KEYWORD(kw_radial, "radial")
ASOS_KEYWORD(kw_onion, "onion")
ASOS_KEYWORD(kw_marble, "marble")
ASOS_KEYWORD(kw_wood, "wood")
ASOS_KEYWORD(kw_leopard, "leopard")
ASOS_KEYWORD(kw_bozo, "bozo")
ASOS_KEYWORD(kw_spotted, "spotted")
ASOS_KEYWORD(kw_granite, "granite")
ASOS_KEYWORD(kw_agate, "agate")
ASOS_KEYWORD(kw_agate_turb, "agate_turb")
ASOS_KEYWORD(kw_crackle, "crackle")
ASOS_KEYWORD(kw_form, "form")
ASOS_KEYWORD(kw_metric, "metric")
ASOS_KEYWORD(kw_offset, "offset")
ASOS_KEYWORD(kw_solid, "solid")
ASOS_KEYWORD(kw_turbulence, "turbulence")
ASOS_KEYWORD(kw_octaves, "octaves")
ASOS_KEYWORD(kw_omega, "omega")
ASOS_KEYWORD(kw_lambda, "lambda")
ASOS_KEYWORD(kw_ramp_wave, "ramp_wave")
ASOS_KEYWORD(kw_triangle_wave, "triangle_wave")
ASOS_KEYWORD(kw_sine_wave, "sine_wave")
ASOS_KEYWORD(kw_frequency, "frequency")
ASOS_KEYWORD(kw_phase, "phase")
ASOS_KEYWORD(kw_noise_generator, "noise_generator")
struct kw_colour_map : tok<sor<TAO_PEGTL_KEYWORD("color_map"), TAO_PEGTL_KEYWORD("colour_map")>> {};
ASOS_KEYWORD(kw_ambient, "ambient")
ASOS_KEYWORD(kw_diffuse, "diffuse")
ASOS_KEYWORD(kw_brilliance, "brilliance")
ASOS_KEYWORD(kw_phong, "phong")
ASOS_KEYWORD(kw_phong_size, "phong_size")
ASOS_KEYWORD(kw_specular, "specular")
ASOS_KEYWORD(kw_roughness, "roughness")
ASOS_KEYWORD(kw_reflection, "reflection")
ASOS_KEYWORD(kw_crand, "crand")
ASOS_KEYWORD(kw_normal, "normal")
ASOS_KEYWORD(kw_bumps, "bumps")
ASOS_KEYWORD(kw_dents, "dents")
ASOS_KEYWORD(kw_wrinkles, "wrinkles")
ASOS_KEYWORD(kw_ripples, "ripples")
ASOS_KEYWORD(kw_waves, "waves")
ASOS_KEYWORD(kw_bump_size, "bump_size")
ASOS_KEYWORD(kw_accuracy, "accuracy")
ASOS_KEYWORD(kw_assumed_gamma, "assumed_gamma")
ASOS_KEYWORD(kw_max_trace_level, "max_trace_level")
ASOS_KEYWORD(kw_ambient_light, "ambient_light")
// our extension
ASOS_KEYWORD(kw_asos, "asos")
ASOS_KEYWORD(kw_eps, "eps")
ASOS_KEYWORD(kw_highlights, "highlights")
ASOS_KEYWORD(kw_max, "max")
ASOS_KEYWORD(kw_emitter, "emitter")
ASOS_KEYWORD(kw_povray, "povray")
ASOS_KEYWORD(kw_panel, "panel")
// colours
struct kw_color : tok<sor<TAO_PEGTL_KEYWORD("color"), TAO_PEGTL_KEYWORD("colour")>> {};
// directives (after '#')
ASOS_KEYWORD(kw_declare, "declare")
ASOS_KEYWORD(kw_local, "local")
ASOS_KEYWORD(kw_undef, "undef")
ASOS_KEYWORD(kw_include, "include")
ASOS_KEYWORD(kw_if, "if")
ASOS_KEYWORD(kw_ifdef, "ifdef")
ASOS_KEYWORD(kw_ifndef, "ifndef")
ASOS_KEYWORD(kw_elseif, "elseif")
ASOS_KEYWORD(kw_else, "else")
ASOS_KEYWORD(kw_end, "end")
ASOS_KEYWORD(kw_while, "while")
ASOS_KEYWORD(kw_for, "for")
ASOS_KEYWORD(kw_version, "version")
ASOS_KEYWORD(kw_debug, "debug")
ASOS_KEYWORD(kw_warning, "warning")
ASOS_KEYWORD(kw_error, "error")
ASOS_KEYWORD(kw_macro, "macro")
ASOS_KEYWORD(kw_switch, "switch")
ASOS_KEYWORD(kw_case, "case")
ASOS_KEYWORD(kw_range, "range")
ASOS_KEYWORD(kw_break, "break")
ASOS_KEYWORD(kw_default, "default")
// values
ASOS_KEYWORD(kw_array, "array")

#undef ASOS_KEYWORD

// Families matched through the word table.
struct function_word : word_if<accept_class<lang::kFunction>> {};
struct function_name : tok<function_word> {};
struct constant_word : word_if<accept_class<lang::kConstant>> {};
struct constant : tok<constant_word> {};
struct member_word : word_if<accept_class<lang::kMember>> {};
struct member_name : tok<member_word> {};
struct colour_component_word : word_if<accept_class<lang::kColourItem>> {};
struct colour_component_name : tok<colour_component_word> {};
struct colour_whole_word : word_if<accept_class<lang::kColourWhole>> {};
struct colour_whole_name : tok<colour_whole_word> {};

// A POV-Ray keyword asos does not accept. Wherever it is met, its action
// reports "'isosurface' is not supported by asos" at the keyword.
struct unsupported_keyword : word_if<accept_unsupported> {};

}  // namespace asos::grammar
