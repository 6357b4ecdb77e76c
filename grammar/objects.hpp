#pragma once
// Scene items: camera, light_source, the objects, global_settings and
// background. An object's leading arguments are separated by optional commas,
// as in POV-Ray; `arguments_end` marks where they stop and modifiers begin.
#include "grammar/modifiers.hpp"

namespace asos::grammar {

struct arguments_end : success {};
struct object_end : rbrace {};
struct object_body : entries<object_modifier> {};

// --- shapes -------------------------------------------------------------------------
struct sphere_center : seq<expression> {};
struct sphere_radius : seq<expression> {};
struct sphere_block : if_must<kw_sphere, block_open, sphere_center, opt_comma, sphere_radius,
                              arguments_end, object_body, object_end> {};

struct box_corner : seq<expression> {};
struct box_block : if_must<kw_box, block_open, box_corner, opt_comma, box_corner, arguments_end,
                           object_body, object_end> {};

struct cone_base : seq<expression> {};
struct cone_base_radius : seq<expression> {};
struct cone_cap : seq<expression> {};
struct cone_cap_radius : seq<expression> {};
struct cone_block : if_must<kw_cone, block_open, cone_base, opt_comma, cone_base_radius, opt_comma,
                            cone_cap, opt_comma, cone_cap_radius, arguments_end, object_body,
                            object_end> {};

struct cylinder_base : seq<expression> {};
struct cylinder_cap : seq<expression> {};
struct cylinder_radius : seq<expression> {};
struct cylinder_block : if_must<kw_cylinder, block_open, cylinder_base, opt_comma, cylinder_cap,
                                opt_comma, cylinder_radius, arguments_end, object_body,
                                object_end> {};

struct disc_center : seq<expression> {};
struct disc_normal : seq<expression> {};
struct disc_radius : seq<expression> {};
struct disc_hole_radius : opt<opt_comma, expression> {};
struct disc_block : if_must<kw_disc, block_open, disc_center, opt_comma, disc_normal, opt_comma,
                            disc_radius, disc_hole_radius, arguments_end, object_body, object_end> {};

// polygon { N, <p1>, … <pN> }: the points become one Sequence node.
struct polygon_count : seq<expression> {};
struct polygon_point : seq<expression> {};
struct polygon_points : seq<sequence_start, polygon_point, star<opt_comma, expression>> {};
struct polygon_block : if_must<kw_polygon, block_open, polygon_count, opt_comma, polygon_points,
                               arguments_end, object_body, object_end> {};

struct plane_normal : seq<expression> {};
struct plane_distance : seq<expression> {};
struct plane_block : if_must<kw_plane, block_open, plane_normal, opt_comma, plane_distance,
                             arguments_end, object_body, object_end> {};

// quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }
struct quadric_squares : seq<expression> {};
struct quadric_mixed : seq<expression> {};
struct quadric_linear : seq<expression> {};
struct quadric_constant : seq<expression> {};
struct quadric_block : if_must<kw_quadric, block_open, quadric_squares, opt_comma, quadric_mixed, opt_comma,
                               quadric_linear, opt_comma, quadric_constant, arguments_end, object_body,
                               object_end> {};

// torus { R, r }
struct torus_major : seq<expression> {};
struct torus_minor : seq<expression> {};
struct torus_block : if_must<kw_torus, block_open, torus_major, opt_comma, torus_minor, arguments_end, object_body,
                             object_end> {};

// poly { N, <a0, a1, ...> }   quartic { <a0, ... a34> }   cubic { <a0, ... a19> }:
// the coefficients become one Sequence node (their count is the interpreter's
// check); POV-Ray reads the commas between them as optional.
struct poly_order : seq<expression> {};
struct poly_coefficient : seq<expression> {};
struct poly_next_coefficient : seq<expression> {};  // no message: its failure ends the list
struct poly_coefficients
    : if_must<vector_open, poly_coefficient, star<sor<seq<comma, poly_coefficient>, poly_next_coefficient>>,
              vector_close> {};
struct poly_block : if_must<kw_poly, block_open, poly_order, opt_comma, poly_coefficients, arguments_end,
                            object_body, object_end> {};
struct quartic_block : if_must<kw_quartic, block_open, poly_coefficients, arguments_end, object_body, object_end> {};
struct cubic_block : if_must<kw_cubic, block_open, poly_coefficients, arguments_end, object_body, object_end> {};

// text { ttf "font.ttf" "string" thickness, <offset> }
struct text_font : seq<expression> {};
struct text_string : seq<expression> {};
struct text_thickness : seq<expression> {};
struct text_offset : seq<expression> {};
struct text_block : if_must<kw_text, block_open, kw_ttf, text_font, opt_comma, text_string, opt_comma,
                            text_thickness, opt_comma, text_offset, arguments_end, object_body, object_end> {};

// prism { [linear_sweep | conic_sweep] [linear_spline | quadratic_spline |
//         cubic_spline | bezier_spline]  height1, height2, N, <p1>, … <pN> }
// (open and sturm are object modifiers): the sweep and spline words become
// one Sequence node, the points another.
struct prism_linear_sweep : kw_linear_sweep {};
struct prism_conic_sweep : kw_conic_sweep {};
struct prism_linear_spline : kw_linear_spline {};
struct prism_quadratic_spline : kw_quadratic_spline {};
struct prism_cubic_spline : kw_cubic_spline {};
struct prism_bezier_spline : kw_bezier_spline {};
struct prism_option : sor<prism_linear_sweep, prism_conic_sweep, prism_linear_spline, prism_quadratic_spline,
                          prism_cubic_spline, prism_bezier_spline> {};
struct prism_options : seq<sequence_start, star<prism_option>> {};
struct prism_height1 : seq<expression> {};
struct prism_height2 : seq<expression> {};
struct prism_count : seq<expression> {};
struct prism_point : seq<expression> {};
struct prism_points : seq<sequence_start, prism_point, star<opt_comma, expression>> {};
struct prism_block : if_must<kw_prism, block_open, prism_options, prism_height1, opt_comma, prism_height2, opt_comma,
                             prism_count, opt_comma, prism_points, arguments_end, object_body, object_end> {};

// triangle { <a>, <b>, <c> }   smooth_triangle { <a>, <na>, <b>, <nb>, <c>, <nc> }
struct triangle_corner : seq<expression> {};
struct triangle_block : if_must<kw_triangle, block_open, triangle_corner, opt_comma, triangle_corner, opt_comma,
                                triangle_corner, arguments_end, object_body, object_end> {};
struct smooth_triangle_corner : seq<expression> {};
struct smooth_triangle_normal : seq<expression> {};
struct smooth_triangle_block
    : if_must<kw_smooth_triangle, block_open, smooth_triangle_corner, opt_comma, smooth_triangle_normal, opt_comma,
              smooth_triangle_corner, opt_comma, smooth_triangle_normal, opt_comma, smooth_triangle_corner, opt_comma,
              smooth_triangle_normal, arguments_end, object_body, object_end> {};

// mesh { triangles…  modifiers… }: the triangles' entries (a macro called
// among them reads its body as a mesh's).
struct mesh_entry : sor<triangle_block, smooth_triangle_block, object_modifier> {};
struct mesh_end : rbrace {};
struct mesh_block : if_must<kw_mesh, block_open, arguments_end, entries<mesh_entry>, mesh_end> {};

// mesh2 { vertex_vectors { N, <v>… } [normal_vectors { N, <n>… }]
//         face_indices { N, <a, b, c>… } [normal_indices { N, <a, b, c>… }]  modifiers… }
// Each list is its count, then its items as entries (directives and macro
// calls may make them). POV-Ray's uv_vectors, texture_list and uv_indices are
// refused by name.
struct mesh2_count : seq<expression> {};
struct mesh2_item : seq<expression, opt_comma> {};
struct mesh2_list_end : rbrace {};
template <typename Keyword>
struct mesh2_list
    : if_must<Keyword, block_open, mesh2_count, opt_comma, arguments_end, entries<mesh2_item>, mesh2_list_end> {};
struct vertex_vectors_block : mesh2_list<kw_vertex_vectors> {};
struct normal_vectors_block : mesh2_list<kw_normal_vectors> {};
struct face_indices_block : mesh2_list<kw_face_indices> {};
struct normal_indices_block : mesh2_list<kw_normal_indices> {};
struct mesh2_block : if_must<kw_mesh2, block_open, vertex_vectors_block, opt<normal_vectors_block>,
                             opt<unsupported_item>, face_indices_block, opt<normal_indices_block>, arguments_end,
                             object_body, object_end> {};

// --- grouping ---------------------------------------------------------------------
// union { objects and lights…  modifiers… }
struct union_entry;
struct union_end : rbrace {};
struct union_block : if_must<kw_union, block_open, arguments_end, entries<union_entry>, union_end> {};
// difference | intersection | merge { objects and lights…  modifiers… }: the
// union's entries (a macro called among them reads its body as a union's).
struct difference_end : rbrace {};
struct difference_block
    : if_must<kw_difference, block_open, arguments_end, entries<union_entry>, difference_end> {};
struct intersection_end : rbrace {};
struct intersection_block
    : if_must<kw_intersection, block_open, arguments_end, entries<union_entry>, intersection_end> {};
struct merge_end : rbrace {};
struct merge_block : if_must<kw_merge, block_open, arguments_end, entries<union_entry>, merge_end> {};

// object { Name | A[i] | M(…) | an object,  modifiers… }
struct object_reference : seq<expression> {};
struct object_base : sor<object_statement, object_reference> {};
struct object_block : if_must<kw_object, block_open, object_base, arguments_end, object_body,
                              object_end> {};

struct object_statement : sor<sphere_block, box_block, cone_block, cylinder_block, disc_block,
                              polygon_block, plane_block, union_block, difference_block,
                              intersection_block, merge_block, object_block, quadric_block, torus_block, poly_block,
                              quartic_block, cubic_block, text_block, prism_block,
                              triangle_block, smooth_triangle_block, mesh_block, mesh2_block> {};

// clipped_by { objects… } | clipped_by { bounded_by }, and bounded_by { objects… } |
// bounded_by { clipped_by }: POV-Ray's clip and bound lists, or the link that
// makes one list serve as both.
struct clip_entry : sor<object_statement, transform_item, unsupported_item> {};
struct clip_link : kw_bounded_by {};   // in clipped_by: the bound's objects clip
struct bound_link : kw_clipped_by {};  // in bounded_by: the clip's objects bound
struct clip_end : rbrace {};
struct clip_body : sor<clip_link, entries<clip_entry>> {};
struct bound_body : sor<bound_link, entries<clip_entry>> {};
struct clipped_by_block : if_must<kw_clipped_by, block_open, clip_body, clip_end> {};
struct bounded_by_block : if_must<kw_bounded_by, block_open, bound_body, clip_end> {};

// --- light_source { <position>, colour  modifiers… } --------------------------------
struct light_position : seq<expression> {};
struct light_colour : opt<opt_comma, colour_in_place> {};  // absent only after a light identifier
struct area_light_item : if_must<kw_area_light, vector_value, opt_comma, vector_value, opt_comma,
                                 float_value, opt_comma, float_value> {};
struct adaptive_item : if_must<kw_adaptive, float_value> {};
struct jitter_item : kw_jitter {};
struct circular_item : kw_circular {};
struct orient_item : kw_orient {};
struct fade_distance_item : if_must<kw_fade_distance, float_value> {};
struct fade_power_item : if_must<kw_fade_power, float_value> {};
struct shadowless_item : kw_shadowless {};
// area_illumination [on|off]: POV-Ray's Allow_Float(1.0). Our `asos` is no
// reserved word, so it is not taken for the value.
struct area_illumination_start : kw_area_illumination {};
struct area_illumination_value : seq<expression> {};  // optional: no message of its own
struct area_illumination_item : seq<area_illumination_start, opt<not_at<kw_asos>, area_illumination_value>> {};
// spotlight | cylinder  parallel  point_at <p>  radius r  falloff f  tightness t
struct spotlight_item : kw_spotlight {};
struct cylinder_light : kw_cylinder {};
struct parallel_item : kw_parallel {};
struct point_at_item : if_must<kw_point_at, vector_value> {};
struct light_radius_item : if_must<kw_radius, float_value> {};
struct light_falloff_item : if_must<kw_falloff, float_value> {};
struct tightness_item : if_must<kw_tightness, float_value> {};
struct light_entry
    : sor<area_light_item, adaptive_item, jitter_item, circular_item, orient_item, fade_distance_item,
          fade_power_item, shadowless_item, area_illumination_item, spotlight_item, cylinder_light,
          parallel_item, point_at_item, light_radius_item, light_falloff_item, tightness_item, transform_item,
          asos_block, unsupported_item> {};
struct light_end : rbrace {};
struct light_source_block : if_must<kw_light_source, block_open, light_position, light_colour,
                                    arguments_end, entries<light_entry>, light_end> {};

struct union_entry : sor<object_statement, light_source_block, object_modifier> {};

// --- camera { perspective | orthographic  location …  look_at … } -------------------
struct perspective_item : kw_perspective {};
struct orthographic_item : kw_orthographic {};
struct location_item : if_must<kw_location, vector_value> {};
struct look_at_item : if_must<kw_look_at, vector_value> {};
struct angle_item : if_must<kw_angle, float_value> {};
struct right_item : if_must<kw_right, vector_value> {};
struct up_item : if_must<kw_up, vector_value> {};
struct direction_item : if_must<kw_direction, vector_value> {};
struct sky_item : if_must<kw_sky, vector_value> {};
struct cylinder_camera : kw_cylinder {};  // POV-Ray's cylindrical projection: not ours
struct camera_normal : kw_normal {};      // POV-Ray's perturbed camera rays: not ours
struct camera_name : indexed_name {};  // a declared camera
struct camera_entry
    : sor<perspective_item, orthographic_item, location_item, look_at_item, angle_item, right_item,
          up_item, direction_item, sky_item, transform_item, cylinder_camera, camera_normal, camera_name,
          unsupported_item> {};
struct camera_end : rbrace {};
struct camera_block : if_must<kw_camera, block_open, entries<camera_entry>, camera_end> {};

// --- global_settings { … }   background { colour } ----------------------------------
struct assumed_gamma_item : if_must<kw_assumed_gamma, float_value> {};
struct max_trace_level_item : if_must<kw_max_trace_level, float_value> {};
struct ambient_light_item : if_must<kw_ambient_light, colour_value> {};
struct global_entry
    : sor<assumed_gamma_item, max_trace_level_item, ambient_light_item, noise_generator_item, asos_block,
          unsupported_item> {};
struct global_settings_end : rbrace {};
struct global_settings_block
    : if_must<kw_global_settings, block_open, entries<global_entry>, global_settings_end> {};

struct background_colour : seq<colour_in_place> {};
struct background_end : rbrace {};
struct background_block
    : if_must<kw_background, block_open, background_colour, arguments_end, background_end> {};

// --- sky_sphere { pigment {…} … emission C transforms } --------------------------
struct emission_item : if_must<kw_emission, colour_value> {};
struct sky_sphere_name : indexed_name {};  // a declared sky_sphere, first in the block
struct sky_sphere_entry : sor<pigment_block, emission_item, transform_item, unsupported_item, sky_sphere_name> {};
struct sky_sphere_end : rbrace {};
struct sky_sphere_block : if_must<kw_sky_sphere, block_open, entries<sky_sphere_entry>, sky_sphere_end> {};

// --- fog { fog_type N distance D colour C fog_offset F fog_alt F up V
//           turbulence V octaves N omega F lambda F turb_depth F transforms } ----
// A bare colour is the fog's colour; a bare float its distance (POV-Ray
// warns "Should use distance keyword"); a declared fog, first, is the one
// this starts from (the interpreter tells them apart by value).
struct fog_type_item : if_must<kw_fog_type, float_value> {};
struct distance_item : if_must<kw_distance, float_value> {};
struct fog_offset_item : if_must<kw_fog_offset, float_value> {};
struct fog_alt_item : if_must<kw_fog_alt, float_value> {};
struct turb_depth_item : if_must<kw_turb_depth, float_value> {};
struct fog_colour : seq<colour_in_place> {};
struct fog_entry
    : sor<fog_type_item, distance_item, fog_offset_item, fog_alt_item, turb_depth_item, up_item, turbulence_item,
          octaves_item, omega_item, lambda_item, transform_item, unsupported_item, fog_colour> {};
struct fog_end : rbrace {};
struct fog_block : if_must<kw_fog, block_open, entries<fog_entry>, fog_end> {};

}  // namespace asos::grammar
