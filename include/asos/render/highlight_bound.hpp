#pragma once
// How much a surface's highlights can vary inside a pyray that one object
// covers (docs/algorithm.md, "Highlights inside covered pixels"). ASOS
// shades such a pyray with its central ray, which is exact for what is
// constant over the pyray and close for what varies slowly (the ambient and
// diffuse terms), but a phong or specular highlight a pixel wide, or narrower,
// is then point sampled. From the spread of the view direction, the normal
// and the light direction over the pyray's footprint, an interval of each
// light's highlight term bounds what a finer sampling could change; where
// its width exceeds EPS the pyray is subdivided as a marginal one is.
#include <span>

#include "asos/geometry/beam_eye.hpp"
#include "asos/geometry/hit.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/primitive.hpp"

namespace asos {

// What varies over a pyray's footprint on one smooth part of a surface,
// seen from its central hit.
struct SurfaceSpread {
    Vec3 position{0.0};  // the central ray's hit
    Vec3 normal{0.0};    // unit normal there, turned toward the viewer
    Vec3 viewDir{0.0};   // unit direction of the central ray
    double view = 0.0;   // largest angle between viewDir and any ray of the pyray
    double turn = 0.0;   // largest angle between `normal` and the normal at any footprint point
    double radius = 0.0; // largest distance from `position` to any footprint point

    // The margin by which the corners' spread is widened for the
    // footprint's edges, which bulge between the corners on a curved surface.
    static constexpr double kMargin = 1.5;

    // The spread over `pyray` on `object`, from the central hit and the hits
    // of the pyray's four corner rays on the object (four ray tests): the
    // view spread is the pyray cone's half-angle; the normal turn and the
    // radius are the corners' widened by kMargin. Where a corner misses the
    // object or meets another part of it, the normal may turn anywhere.
    static SurfaceSpread over(const EyePyray& pyray, const SurfaceHit& centre, const Primitive& object);
};

// A closed interval of values.
struct ValueRange {
    double lo = 0.0, hi = 0.0;
    double width() const { return hi - lo; }
};

// Whether the finish has highlights at all (phong or specular).
inline bool hasHighlights(const Finish& f) { return f.phong > 0.0 || f.specular > 0.0; }
// Whether any layer of the texture has highlights.
bool hasHighlights(const Texture& t);

// An interval that holds the highlight term of `light` (phong + specular as
// directLight computes them, per unit of the light's colour, with its fade,
// before shadows) at every point of the spread: for any ray of the pyray,
// any normal and position of its footprint, and any point of an area
// light's extent. Empty ({0, 0}) for a shadowless light.
ValueRange highlightRange(const Finish& finish, const Light& light, const SurfaceSpread& spread);

// How far the central ray's highlight term of `light` may lie from its mean
// over the footprint. The range's width bounds it, but the part of the
// change that is linear across the footprint averages out about the central
// ray, as the diffuse term's does: so the estimate is the most each term
// (as a function of its angle) strays from its tangent at the centre over
// the angle's spread, at both ends of the spread and at the highlight's
// peak where the spread holds it; the range's width where N.L may fall to
// zero inside (the highlight is cut there), and never more than the width.
// A narrow highlight inside the footprint strays by its height; a broad one
// across it, by its curvature times the spread squared.
double highlightError(const Finish& finish, const Light& light, const SurfaceSpread& spread);

// The sum over the lights of their highlight errors, each times the light's
// largest colour component: how far the highlights' contribution to any
// colour channel of the central ray may lie from the pyray's mean. An area
// light's points each shade as a point light with a share of its colour, so
// its error is the mean of theirs, taken over a 3 x 3 grid of its points.
double highlightVariation(const Finish& finish, std::span<const Light> lights, const SurfaceSpread& spread);

// The same for a layered texture: its layers' highlights add up, each seen
// through the layers above it (shading.hpp, shadeSurface), so the sum of the
// layers' variations, each times the most the layers above can let through
// (the product of their largest rgb x filter + transmit over their colours).
// The layers' patterns are point sampled; this bounds the highlights only.
double highlightVariation(const Texture& texture, std::span<const Light> lights, const SurfaceSpread& spread);

}  // namespace asos
