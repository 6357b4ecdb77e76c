#pragma once
// The light an area light sends a shaded point, as a list of samples
// (render/shading.hpp's LightSample), each shaded along its own direction
// (diffuse and highlights). docs/lights.md has the model.
//
// POV-Ray's emitter (the default): the fraction of the light that reaches
// the point, by ASOS shadow beams (render/area_light_shadow.hpp) or by
// POV-Ray's grid (render/grid_light.hpp), lights it as one sample along the
// direction of the light's centre, colour x fraction; with
// area_illumination, as one sample per point of POV-Ray's lattice, each
// colour x fraction / (n1 n2) along its own direction.
//
// The paper's emitter (`asos { emitter panel }`): one sample per sub-beam of
// an ASOS shadow beam that reaches the light, or one per point of the
// classic grid that a plain shadow ray reaches; the samples' colours add up
// to the light's colour times the emitter weighting (cos theta for
// rectangles) when nothing is in the way.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "asos/render/interiors.hpp"
#include "asos/render/spectral.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/lights/light_piece.hpp"
#include "asos/render/cone_candidates.hpp"
#include "asos/render/point_light_shadow.hpp"
#include "asos/render/sampling.hpp"
#include "asos/render/scene_lights.hpp"
#include "asos/render/shading.hpp"
#include "asos/render/stats.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

// The running sum of mergeDiffuse: samples added one by one, in order, give
// bit for bit the sample mergeDiffuse makes of them all, without storing them.
struct DiffuseSum {
    Vec3 sum{0.0}, color{0.0};
    double distance = 0.0, total = 0.0;
    std::size_t count = 0;
    LightSample first;  // the one sample, while there is one

    void clear() { *this = DiffuseSum{}; }
    void add(const LightSample& s) {
        // The colours are the light's colour times a weight each: weigh the
        // directions by the colours' sum of channels (any one would do).
        const double w = s.color.x + s.color.y + s.color.z;
        sum += w * s.direction;
        color += s.color;
        distance += w * s.distance;
        total += w;
        if (count++ == 0) first = s;
    }
    // The merged sample, or none when the samples carry no light.
    std::optional<LightSample> merged() const;
};

// The ASOS beams' running sum of their samples at a diffuse-only point.
// Every sample of one light is the light's colour times a weight k along a
// direction, so the sum keeps only sum k d, sum k distance and sum k, and
// makes of them the sample mergeDiffuse would make of all the samples (the
// same up to rounding): direction sum k d / |sum k d|, distance
// sum k distance / sum k, colour x |sum k d|.
struct WeightedDiffuseSum {
    Vec3 sum{0.0};
    double distance = 0.0, total = 0.0;
    std::size_t count = 0;
    Vec3 firstDirection{0.0};  // the one sample, while there is one
    double firstDistance = 0.0, firstWeight = 0.0;

    void clear() { *this = WeightedDiffuseSum{}; }
    void add(const Vec3& direction, double dist, double k) {
        sum += k * direction;
        distance += k * dist;
        total += k;
        if (count++ == 0) {
            firstDirection = direction;
            firstDistance = dist;
            firstWeight = k;
        }
    }
    // The one sample that lights the point as all of them, for a light of
    // `color`; none when they carry no light (as mergeDiffuse).
    std::optional<LightSample> merged(const Vec3& color) const;
};

// A marginal sub-beam awaiting the stopping decision of its level.
struct AreaBeamNode {
    LightPiece piece;
    std::uint32_t first, count;  // its occluders in AreaLightScratch::items[]
    bool blocked;                // its central ray is blocked (once traced)
};

// Per-thread buffers: once grown, a shaded point allocates nothing.
struct AreaLightScratch {
    struct Item {
        std::uint32_t object;
        ConeClass cls;
    };
    std::vector<Item> items[2];
    std::vector<std::uint8_t> hits[2];  // per item: the node's central ray hits the object
    std::vector<AreaBeamNode> nodes[2];
    std::vector<LightSample> samples;       // the answer
    std::vector<LightSample> filtered;      // the answer through transparent occluders
    LightSample merged;                     // the answer, summed (mergeDiffuse)
    WeightedDiffuseSum diffuseSum;          // ASOS beams: the answer, summed as it is made
    std::vector<LightSample> gridSamples;   // grid: per lattice point, its sample
    std::vector<double> gridWeights;        // grid: per lattice point, its weight
    std::vector<std::int8_t> gridState;     // grid: per lattice point, -1 unknown, 0 blocked, 1 lit
    SubdivisionTally tally;
    // ASOS beams: a sub-beam's occluders for its point samples, each with
    // the shaded point in its local frame.
    struct SampleOccluder {
        const Primitive* primitive;
        Vec3 origin;
    };
    std::vector<SampleOccluder> sampleOccluders;
    std::vector<BeamCandidateCache> beamCandidates;  // per light: the objects near the last beams
};

