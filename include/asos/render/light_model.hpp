#pragma once
// What a light source is to the renderer (paper: "Distributed Light
// Sources"): a point, a rectangle, a segment or a sphere, with its total
// power, the classic model's grid of sample points, and its ASOS settings.
// docs/lights.md gives the rules; in short:
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
#include <string_view>
#include <vector>

#include "asos/diag/diagnostics.hpp"
#include "asos/geometry/beam_rect.hpp"
#include "asos/render/asos_settings.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// How area lights are shadowed: ASOS shadow beams (the paper's), or the
// classic grid of point lights with plain shadow rays (POV-Ray's).
enum class LightMethod { Asos, Grid };
const char* lightMethodName(LightMethod method);  // "asos", "grid"
std::optional<LightMethod> parseLightMethod(std::string_view name);

// Where ASOS shadow beams toward area lights start: at the shaded point (the
// paper), or behind the surface so that the beam also encloses the eye
// pyray's footprint (the paper's "Future Work"; docs/lights.md).
enum class ShadowApex { Surface, Behind };
const char* shadowApexName(ShadowApex apex);  // "surface", "behind"
std::optional<ShadowApex> parseShadowApex(std::string_view name);

enum class LightShape { Point, Rectangle, Segment, Sphere };
const char* lightShapeName(LightShape shape);  // "point", "rectangular", "linear", "spherical"

// The largest grid count per side that --light-samples or a scene may ask for.
inline constexpr int kMaxLightSamplesPerSide = 1024;

struct LightModel {
    LightShape shape = LightShape::Point;
    Vec3 position{0.0};  // the centre
    Vec3 color{1.0};     // total power
    LightRectangle rectangle;       // Rectangle: corner + s edgeA + t edgeB, s, t in [0, 1]
    Vec3 start{0.0}, end{0.0};      // Segment
    double radius = 0.0;            // Sphere
    // Area (rectangle), length (segment) or pi r^2 (sphere); 0 for a point.
    double size = 0.0;
    // The classic model: counts along edgeA and edgeB (the rectangle, and the
    // sphere's disc), or along the segment (count1; count2 is 1);
    // POV-Ray's adaptive level (none: every point) and jitter.
    int count1 = 1, count2 = 1;
    std::optional<int> adaptive;
    bool jitter = false;
    bool shadowless = false;
    AsosSettings asos;  // the light's eps, max and jitter for ASOS shadow beams

    bool isArea() const { return shape != LightShape::Point; }
    // Intensity per unit area, length or disc area: colour / size.
    Vec3 intensity() const { return size > 0.0 ? color / size : color; }
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

// Every light of a scene as the renderer sees it, and how area lights are
// shadowed.
struct LightSetup {
    LightMethod method = LightMethod::Grid;
    std::optional<int> samples;  // --light-samples
    ShadowApex apex = ShadowApex::Surface;
    // Grid lights skip the shadow rays that one cone test over the whole
    // light decides (all lit, or all blocked): the same image for less time.
    // For references (asos bench lights); the classic method traces them all.
    bool gridCulling = false;
    // The command line's asos options over global_settings'; by default
    // global_settings' over the built-in defaults.
    std::optional<AsosSettings> sceneSettings;
};

class SceneLights {
public:
    SceneLights() = default;
    SceneLights(const SceneDescription& description, const LightSetup& setup);

    const LightModel& operator[](std::size_t light) const { return models_[light]; }
    std::size_t size() const { return models_.size(); }
    const LightSetup& setup() const { return setup_; }

private:
    LightSetup setup_;
    std::vector<LightModel> models_;
};

}  // namespace asos
