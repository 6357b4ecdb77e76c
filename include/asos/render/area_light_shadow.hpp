#pragma once
// ASOS shadows from distributed light sources (paper: "Distributed Light
// Sources", Figure 5). From the shaded point a shadow beam toward the whole
// light (a pyray to a rectangle's corners, a triangle to a segment's ends, a
// cone tangent to a sphere) is bounded by a cone and tested against the
// objects in its way like an eye pyray ("Detection Phase"); where it is
// marginal it is split (into four quarters, two halves, four equal-area
// pieces of the sphere's apparent disc), level by level, with the light's own
// EPS, MAX and jitter and the paper's stopping rule (SubdivisionTally). Each
// sub-beam that reaches the light becomes one LightSample along its central
// ray carrying I A cos(theta) (rectangle), I A (sphere: a disc facing the
// point) or I L (segment: the point on the line as a point light).
//
// Beyond the paper: a sub-beam that no occluder touches is refined without
// any ray while the light it carries varies across it by more than EPS (a
// point near a large light), so that unshadowed light is integrated to EPS
// too; and, with ShadowApex::Behind, the beam starts behind the surface so
// that it encloses the eye pyray's footprint as well as the light (the
// paper's "Future Work"). docs/lights.md has the rules.
#include <optional>
#include <span>

#include "asos/render/area_light.hpp"

namespace asos {

// POV-Ray's emitter: the fraction of an area light (model.isArea()) that
// reaches the point, by ASOS shadow beams: the share of the light (its
// form's pieces: uniform over a rectangle or a segment, over the square of
// POV-Ray's disc map) whose rays no object blocks, parts of the light below
// the surface's horizon included (they count as POV-Ray's shadow rays say:
// blocked by the shaded object itself where it is a solid, not by a flat
// one).
double asosVisibleFraction(const Scene& scene, const LightModel& model, ShadowApex apex,
                           const AreaLightQuery& query, AreaLightScratch& scratch, RenderCounters& counters);

// The paper's emitter: the samples of an area light (model.isArea()) by ASOS
// shadow beams. Nothing comes from parts of the light behind the surface.
std::span<const LightSample> asosAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  ShadowApex apex, const AreaLightQuery& query,
                                                  AreaLightScratch& scratch, RenderCounters& counters);

// Where a beam starts behind the surface (ShadowApex::Behind): on the line
// from the light's centre through `point`, the nearest point behind the
// surface from which the beam to the light holds every corner of the
// footprint (so its rays cross the tangent plane all over the footprint).
// Empty when there is none within reach (a light no larger than the
// footprint, a footprint off the tangent plane, a light at the horizon):
// then the beam starts at the point, as in the paper.
std::optional<Vec3> behindApex(const LightModel& model, const Vec3& point, const Vec3& normal,
                               const Footprint& footprint);

}  // namespace asos
