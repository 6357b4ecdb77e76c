#include "asos/render/scene_lights.hpp"

namespace asos {

const char* lightMethodName(LightMethod method) {
    return method == LightMethod::Asos ? "asos" : "grid";
}

std::optional<LightMethod> parseLightMethod(std::string_view name) {
    if (name == "asos") return LightMethod::Asos;
    if (name == "grid") return LightMethod::Grid;
    return std::nullopt;
}

const char* shadowApexName(ShadowApex apex) { return apex == ShadowApex::Behind ? "behind" : "surface"; }

std::optional<ShadowApex> parseShadowApex(std::string_view name) {
    if (name == "surface") return ShadowApex::Surface;
    if (name == "behind") return ShadowApex::Behind;
    return std::nullopt;
}

SceneLights::SceneLights(const SceneDescription& description, const LightSetup& setup)
    : setup_(setup) {
    const AsosSettings scene = setup.sceneSettings.value_or(sceneAsosSettings(description.globals, {}));
    models_.reserve(description.lights.size());
    for (const Light& light : description.lights)
        models_.push_back(makeLightModel(light, scene, setup.samples));
}

}  // namespace asos
