#pragma once
// Shadows of transparent objects (docs/rendering.md, "Transparency"): what
// the objects that let light through pass of a light's colour toward a
// point, per channel. Opaque occluders are the callers' to account for
// (plain shadow rays, ASOS shadow pyrays and beams); this filters what they
// let through, along one ray.
#include "asos/render/interiors.hpp"
#include "asos/render/stats.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

// The product of the shadow transmittance (render/shading.hpp,
// shadowTransmittance) at every hit of a transparent object that casts
// shadows on the segment from `point` to `lightPoint` (POV-Ray's
// ComputeShadowColour), from the shadow tolerance to the tolerance before
// the light; opaque objects are passed. 1 in a scene without transparent
// objects, and no ray counted then. `inside`: the insides the shadow ray
// starts in (those of the ray that found the point, as POV-Ray's shadow ray
// copies them): leaving one fades the light over the way through it
// (render/interiors.hpp), as does leaving one it entered.
Vec3 transparentShadowFilter(const Scene& scene, const Vec3& point, const Vec3& lightPoint,
                             RenderCounters& counters, const InteriorList& inside = {});

}  // namespace asos
