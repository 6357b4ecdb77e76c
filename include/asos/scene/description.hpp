#pragma once
// The scene description: plain data produced by the interpreter and consumed
// by every later stage (dump writer, scene build, renderer). No text, no
// behaviour. Every record keeps the SourceLoc it came from. Field meanings and
// defaults are POV-Ray 3.7's unless a comment says otherwise.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "asos/diag/source_loc.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/scene/function_program.hpp"

namespace asos {

// rgb plus POV-Ray's filter and transmit.
struct Color {
    Vec3 rgb{0.0};
    double filter = 0.0;
    double transmit = 0.0;
    bool operator==(const Color&) const = default;
};

// What an area light's points are (docs/lights.md, "The light model"):
// POV-Ray's isotropic point lights, shaded once along the direction of the
// light's centre (the default), or the paper's emitters, each element
// shaded along its own direction (a Lambertian panel for a rectangle).
enum class LightEmitter { Povray, Panel };

// Our extension, `asos { eps E max M jitter on|off highlights on|off }`:
// unset fields inherit (object/light -> global_settings -> command line ->
// built-in defaults).
// A light's block may also say `emitter povray|panel` (no inheritance: the
// default is POV-Ray's).
struct AsosOptions {
    std::optional<double> eps;
    std::optional<int> maxLevel;
    std::optional<bool> jitter;
    std::optional<bool> highlights;
    std::optional<LightEmitter> emitter;
    bool operator==(const AsosOptions&) const = default;
};

struct Camera {
    enum class Projection { Perspective, Orthographic };
    Projection projection = Projection::Perspective;
    // Final vectors after look_at, angle and sky have been applied; the image
    // plane is spanned by right and up at location + direction.
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};
    Vec3 right{1.33, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    SourceLoc loc;
};

struct AreaLight {
    Vec3 axis1{0.0};
    Vec3 axis2{0.0};
    int size1 = 1;
    int size2 = 1;
    // POV-Ray's `adaptive n`; absent, every point of the grid is sampled
    // (POV-Ray's default Adaptive_Level of 100 subdivides to the full grid).
    std::optional<int> adaptive;
    bool jitter = false;
    bool circular = false;
    bool orient = false;
};

// POV-Ray's light types: a point light, a spotlight (a cone of light toward
// point_at) and a cylinder light (a parallel beam around the axis from the
// position toward point_at).
enum class LightType { Point, Spot, Cylinder };

struct Light {
    Vec3 position{0.0};
    Vec3 color{1.0};  // total power, as in POV-Ray
    std::optional<AreaLight> area;
    LightType type = LightType::Point;
    // spotlight / cylinder, as written: radius and falloff are the cone's
    // half-angles in degrees for a spotlight (POV-Ray's defaults 30 and 45),
    // distances from the axis for a cylinder (0.75 and 1); tightness is the
    // power of the cosine (spotlight) or of 1 - distance / falloff
    // (cylinder), 0 by default. lights/light_beam.hpp has the factor.
    Vec3 pointAt{0.0, 0.0, 1.0};
    double radius = 0.0, falloff = 0.0, tightness = 0.0;
    // POV-Ray's `parallel` (a cylinder light is parallel): light arrives
    // along pointAt - position everywhere, from the plane through the
    // position square to it.
    bool parallel = false;
    double fadeDistance = 0.0;  // 0: no fade
    double fadePower = 0.0;
    bool shadowless = false;
    // POV-Ray 3.7's area_illumination: each point of an area light shaded
    // along its own direction (without it, once along the centre's).
    bool areaIllumination = false;
    AsosOptions asos;
    SourceLoc loc;
};

// Shapes in object space, parameters as written in the scene.
struct SphereShape { Vec3 center{0.0}; double radius = 1.0; };
struct BoxShape { Vec3 corner1{0.0}; Vec3 corner2{1.0}; };
struct ConeShape {
    Vec3 base{0.0}; double baseRadius = 1.0;
    Vec3 cap{0.0, 1.0, 0.0}; double capRadius = 0.0;
    bool open = false;
};
struct CylinderShape { Vec3 base{0.0}; Vec3 cap{0.0, 1.0, 0.0}; double radius = 1.0; bool open = false; };
struct DiscShape { Vec3 center{0.0}; Vec3 normal{0.0, 1.0, 0.0}; double radius = 1.0; double holeRadius = 0.0; };
// POV-Ray's vertex-list form, points as written (2-D points have z = 0): a
// sub-polygon is closed by repeating its first vertex; the last one may be left
// open. Its shape checks (validate, shapes/polygon.hpp): at least 3 points,
// not all on one line, all in one plane.
struct PolygonShape { std::vector<Vec3> points; };
// POV-Ray normalises the normal and keeps the distance: the plane is
// {p : dot(normalize(normal), p) = distance}, its inside on the -normal side.
struct PlaneShape { Vec3 normal{0.0, 1.0, 0.0}; double distance = 0.0; };

// POV-Ray's quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }: the points
// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, its
// inside where the sum is negative.
struct QuadricShape {
    Vec3 squares{0.0};  // A, B, C
    Vec3 mixed{0.0};    // D, E, F
    Vec3 linear{0.0};   // G, H, I
    double constant = 0.0;  // J
};

// POV-Ray's torus { R, r }: the points at distance r from the circle of radius
// R about the y axis in y = 0; `sturm` as written (the roots are found
// robustly either way).
struct TorusShape { double major = 1.0; double minor = 0.5; bool sturm = false; };

// POV-Ray's poly { N, <a0, a1, ...> } (quartic: N = 4, cubic: N = 3): the
// points where the sum of a_n x^i y^j z^k is 0, its inside where the sum is
// negative. The terms run in POV-Ray's order: i from N down to 0, within it j
// from N - i down, within that k from N - i - j down (35 terms for a quartic:
// x^4, x^3 y, x^3 z, x^3, x^2 y^2, ..., z, 1). `sturm` and the keyword as written
// (the roots are found robustly either way).
struct PolyShape {
    static constexpr int kMaxOrder = 35;  // POV-Ray 3.7's MAX_ORDER
    static constexpr int termCount(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }
    int order = 4;
    std::vector<double> coefficients;
    bool sturm = false;
    const char* keyword = "poly";  // "poly", "quartic" or "cubic"
};

// POV-Ray's triangle, smooth_triangle, mesh and mesh2, all as faces over a
// shared list of vertices (and of normals for smooth faces), in object space
// as written: a mesh's triangles are one Object each (TriangleShape), so that
// the scene's BVH holds them and the tracer classifies cones against each.
struct TriangleMesh {
    struct Face {
        std::array<std::uint32_t, 3> vertex{};
        std::array<std::uint32_t, 3> normal{};  // smooth faces only
        bool smooth = false;
    };
    std::vector<Vec3> vertices;
    std::vector<Vec3> normals;  // unit
    std::vector<Face> faces;
};
// One face of a mesh (a lone triangle is a mesh of one).
struct TriangleShape {
    std::shared_ptr<const TriangleMesh> mesh;
    std::uint32_t face = 0;
};

// A closed outline swept along y (POV-Ray's prism, and each glyph of its
// text): closed contours of Bezier pieces in the plane (x, z), each piece of
// degree 1 (a line), 2 or 3 with its degree + 1 control points, between the
// planes y = y0 and y = y1 (y0 < y1). Its inside is the even-odd rule's
// (shapes/extrusion.hpp). `keyword` names it ("prism", "text").
struct OutlinePiece {
    int degree = 1;
    std::array<double, 8> p{};  // x0, z0, x1, z1, ... (degree + 1 points)
};
struct OutlineContour { std::vector<OutlinePiece> pieces; };
struct ExtrusionShape {
    std::shared_ptr<const std::vector<OutlineContour>> outline;
    double y0 = 0.0, y1 = 1.0;
    const char* keyword = "prism";
    bool open = false;   // POV-Ray's open prism: no caps
    bool sturm = false;  // kept for the dump (the pieces' roots need no Sturm chains)
};

struct CsgTree;
// One leaf of a CSG object (POV-Ray's difference, intersection, merge, or a
// union inside one of those): the part of the leaf's surface that bounds the
// tree's solid, with the leaf's own texture. The interpreter makes one Object
// per leaf (but a clip's), in leaf order, all sharing the tree; the leaf's
// shape and full transform are the tree's (CsgTree::Leaf), the Object's
// worldFromObject is the identity.
struct CsgShape {
    std::shared_ptr<const CsgTree> tree;
    std::uint32_t leaf = 0;
};

using Shape = std::variant<SphereShape, BoxShape, ConeShape, CylinderShape, DiscShape,
                           PolygonShape, PlaneShape, QuadricShape, CsgShape, TorusShape, TriangleShape,
                           ExtrusionShape, PolyShape>;

// A CSG object as written: nodes (node 0 the root), each an operation over
// its children or a leaf shape; `inverse` as POV-Ray's (toggled by each
// `inverse` written). Transforms are applied to the leaves. An object
// clipped_by others is the intersection of it and them, those members
// marked `clip`: their leaves bound the solid but show no surface (they
// have no Object).
struct CsgTree {
    enum class Op : std::uint8_t { Union, Merge, Intersection, Difference, Leaf };
    struct Node {
        Op op = Op::Leaf;
        bool inverse = false;
        bool clip = false;  // a clipped_by member: its leaves have no Object
        std::vector<std::uint32_t> children;  // node indices, in the order written
        std::uint32_t leaf = 0;               // Op::Leaf: index into leaves
    };
    struct Leaf {
        Shape shape;  // never a CsgShape
        Transform worldFromObject;
        std::uint32_t node = 0;
    };
    std::vector<Node> nodes;
    std::vector<Leaf> leaves;
};

// One entry of a colour map: the colour at a pattern value.
struct ColourMapEntry {
    double value = 0.0;
    Color color{};
    bool operator==(const ColourMapEntry&) const = default;
};

struct Pigment;
// One entry of POV-Ray's pigment_map: the pigment at a pattern value (for
// `average`, its weight). The pigment is shared (a declared one, and every
// copy of the pigment that holds the map, point to one).
struct PigmentMapEntry {
    double value = 0.0;
    std::shared_ptr<const Pigment> pigment;
    bool operator==(const PigmentMapEntry&) const = default;
};
using PigmentMap = std::vector<PigmentMapEntry>;

struct Pigment {
    // Checker and Brick have two colours and plane edges; the others run a
    // value over [0, 1] through a colour map (render/map_pattern.hpp), or
    // through a pigment map; Average is POV-Ray's weighted mean of its
    // pigment map's pigments.
    enum class Kind {
        Solid, Checker, Brick, Gradient, Radial, Onion, Marble, Wood, Leopard, Bozo, Spotted, Granite, Agate,
        Crackle,
        // The normal patterns' own values as pigment patterns (POV-Ray's
        // pattern.cpp): bumps is bozo's noise, dents its cube, wrinkles ten
        // octaves of it, ripples and waves POV-Ray's ten wave sources.
        Bumps, Dents, Wrinkles, Ripples, Waves, Function, Average
    };
    enum class Wave { Ramp, Triangle, Sine };
    Kind kind = Kind::Solid;
    Color color1{};                       // the solid colour, or the pattern's first (brick: the mortar)
    Color color2{};                       // the pattern's second (brick: the brick)
    Vec3 brickSize{8.0, 3.0, 4.5};        // brick's brick_size and mortar, as written
    double mortar = 0.5;
    // The map patterns' parameters, POV-Ray's defaults (the wave and the map
    // are the pattern's own where they are not given).
    std::vector<ColourMapEntry> colourMap;  // in value order; empty: the pattern's default map
    // POV-Ray's pigment_map, in place of the colour map where it is not null:
    // whole pigments, blended as the colour map's colours are, each
    // evaluated at the point in this pigment's pattern space (after its
    // transform and turbulence: the entries' transforms are relative to
    // this pigment's, as POV-Ray applies them). Shared, never copied per
    // object; compared by address.
    std::shared_ptr<const PigmentMap> pigmentMap;
    Vec3 gradient{0.0, 1.0, 0.0};         // normalised, as POV-Ray keeps it
    Vec3 turbulence{0.0};                 // per axis; zero: none
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    Wave wave = Wave::Ramp;
    double frequency = 1.0;
    double phase = 0.0;
    double agateTurb = 1.0;
    // crackle's form (the weights of the distances to the nearest three
    // points), metric (the exponent of its distance), offset, and solid
    // (each cell the noise at its point), POV-Ray's defaults.
    Vec3 crackleForm{-1.0, 1.0, 0.0};
    double crackleMetric = 2.0;
    double crackleOffset = 0.0;
    bool crackleSolid = false;
    int noiseGenerator = 0;               // 1, 2 or 3; 0: the scene's (global_settings)
    Transform worldFromPattern;           // full transform of the pattern space
    // Kind::Function: the function of x, y, z (shared; equal when the same one).
    std::shared_ptr<const FunctionProgram> function;
    bool operator==(const Pigment&) const = default;
};

// POV-Ray's normal { … }: a pattern that tilts the surface normal (its
// core/material/normal.cpp). The five normal-only patterns add a vector of
// their own; any other pattern (`Pattern`, a map pattern kept in `pattern`)
// tilts the normal by its slope, POV-Ray's finite differences over four
// points `accuracy` away.
struct Normal {
    enum class Kind { Bumps, Dents, Wrinkles, Ripples, Waves, Pattern };
    Kind kind = Kind::Bumps;
    // The pattern space (worldFromPattern), turbulence with octaves, omega
    // and lambda, frequency and phase (ripples, waves, and the map
    // patterns' wave), the noise generator (dents, the map patterns); for
    // Pattern, its kind and parameters. Its colours and map are unused.
    Pigment pattern;
    double amount = 0.5;     // the bump size: the number after the pattern, or bump_size
    double accuracy = 0.02;  // POV-Ray's Delta, for Pattern
    bool operator==(const Normal&) const = default;
};

struct Finish {
    Vec3 ambient{0.1};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double phong = 0.0;
    double phongSize = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    // POV-Ray's reflection: `reflection` at grazing angles (Reflection_Max),
    // `reflectionMin` seen head-on (the same when not set). Between them
    // by (1 - cos)^falloff, or by the Fresnel equation for the object's
    // ior; `reflectionExponent` is POV-Ray's Reflect_Exp (1 / exponent);
    // `reflectionMetallic` tints the reflection with the pigment
    // (docs/rendering.md, "Reflection").
    Vec3 reflection{0.0};
    std::optional<Vec3> reflectionMin;
    double reflectionFalloff = 1.0;
    bool fresnel = false;
    double reflectionExponent = 1.0;
    double reflectionMetallic = 0.0;
    // metallic: highlights take the pigment's colour; conserve_energy: what
    // a layer reflects is taken off what it lets through.
    double metallic = 0.0;
    bool conserveEnergy = false;
    // POV-Ray's graininess: each light's diffuse intensity less crand times
    // a random number in [0, 1) (docs/rendering.md, "crand").
    double crand = 0.0;
    bool operator==(const Finish&) const = default;
};

// Whether a finish reflects at some angle.
inline bool reflects(const Finish& f) {
    return f.reflection != Vec3(0.0) || (f.reflectionMin && *f.reflectionMin != Vec3(0.0));
}

// One layer of a texture: its pigment, the finish it is lit with and the
// normal pattern that tilts its surface normal, if any.
struct TextureLayer {
    Pigment pigment;
    Finish finish;
    std::optional<Normal> normal;
};

// The texture's own pigment and finish are its bottom layer. `above` holds
// POV-Ray's layered texture (`texture { A } texture { B }`: B over A), lowest
// first: each layer is lit with its own finish, and what it lets through
// (its colour's filter and transmit) shows the layers under it
// (docs/rendering.md, "Layered textures"). Where the bottom layer lets
// light through, the object is transparent (mayBeTransparent).
struct Texture : TextureLayer {
    std::vector<TextureLayer> above;
};

// Whether a colour lets light through (its filter or transmit is not zero).
inline bool seeThrough(const Color& c) { return c.filter != 0.0 || c.transmit != 0.0; }

// Whether a surface with this texture may let light through somewhere: a
// colour of its bottom layer's pigment filters or transmits (the layers
// above only show the ones under them). Such an object is transparent: rays
// go on through it and it filters the shadows it casts.
inline bool mayBeTransparent(const Pigment& p) {
    if (p.pigmentMap) {
        for (const PigmentMapEntry& e : *p.pigmentMap)
            if (mayBeTransparent(*e.pigment)) return true;
        return false;
    }
    if (seeThrough(p.color1) || seeThrough(p.color2)) return true;
    for (const ColourMapEntry& e : p.colourMap)
        if (seeThrough(e.color)) return true;
    return false;
}
inline bool mayBeTransparent(const Texture& t) { return mayBeTransparent(t.pigment); }

// POV-Ray's default texture (black pigment, default finish), shared.
inline const std::shared_ptr<const Texture>& defaultTexture() {
    static const std::shared_ptr<const Texture> texture = std::make_shared<const Texture>();
    return texture;
}

// POV-Ray's interior { ior caustics fade_distance fade_power fade_color }:
// what the inside of a transparent object does to the rays through it
// (docs/rendering.md, "Refraction"). Shared by the members of a CSG and the
// copies of a declared object, as POV-Ray shares one: a ray that enters
// through one member and leaves through another has left the same inside.
// The defaults are POV-Ray's.
struct Interior {
    double ior = 1.0;           // the index of refraction (the air's is 1)
    double caustics = 0.0;      // POV-Ray's faked caustics in the shadows it casts
    // Dispersion: the ior at the violet end over the one at the red end; a
    // ray refracted by it splits into dispersionSamples bands of colour.
    double dispersion = 1.0;
    int dispersionSamples = 7;
    double fadeDistance = 0.0;  // 0: no fade
    double fadePower = 0.0;
    Vec3 fadeColor{0.0};
    bool operator==(const Interior&) const = default;
};

struct Object {
    Shape shape;
    Transform worldFromObject;
    // Shared and never null: objects with equal textures (one declared texture,
    // the default, or the same colours written out again) point to one Texture.
    // A Texture with its pattern transform is 432 bytes; sharing keeps a
    // million spheres under 1 GiB.
    std::shared_ptr<const Texture> texture = defaultTexture();
    bool noShadow = false;
    // Null: POV-Ray's default interior (Interior{}), the object's own.
    std::shared_ptr<const Interior> interior;
    AsosOptions asos;
    SourceLoc loc;
};

// The deepest max_trace_level, POV-Ray 3.7's MAX_TRACE_LEVEL_LIMIT: a scene
// that asks for more gets this many, with a warning. Reflection recurses once
// per level, so this also bounds the stack a render thread needs.
inline constexpr int kMaxTraceLevelLimit = 256;

struct GlobalSettings {
    // The working gamma. None: POV-Ray's gamma correction is off, as for a
    // scene older than 3.7 (by its #version, or without one) that does not set
    // assumed_gamma; its colours are then written to files as they are.
    std::optional<double> assumedGamma = 1.0;
    int maxTraceLevel = 5;  // 1 to kMaxTraceLevelLimit
    Vec3 ambientLight{1.0};
    int noiseGenerator = 2;  // POV-Ray's default, the range-corrected original noise
    AsosOptions asos;
};

// POV-Ray's sky_sphere { pigment {…} … emission C transforms }: the colour
// of a ray that hits nothing, its pigments (lowest first, the last written
// on top) evaluated at the ray's unit direction taken back through
// worldFromSky, each times `emission`, over the background
// (render/atmosphere.hpp).
struct SkySphere {
    std::vector<Pigment> pigments;
    Vec3 emission{1.0};
    Transform worldFromSky;
    SourceLoc loc;
};

// POV-Ray's fog { fog_type 1|2 distance D colour C … }: constant fog (1)
// or ground fog (2, its density 1 below fog_offset along `up` and falling
// as 1 / (1 + h^2) above, h the height over fog_offset in units of
// fog_alt), with POV-Ray's optional turbulence of its depth.
struct Fog {
    int type = 1;
    double distance = 0.0;
    Color color{};
    double offset = 0.0;  // fog_offset
    double alt = 0.0;     // fog_alt
    Vec3 up{0.0, 1.0, 0.0};  // unit (POV-Ray normalises it)
    bool turbulent = false;  // any of turbulence, octaves, omega, lambda given
    Vec3 turbulence{0.0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    double turbDepth = 0.5;
    SourceLoc loc;
};

struct SceneDescription {
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;  // unions are flattened, a CSG gives one per leaf; order of appearance
    GlobalSettings globals;
    Color background{};  // its transmit darkens it (POV-Ray without alpha output)
    std::optional<SkySphere> skySphere;  // the last one written
    std::vector<Fog> fogs;               // in the order written
    // The POV-Ray version the scene is read as, in hundredths as POV-Ray keeps
    // it: its last #version, or 3.62 when it has none (POV-Ray's assumption).
    double version = 3.7;
};

}  // namespace asos
