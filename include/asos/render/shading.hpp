#pragma once
// POV-Ray 3.7's local lighting model for what the scene language accepts:
// pigment (solid, checker, brick), ambient x ambient_light, diffuse with brilliance,
// phong + phong_size, specular + roughness, reflection traced recursively up
// to max_trace_level (with POV-Ray's adc_bailout), light fade, shadowless
// lights. The formulas and their sources are in docs/rendering.md; each was
// checked against renders by the installed povray
// (tests/unit/povray_crosscheck_test.cpp).
//
// Shading knows nothing about the scene's geometry. The caller supplies:
//  - for each light, the light arriving at the point, as a list of samples
//    (direction, distance, colour): one for a point light, several weighted
//    ones for an area light; shadows are already applied to their colours;
//  - the colour seen along the reflected ray.
// All colours are linear RGB in the scene's working space.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "asos/geometry/hit.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/render/normal_pattern.hpp"
#include "asos/render/sampling.hpp"
#include "asos/scene/description.hpp"
#include "asos/lights/light_beam.hpp"
#include "asos/scene/pov_tolerances.hpp"

namespace asos {

// POV-Ray's default adc_bailout: rays whose weight falls below it are not traced.
inline constexpr double kDefaultAdcBailout = 1.0 / 255.0;

// Light reaching the shaded point from (part of) one light source.
struct LightSample {
    Vec3 direction{0.0, 1.0, 0.0};  // unit, from the shaded point toward the light point
    double distance = 0.0;          // from the shaded point to the light point (for fade)
    Vec3 color{0.0};                // light colour x lit fraction x sample weight, before fade
};

// The one sample of a point light (or of any light taken at one point, as
// POV-Ray does for an area light's diffuse and highlights: its centre, with
// the colour scaled by the lit fraction).
inline LightSample pointLightSample(const Vec3& lightPosition, const Vec3& lightColor,
                                    const Vec3& point, double litFraction = 1.0) {
    const Vec3 d = lightPosition - point;
    const double distance = glm::length(d);
    return {distance > 0.0 ? d / distance : Vec3(0.0), distance, lightColor * litFraction};
}

// What the light callback is asked about.
struct ShadingPoint {
    int lightIndex = 0;
    const Light* light = nullptr;
    const SurfaceHit* hit = nullptr;
    Vec3 position{0.0};  // == hit->position
    Vec3 normal{0.0};    // unit surface normal turned toward the incoming ray
    const Ray* ray = nullptr;
    int depth = 1;       // trace level of the ray that hit (1: eye ray)
};

struct ShadingSettings {
    Vec3 ambientLight{1.0};
    int maxTraceLevel = 5;
    double adcBailout = kDefaultAdcBailout;
    // A scene read as older than 3.7 takes a layer's own share of its light
    // with POV-Ray's legacy formula (layerOpacity).
    bool legacyLayerOpacity = false;

