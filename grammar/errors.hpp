#pragma once
// The one table of error messages. must_if raises with `error_message<Rule>`
// wherever Rule fails and refuses, at compile time, a rule under must<> that
// has none. After a message that starts with "expected", the parser says what
// it found instead ("…, found 'foo'").
//
// Rules that cannot fail (opt, star, success and sequences of those) get an
// empty message that is never shown: must<> instantiates raise() for them too.
//
// The second table, `rejection_message<Rule>`, holds what the parser reports
// when Rule MATCHES: the POV-Ray constructs asos does not support, named at
// their keyword. "{}" stands for the word that was met.
#include "asos/lang/parse.hpp"
#include "grammar/scene.hpp"

namespace asos::grammar {

// Which kind of entries each block body holds (a macro called among them reads
// its body as such entries), and what a body that does not fit is told. Every
// `entries<Entry>` needs its line here: the parser's actions refuse, at
// compile time, an Entry without one.
template <typename Entry>
struct body_context;
#define ASOS_BODY_CONTEXT(Entry, Context, Misfit)                        \
    template <>                                                          \
    struct body_context<Entry> {                                         \
        static constexpr lang::BodyContext value = lang::BodyContext::Context; \
        static constexpr const char* misfit = Misfit;                    \
    };
// clang-format off
ASOS_BODY_CONTEXT(value_entry, Value, "expected one value (an expression, an object, a light_source, a camera, a pigment, a finish, a texture or an array), as the macro is called for its value")
ASOS_BODY_CONTEXT(top_entry, Top, "expected a scene item (camera, light_source, an object, global_settings, background, sky_sphere, fog) or a directive, as the macro is called at the top of the scene")
ASOS_BODY_CONTEXT(object_modifier, ObjectModifier, "expected an object modifier, as the macro is called among an object's modifiers")
ASOS_BODY_CONTEXT(union_entry, Union, "expected an object, a light_source or an object modifier, as the macro is called in a union")
ASOS_BODY_CONTEXT(clip_entry, Clip, "expected an object, as the macro is called in clipped_by or bounded_by")
ASOS_BODY_CONTEXT(mesh_entry, Mesh, "expected a triangle, a smooth_triangle or an object modifier, as the macro is called in a mesh")
ASOS_BODY_CONTEXT(mesh2_item, Mesh2List, "expected a vector, as the macro is called in a mesh2's list")
ASOS_BODY_CONTEXT(light_entry, Light, "expected a light_source item, as the macro is called in a light_source")
ASOS_BODY_CONTEXT(camera_entry, Camera, "expected a camera item, as the macro is called in a camera")
ASOS_BODY_CONTEXT(pigment_entry, Pigment, "expected a colour, a pattern, a transform or a pattern modifier, as the macro is called in a pigment")
ASOS_BODY_CONTEXT(normal_entry, Normal, "expected a normal pattern, a transform or a pattern modifier, as the macro is called in a normal")
ASOS_BODY_CONTEXT(finish_entry, Finish, "expected a finish item, as the macro is called in a finish")
ASOS_BODY_CONTEXT(interior_entry, Interior, "expected an interior item, as the macro is called in an interior")
ASOS_BODY_CONTEXT(material_entry, Material, "expected texture, interior or a transform, as the macro is called in a material")
ASOS_BODY_CONTEXT(texture_entry, Texture, "expected pigment, normal, finish or a transform, as the macro is called in a texture")
ASOS_BODY_CONTEXT(sky_sphere_entry, SkySphere, "expected a declared sky_sphere, pigment, emission or a transform, as the macro is called in a sky_sphere")
ASOS_BODY_CONTEXT(fog_entry, Fog, "expected a fog item, as the macro is called in a fog")
ASOS_BODY_CONTEXT(global_entry, GlobalSettings, "expected a global setting, as the macro is called in global_settings")
ASOS_BODY_CONTEXT(asos_entry, Asos, "expected eps, max, jitter or highlights, as the macro is called in an asos block")
ASOS_BODY_CONTEXT(default_entry, Default, "expected texture, pigment, normal or finish, as the macro is called in #default")
// clang-format on
#undef ASOS_BODY_CONTEXT

namespace detail {
template <typename RuleT>
inline constexpr bool never_fails_rt = false;
template <typename Rule>
inline constexpr bool never_fails = never_fails_rt<typename Rule::rule_t>;
template <typename Rule>
inline constexpr bool never_fails_rt<internal::opt<Rule>> = true;
template <typename Rule>
inline constexpr bool never_fails_rt<internal::star<Rule>> = true;
template <>
inline constexpr bool never_fails_rt<internal::success> = true;
template <>
inline constexpr bool never_fails_rt<blank_run> = true;
template <typename... Rules>
inline constexpr bool never_fails_rt<internal::seq<Rules...>> = (never_fails<Rules> && ...);
}  // namespace detail

template <typename Rule>
inline constexpr const char* error_message = detail::never_fails<Rule> ? "" : nullptr;

// clang-format off
// lexical
template <> inline constexpr auto error_message<unterminated_comment> = "unterminated comment: no '*/' closes this '/*'";
template <> inline constexpr auto error_message<string_body> = "unterminated string: expected '\"' before the end of the line";
// expressions
template <> inline constexpr auto error_message<logical_expression> = "expected an expression";
template <> inline constexpr auto error_message<rparen> = "expected ')'";
template <> inline constexpr auto error_message<vector_components> = "expected a vector component";
template <> inline constexpr auto error_message<vector_component> = "expected a vector component";
template <> inline constexpr auto error_message<vector_close> = "expected ',' or '>' to close the vector";
template <> inline constexpr auto error_message<call_open> = "expected '(' after the function name";
template <> inline constexpr auto error_message<call_arguments> = "expected a function argument";
template <> inline constexpr auto error_message<call_argument> = "expected a function argument";
template <> inline constexpr auto error_message<colour_operand> = "expected a value after the colour keyword";
template <> inline constexpr auto error_message<colour_after_keyword> = "expected a colour after 'color'";
template <> inline constexpr auto error_message<member_name> = "expected a member name: x, y, z, t, u, v, red, green, blue, filter, transmit or gray";
template <> inline constexpr auto error_message<unary_operand> = "expected an operand";
template <> inline constexpr auto error_message<factor_operand> = "expected an operand";
template <> inline constexpr auto error_message<term_operand> = "expected an operand";
template <> inline constexpr auto error_message<comparison_operand> = "expected an operand";
template <> inline constexpr auto error_message<conjunction_operand> = "expected an operand";
template <> inline constexpr auto error_message<disjunction_operand> = "expected an operand";
template <> inline constexpr auto error_message<op_colon> = "expected ':' of the '?:' expression";
// functions
template <> inline constexpr auto error_message<internal_open> = "expected '(' after 'internal'";
template <> inline constexpr auto error_message<internal_number> = "expected the number of the internal function";
template <> inline constexpr auto error_message<function_parameter_list> = "expected the function's parameter names";
template <> inline constexpr auto error_message<function_parameter> = "expected a parameter name";
template <> inline constexpr auto error_message<function_open> = "expected '{' to open the function's body";
template <> inline constexpr auto error_message<function_pattern_open> = "expected '{' to open the function's body";
template <> inline constexpr auto error_message<function_body> = "expected the function's expression";
template <> inline constexpr auto error_message<function_expression> = "expected the function's expression";
template <> inline constexpr auto error_message<function_close> = "expected '}' to close the function";
// directives
template <> inline constexpr auto error_message<condition> = "expected a condition in parentheses";
template <> inline constexpr auto error_message<if_end> = "expected #elseif, #else or #end to close #if";
template <> inline constexpr auto error_message<while_end> = "expected #end to close #while";
template <> inline constexpr auto error_message<for_end> = "expected #end to close #for";
template <> inline constexpr auto error_message<ifdef_condition> = "expected '(' and an identifier";
template <> inline constexpr auto error_message<tested_name> = "expected an identifier";
template <> inline constexpr auto error_message<for_open> = "expected '(' after #for";
template <> inline constexpr auto error_message<for_variable> = "expected the name of the loop variable";
template <> inline constexpr auto error_message<for_comma> = "expected ','";
template <> inline constexpr auto error_message<for_value> = "expected an expression";
template <> inline constexpr auto error_message<declared_target> = "expected an identifier to declare";
template <> inline constexpr auto error_message<declare_equals> = "expected '='";
template <> inline constexpr auto error_message<declared_value> = "expected a value to declare: an expression, an object, a light_source, a camera, a pigment, a normal, a finish, a texture or an array";
template <> inline constexpr auto error_message<declare_semicolon> = "expected ';' after the declared value";
template <> inline constexpr auto error_message<undefined_name> = "expected an identifier";
template <> inline constexpr auto error_message<included_file> = "expected the name of the file to include";
template <> inline constexpr auto error_message<version_value> = "expected a version number";
template <> inline constexpr auto error_message<opened_handle> = "expected the name of the file handle to open, an identifier not declared";
template <> inline constexpr auto error_message<opened_file> = "expected the name of the file to open";
template <> inline constexpr auto error_message<open_mode> = "expected read, write or append after the file's name";
template <> inline constexpr auto error_message<closed_handle> = "expected the name of the file handle to close";
template <> inline constexpr auto error_message<file_open> = "expected '(' and the file handle";
template <> inline constexpr auto error_message<file_handle> = "expected the name of a file handle";
template <> inline constexpr auto error_message<read_close> = "expected the name of a variable to read into, or ')'";
template <> inline constexpr auto error_message<write_close> = "expected a value to write (a string, a float or a vector), or ')'";
template <> inline constexpr auto error_message<subscript_index> = "expected an array index";
template <> inline constexpr auto error_message<subscript_close> = "expected ']' after the array index";
template <> inline constexpr auto error_message<array_first_dimension> = "expected '[' and the size of the array after 'array'";
template <> inline constexpr auto error_message<array_size> = "expected the size of the array";
template <> inline constexpr auto error_message<array_size_close> = "expected ']' after the size of the array";
template <> inline constexpr auto error_message<initialiser_end> = "expected an element, ',' or '}' in the array's initialiser";
template <> inline constexpr auto error_message<macro_open> = "expected '(' after the name of the macro";
template <> inline constexpr auto error_message<macro_argument> = "expected an argument of the macro";
template <> inline constexpr auto error_message<macro_close> = "expected ',' or ')' after an argument of the macro";
template <> inline constexpr auto error_message<macro_defined_name> = "expected the name of the macro";
template <> inline constexpr auto error_message<macro_parameters_open> = "expected '(' and the macro's parameters";
template <> inline constexpr auto error_message<macro_parameters_close> = "expected a parameter name, ',' or ')'";
template <> inline constexpr auto error_message<macro_body_text> = "no #end closes the body of this #macro";
template <> inline constexpr auto error_message<macro_end> = "expected #end to close #macro";
template <> inline constexpr auto error_message<range_condition> = "expected '(', the low and the high end of the range, and ')'";
template <> inline constexpr auto error_message<range_comma> = "expected ',' between the ends of the range";
template <> inline constexpr auto error_message<switch_end> = "expected #case, #range, #else or #end in the #switch";
template <> inline constexpr auto error_message<default_end> = "expected texture, pigment, normal, finish or '}' in #default";
template <typename Entry> inline constexpr const char* error_message<switch_first_clause<Entry>> = "expected #case or #range after #switch";
template <> inline constexpr auto error_message<message_value> = "expected a message";
// modifiers
template <> inline constexpr auto error_message<float_value> = "expected a float expression";
template <> inline constexpr auto error_message<vector_value> = "expected a vector expression";
template <> inline constexpr auto error_message<colour_value> = "expected a colour expression";
template <> inline constexpr auto error_message<block_open> = "expected '{'";
template <> inline constexpr auto error_message<matrix_values> = "expected '<' and the 12 numbers of a matrix";
template <> inline constexpr auto error_message<matrix_components> = "expected a number of the matrix";
template <> inline constexpr auto error_message<matrix_value> = "expected a number of the matrix";
template <> inline constexpr auto error_message<matrix_close> = "expected ',' or '>' after the numbers of the matrix";
template <> inline constexpr auto error_message<asos_end> = "expected eps, max, jitter, highlights, emitter or '}' in the asos block";
template <> inline constexpr auto error_message<emitter_kind> = "expected povray or panel after emitter";
template <> inline constexpr auto error_message<pattern_second_colour<kw_checker>> = "expected the second colour of checker";
template <> inline constexpr auto error_message<pattern_second_colour<kw_brick>> = "expected the second colour of brick";
template <> inline constexpr auto error_message<pigment_end> = "expected a colour, a pattern (checker, brick, gradient, radial, onion, marble, wood, leopard, bozo, spotted, granite, agate, crackle), a transform, a pattern modifier or '}' in the pigment";
template <> inline constexpr auto error_message<map_entry_value> = "expected the value of the colour map entry";
template <> inline constexpr auto error_message<map_entry_colour> = "expected the colour of the colour map entry";
template <> inline constexpr auto error_message<map_entry_close> = "expected ']' to close the colour map entry";
template <> inline constexpr auto error_message<pigment_map_entry_close> = "expected a pigment's colour, pattern, modifier or transform, or ']' to close the pigment map entry";
template <> inline constexpr auto error_message<pigment_map_end> = "expected an entry '[value pigment]' or '}' in the pigment map";
template <> inline constexpr auto error_message<colour_map_end> = "expected an entry '[value colour]' or '}' in the colour map";
template <> inline constexpr auto error_message<reflection_value> = "expected a colour or a float after reflection";
template <> inline constexpr auto error_message<reflection_colours> = "expected a colour or a float in reflection { … }";
template <> inline constexpr auto error_message<reflection_block_end> = "expected fresnel, falloff, exponent, metallic or '}' in reflection { … }";
template <> inline constexpr auto error_message<normal_end> = "expected a normal pattern (bumps, dents, wrinkles, ripples, waves, or gradient, radial, onion, marble, wood, leopard, bozo, spotted, granite, agate, crackle), bump_size, accuracy, a transform, a pattern modifier or '}' in the normal";
template <> inline constexpr auto error_message<interior_end> = "expected an interior item (ior, dispersion, dispersion_samples, caustics, fade_distance, fade_power, fade_color) or '}'";
template <> inline constexpr auto error_message<material_end> = "expected texture, interior, a transform or '}'";
template <> inline constexpr auto error_message<deprecation_message> = "expected the message of a deprecated declaration, a string";
template <> inline constexpr auto error_message<finish_end> = "expected a finish item (ambient, diffuse, brilliance, phong, phong_size, specular, roughness, crand, reflection, reflection_exponent, metallic, conserve_energy) or '}'";
template <> inline constexpr auto error_message<texture_end> = "expected pigment, normal, finish, a transform or '}' in the texture";
// objects
template <> inline constexpr auto error_message<object_end> = "expected an object modifier or '}'";
template <> inline constexpr auto error_message<clip_body> = "expected objects or bounded_by in clipped_by";
template <> inline constexpr auto error_message<bound_body> = "expected objects or clipped_by in bounded_by";
template <> inline constexpr auto error_message<clip_end> = "expected an object or '}' (or one of bounded_by, clipped_by alone)";
template <> inline constexpr auto error_message<sphere_center> = "expected the center of the sphere";
template <> inline constexpr auto error_message<sphere_radius> = "expected the radius of the sphere";
template <> inline constexpr auto error_message<box_corner> = "expected a corner of the box";
template <> inline constexpr auto error_message<cone_base> = "expected the base point of the cone";
template <> inline constexpr auto error_message<cone_base_radius> = "expected the base radius of the cone";
template <> inline constexpr auto error_message<cone_cap> = "expected the cap point of the cone";
template <> inline constexpr auto error_message<cone_cap_radius> = "expected the cap radius of the cone";
template <> inline constexpr auto error_message<cylinder_base> = "expected the base point of the cylinder";
template <> inline constexpr auto error_message<cylinder_cap> = "expected the cap point of the cylinder";
template <> inline constexpr auto error_message<cylinder_radius> = "expected the radius of the cylinder";
template <> inline constexpr auto error_message<disc_center> = "expected the center of the disc";
template <> inline constexpr auto error_message<disc_normal> = "expected the normal of the disc";
template <> inline constexpr auto error_message<disc_radius> = "expected the radius of the disc";
template <> inline constexpr auto error_message<polygon_count> = "expected the number of points of the polygon";
template <> inline constexpr auto error_message<polygon_points> = "expected the points of the polygon";
template <> inline constexpr auto error_message<prism_options> = "expected the sweep or spline of the prism";
template <> inline constexpr auto error_message<prism_height1> = "expected the first height of the prism";
template <> inline constexpr auto error_message<prism_height2> = "expected the second height of the prism";
template <> inline constexpr auto error_message<prism_count> = "expected the number of points of the prism";
template <> inline constexpr auto error_message<prism_points> = "expected the points of the prism";
template <> inline constexpr auto error_message<polygon_point> = "expected a point of the polygon";
template <> inline constexpr auto error_message<plane_normal> = "expected the normal of the plane";
template <> inline constexpr auto error_message<plane_distance> = "expected the distance of the plane";
template <> inline constexpr auto error_message<quadric_squares> = "expected the quadric's <A, B, C> (of x^2, y^2, z^2)";
template <> inline constexpr auto error_message<quadric_mixed> = "expected the quadric's <D, E, F> (of xy, xz, yz)";
template <> inline constexpr auto error_message<quadric_linear> = "expected the quadric's <G, H, I> (of x, y, z)";
template <> inline constexpr auto error_message<quadric_constant> = "expected the quadric's constant J";
template <> inline constexpr auto error_message<torus_major> = "expected the torus' major radius";
template <> inline constexpr auto error_message<torus_minor> = "expected the torus' minor radius";
template <> inline constexpr auto error_message<poly_order> = "expected the poly's order (2 to 35)";
template <> inline constexpr auto error_message<poly_coefficients> = "expected the coefficients, as <a0, a1, ...>";
template <> inline constexpr auto error_message<poly_coefficient> = "expected a coefficient";
template <> inline constexpr auto error_message<kw_ttf> = "expected 'ttf' and a font file name ('internal' fonts are not supported by asos)";
template <> inline constexpr auto error_message<text_font> = "expected the text's font file name";
template <> inline constexpr auto error_message<text_string> = "expected the text's string";
template <> inline constexpr auto error_message<text_thickness> = "expected the text's thickness";
template <> inline constexpr auto error_message<text_offset> = "expected the text's offset vector";
template <> inline constexpr auto error_message<triangle_corner> = "expected a corner of the triangle";
template <> inline constexpr auto error_message<smooth_triangle_corner> = "expected a corner of the smooth_triangle";
template <> inline constexpr auto error_message<smooth_triangle_normal> = "expected the normal at the smooth_triangle's corner";
template <> inline constexpr auto error_message<mesh_end> = "expected a triangle, a smooth_triangle, an object modifier or '}' in the mesh";
template <> inline constexpr auto error_message<mesh2_count> = "expected the number of entries of the list";
template <> inline constexpr auto error_message<mesh2_list_end> = "expected a vector or '}' in the list";
template <> inline constexpr auto error_message<vertex_vectors_block> = "expected vertex_vectors { … }, a mesh2's first list";
template <> inline constexpr auto error_message<face_indices_block> = "expected face_indices { … } in the mesh2";
template <> inline constexpr auto error_message<union_end> = "expected an object, a light_source, an object modifier or '}' in the union";
template <> inline constexpr auto error_message<difference_end> = "expected an object, a light_source, an object modifier or '}' in the difference";
template <> inline constexpr auto error_message<intersection_end> = "expected an object, a light_source, an object modifier or '}' in the intersection";
template <> inline constexpr auto error_message<merge_end> = "expected an object, a light_source, an object modifier or '}' in the merge";
template <> inline constexpr auto error_message<object_base> = "expected an object or the name of a declared object";
template <> inline constexpr auto error_message<light_position> = "expected the position of the light";
template <> inline constexpr auto error_message<light_end> = "expected a light_source item or '}'";
template <> inline constexpr auto error_message<camera_end> = "expected a camera item or '}'";
template <> inline constexpr auto error_message<global_settings_end> = "expected assumed_gamma, max_trace_level, ambient_light, noise_generator, asos or '}' in global_settings";
template <> inline constexpr auto error_message<sky_sphere_end> = "expected pigment, emission, a transform or '}' in sky_sphere";
template <> inline constexpr auto error_message<fog_end> = "expected fog_type, distance, a colour, fog_offset, fog_alt, up, turbulence, octaves, omega, lambda, turb_depth, a transform or '}' in fog";
template <> inline constexpr auto error_message<background_colour> = "expected the colour of the background";
template <> inline constexpr auto error_message<background_end> = "expected '}' after the colour of the background";
// top
template <> inline constexpr auto error_message<end_of_file> = "expected a scene item (camera, light_source, an object, global_settings, background, sky_sphere, fog) or a directive";
template <> inline constexpr auto error_message<lone_expression> = "expected an expression";
// A macro's body that does not fit where the macro is called.
template <typename Entry> inline constexpr const char* error_message<macro_body_end<Entry>> = body_context<Entry>::misfit;
template <> inline constexpr auto error_message<end_of_expression> = "expected the end of the expression";

template <typename Rule> inline constexpr const char* rejection_message = nullptr;
template <> inline constexpr auto rejection_message<unsupported_item> = "'{}' is not supported by asos";
template <> inline constexpr auto rejection_message<unsupported_in_expression> = "'{}' is not supported by asos";
template <> inline constexpr auto rejection_message<unsupported_directive> = "'#{}' is not supported by asos";
template <> inline constexpr auto rejection_message<unknown_directive> = "unknown directive '#{}'";
template <> inline constexpr auto rejection_message<cylinder_camera> = "the 'cylinder' camera is not supported by asos";
template <> inline constexpr auto rejection_message<camera_normal> = "'normal' in a camera is not supported by asos";
template <> inline constexpr auto rejection_message<texture_pattern> = "texture patterns ('{}' of textures) are not supported by asos; use {} in the pigment";
template <> inline constexpr auto rejection_message<finish_emission> = "'{}' in a finish is not supported by asos";
template <> inline constexpr auto rejection_message<normal_pigment_map> = "'{}' can only be used in a pigment";
template <> inline constexpr auto rejection_message<normal_block_pattern> = "'{}' in a normal (a pattern of normals) is not supported by asos";
template <> inline constexpr auto rejection_message<pattern_of_textures<kw_checker>> = "'checker' of textures is not supported by asos; give checker two colours or two pigments";
template <> inline constexpr auto rejection_message<pattern_of_textures<kw_brick>> = "'brick' of textures is not supported by asos; give brick two colours or two pigments";
// clang-format on

struct errors {
    template <typename Rule>
    static constexpr const char* message = error_message<Rule>;
};

template <typename Rule>
using control = must_if<errors>::control<Rule>;

}  // namespace asos::grammar
