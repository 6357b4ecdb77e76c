#include "asos/lang/words.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace asos::lang {

namespace {

constexpr std::string_view kTexts[] = {
    "",
#define ASOS_LANG_WORD_TEXT(id, text) text,
    ASOS_LANG_WORDS(ASOS_LANG_WORD_TEXT)
#undef ASOS_LANG_WORD_TEXT
};
static_assert(std::size(kTexts) == static_cast<std::size_t>(Word::Count));

std::uint8_t classesOf(Word w) {
    switch (w) {
    case Word::Abs: case Word::Sqrt: case Word::Pow: case Word::Sin: case Word::Cos:
    case Word::Tan: case Word::Asin: case Word::Acos: case Word::Atan: case Word::Atan2:
    case Word::Sinh: case Word::Cosh: case Word::Tanh: case Word::Asinh: case Word::Acosh:
    case Word::Atanh: case Word::Min: case Word::Max: case Word::Mod: case Word::Floor:
    case Word::Ceil: case Word::Int: case Word::Div: case Word::Sqr: case Word::Radians:
    case Word::Degrees: case Word::Exp: case Word::Log: case Word::Ln: case Word::Vlength:
    case Word::Vnormalize: case Word::Vcross: case Word::Vdot: case Word::Vrotate:
    case Word::VaxisRotate: case Word::Select: case Word::Concat: case Word::Str:
    case Word::Chr: case Word::Strlen: case Word::Val: case Word::Defined: case Word::Substr:
    case Word::Strcmp: case Word::Vstr: case Word::Asc: case Word::Strupr: case Word::Strlwr:
    case Word::Rand: case Word::Seed: case Word::Dimensions: case Word::DimensionSize:
    case Word::Sum: case Word::Prod: case Word::FileExists:
        return kKeyword | kFunction;
    case Word::X: case Word::Y: case Word::Z: case Word::T: case Word::U: case Word::V:
        return kKeyword | kConstant | kMember;
    case Word::Pi: case Word::Clock: case Word::ClockDelta: case Word::ClockOn:
    case Word::Version: case Word::True: case Word::False: case Word::On: case Word::Off:
    case Word::Yes: case Word::No: case Word::ImageWidth: case Word::ImageHeight:
    case Word::FrameNumber: case Word::InitialClock: case Word::FinalClock: case Word::InitialFrame:
    case Word::FinalFrame:
        return kKeyword | kConstant;
    case Word::Rgb: case Word::Rgbf: case Word::Rgbt: case Word::Rgbft:
        return kKeyword | kColourWhole;
    case Word::Red: case Word::Green: case Word::Blue: case Word::Filter: case Word::Transmit:
        return kKeyword | kColourItem | kMember;
    case Word::Gray: case Word::Grey:
        return kKeyword | kMember;
    case Word::Asos: case Word::Eps: case Word::Highlights: case Word::Emitter: case Word::Povray: case Word::Panel:
        // Our extension's words are not POV-Ray's: they stay usable as identifiers
        // (a POV-Ray scene may well `#declare eps = …`).
        return 0;
    default:
        return kKeyword;
    }
}

// Our words that are identifiers (operators are not), sorted by spelling.
const std::vector<WordInfo>& wordTable() {
    static const std::vector<WordInfo> table = [] {
        std::vector<WordInfo> t;
        for (std::size_t i = 1; i < std::size(kTexts); ++i) {
            const char c = kTexts[i].front();
            if ((c >= 'a' && c <= 'z') || c == '_')
                t.push_back({kTexts[i], static_cast<Word>(i), classesOf(static_cast<Word>(i))});
        }
        std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return a.text < b.text; });
        return t;
    }();
    return table;
}