    static ShadingSettings from(const SceneDescription& d) {
        // Capped here too, for a description not made by the interpreter: a
        // deeper recursion could overflow a worker thread's stack.
        return {d.globals.ambientLight, std::clamp(d.globals.maxTraceLevel, 1, kMaxTraceLevelLimit),
                kDefaultAdcBailout, d.version < 3.7};
    }
};

// Where a finish's crand draws its numbers: the pixel's random numbers and
// the key of the sample being shaded (LightContext's), so that the grain
// depends on the pixel, the sample and the seed only.
struct GrainSource {
    PixelRandom rng{0, 0, 0};
    std::uint64_t key = 0;
    // A number in [0, 1) for light `light`'s sample `sample` on layer `layer`.
    double draw(int light, std::size_t sample, std::size_t layer) const {
        const std::uint64_t index = std::uint64_t(static_cast<std::uint32_t>(light)) << 40 ^
                                    std::uint64_t(sample) << 8 ^ std::uint64_t(layer);
        return rng.uniform(SampleStream::Grain, mix64(key ^ index));
    }
};

// The ray being shaded and where it ended. `depth` is POV-Ray's trace level
// (eye rays 1, their reflections 2, ...) and `weight` its ADC weight (eye
// rays 1). `pigment`: the pigment's colour when the caller has it already
// (ASOS's pattern filter, averaged over the ray's footprint); otherwise the
// pigment is evaluated at the hit.
struct ShadeRequest {
    const SurfaceHit& hit;
    const Texture& texture;
    const Ray& ray;
    int depth = 1;
    double weight = 1.0;
    std::optional<Color> pigment = std::nullopt;
    GrainSource grain{};
    // The ratio of the iors across the surface that a Fresnel reflection
    // uses (POV-Ray's ComputeRelativeIOR; reflectionIor in interiors.hpp).
    double reflectionIor = 1.0;
};

// The pigment's colour at a world point: CheckerPattern and BrickPattern in
// pattern space (1: color2).
Color evaluatePigment(const Pigment& pigment, const Vec3& worldPoint);

// POV-Ray's greyscale of a colour (its RED/GREEN/BLUE_INTENSITY weights).
inline double povGreyscale(const Vec3& c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }

// The share of its own light a texture layer of colour `c` keeps: 1 for an
// opaque one. POV-Ray 3.7 (trace.cpp, ComputeLightedTexture, the colour's
// opacity): 1 - (filter + transmit), measured with `povray`; a scene older
// than 3.7 takes POV-Ray's legacy 1 - (filter x the colour's largest
// component + transmit).
inline double layerOpacity(const Color& c, bool legacy) {
    const double filtered = legacy ? c.filter * std::max(c.rgb.x, std::max(c.rgb.y, c.rgb.z)) : c.filter;
    return 1.0 - (filtered + c.transmit);
}

// What a layer of colour `c` lets through of the layers under it, per
// channel: POV-Ray's rgbTransm, filter by the colour plus transmit.
inline Vec3 layerTransmittance(const Color& c) { return c.rgb * c.filter + Vec3(c.transmit); }

// The normal turned to face the incoming ray (POV-Ray flips it so).
inline Vec3 facingNormal(const Vec3& normal, const Vec3& rayDir) {
    return glm::dot(normal, rayDir) > 0.0 ? -normal : normal;
}
// Mirror direction of unit d about unit normal n.
inline Vec3 reflectDirection(const Vec3& d, const Vec3& n) {
    return glm::normalize(d - 2.0 * glm::dot(d, n) * n);
}

// The mirror direction off a layer's normal `tilted`, kept on the viewer's
// side of the surface's own normal `surface` (both unit, facing the ray), as
// POV-Ray's ComputeReflection: a direction below the surface is mirrored
// once more off it, or, when it is below the tilted normal's plane too,
// taken off the surface's normal instead.
inline Vec3 mirrorDirection(const Vec3& d, const Vec3& tilted, const Vec3& surface) {
    if (tilted == surface) return reflectDirection(d, surface);
    Vec3 r = d - 2.0 * glm::dot(d, tilted) * tilted;
    const double below = glm::dot(r, surface);
    if (below < 0.0) {
        if (glm::dot(r, tilted) < 0.0) r = d - 2.0 * glm::dot(d, surface) * surface;
        else r -= 2.0 * below * surface;
    }
    return glm::normalize(r);
}

// POV-Ray's empirical Fresnel curve for metallic surfaces (its
// ComputeSpecularColour and ComputeLightedTexture): 0 head-on (the full
// tint), 1 at grazing angles, for the cosine `cosAngle` of the angle to the
// normal.
inline double metallicFresnel(double cosAngle) {
    const double x = std::fabs(std::acos(std::clamp(cosAngle, -1.0, 1.0))) / (0.5 * std::numbers::pi);
    const double F = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return std::clamp(F, 0.0, 1.0);
}

// What `metallic` multiplies a highlight or a reflection by: the surface's
// `colour` head-on, white at grazing angles (metallicFresnel), by `amount`.
inline Vec3 metallicTint(double amount, double cosAngle, const Vec3& colour) {
    return Vec3(1.0) + amount * (1.0 - metallicFresnel(cosAngle)) * (colour - Vec3(1.0));
}

// ambient x pigment x ambient_light.
Vec3 ambientTerm(const Finish& finish, const Vec3& pigment, const Vec3& ambientLight);

// One light sample's diffuse, phong and specular (POV-Ray's
// ComputeDiffuseColour, ComputePhongColour, ComputeSpecularColour). `normal`
// faces the ray; `rayDir` is the unit direction of the ray that hit. A sample
// from behind the surface gives nothing; shadowless lights give no highlights.
// `grain`: the number in [0, 1) crand takes off the diffuse intensity,
// times crand.
// `colour`: the layer's pigment colour before its opacity, which metallic
// highlights take (the pigment when null).
Vec3 directLight(const Finish& finish, const Vec3& pigment, const Vec3& normal, const Vec3& rayDir,
                 const Light& light, const LightSample& sample, double grain = 0.0,
                 const Vec3* colour = nullptr);

// Whether the finish reacts to lights at all (otherwise no light is queried).
inline bool usesLights(const Finish& f) {
    return f.diffuse != 0.0 || f.phong != 0.0 || f.specular != 0.0;
}

// The colour of a ray that hits nothing. POV-Ray, writing no alpha channel,
// composes the background over black: its transmit darkens it wherever it is
// seen, reflections included, and its filter does nothing (measured).
inline Vec3 backgroundColor(const SceneDescription& scene) {
    return scene.background.rgb * (1.0 - scene.background.transmit);
}

// The shaded colour of a surface point.
//
// lightArriving(const ShadingPoint&) -> std::span<const LightSample>
//   the light reaching the point from light `lightIndex`; the span must stay
//   valid until the next call (e.g. a per-thread buffer). It is called only
//   when the finish uses lights; it may return no samples (light blocked, or
//   facing away: samples from behind the surface are ignored anyway).
// traceReflected(const Ray& ray, int depth, double weight) -> Vec3
//   the colour along the mirror ray (unit direction, origin at the hit point:
//   the callee must skip the surface itself). Called only when the finish
//   reflects, depth <= max_trace_level and weight >= adc_bailout, as POV-Ray's
//   TraceRay decides; otherwise the reflection is black.
// A texture layer as the shading sees it: lit with its finish, its pigment
// scaled by its opacity, its light seen through the layers above it.
struct ShadedLayer {
    const Finish* finish = nullptr;
    Vec3 normal{0.0};   // unit, facing the ray: tilted by the layer's normal pattern
    Vec3 pigment{0.0};  // the pigment's colour x its opacity
    Vec3 through{1.0};  // what the layers above let through (POV-Ray's filCol)
    double weight = 1.0;  // the ray's weight left for it (POV-Ray's trans)
    Vec3 after{1.0};    // what this layer and those above let through
    Vec3 colour{0.0};   // the pigment's colour (metallic tints with it)
    Vec3 reflectivity{0.0};  // what it reflects at this angle (reflectivity())
    double reflectionWeight = 0.0;  // the reflected ray's weight, before the ray's own
};

// What a finish reflects of a ray meeting its layer at `cosAngle` (the
// cosine between the reversed ray and the layer's normal), and the factor
// the reflected ray's weight takes (POV-Ray's ComputeReflectivity): between
// reflectionMin head-on and reflection at grazing angles by
// (1 - cos)^falloff, or by the Fresnel equation for unpolarised light at the
// ior ratio `ior` (ComputeRelativeIOR's); then tinted by `colour` for
// reflection's metallic (ComputeLightedTexture).
struct Reflectivity {
    Vec3 colour{0.0};
    double weight = 0.0;
};
inline Reflectivity reflectivity(const Finish& f, double cosAngle, double ior, const Vec3& colour) {
    Reflectivity r;
    const Vec3& hi = f.reflection;
    const Vec3& lo = f.reflectionMin ? *f.reflectionMin : hi;
    const auto max3 = [](const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); };
    if (f.fresnel) {
        const double sqx = ior * ior + cosAngle * cosAngle - 1.0;
        if (sqx > 0.0) {
            const double g = std::sqrt(sqx);
            const double a = (g - cosAngle) / (g + cosAngle);
            const double b = (cosAngle * (g + cosAngle) - 1.0) / (cosAngle * (g - cosAngle) + 1.0);
            const double F = std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
            r.colour = F * hi + (1.0 - F) * lo;
        } else {
            r.colour = hi;
        }
        r.weight = max3(r.colour);
    } else {
        r.weight = std::max(max3(hi), max3(lo));
        const double frac = std::fabs(f.reflectionFalloff - 1.0) > kPovEpsilon
                                ? std::pow(1.0 - cosAngle, f.reflectionFalloff)
                                : 1.0 - cosAngle;
        if (std::fabs(frac) < kPovEpsilon)
            r.colour = lo;
        else if (std::fabs(frac - 1.0) < kPovEpsilon)
            r.colour = hi;
        else
            r.colour = frac * hi + (1.0 - frac) * lo;
    }
    if (f.reflectionMetallic != 0.0) r.colour *= metallicTint(f.reflectionMetallic, cosAngle, colour);
    return r;
}

