#pragma once
// The render pipeline as a library function: a scene description in, an
// image with its samples AOV and statistics out, by ASOS or one of the
// classic methods. All methods share the camera (render/camera.hpp), the
// scene and its BVH, and the shading (render/ray_tracer.hpp), so differences
// between their images are differences of method only. The command line
// (`asos render`) is a thin layer over this.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "asos/diag/diagnostics.hpp"
#include "asos/image/image.hpp"
#include "asos/render/classic_methods.hpp"
#include "asos/render/scene_lights.hpp"
#include "asos/render/stats.hpp"
#include "asos/render/tile_renderer.hpp"
#include "asos/scene/description.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

// Adaptive is POV-Ray's +AM2, Am1 its +AM1 (classic_methods.hpp).
enum class RenderMethod { Asos, Single, Grid, Jitter, Adaptive, Am1 };

// "asos", "single", "grid", "jitter", "adaptive", "am1".
const char* methodName(RenderMethod method);
std::optional<RenderMethod> parseMethod(std::string_view name);

// The most worker threads a render takes: far beyond any machine's cores,
// and below where TBB's own arena fails.
inline constexpr int kMaxThreads = 1024;

struct RenderSettings {
    RenderMethod method = RenderMethod::Asos;
    int width = 640, height = 480;
    // ASOS: the command line's eps/max/jitter, which override global_settings'
    // asos block; objects' and lights' own blocks refine both.
    AsosOptions asos;
    // ASOS: also subdivide where a pigment pattern's edge crosses a pyray
    // (docs/algorithm.md, "Pattern edges").
    bool patternEdges = false;
    // ASOS: shade each leaf with its pigment averaged over its footprint
    // (docs/algorithm.md, "Pattern filter"). By default on under ASOS
    // without pattern edges (so that pattern edges stay the point-sampled
    // reference the filter is checked against), and never under the classic
    // methods, which sample patterns at points as POV-Ray does: on with a
    // classic method is refused. Both pattern options off: the paper's
    // method alone.
    std::optional<bool> patternFilter;
    int samples = 4;            // grid and jitter: samples x samples rays per pixel
    AdaptiveSettings adaptive;  // adaptive and am1: threshold, depth, jitter (gamma from the scene)
    // Area lights (docs/lights.md): ASOS shadow beams or the classic grid of
    // point lights, with any eye method; by default ASOS beams under the ASOS
    // eye method and the grid under the classic ones.
    std::optional<LightMethod> lightMethod;
    std::optional<int> lightSamples;  // replaces every area light's counts by N x N
    ShadowApex shadowApex = ShadowApex::Surface;  // behind: ASOS eye and light methods only
    // A sampler of area lights in place of the light method's (a
    // benchmark's reference from asos_testing): LightSetup::sampler.
    AreaLightSampler areaLightSampler = nullptr;
    int threads = 0;            // 0: all cores; at most kMaxThreads
    std::uint64_t seed = 0;
    std::optional<PixelRegion> region;  // default: the whole image
    int tileSize = 16;
    std::function<void(const TileProgress&)> progress;  // after each tile
};

struct RenderOutput {
    Image color;    // linear RGB in the scene's working space, full size (outside the region: 0)
    Image samples;  // channels "rays" (rays, or pyrays for ASOS) and "level", per pixel
    RenderStats stats;
};

// Empty when the settings can be used for `scene`; otherwise every problem
// found, one per line (bad sizes, counts, asos options, region).
std::string checkRenderSettings(const RenderSettings& settings);

// The way area lights are shadowed under these settings.
LightMethod effectiveLightMethod(const RenderSettings& settings);

// Whether ASOS filters patterns under these settings (RenderSettings::patternFilter).
bool effectivePatternFilter(const RenderSettings& settings);

// Checks what the renderer needs of a description beyond what Scene::build
// checks: asos blocks in range, lights it can render (checkLight, which also
// warns). Reports each problem with its source location; returns false when
// there was an error.
bool checkRenderable(const SceneDescription& description, Diagnostics& diagnostics);


// Renders a built scene. Throws std::invalid_argument for settings that
// checkRenderSettings rejects. stats.times.buildSeconds is left 0.
RenderOutput render(const Scene& scene, const RenderSettings& settings);

// Builds the scene (timed) and renders it. Problems with the description go
// to `diagnostics` and give nothing; bad settings throw std::invalid_argument.
std::optional<RenderOutput> render(const SceneDescription& description,
                                   const RenderSettings& settings, Diagnostics& diagnostics);

}  // namespace asos
