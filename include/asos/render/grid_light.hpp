#pragma once
// The classic model of an area light: POV-Ray's array of n1 x n2 point
// lights, each tested with a plain shadow ray, jittered with `jitter`, and
// sampled by POV-Ray's adaptive corner scheme with `adaptive n` (the four
// corners of the array first; a rectangle of it is split in four while its
// corners disagree, or down to level n at least). Unlike POV-Ray, which
// shades an area light along the direction of its centre, every point is
// shaded as the point light it is (diffuse and highlights along its own
// direction), and carries the same emitter weighting as the ASOS beams
// (cos theta for rectangles), so that both converge to the same image.
//
// Where the points lie (docs/lights.md): without adaptive, at the centres of
// n1 x n2 equal cells tiling the light, jitter moving each uniformly within
// its cell, so that every count samples the same light; with adaptive, on
// POV-Ray's lattice from edge to edge (i / (n - 1)), jitter moving a point by
// up to half a step (kept on the light). A spherical light's cells are mapped
// onto its apparent disc by Shirley and Chiu's equal-area concentric map
// (geometry/concentric_disc.hpp), as the ASOS beams' pieces are. Each light
// form says where its points lie and how it weights them
// (lights/light_form.hpp, GridPoints).
#include <span>

#include "asos/render/area_light.hpp"

namespace asos {

std::span<const LightSample> gridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  const AreaLightQuery& query,
                                                  AreaLightScratch& scratch, RenderCounters& counters);

}  // namespace asos