// The texture's layers that the ray sees, top first: POV-Ray's loop in
// ComputeLightedTexture, which stops where the layers above let less than
// adc_bailout through. What the bottom layer's `after` lets through shows
// what is behind the surface (shadeSurface).
// `bottomPigment`: the pigment's colour of a texture of one layer, when the
// caller has it (ShadeRequest::pigment). `normal`: the surface's, unit and
// turned toward the ray, which POV-Ray tilts (ComputeTextureColour turns it
// first).
// `rayDir` (unit) and `ior` (ShadeRequest::reflectionIor) give each layer
// its reflectivity; with conserve_energy a layer lets through less by what it
// reflects.
template <std::size_t N>
std::span<const ShadedLayer> shadedLayers(const Texture& texture, const Vec3& point, const Vec3& normal,
                                          const std::optional<Color>& bottomPigment,
                                          const ShadingSettings& settings,
                                          std::array<ShadedLayer, N>& storage,
                                          std::vector<ShadedLayer>& overflow, const Vec3& rayDir = Vec3(0.0),
                                          double ior = 1.0) {
    const std::size_t count = texture.above.size() + 1;
    ShadedLayer* out = storage.data();
    if (count > N) {
        overflow.resize(count);
        out = overflow.data();
    }
    std::size_t n = 0;
    Vec3 through(1.0);
    double weight = 1.0;
    for (std::size_t i = count; i-- > 0 && (n == 0 || weight > settings.adcBailout);) {
        const TextureLayer& layer = i == 0 ? static_cast<const TextureLayer&>(texture) : texture.above[i - 1];
        const Color c = (count == 1 && bottomPigment) ? *bottomPigment : evaluatePigment(layer.pigment, point);
        const Vec3 tilted = layer.normal ? perturbedNormal(*layer.normal, point, normal) : normal;
        const Vec3 before = through;
        through *= layerTransmittance(c);
        Reflectivity r;
        if (reflects(layer.finish)) {
            r = reflectivity(layer.finish, -glm::dot(rayDir, tilted), ior, c.rgb);
            if (layer.finish.conserveEnergy)
                through *= glm::min(Vec3(1.0), Vec3(1.0) - r.colour);
        }
        out[n++] = {&layer.finish, tilted, c.rgb * layerOpacity(c, settings.legacyLayerOpacity), before, weight,
                    through, c.rgb, r.colour, weight * r.weight};
        weight = std::min(1.0, std::fabs(povGreyscale(through)));
    }
    return {out, n};
}

