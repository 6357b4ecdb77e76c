#pragma once
// The classic grid of an area light: POV-Ray's array of n1 x n2 point
// lights, each tested with a plain shadow ray, jittered with `jitter`.
//
// POV-Ray's emitter (the default; trace.cpp, TraceAreaLightShadowRay): the
// visible fraction of its lattice from edge to edge (i / (n - 1)), jitter
// moving a point by up to half a step either way (past the light's edges,
// as POV-Ray's), weighted by its corner recursion: the four corners first;
// a rectangle of the array is split into four at its middle indices
// (POV-Ray's floor/ceil split) while it spans more than one step and is
// above the adaptive level (POV-Ray's default 100: every rectangle) or two
// of its corners differ (colours more than 0.1 apart in the sum of
// channels), and a rectangle not split is the mean of its corners. Each
// point is traced once. A disc's lattice is squeezed by POV-Ray's map and
// turned to face the point (lights/oriented_disc_light.hpp).
//
// The paper's emitter (`asos { emitter panel }`): every point is shaded as
// the point light it is (diffuse and highlights along its own direction),
// with the same emitter weighting as the ASOS beams (cos theta for
// rectangles), so that both converge to the same image. Without adaptive
// its points lie at the centres of n1 x n2 equal cells tiling the light,
// jitter moving each uniformly within its cell, so that every count samples
// the same light; with adaptive, POV-Ray's lattice and recursion as above,
// jitter kept on the light. A spherical light's cells are mapped onto its
// apparent disc by Shirley and Chiu's equal-area concentric map
// (geometry/concentric_disc.hpp), as the ASOS beams' pieces are. Each light
// form says where its points lie and how it weights them
// (lights/light_form.hpp, GridPoints).
#include <span>

#include "asos/render/area_light.hpp"

namespace asos {

// POV-Ray's emitter: the fraction of the light that reaches the point, by
// POV-Ray's recursion over its lattice.
double gridVisibleFraction(const Scene& scene, const LightModel& model, const AreaLightQuery& query,
                           AreaLightScratch& scratch, RenderCounters& counters);

// The paper's emitter: the samples of the grid's points that reach the point.
std::span<const LightSample> gridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  const AreaLightQuery& query,
                                                  AreaLightScratch& scratch, RenderCounters& counters);

}  // namespace asos
