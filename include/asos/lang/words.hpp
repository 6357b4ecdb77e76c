#pragma once
// The vocabulary of the scene language: every keyword, built-in constant,
// function, member name and operator we accept, and the list of POV-Ray 3.7
// keywords we do not (so that they are rejected by name, never as a puzzling
// syntax error later). Shared by the grammar, the interpreter and the dump.
#include <cstdint>
#include <string_view>

namespace asos::lang {

// WORD(enumerator, spelling), one entry per spelling.
#define ASOS_LANG_WORDS(WORD)                                                                      \
    /* scene items and objects */                                                               \
    WORD(Camera, "camera") WORD(LightSource, "light_source") WORD(Sphere, "sphere") WORD(Box, "box")        \
    WORD(Cone, "cone") WORD(Cylinder, "cylinder") WORD(Disc, "disc") WORD(Polygon, "polygon")               \
    WORD(Plane, "plane") WORD(Union, "union") WORD(Difference, "difference") WORD(Intersection, "intersection") WORD(Merge, "merge") WORD(Object, "object") WORD(GlobalSettings, "global_settings") \
    WORD(Background, "background") WORD(SkySphere, "sky_sphere") WORD(Emission, "emission")       \
    WORD(Fog, "fog") WORD(FogType, "fog_type") WORD(Distance, "distance") WORD(FogOffset, "fog_offset") \
    WORD(FogAlt, "fog_alt") WORD(TurbDepth, "turb_depth")                                          \
    WORD(Quadric, "quadric")                                                                       \
    WORD(Torus, "torus") WORD(Sturm, "sturm")                                                      \
    WORD(Poly, "poly") WORD(Quartic, "quartic") WORD(Cubic, "cubic")                               \
    WORD(Text, "text") WORD(Ttf, "ttf")                                                            \
    WORD(Prism, "prism") WORD(LinearSweep, "linear_sweep") WORD(ConicSweep, "conic_sweep")       \
    WORD(LinearSpline, "linear_spline") WORD(QuadraticSpline, "quadratic_spline")                 \
    WORD(CubicSpline, "cubic_spline") WORD(BezierSpline, "bezier_spline")                         \
    WORD(Triangle, "triangle") WORD(SmoothTriangle, "smooth_triangle") WORD(Mesh, "mesh") WORD(Mesh2, "mesh2") \
    WORD(VertexVectors, "vertex_vectors") WORD(NormalVectors, "normal_vectors")                   \
    WORD(FaceIndices, "face_indices") WORD(NormalIndices, "normal_indices")                       \
    /* camera */                                                                                \
    WORD(Perspective, "perspective") WORD(Orthographic, "orthographic") WORD(Location, "location")       \
    WORD(LookAt, "look_at") WORD(Angle, "angle") WORD(Right, "right") WORD(Up, "up")                        \
    WORD(Direction, "direction") WORD(Sky, "sky")                                                     \
    /* lights */                                                                                \
    WORD(AreaLight, "area_light") WORD(Adaptive, "adaptive") WORD(Jitter, "jitter")                      \
    WORD(Circular, "circular") WORD(Orient, "orient") WORD(FadeDistance, "fade_distance")                \
    WORD(FadePower, "fade_power") WORD(Shadowless, "shadowless")                                      \
    WORD(AreaIllumination, "area_illumination") WORD(Spotlight, "spotlight") WORD(Parallel, "parallel")  \
    WORD(PointAt, "point_at") WORD(Radius, "radius") WORD(Tightness, "tightness")                     \
    /* object modifiers, pigments, finishes */                                                  \
    WORD(Open, "open") WORD(Pigment, "pigment") WORD(Finish, "finish") WORD(Texture, "texture")             \
    WORD(Translate, "translate") WORD(Rotate, "rotate") WORD(Scale, "scale") WORD(Matrix, "matrix")         \
    WORD(Interior, "interior") WORD(Ior, "ior") WORD(Caustics, "caustics") WORD(FadeColor, "fade_color")    \
    WORD(FadeColour, "fade_colour") WORD(Material, "material")                                     \
    WORD(NoShadow, "no_shadow") WORD(Asos, "asos") WORD(Eps, "eps") WORD(Highlights, "highlights")     \
    WORD(Emitter, "emitter") WORD(Povray, "povray") WORD(Panel, "panel") WORD(Checker, "checker")    \
    WORD(Brick, "brick") WORD(BrickSize, "brick_size") WORD(Mortar, "mortar")                          \
    WORD(Hollow, "hollow") WORD(Inverse, "inverse") WORD(ClippedBy, "clipped_by") WORD(BoundedBy, "bounded_by") WORD(ColorMap, "color_map") WORD(ColourMap, "colour_map")                      \
    WORD(Gradient, "gradient") WORD(Radial, "radial") WORD(Onion, "onion") WORD(Marble, "marble")          \
    WORD(Wood, "wood") WORD(Leopard, "leopard") WORD(Bozo, "bozo") WORD(Spotted, "spotted")                \
    WORD(Granite, "granite") WORD(Agate, "agate") WORD(AgateTurb, "agate_turb")                          \
    WORD(Average, "average") WORD(PigmentMap, "pigment_map")                                       \
    WORD(Crackle, "crackle") WORD(Form, "form") WORD(Metric, "metric") WORD(Offset, "offset")              \
    WORD(Solid, "solid")                                                                           \
    WORD(Turbulence, "turbulence") WORD(Octaves, "octaves") WORD(Omega, "omega") WORD(Lambda, "lambda")    \
    WORD(RampWave, "ramp_wave") WORD(TriangleWave, "triangle_wave") WORD(SineWave, "sine_wave")          \
    WORD(Frequency, "frequency") WORD(Phase, "phase") WORD(NoiseGenerator, "noise_generator")             \
    WORD(Ambient, "ambient") WORD(Diffuse, "diffuse") WORD(Brilliance, "brilliance") WORD(Phong, "phong")   \
    WORD(PhongSize, "phong_size") WORD(Specular, "specular") WORD(Roughness, "roughness")                \
    WORD(Reflection, "reflection") WORD(AssumedGamma, "assumed_gamma")                                \
    WORD(Crand, "crand") WORD(Metallic, "metallic") WORD(Fresnel, "fresnel") WORD(Falloff, "falloff")     \
    WORD(Exponent, "exponent") WORD(ReflectionExponent, "reflection_exponent")                        \
    WORD(ConserveEnergy, "conserve_energy") WORD(Refraction, "refraction")                           \
    WORD(Dispersion, "dispersion") WORD(DispersionSamples, "dispersion_samples")                      \
    WORD(Deprecated, "deprecated") WORD(Once, "once")                                               \
    WORD(Normal, "normal") WORD(Bumps, "bumps") WORD(Dents, "dents") WORD(Wrinkles, "wrinkles")        \
    WORD(Ripples, "ripples") WORD(Waves, "waves") WORD(BumpSize, "bump_size") WORD(Accuracy, "accuracy") \
    WORD(MaxTraceLevel, "max_trace_level") WORD(AmbientLight, "ambient_light")                        \
    /* colours */                                                                               \
    WORD(Color, "color") WORD(Colour, "colour") WORD(Rgb, "rgb") WORD(Rgbf, "rgbf") WORD(Rgbt, "rgbt")         \
    WORD(Rgbft, "rgbft") WORD(Red, "red") WORD(Green, "green") WORD(Blue, "blue") WORD(Filter, "filter")       \
    WORD(Transmit, "transmit") WORD(Gray, "gray") WORD(Grey, "grey")                                     \
    /* directives */                                                                            \
    WORD(Declare, "declare") WORD(Local, "local") WORD(Undef, "undef") WORD(Include, "include")             \
    WORD(If, "if") WORD(Ifdef, "ifdef") WORD(Ifndef, "ifndef") WORD(Elseif, "elseif") WORD(Else, "else")       \
    WORD(End, "end") WORD(While, "while") WORD(For, "for") WORD(Version, "version") WORD(Debug, "debug")       \
    WORD(Warning, "warning") WORD(Error, "error") WORD(Macro, "macro") WORD(Switch, "switch")            \
    WORD(Case, "case") WORD(Range, "range") WORD(Break, "break") WORD(Default, "default")                 \
    WORD(Fopen, "fopen") WORD(Fclose, "fclose") WORD(Read, "read") WORD(Write, "write") WORD(Append, "append") \
    /* arrays */                                                                                \
    WORD(Array, "array")                                                                           \
    /* built-in constants */                                                                    \
    WORD(X, "x") WORD(Y, "y") WORD(Z, "z") WORD(T, "t") WORD(U, "u") WORD(V, "v") WORD(Pi, "pi") WORD(Clock, "clock")   \
    WORD(ClockDelta, "clock_delta") WORD(ClockOn, "clock_on") WORD(True, "true") WORD(False, "false")       \
    WORD(On, "on") WORD(Off, "off") WORD(Yes, "yes") WORD(No, "no") WORD(ImageWidth, "image_width")            \
    WORD(ImageHeight, "image_height") WORD(FrameNumber, "frame_number") WORD(InitialClock, "initial_clock") \
    WORD(FinalClock, "final_clock") WORD(InitialFrame, "initial_frame") WORD(FinalFrame, "final_frame")   \
    /* functions */                                                                             \
    WORD(Abs, "abs") WORD(Sqrt, "sqrt") WORD(Pow, "pow") WORD(Sin, "sin") WORD(Cos, "cos") WORD(Tan, "tan")       \
    WORD(Asin, "asin") WORD(Acos, "acos") WORD(Atan, "atan") WORD(Atan2, "atan2") WORD(Sinh, "sinh")           \
    WORD(Cosh, "cosh") WORD(Tanh, "tanh") WORD(Asinh, "asinh") WORD(Acosh, "acosh") WORD(Atanh, "atanh")       \
    WORD(Min, "min") WORD(Max, "max") WORD(Mod, "mod") WORD(Floor, "floor") WORD(Ceil, "ceil") WORD(Int, "int")   \
    WORD(Div, "div") WORD(Sqr, "sqr") WORD(Radians, "radians") WORD(Degrees, "degrees") WORD(Exp, "exp")       \
    WORD(Log, "log") WORD(Ln, "ln") WORD(Vlength, "vlength") WORD(Vnormalize, "vnormalize")                 \
    WORD(Vcross, "vcross") WORD(Vdot, "vdot") WORD(Vrotate, "vrotate") WORD(VaxisRotate, "vaxis_rotate")    \
    WORD(Select, "select") WORD(Concat, "concat") WORD(Str, "str") WORD(Chr, "chr") WORD(Strlen, "strlen")     \
    WORD(Val, "val") WORD(Defined, "defined") WORD(Substr, "substr") WORD(Strcmp, "strcmp")              \
    WORD(Vstr, "vstr") WORD(Asc, "asc") WORD(Strupr, "strupr") WORD(Strlwr, "strlwr") WORD(Rand, "rand")        \
    WORD(Seed, "seed") WORD(Dimensions, "dimensions") WORD(DimensionSize, "dimension_size")            \
    WORD(Sum, "sum") WORD(Prod, "prod") WORD(FileExists, "file_exists")                               \
    /* user-defined functions */                                                                \
    WORD(Function, "function") WORD(Internal, "internal")                                          \
    /* operators (spelled as written) */                                                        \
    WORD(OpAdd, "+") WORD(OpSub, "-") WORD(OpMul, "*") WORD(OpDiv, "/") WORD(OpNot, "!") WORD(OpLess, "<")        \
    WORD(OpLessEqual, "<=") WORD(OpEqual, "=") WORD(OpNotEqual, "!=") WORD(OpGreaterEqual, ">=")            \
    WORD(OpGreater, ">") WORD(OpAnd, "&") WORD(OpOr, "|")

enum class Word : std::uint16_t {
    None,
#define ASOS_LANG_WORD_ENUM(id, text) id,
    ASOS_LANG_WORDS(ASOS_LANG_WORD_ENUM)
#undef ASOS_LANG_WORD_ENUM
        Count
};

// What a word may be used as, beyond a plain keyword.
enum WordClass : std::uint8_t {
    kKeyword = 1,     // reserved: never a user identifier
    kFunction = 2,    // abs(…)
    kConstant = 4,    // x, pi, clock, on, …
    kMember = 8,      // V.x, C.red
    kColourItem = 16, // a colour component: red F, filter F, …
    kColourWhole = 32, // a whole colour: rgb V, rgbf V, rgbt V, rgbft V
};

struct WordInfo {
    std::string_view text;
    Word word = Word::None;
    std::uint8_t classes = 0;
};

// The spelling of a word, e.g. "light_source" or "<=".
std::string_view wordText(Word w);
// The word spelled `text`, or null when `text` is not one of ours.
const WordInfo* lookupWord(std::string_view text);
// True when `text` is a POV-Ray 3.7 keyword that asos does not accept.
bool isUnsupportedKeyword(std::string_view text);
// True when `text` names a POV-Ray directive that asos does not accept (macro, switch, …).
bool isUnsupportedDirective(std::string_view text);
// True when `text` may not be used as an identifier (ours or POV-Ray's).
bool isReservedWord(std::string_view text);

}  // namespace asos::lang