// The shaded colour of a surface point.
//
// lightArriving(const ShadingPoint&) -> std::span<const LightSample>
//   the light reaching the point from light `lightIndex`; the span must stay
//   valid until the next call (e.g. a per-thread buffer). It is called only
//   when some layer's finish uses lights; it may return no samples (light
//   blocked, or facing away: samples from behind the surface are ignored
//   anyway).
// traceReflected(const Ray& ray, int depth, double weight) -> Vec3
//   the colour along the mirror ray (unit direction, origin at the hit point:
//   the callee must skip the surface itself). Called only when a layer's
//   finish reflects, depth <= max_trace_level and weight >= adc_bailout, as
//   POV-Ray's TraceRay decides; otherwise the reflection is black.
//
// traceTransmitted(const Vec3& topNormal, double weight) -> Transmitted
//   what shows through a transparent surface: called, as POV-Ray's
//   ComputeLightedTexture and TraceRay decide, when every layer was seen and
//   what they let through together, F, has a greyscale above adc_bailout,
//   depth < max_trace_level and the weight (times F's largest channel) is at
//   least adc_bailout. The callee crosses the object's interior at the hit
//   (render/interiors.hpp): the ray goes on unbent at the same trace level,
//   is refracted, or is reflected whole off `topNormal` (the top layer's,
//   facing the ray) at the next level; the answer is faded by the interior
//   the ray came through. It is added times F, or, after a total internal
//   reflection, as it is, and then the layers whose normal is the top one's
//   reflect nothing more (ComputeLightedTexture's tir_occured).
//
// A layered texture: each layer adds its ambient, diffuse and highlights, the
// pigment's terms times its opacity, all times what the layers above let
// through; each adds its reflection, traced with the weight the layers above
// leave it, unfiltered (POV-Ray's ComputeLightedTexture). Each layer is lit
// and reflects with its own normal, tilted by its normal pattern; the lights
// are asked with the surface's (ShadingPoint::normal), so a light below the
// surface's horizon lights no tilted normal (POV-Ray's would, on a surface
// that does not shadow itself there, as a plane).
// What shows through a transparent surface (shadeSurface's traceTransmitted).
struct Transmitted {
    Vec3 colour{0.0};
    bool totalReflection = false;  // reflected whole: not filtered by the surface
};

