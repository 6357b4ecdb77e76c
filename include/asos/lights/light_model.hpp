#pragma once
// What a light source is to the renderer (paper: "Distributed Light
// Sources"): its form (a point, a rectangle, a segment or a sphere:
// lights/light_form.hpp), its total power, the classic model's grid of
// sample points, and its ASOS settings. Made here from the scene's
// description; docs/lights.md gives the rules; in short:
//
//   area_light <a>, <b>, n1, n2       a rectangle (parallelogram) centred on
//                                     the light's position, edges a and b;
//   one axis of zero length, or its   a segment along the other axis
//   count 1 (POV-Ray's linear light)  (its count is the grid's);
//   circular orient                   a sphere of radius |a| / 2 (POV-Ray's
//                                     disc that always faces the point);
//   both counts 1 or both axes zero   a point light at the position.
//
// The light's colour is its total power, as in POV-Ray: the emitted
// intensity per unit area (length) is I = colour / area (length), so a point
// straight in front of a rectangular light, far away, receives the colour,
// as from a point light at its centre; a spherical light sends every point
// its whole colour (a disc facing the point, I A with A = pi r^2). Nothing
// falls off with distance unless fade_distance / fade_power ask for it.
#include <optional>
#include <string>

#include "asos/diag/diagnostics.hpp"
#include "asos/lights/light_form.hpp"
#include "asos/scene/asos_settings.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// The largest grid count per side that --light-samples or a scene may ask for.
inline constexpr int kMaxLightSamplesPerSide = 1024;

struct LightModel {
    LightForm form;      // a point by default
    Vec3 position{0.0};  // the light's position: the centre of an area form
    Vec3 color{1.0};     // total power
    // The classic model: counts along the rectangle's edges (the sphere's
    // disc's), or along the segment (count1; count2 is 1); POV-Ray's
    // adaptive level (none: every point) and jitter.
    int count1 = 1, count2 = 1;
    std::optional<int> adaptive;
    bool jitter = false;
    bool shadowless = false;
    AsosSettings asos;  // the light's eps, max and jitter for ASOS shadow beams

    bool isArea() const { return !std::holds_alternative<PointLight>(form); }
    // Area (rectangle), length (segment) or pi r^2 (sphere); 0 for a point.
    double size() const {
        return std::visit([](const auto& light) { return light.size(); }, form);
    }
    // Intensity per unit area, length or disc area: colour / size.
    Vec3 intensity() const {
        const double s = size();
        return s > 0.0 ? color / s : color;
    }
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
// parallel axes, counts outside 1..kMaxLightSamplesPerSide and a negative
// adaptive level; warnings where POV-Ray warns and goes on (orient without
// circular, orient with axes of unequal length). Returns false on an error.
bool checkLight(const Light& light, Diagnostics& diagnostics);

}  // namespace asos
