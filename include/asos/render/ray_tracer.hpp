#pragma once
// Plain rays through a built Scene, shaded with POV-Ray 3.7's model
// (render/shading.hpp): the radiance of eye rays for the classic methods, and
// of reflected rays for every method. The paper traces reflections with plain
// rays too ("Future Work": a reflected pyramid off a curved surface is left
// for further research), and such rays use plain shadow rays.
//
// Tolerances are POV-Ray's, so that images match its renders: hits nearer
// than MIN_ISECT_DEPTH along a ray are ignored, and a shadow ray ignores hits
// within SHADOW_TOLERANCE of the shaded point and of the light.
#include <optional>
#include <span>

#include "asos/render/area_light.hpp"
#include "asos/render/atmosphere.hpp"
#include "asos/render/scene_lights.hpp"
#include "asos/render/shading.hpp"
#include "asos/render/stats.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

// The texture of an object (shared between objects, never null).
inline const Texture& textureOf(const Object& object) { return *object.texture; }

class RayTracer {
public:
    // `lights`: how area lights are shadowed (render/scene_lights.hpp).
    explicit RayTracer(const Scene& scene, const LightSetup& lights = {})
        : scene_(scene),
          shading_(ShadingSettings::from(scene.description())),
          lights_(scene.description(), lights),
          atmosphere_(scene.description()) {}

    const Scene& scene() const { return scene_; }
    const SceneDescription& description() const { return scene_.description(); }
    const ShadingSettings& shadingSettings() const { return shading_; }
    std::span<const Light> lights() const { return scene_.description().lights; }
    const SceneLights& sceneLights() const { return lights_; }
    // The sky and the fogs (render/atmosphere.hpp).
    const Atmosphere& atmosphere() const { return atmosphere_; }

    // The nearest hit of an eye or reflected ray.
    std::optional<SurfaceHit> nearestHit(const Ray& ray) const {
        return scene_.intersect(ray, kPovMinIsectDepth, kInfinity);
    }
    // hits[i] = nearestHit(rays[i]) for many rays at once (a packet through
    // Scene::intersect: coherent eye rays share the BVH traversal).
    void nearestHits(std::span<const Ray> rays, std::span<std::optional<SurfaceHit>> hits) const {
        scene_.intersect(rays, kPovMinIsectDepth, kInfinity, hits);
    }

    // The colour seen along a ray (unit direction) of trace level `depth`
    // (eye rays 1) and ADC weight `weight` (eye rays 1). Does not count the
    // ray itself; counts the reflected and shadow rays it spawns. `context`:
    // the area lights' buffers and random numbers for this sample.
    Vec3 radiance(const Ray& ray, int depth, double weight, RenderCounters& counters,
                  const LightContext& context = {}) const;
    // The same, given the ray's nearest hit (nearestHit or nearestHits):
    // the sky (or background) where there is none; fogged either way.
    Vec3 radiance(const std::optional<SurfaceHit>& hit, const Ray& ray, int depth, double weight,
                  RenderCounters& counters, const LightContext& context = {}) const;

    // A known hit of `ray`, shaded with plain shadow rays toward point
    // lights and the lights' method toward area lights.
    Vec3 shade(const SurfaceHit& hit, const Ray& ray, int depth, double weight,
               RenderCounters& counters, const LightContext& context = {}) const;

    // A known hit of `ray`, shaded with the caller's light function (as
    // shadeSurface takes it), and with `pigment` where the caller has the
    // pigment's colour (ShadeRequest::pigment); reflections are traced with
    // plain rays.
    template <class LightFn>
    Vec3 shadeWith(const SurfaceHit& hit, const Ray& ray, int depth, double weight,
                   LightFn&& lightArriving, RenderCounters& counters,
                   const LightContext& context = {},
                   const std::optional<Color>& pigment = std::nullopt) const {
        const Object& object = scene_.object(static_cast<std::uint32_t>(hit.objectIndex));
        return shadeSurface({hit, textureOf(object), ray, depth, weight, pigment, {context.rng, context.key},
                             reflectionIor(context.inside, object)},
                            lights(),
                            shading_, lightArriving,
                            [&](const Ray& mirror, int d, double w) {
                                ++counters.reflectedRays;
                                return radiance(mirror, d, w, counters, context.reflected(d));
                            },
                            [&](const Vec3& topNormal, double w) {
                                return transmitted(hit, ray, depth, topNormal, w, counters, context);
                            });
    }

    // What shows through the transparent surface of `hit` (shadeSurface's
    // traceTransmitted): the ray crosses the object's interior, goes on
    // unbent, refracted or totally reflected, and is faded by the interior
    // it came through (render/interiors.hpp). Counted with the reflected rays.
    Transmitted transmitted(const SurfaceHit& hit, const Ray& ray, int depth, const Vec3& topNormal,
                            double weight, RenderCounters& counters, const LightContext& context) const;

    // The samples of area light `point.lightIndex` at a shading point, by
    // the lights' method; they live in context.scratch (which must be set)
    // until its next use.
    std::span<const LightSample> areaLightSamples(const ShadingPoint& point, const LightContext& context,
                                                  RenderCounters& counters) const;

    // Whether a plain shadow ray from `point` toward the point light at
    // `lightPosition` is blocked by an object that casts shadows.
    bool shadowRayBlocked(const Vec3& point, const Vec3& lightPosition,
                          RenderCounters& counters) const;
    // What reaches `point` of the point light at `lightPosition` along a
    // plain shadow ray, per channel: 0 where an opaque object that casts
    // shadows blocks it, else what the transparent ones between let through
    // (transparentShadowFilter; POV-Ray's ComputeShadowColour).
    Vec3 shadowRayFilter(const Vec3& point, const Vec3& lightPosition, RenderCounters& counters,
                         const InteriorList& inside = {}) const;

    // The sample of point light `light` at a shading point, through a plain
    // shadow ray: none when the light is behind the surface (it would light
    // nothing) or blocked. `storage` holds the sample the span refers to;
    // `inside`: the insides of the ray that found the point.
    std::span<const LightSample> plainLightSample(const ShadingPoint& point, LightSample& storage,
                                                  RenderCounters& counters, const InteriorList& inside = {}) const;

private:
    const Scene& scene_;
    ShadingSettings shading_;
    SceneLights lights_;
    Atmosphere atmosphere_;
};

// Whether the light at `lightPosition` can light a surface point with
// `normal` (turned toward the viewer) at all: POV-Ray's test on the cosine of
// incidence, below which a light contributes nothing and no shadow ray is traced.
inline bool facesLight(const Vec3& point, const Vec3& normal, const Vec3& lightPosition) {
    const Vec3 d = lightPosition - point;
    const double len = glm::length(d);
    return len > 0.0 && glm::dot(normal, d) >= kPovEpsilon * len;
}

}  // namespace asos
