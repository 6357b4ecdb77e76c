#pragma once
// Brute-force reference images (`asos reference`, `asos-bench accuracy`):
// every pixel an N x N jittered grid of eye rays, every area light M x M
// stratified points over its true area (one uniform in each of M x M equal
// cells, asos_testing's culledGridAreaLightSamples: not POV-Ray's jittered
// lattice, which reaches half a step past the light's edges), each traced
// where one cone test over the whole light cannot tell (POV-Ray's `adaptive`
// ignored), the classic shading otherwise. Slow on purpose: the image every
// method is measured against. References are cached in a folder of files
// named by a hash of what makes them (docs/performance.md, "References").
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "asos/image/image.hpp"
#include "asos/render/renderer.hpp"
#include "asos/scene/description.hpp"

namespace asos::cli {

struct ReferenceSettings {
    int width = 320, height = 240;
    int eyeSamples = 32;   // N x N jittered eye rays per pixel
    int lightSamples = 4;  // M x M stratified points per area light (M along a linear light), new for each eye ray
    int threads = 0;       // 0: all cores (a reference is not timed)
};

// The render settings of a reference.
RenderSettings referenceRenderSettings(const ReferenceSettings& settings);

// The description with every area light jittered and every point of its
// grid traced: the light's `adaptive` dropped (the paper's emitter then
// samples equal cells of the light, as the reference's sampler does).
SceneDescription withEveryLightPoint(SceneDescription description);

// The folder references are cached in: $ASOS_REFERENCE_CACHE when set, else
// $XDG_CACHE_HOME/asos/references, else ~/.cache/asos/references (the XDG
// base directories' rule), else none (no HOME).
std::optional<std::filesystem::path> referenceCacheFolder();

// The cache's file for a reference: the scene's stem, a 64-bit FNV-1a hash of
// the scene text, the settings, the -D declarations and the clock, and the
// size: "edges-0123456789abcdef-320x240.exr". Files the scene includes are
// not hashed: a change there needs --no-cache or a new cache folder.
std::string referenceFileName(const std::filesystem::path& scene, const std::string& sceneText,
                              const ReferenceSettings& settings, const std::vector<std::string>& defines,
                              double clock);

struct ReferenceImage {
    Image image;                  // linear, as rendered
    std::filesystem::path cached;  // the cache's file; empty without a cache
    bool fromCache = false;
    double seconds = 0.0;          // the render's wall time; 0 from the cache
    std::string error;             // empty on success
};

// The reference of `description` (interpreted from `scene`, whose text is
// `sceneText`): read from the cache when it holds it (and `useCache`), else
// rendered and, with a cache folder, stored there (a cache that cannot be
// written is no error: the image is still returned). `cacheFolder`: none for
// no cache; `useCached` false renders even when the cache holds it.
// `progress`, when set, is called after each tile of a render.
ReferenceImage loadOrRenderReference(const SceneDescription& description, const std::filesystem::path& scene,
                                     const std::string& sceneText, const ReferenceSettings& settings,
                                     const std::vector<std::string>& defines, double clock,
                                     const std::optional<std::filesystem::path>& cacheFolder, bool useCached,
                                     const std::function<void(const TileProgress&)>& progress);

}  // namespace asos::cli