// Every reserved word of POV-Ray 3.7 (its "Reserved Keywords" list).
constexpr std::string_view kPovrayKeywords[] = {
    "aa_level", "aa_threshold", "abs", "absorption", "accuracy", "acos", "acosh", "adaptive",
    "adc_bailout", "agate", "agate_turb", "albedo", "all", "all_intersections", "alpha",
    "altitude", "always_sample", "ambient", "ambient_light", "angle", "aoi", "aperture", "append",
    "arc_angle", "area_illumination", "area_light", "array", "asc", "ascii", "asin", "asinh",
    "assumed_gamma", "atan", "atan2", "atanh", "autostop", "average", "b_spline", "background",
    "bezier_spline", "bicubic_patch", "bitwise_and", "bitwise_or", "bitwise_xor", "black_hole",
    "blob", "blue", "blur_samples", "bokeh", "bounded_by", "box", "boxed", "bozo", "break",
    "brick", "brick_size", "brightness", "brilliance", "bump_map", "bump_size", "bumps", "camera",
    "case", "caustics", "ceil", "cells", "charset", "checker", "chr", "circular", "clipped_by",
    "clock", "clock_delta", "clock_on", "collect", "color", "color_map", "colour", "colour_map",
    "component", "composite", "concat", "cone", "confidence", "conic_sweep", "conserve_energy",
    "contained_by", "control0", "control1", "coords", "cos", "cosh", "count", "crackle", "crand",
    "cube", "cubic", "cubic_spline", "cubic_wave", "cutaway_textures", "cylinder", "cylindrical",
    "datetime", "debug", "declare", "default", "defined", "degrees", "density", "density_file",
    "density_map", "dents", "deprecated", "df3", "difference", "diffuse", "dimension_size",
    "dimensions", "direction", "disc", "dispersion", "dispersion_samples", "dist_exp", "distance",
    "div", "double_illuminate", "eccentricity", "else", "elseif", "emission", "end", "error",
    "error_bound", "evaluate", "exp", "expand_thresholds", "exponent", "exterior", "extinction",
    "face_indices", "facets", "fade_color", "fade_colour", "fade_distance", "fade_power",
    "falloff", "falloff_angle", "false", "fclose", "file_exists", "filter", "final_clock",
    "final_frame", "finish", "fisheye", "flatness", "flip", "floor", "focal_point", "fog",
    "fog_alt", "fog_offset", "fog_type", "fopen", "for", "form", "frame_number", "frequency",
    "fresnel", "function", "gather", "gif", "global_lights", "global_settings", "gradient",
    "granite", "gray", "gray_threshold", "green", "grey", "height_field", "hexagon", "hf_gray_16",
    "hierarchy", "hollow", "hypercomplex", "if", "ifdef", "iff", "ifndef", "image_height",
    "image_map", "image_pattern", "image_width", "importance", "include", "initial_clock",
    "initial_frame", "inside", "inside_vector", "int", "interior", "interior_texture", "internal",
    "interpolate", "intersection", "intervals", "inverse", "ior", "irid", "irid_wavelength",
    "isosurface", "jitter", "jpeg", "julia", "julia_fractal", "lambda", "lathe", "leopard",
    "light_group", "light_source", "linear_spline", "linear_sweep", "ln", "load_file", "local",
    "location", "log", "look_at", "looks_like", "low_error_factor", "macro", "magnet",
    "major_radius", "mandel", "map_type", "marble", "material", "material_map", "matrix", "max",
    "max_extent", "max_gradient", "max_intersections", "max_iteration", "max_sample", "max_trace",
    "max_trace_level", "maximum_reuse", "media", "media_attenuation", "media_interaction", "merge",
    "mesh", "mesh2", "mesh_camera", "metallic", "method", "metric", "min", "min_extent",
    "minimum_reuse", "mm_per_unit", "mod", "mortar", "natural_spline", "nearest_count", "no",
    "no_bump_scale", "no_image", "no_radiosity", "no_reflection", "no_shadow", "noise_generator",
    "normal", "normal_indices", "normal_map", "normal_vectors", "now", "number_of_waves", "object",
    "octaves", "off", "offset", "omega", "omnimax", "on", "once", "onion", "open", "orient",
    "orientation", "orthographic", "ovus", "panoramic", "parallel", "parametric", "pass_through",
    "pattern", "perspective", "pgm", "phase", "phong", "phong_size", "photons", "pi", "pigment",
    "pigment_map", "pigment_pattern", "planar", "plane", "png", "point_at", "poly", "poly_wave",
    "polygon", "polynomial", "pot", "pow", "ppm", "precision", "precompute", "premultiplied",
    "pretrace_end", "pretrace_start", "prism", "prod", "projected_through", "pwr",
    "quadratic_spline", "quadric", "quartic", "quaternion", "quick_color", "quick_colour",
    "quilted", "radial", "radians", "radiosity", "radius", "rainbow", "ramp_wave", "rand", "range",
    "ratio", "read", "reciprocal", "recursion_limit", "red", "reflection", "reflection_exponent",
    "refraction", "render", "repeat", "rgb", "rgbf", "rgbft", "rgbt", "right", "ripples",
    "rotate", "roughness", "samples", "save_file", "scale", "scallop_wave", "scattering", "seed",
    "select", "shadowless", "sin", "sine_wave", "sinh", "sint16be", "sint16le", "sint32be",
    "sint32le", "sint8", "size", "sky", "sky_sphere", "slice", "slope", "slope_map", "smooth",
    "smooth_triangle", "solid", "sor", "spacing", "specular", "sphere", "sphere_sweep",
    "spherical", "spiral1", "spiral2", "spline", "split_union", "spotlight", "spotted", "sqr",
    "sqrt", "srgb", "srgbf", "srgbft", "srgbt", "statistics", "str", "strcmp", "strength",
    "strlen", "strlwr", "strupr", "sturm", "substr", "subsurface", "sum", "superellipsoid",
    "switch", "sys", "t", "tan", "tanh", "target", "text", "texture", "texture_list",
    "texture_map", "tga", "thickness", "threshold", "tiff", "tightness", "tile2", "tiles",
    "tiling", "tolerance", "toroidal", "torus", "trace", "transform", "translate", "translucency",
    "transmit", "triangle", "triangle_wave", "true", "ttf", "turb_depth", "turbulence", "type",
    "u", "u_steps", "uint16be", "uint16le", "uint8", "ultra_wide_angle", "undef", "union", "up",
    "use_alpha", "use_color", "use_colour", "use_index", "utf8", "uv", "uv_indices", "uv_mapping",
    "uv_vectors", "v", "v_steps", "val", "variance", "vaxis_rotate", "vcross", "vdot", "version",
    "vertex_vectors", "vlength", "vnormalize", "vrotate", "vstr", "vturbulence", "warning", "warp",
    "water_level", "waves", "while", "width", "wood", "wrinkles", "write", "x", "y", "yes", "z",
};