template <class LightFn, class ReflectFn, class TransmitFn>
Vec3 shadeSurface(const ShadeRequest& req, std::span<const Light> lights,
                  const ShadingSettings& settings, LightFn&& lightArriving,
                  ReflectFn&& traceReflected, TransmitFn&& traceTransmitted) {
    const Vec3 rayDir = glm::normalize(req.ray.dir);
    const Vec3 normal = facingNormal(req.hit.normal, rayDir);
    // Every term that uses the pigment (ambient, diffuse) is linear in it, so
    // a pigment averaged over a footprint gives the average of those terms.
    std::array<ShadedLayer, 4> storage;
    std::vector<ShadedLayer> overflow;
    const std::span<const ShadedLayer> layers =
        shadedLayers(req.texture, req.hit.position, normal, req.pigment, settings, storage, overflow, rayDir,
                     req.reflectionIor);

    Vec3 color(0.0);
    bool lit = false;
    for (const ShadedLayer& l : layers) {
        color += l.through * ambientTerm(*l.finish, l.pigment, settings.ambientLight);
        lit = lit || usesLights(*l.finish);
    }
    if (lit) {
        for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
            const ShadingPoint point{i, &lights[i], &req.hit, req.hit.position, normal, &req.ray,
                                     req.depth};
            const std::span<const LightSample> samples = lightArriving(point);
            // A spotlight or cylinder light scales each sample by its
            // direction from the light (lights/light_beam.hpp).
            const std::optional<LightBeam> beam =
                lights[i].type == LightType::Point ? std::nullopt : std::optional(LightBeam::of(lights[i]));
            for (std::size_t k = 0; k < samples.size(); ++k) {
                LightSample sample = samples[k];
                if (beam) sample.color *= beam->factor(req.hit.position, sample.direction);
                for (std::size_t j = 0; j < layers.size(); ++j) {
                    const ShadedLayer& l = layers[j];
                    if (!usesLights(*l.finish)) continue;
                    const double grain = l.finish->crand > 0.0 ? l.finish->crand * req.grain.draw(i, k, j) : 0.0;
                    color += l.through * directLight(*l.finish, l.pigment, l.normal, rayDir, lights[i], sample,
                                                     grain, &l.colour);
                }
            }
        }
    }
    // Transmission (POV-Ray's ComputeLightedTexture after its layer loop):
    // only where every layer was seen, the bottom one included.
    bool totalReflection = false;
    if (layers.size() == req.texture.above.size() + 1) {
        const Vec3& filter = layers.back().after;
        const double trans = std::min(1.0, std::fabs(povGreyscale(filter)));
        const double weight =
            req.weight * std::max(std::fabs(filter.x), std::max(std::fabs(filter.y), std::fabs(filter.z)));
        if (trans > settings.adcBailout && req.depth < settings.maxTraceLevel && weight >= settings.adcBailout) {
            const Transmitted t = traceTransmitted(layers.front().normal, weight);
            totalReflection = t.totalReflection;
            color += totalReflection ? t.colour : filter * t.colour;
        }
    }
    // Reflection (POV-Ray's ComputeReflectivity, ComputeReflection, and the
    // trace-level and ADC tests at the top of TraceRay); after a total
    // internal reflection, not where a layer's normal is the top one's.
    // Each layer reflects by its reflectivity at the ray's angle; a
    // reflection exponent raises what is reflected to its power.
    for (const ShadedLayer& l : layers) {
        const Vec3& reflection = l.reflectivity;
        if (reflection == Vec3(0.0)) continue;
        if (totalReflection && glm::all(glm::lessThanEqual(glm::abs(l.normal - layers.front().normal), Vec3(1e-10))))
            continue;
        const double weight = req.weight * l.reflectionWeight;
        if (req.depth < settings.maxTraceLevel && weight >= settings.adcBailout) {
            const Ray mirror{req.hit.position, mirrorDirection(rayDir, l.normal, normal)};
            const Vec3 seen = traceReflected(mirror, req.depth + 1, weight);
            const double e = l.finish->reflectionExponent;
            color += reflection * (e != 1.0 ? glm::pow(glm::max(seen, Vec3(0.0)), Vec3(e)) : seen);
        }
    }
    return color;
}

// The same for a caller with no transparent surfaces to show through (what
// would show is black).
template <class LightFn, class ReflectFn>
Vec3 shadeSurface(const ShadeRequest& req, std::span<const Light> lights,
                  const ShadingSettings& settings, LightFn&& lightArriving,
                  ReflectFn&& traceReflected) {
    return shadeSurface(req, lights, settings, lightArriving, traceReflected,
                        [](const Vec3&, double) { return Transmitted{}; });
}

// What a surface with this texture lets through toward a light at a world
// point, per channel (POV-Ray's ComputeShadowTexture without an interior):
// the product of its layers' filter x colour + transmit; 0 for an opaque one.
inline Vec3 shadowTransmittance(const Texture& texture, const Vec3& point) {
    Vec3 through = layerTransmittance(evaluatePigment(texture.pigment, point));
    for (const TextureLayer& layer : texture.above) through *= layerTransmittance(evaluatePigment(layer.pigment, point));
    return through;
}

}  // namespace asos
