#pragma once
// Adaptive supersampling in object space (Genetti & Gordon 1993, "Adaptive
// Supersampling in Object-Space"): a pixel's 0-pyray and its bounding cone
// are tested against the objects the BVH offers ("Detection Phase"); a pixel
// whose nearest object covers it wholly costs one ray; otherwise its marginal
// pyrays are split into four, level by level, against the pixel's own list
// of objects, until the paper's bound on the change that another level could
// make falls within EPS or the level reaches MAX ("Subdivision Phase",
// "Proximity to One Edge", "Jittering of MAX-rays"). Leaves are shaded with
// their central rays weighted by their area; point lights are shadowed by
// shadow pyrays through the leaves' footprints (render/point_light_shadow.hpp);
// reflections use plain rays. docs/algorithm.md gives the rules in full.
#include <cstdint>
#include <optional>
#include <vector>

#include "asos/geometry/beam_eye.hpp"
#include "asos/scene/asos_settings.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/cone_candidates.hpp"
#include "asos/render/mesh_cover.hpp"
#include "asos/render/pattern_edges.hpp"
#include "asos/render/point_light_shadow.hpp"
#include "asos/render/ray_tracer.hpp"
#include "asos/render/subdivision_criterion.hpp"
#include "asos/render/tile_renderer.hpp"

namespace asos {

// Per-thread buffers: a pixel allocates nothing once they have grown.
struct AsosScratch {
    struct Item {
        std::uint32_t object;
        ConeClass cls;
        // Full, and which of it and another object of the pyray a ray meets
        // first is not known: the visible surface may switch between them
        // inside the pyray, though neither has a boundary there.
        bool crossed = false;
    };
    // A marginal pyray awaiting the stopping decision of its level.
    struct Node {
        EyePyray pyray;
        std::uint32_t ix, iy;        // position among the 2^K x 2^K squares of the pixel
        std::uint32_t first, count;  // its objects in items[]
        std::optional<SurfaceHit> hit;  // its K-ray's nearest hit among them
        // Resolved by one Full object whose pigment pattern may change in
        // the pyray: marginal on the pattern, not on the object's outline.
        PatternChange pattern;
        // Covered by one Full object without a crease, whose highlights may
        // stray from the K-ray's by this much inside the pyray
        // (render/highlight_bound.hpp); 0 otherwise.
        double shading = 0.0;
        // Covered by a sheet of one mesh's faces (render/mesh_cover.hpp),
        // its items those faces: only its creases (shading) or its pattern
        // can change inside it.
        bool meshSheet = false;
    };
    std::vector<Item> items[2];
    std::vector<std::uint8_t> hits[2];  // per item: the node's K-ray hits the object
    std::vector<std::uint8_t> hidden;   // per item of the pyray being settled
    std::vector<Node> nodes[2];
    SubdivisionTally tally;
    ShadowScratch shadow;
    AreaLightScratch area;
    ConeCandidateCache eyeCandidates;
    std::vector<MeshCandidate> meshCandidates;
};

// One level of a pixel's subdivision, as the paper's Tables 1 and 2 show it.
struct AsosLevelReport {
    int level = 0;
    int marginal = 0;   // M: marginal pyrays at this level
    int in = 0, out = 0;  // summed over the objects of the tally
    double bound = 0.0;   // the change bound of the tally
    AsosSettings settings;  // the finest among the objects involved
};

struct AsosPixelReport {
    PixelResult result;
    int leaves = 0;  // pyrays shaded (each with one ray), or that saw nothing
    std::vector<AsosLevelReport> levels;  // levels that reached the stopping decision
};

class AsosTracer {
public:
    // `sceneSettings`: the command line over global_settings over the
    // defaults; each object's own asos block refines it. `patternEdges`:
    // also subdivide where a pigment pattern's edge crosses a pyray that
    // one object covers (docs/algorithm.md, "Pattern edges").
    // `patternFilter`: shade each leaf with its pigment averaged over the
    // leaf's footprint ("Pattern filter"). Both false: the paper's method
    // alone.
    AsosTracer(const RayTracer& tracer, const CameraModel& camera, const AsosSettings& sceneSettings,
               std::uint64_t seed, bool patternEdges = false, bool patternFilter = false);

    // One pixel: its colour, the pyrays it took (result.rays) and the
    // deepest level reached.
    PixelResult tracePixel(int x, int y, AsosScratch& scratch, RenderCounters& counters) const;
    // The same, with what happened at each level.
    AsosPixelReport tracePixelReport(int x, int y, AsosScratch& scratch,
                                     RenderCounters& counters) const;

    const AsosSettings& objectSettings(std::uint32_t object) const { return objectSettings_[object]; }
    const AsosSettings& lightSettings(std::size_t light) const { return lightSettings_[light]; }

private:
    // One pixel's trace: the paper's phases, and the pixel's running sums
    // (src/render/asos_tracer.cpp).
    class PixelTrace;

    const RayTracer& tracer_;
    const Scene& scene_;
    const CameraModel& camera_;
    std::uint64_t seed_;
    AsosSettings sceneSettings_;  // the sky's
    std::vector<AsosSettings> objectSettings_;
    std::vector<AsosSettings> lightSettings_;
    bool patternEdges_;
    bool patternFilter_;
    std::vector<std::uint8_t> selfShadowing_;
    std::vector<std::uint8_t> patterned_;
    // Per object: its highlights are bounded inside the pyrays it covers
    // (a finish with phong or specular, its settings' highlights on, and a
    // light that gives highlights and counts them).
    std::vector<std::uint8_t> highlighted_;
    std::vector<Light> highlightLights_;  // the lights whose highlights count
    double eyeTMax_ = kInfinity;  // where eye pyrays end: beyond every object, or never
    // The sheets of mesh faces that cover pyrays (perspective cameras
    // only), and how much a jump of 1 in the shading normal may change a
    // colour: the sum of the lights' brightest channels times the faces'
    // diffuse, at most.
    std::optional<MeshCover> meshCover_;
    double meshJumpScale_ = 0.0;
};

}  // namespace asos
