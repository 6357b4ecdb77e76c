#pragma once
// What a light source is to the renderer (paper: "Distributed Light
// Sources"): its form (a point, a rectangle, a segment, a disc or a sphere:
// lights/light_form.hpp), its total power, its emitter (POV-Ray's or the
// paper's), the grid's sample points, and its ASOS settings. Made here from
// the scene's description; docs/lights.md gives the rules; in short:
//
//   area_light <a>, <b>, n1, n2       a rectangle (parallelogram) centred on
//                                     the light's position, edges a and b;
//   one axis of zero length, or its   a segment along the other axis
//   count 1 (POV-Ray's linear light)  (its count is the grid's);
//   circular orient                   POV-Ray's disc of radius |a| / 2 that
//                                     faces each point (with `asos { emitter
//                                     panel }`, the paper's sphere of that
//                                     radius);
//   both counts 1 or both axes zero   a point light at the position.
//
// The light's colour is its total power, as in POV-Ray. POV-Ray's emitter
// (the default): the light is an array of isotropic point lights; a point
// receives the colour times the fraction of the light it sees, shaded along
// the direction of the light's centre (each point of the array along its own
// with `area_illumination`). The paper's (`emitter panel`): the emitted
// intensity per unit area (length) is I = colour / area (length), each
// element shaded along its own direction, a rectangle's weighted by cos theta
// (a point straight in front of it, far away, receives the colour, as from a
// point light at its centre); a sphere sends every point its whole colour (a
// disc facing the point, I A with A = pi r^2). Nothing falls off with
// distance unless fade_distance / fade_power ask for it.
#include <optional>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/lights/light_beam.hpp"
#include "asos/lights/light_form.hpp"
#include "asos/scene/asos_settings.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// The largest grid count per side that --light-samples or a scene may ask for.
inline constexpr int kMaxLightSamplesPerSide = 1024;
// POV-Ray's Adaptive_Level when `adaptive` is not written (lightsource.cpp):
// its corner recursion splits every rectangle of the array down to single
// steps.
inline constexpr int kPovrayAdaptiveLevel = 100;

// Where POV-Ray's lattice point of (jittered) index `index` lies along an
// axis of `count` points, as a fraction of the axis from its start: from edge
// to edge, index / (count - 1); the middle for a count of 1.
inline double povrayLatticeFraction(double index, int count) {
    return count > 1 ? index / double(count - 1) : 0.5;
}

// POV-Ray's fade of a light at `distance` (lightsource.cpp, Attenuate_Light):
// with fade_power > 0, 2 / (1 + (d / fade_distance)^fade_power), or
// d^-fade_power when fade_distance is 0; 1 otherwise.
double lightFade(double fadeDistance, double fadePower, double distance);

struct LightModel {
    LightForm form;      // a point by default
    Vec3 position{0.0};  // the light's position: the centre of an area form
    Vec3 color{1.0};     // total power
    LightEmitter emitter = LightEmitter::Povray;
    // The grid: counts along the rectangle's edges (the disc's or sphere's
    // square), or along the segment (count1; count2 is 1); the adaptive
    // level as written (none: POV-Ray's kPovrayAdaptiveLevel for its emitter,
    // every point for the paper's) and jitter.
    int count1 = 1, count2 = 1;
    std::optional<int> adaptive;
    bool jitter = false;
    bool shadowless = false;
    bool areaIllumination = false;  // POV-Ray's emitter: each point shaded on its own
    double fadeDistance = 0.0, fadePower = 0.0;
    std::optional<LightBeam> beam;  // a spotlight's cone (lights/light_beam.hpp); none for a point light
    AsosSettings asos;  // the light's eps, max and jitter for ASOS shadow beams

    bool isArea() const { return !std::holds_alternative<PointLight>(form); }
    // Area (rectangle), length (segment) or pi r^2 (disc, sphere); 0 for a point.
    double size() const {
        return std::visit([](const auto& light) { return light.size(); }, form);
    }
    // Intensity per unit area, length or disc area: colour / size.
    Vec3 intensity() const {
        const double s = size();
        return s > 0.0 ? color / s : color;
    }
    double fade(double distance) const { return lightFade(fadeDistance, fadePower, distance); }
};

// The model of a light as the scene describes it. `sceneSettings`: the
// command line's asos options over global_settings'; `samples` (the
// --light-samples option) replaces the grid's counts by samples x samples
// (samples along a segment). Assumes checkLight found no error.
LightModel makeLightModel(const Light& light, const AsosSettings& sceneSettings,
                          std::optional<int> samples = std::nullopt);

// Reports what the renderer cannot do with a light, or does differently
// from what is written, to `diagnostics` at the light's location: errors for
// circular without orient (a flat disc light, which asos does not render),
// parallel area lights (cylinder area lights among them), circular orient
// with a count of 1 along one axis only (POV-Ray drops
// circular and turns a line toward each point), parallel axes, counts
// outside 1..kMaxLightSamplesPerSide and a negative adaptive level; warnings
// where POV-Ray warns and goes on (orient without circular, orient with axes
// of unequal length or unequal counts, circular with a count of 1). Returns
// false on an error.
bool checkLight(const Light& light, Diagnostics& diagnostics);

}  // namespace asos