constexpr std::string_view kUnsupportedDirectives[] = {
    "render", "statistics",
};

// POV-Ray's keywords minus ours, sorted.
const std::vector<std::string_view>& unsupportedTable() {
    static const std::vector<std::string_view> table = [] {
        std::vector<std::string_view> t;
        for (std::string_view k : kPovrayKeywords)
            if (!lookupWord(k)) t.push_back(k);
        std::sort(t.begin(), t.end());
        return t;
    }();
    return table;
}

}  // namespace

std::string_view wordText(Word w) {
    const auto i = static_cast<std::size_t>(w);
    return i < std::size(kTexts) ? kTexts[i] : std::string_view{};
}

const WordInfo* lookupWord(std::string_view text) {
    const auto& t = wordTable();
    auto it = std::lower_bound(t.begin(), t.end(), text,
                               [](const WordInfo& a, std::string_view b) { return a.text < b; });
    return it != t.end() && it->text == text ? &*it : nullptr;
}

bool isUnsupportedKeyword(std::string_view text) {
    const auto& t = unsupportedTable();
    return std::binary_search(t.begin(), t.end(), text);
}

bool isUnsupportedDirective(std::string_view text) {
    return std::find(std::begin(kUnsupportedDirectives), std::end(kUnsupportedDirectives), text) !=
           std::end(kUnsupportedDirectives);
}

bool isReservedWord(std::string_view text) {
    const WordInfo* w = lookupWord(text);
    return (w && (w->classes & kKeyword)) || isUnsupportedKeyword(text);
}

}  // namespace asos::lang
