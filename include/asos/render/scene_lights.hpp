#pragma once
// Every light of a scene as the renderer sees it (lights/light_model.hpp),
// and how its area lights are shadowed: the method, the grid's counts, where
// the ASOS beams start.
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "asos/lights/light_model.hpp"
#include "asos/scene/asos_settings.hpp"
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

class Scene;
struct AreaLightQuery;
struct AreaLightScratch;
struct LightSample;
struct RenderCounters;

// A sampler of area lights in place of the method's (render/area_light.hpp
// says what it answers): how a caller plugs in its own, as the benchmarks
// plug in their references from asos_testing.
using AreaLightSampler = std::span<const LightSample> (*)(const Scene& scene, const LightModel& model,
                                                          const AreaLightQuery& query,
                                                          AreaLightScratch& scratch, RenderCounters& counters);

struct LightSetup {
    LightMethod method = LightMethod::Grid;
    std::optional<int> samples;  // --light-samples
    ShadowApex apex = ShadowApex::Surface;
    // The caller's sampler of area lights, used instead of the method's.
    AreaLightSampler sampler = nullptr;
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