// What the random numbers, the footprint and the buffers of one shading
// are: carried from a primary sample down its reflected rays.
struct LightContext {
    AreaLightScratch* scratch = nullptr;  // null: a temporary one (slow; tests)
    PixelRandom rng{0, 0, 0};
    // The primary sample within the pixel (and, below it, the reflection
    // depth): numbers drawn for it differ from every other sample's.
    std::uint64_t key = 0;
    // The eye pyray's footprint on the surface (ASOS eye method), for
    // ShadowApex::Behind; null elsewhere (classic methods, reflections).
    const Footprint* footprint = nullptr;
    // The interiors the ray is inside (render/interiors.hpp): none for an
    // eye ray; a reflected ray keeps its parent's, a ray through a surface
    // gets them as it crosses.
    InteriorList inside;
    // The band of colour of a ray split by dispersion, which it and the rays
    // it spawns keep (render/spectral.hpp); wavelength 0: white light.
    SpectralBand band{};

    // The context of a ray reflected at trace level `depth`.
    LightContext reflected(int depth) const {
        LightContext c = *this;
        c.key = mix64(key ^ (std::uint64_t(depth) << 56));
        c.footprint = nullptr;
        return c;
    }
};

// One question: the light that area light `light` sends the shaded point.
struct AreaLightQuery {
    std::size_t lightIndex = 0;
    Vec3 point{0.0};
    Vec3 normal{0.0, 1.0, 0.0};  // unit, turned toward the viewer (the shading normal)
    Vec3 outward{0.0, 1.0, 0.0};  // unit, the surface's own, on its outward side (SurfaceHit::normal)
    // The object the point lies on: convex and flat shapes cannot shadow
    // themselves where they face the light and are left out of the occluders.
    std::uint32_t shadedObject = 0;
    bool shadedCanSelfShadow = false;
    PixelRandom rng{0, 0, 0};
    std::uint64_t key = 0;                  // LightContext::key
    const Footprint* footprint = nullptr;   // LightContext::footprint
    // The surface only reflects diffusely (brilliance 1, no phong or
    // specular) and the light does not fade: then the samples may be summed
    // into one (mergeDiffuse), which lights the point exactly alike.
    bool diffuseOnly = false;
    // The insides of the ray that found the point (LightContext::inside),
    // where transparent objects' shadows start (transparentShadowFilter).
    const InteriorList* inside = nullptr;
};

// The samples of an area light at a shaded point, by the lights' method
// (setup().method) and apex, or by the setup's own sampler where it has one;
// the span lives in `scratch` until its next use. A shadowless light is
// unshadowed.
std::span<const LightSample> areaLightSamples(const Scene& scene, const SceneLights& lights,
                                              const AreaLightQuery& query, AreaLightScratch& scratch,
                                              RenderCounters& counters);

// POV-Ray's emitter: whether the light lights the point at all. Without
// area_illumination, only where the direction of the light's centre faces
// the surface (POV-Ray tests it before any shadow ray: cos < EPSILON, the
// light is skipped, however much of it lies above the horizon).
bool povrayLightsPoint(const LightModel& model, const AreaLightQuery& query);
// POV-Ray's emitter: the samples that light the point when `visible` of the
// light reaches it (a point povrayLightsPoint lights). The span lives in
// `scratch` until its next use.
std::span<const LightSample> povrayAreaLightSamples(const LightModel& model, const AreaLightQuery& query,
                                                    double visible, AreaLightScratch& scratch);

// One sample that lights a surface of diffuse-only finish (brilliance 1, no
// highlights, no fade) exactly as `samples` together: the sum of colour x
// direction is linear in the cosine of incidence, so its length and
// direction are the merged sample's weight and direction (the samples share
// the light's colour, and each faces the surface). The span lives in
// `storage`.
std::span<const LightSample> mergeDiffuse(std::span<const LightSample> samples, LightSample& storage);

// The diffuse weighting of a sample set: sum of colour x max(0, N . L), the
// irradiance a diffuse white surface would receive (for tests and the docs).
Vec3 diffuseIrradiance(std::span<const LightSample> samples, const Vec3& normal);

}  // namespace asos
