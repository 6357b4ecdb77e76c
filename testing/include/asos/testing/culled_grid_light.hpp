#pragma once
// References for the benchmarks: an area light's samples from a dense grid,
// with the shadow rays that one cone test over the whole light decides left
// out (where nothing is in the way of the whole light every point is lit,
// where one object blocks all of it none is). `asos bench lights` renders its
// converged references with it, plugged in through
// RenderSettings::areaLightSampler. The renderer's grid traces every ray, as
// POV-Ray does, so that its figures are the method's.
//   - POV-Ray's emitter: the visible fraction from one point uniform in each
//     of the n1 x n2 cells of the light's square (its form's beam's samples:
//     uniform over a rectangle or a segment, POV-Ray's density over its
//     disc), the model POV-Ray's lattice converges to, shaded as POV-Ray
//     shades it (povrayAreaLightSamples);
//   - the paper's emitter: the classic grid's samples (render/grid_light.hpp),
//     bit for bit.
#include <span>

#include "asos/render/area_light.hpp"

namespace asos {

// What one cone test over the whole light (from the point, as the ASOS
// beam's detection phase) says of every ray toward it: none is blocked, all
// are, or it cannot tell. With POV-Ray's emitter the light's parts below the
// surface's horizon count too: where there are any, it cannot tell.
enum class WholeLight { Lit, Blocked, Partial };
WholeLight wholeLightVisibility(const Scene& scene, const LightModel& model, const AreaLightQuery& query,
                                RenderCounters& counters);

// The reference's samples, without the rays wholeLightVisibility decides
// (the paper's adaptive sampling, whose choices depend on the rays, traces
// them all). An AreaLightSampler.
std::span<const LightSample> culledGridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                        const AreaLightQuery& query, AreaLightScratch& scratch,
                                                        RenderCounters& counters);

}  // namespace asos
