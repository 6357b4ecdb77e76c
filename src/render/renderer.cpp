#include "asos/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <span>
#include <stdexcept>

#include <tbb/enumerable_thread_specific.h>

#include "asos/scene/asos_settings.hpp"
#include "asos/render/asos_tracer.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/ray_tracer.hpp"
#include "asos/render/sampling.hpp"

namespace asos {

namespace {

constexpr RenderMethod kMethods[] = {RenderMethod::Asos,   RenderMethod::Single,   RenderMethod::Grid,
                                     RenderMethod::Jitter, RenderMethod::Adaptive, RenderMethod::Am1};

// The largest image side accepted: beyond it pixel counts overflow the
// counters' consumers and no one means it.
constexpr int kMaxImageSide = 1 << 16;

TileRenderOptions tileOptions(const RenderSettings& s) {
    TileRenderOptions o;
    o.tileSize = s.tileSize;
    o.threads = s.threads;
    o.region = s.region;
    o.progress = s.progress;
    return o;
}

// The light context of a primary sample: area lights draw their random
// numbers from its pixel and index.
LightContext sampleContext(AreaLightScratch& scratch, std::uint64_t seed, const PrimarySample& sample) {
    return {&scratch, PixelRandom(seed, sample.pixelX, sample.pixelY), sample.index, nullptr, {}, {}};
}

// The radiance of eye rays for the classic methods; the grid and jitter
// estimators hand it a pixel's rays in batches, whose hits one packet search
// finds (the same hits as one by one, so the same image).
struct EyeRadiance {
    const RayTracer& tracer;
    RenderCounters& counters;
    AreaLightScratch& area;
    std::uint64_t seed;

    Vec3 operator()(const Ray& ray, const PrimarySample& sample) const {
        ++counters.eyeRays;
        return tracer.radiance(ray, 1, 1.0, counters, sampleContext(area, seed, sample));
    }
    void batch(std::span<const Ray> rays, std::span<const PrimarySample> samples,
               std::span<Vec3> colors) const {
        std::array<std::optional<SurfaceHit>, kPrimaryBatch> hits;
        for (std::size_t start = 0; start < rays.size(); start += hits.size()) {
            const std::size_t n = std::min(hits.size(), rays.size() - start);
            tracer.nearestHits(rays.subspan(start, n), std::span(hits).first(n));
            for (std::size_t k = 0; k < n; ++k) {
                ++counters.eyeRays;
                colors[start + k] = tracer.radiance(hits[k], rays[start + k], 1, 1.0, counters,
                                                    sampleContext(area, seed, samples[start + k]));
            }
        }
    }
};

// The classic methods: every primary ray is an eye ray traced with plain
// shadow rays toward point lights (docs/rendering.md, "Classic anti-aliasing
// methods") and the lights' method toward area lights.
TileRenderResult renderClassic(const RayTracer& tracer, const CameraModel& camera,
                               const RenderSettings& s, const TileRenderOptions& options) {
    tbb::enumerable_thread_specific<AreaLightScratch> scratch;
    auto eyeRadiance = [&](RenderCounters& counters) {
        return EyeRadiance{tracer, counters, scratch.local(), s.seed};
    };
    // POV-Ray compares anti-aliasing samples in the scene's working gamma;
    // with gamma correction off it compares the values as they are.
    AdaptiveSettings antialias = s.adaptive;
    antialias.assumedGamma = tracer.description().globals.assumedGamma.value_or(1.0);
    switch (s.method) {
        case RenderMethod::Single:
            return renderTiles(s.width, s.height, options, [&](int x, int y, RenderCounters& c) {
                return estimateSingle(camera, x, y, eyeRadiance(c));
            });
        case RenderMethod::Grid:
            return renderTiles(s.width, s.height, options, [&](int x, int y, RenderCounters& c) {
                return estimateGrid(camera, x, y, s.samples, eyeRadiance(c));
            });
        case RenderMethod::Jitter:
            return renderTiles(s.width, s.height, options, [&](int x, int y, RenderCounters& c) {
                return estimateJitter(camera, x, y, s.samples, PixelRandom(s.seed, x, y),
                                      eyeRadiance(c));
            });
        case RenderMethod::Adaptive: {
            const PixelRegion region = s.region.value_or(PixelRegion::whole(s.width, s.height));
            const CornerGrid corners =
                sampleCorners(camera, region, options,
                              [&](const Ray& ray, const PrimarySample& sample, RenderCounters& c) {
                                  ++c.eyeRays;
                                  return tracer.radiance(ray, 1, 1.0, c,
                                                         sampleContext(scratch.local(), s.seed, sample));
                              });
            TileRenderResult r =
                renderTiles(s.width, s.height, options, [&](int x, int y, RenderCounters& c) {
                    return estimateAdaptive(camera, x, y, corners.ofPixel(x, y), antialias,
                                            PixelRandom(s.seed, x, y), eyeRadiance(c));
                });
            r.counters += corners.counters;
            r.seconds += corners.seconds;
            return r;
        }
        case RenderMethod::Am1:
            return renderBlocks(s.width, s.height, kAm1BlockSize, options,
                                [&](const PixelRegion& block, RenderCounters& c) {
                                    return estimateAm1Block(camera, block, antialias, s.seed, eyeRadiance(c));
                                });
        case RenderMethod::Asos: break;
    }
    throw std::logic_error("renderClassic called for ASOS");
}

}  // namespace

const char* methodName(RenderMethod method) {
    switch (method) {
        case RenderMethod::Asos: return "asos";
        case RenderMethod::Single: return "single";
        case RenderMethod::Grid: return "grid";
        case RenderMethod::Jitter: return "jitter";
        case RenderMethod::Adaptive: return "adaptive";
        case RenderMethod::Am1: return "am1";
    }
    return "?";
}

std::optional<RenderMethod> parseMethod(std::string_view name) {
    for (RenderMethod m : kMethods)
        if (name == methodName(m)) return m;
    return std::nullopt;
}

std::string checkRenderSettings(const RenderSettings& s) {
    std::string problems;
    auto add = [&](const std::string& p) {
        if (!p.empty()) problems += (problems.empty() ? "" : "\n") + p;
    };
    if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
        add("image size must be between 1x1 and " + std::to_string(kMaxImageSide) + "x" +
            std::to_string(kMaxImageSide) + ", not " + std::to_string(s.width) + "x" +
            std::to_string(s.height));
    if (s.samples < 1 || s.samples > kMaxSamplesPerSide)
        add("samples must be between 1 and " + std::to_string(kMaxSamplesPerSide) + ", not " +
            std::to_string(s.samples));
    add(checkAdaptiveSettings(s.adaptive));
    add(checkAsosOptions(s.asos, "asos options"));
    if (s.lightSamples && (*s.lightSamples < 1 || *s.lightSamples > kMaxLightSamplesPerSide))
        add("light samples must be between 1 and " + std::to_string(kMaxLightSamplesPerSide) +
            ", not " + std::to_string(*s.lightSamples));
    if (s.shadowApex == ShadowApex::Behind &&
        (s.method != RenderMethod::Asos || effectiveLightMethod(s) != LightMethod::Asos))
        add("the shadow apex behind the surface needs the ASOS eye method and ASOS light method "
            "(it encloses the eye pyray's footprint)");
    if (s.patternFilter.value_or(false) && s.method != RenderMethod::Asos)
        add("the pattern filter needs the ASOS eye method (the classic methods sample patterns "
            "at points, as POV-Ray does)");
    if (s.threads < 0 || s.threads > kMaxThreads)
        add("threads must be between 0 (every core) and " + std::to_string(kMaxThreads) + ", not " +
            std::to_string(s.threads));
    if (s.tileSize < 1) add("tile size must be at least 1");
    if (s.region && s.width >= 1 && s.height >= 1 && !s.region->within(s.width, s.height))
        add("the region is empty or not inside the " + std::to_string(s.width) + "x" +
            std::to_string(s.height) + " image");
    return problems;
}

bool checkRenderable(const SceneDescription& d, Diagnostics& diagnostics) {
    bool ok = true;
    auto check = [&](const AsosOptions& options, const SourceLoc& loc, const char* what) {
        if (std::string e = checkAsosOptions(options, what); !e.empty()) {
            diagnostics.error(loc, e);
            ok = false;
        }
    };
    check(d.globals.asos, SourceLoc{}, "global_settings asos");
    for (const Object& o : d.objects) check(o.asos, o.loc, "asos");
    for (const Light& l : d.lights) {
        check(l.asos, l.loc, "asos");
        ok = checkLight(l, diagnostics) && ok;
    }
    return ok;
}

LightMethod effectiveLightMethod(const RenderSettings& s) {
    return s.lightMethod.value_or(s.method == RenderMethod::Asos ? LightMethod::Asos : LightMethod::Grid);
}

bool effectivePatternFilter(const RenderSettings& s) {
    return s.method == RenderMethod::Asos && s.patternFilter.value_or(!s.patternEdges);
}

namespace {
// What asos renders differently from POV-Ray with transparent objects, a
// warning each at the first object concerned: a merge of transparent
// objects keeps their inner surfaces (merge renders as union); and the
// shadows transparent objects cast from area lights are filtered along one
// ray per light sample (the centre's, for POV-Ray's lights without
// area_illumination), where POV-Ray filters every point of the light.
void warnTransparency(const SceneDescription& d, Diagnostics& diagnostics) {
    const Object* first = nullptr;
    for (const Object& o : d.objects) {
        if (!mayBeTransparent(*o.texture)) continue;
        if (!first && !o.noShadow) first = &o;
        const auto* csg = std::get_if<CsgShape>(&o.shape);
        if (!csg) continue;
        for (const CsgTree::Node& n : csg->tree->nodes)
            if (n.op == CsgTree::Op::Merge) {
                diagnostics.warning(o.loc, "a merge of transparent objects keeps their inner surfaces in asos "
                                           "(it renders as a union; POV-Ray removes them)");
                csg = nullptr;
                break;
            }
        if (!csg) break;
    }
    if (!first) return;
    if (!d.fogs.empty())
        diagnostics.warning(first->loc, "asos applies fog along rays inside transparent objects too; POV-Ray "
                                        "applies it only inside hollow ones");
    for (const Light& l : d.lights)
        if (l.area && !l.shadowless) {
            diagnostics.warning(first->loc,
                                "asos filters the shadow a transparent object casts from an area light along one "
                                "ray per light sample (toward the light's centre, without area_illumination): "
                                "its edges are sharper than POV-Ray's, which filters every point of the light");
            return;
        }
}
}  // namespace

RenderOutput render(const Scene& scene, const RenderSettings& settings) {
    if (std::string problems = checkRenderSettings(settings); !problems.empty())
        throw std::invalid_argument(problems);
    const CameraModel camera(scene.description().camera, settings.width, settings.height);
    LightSetup lights;
    lights.method = effectiveLightMethod(settings);
    lights.samples = settings.lightSamples;
    lights.apex = settings.shadowApex;
    lights.sampler = settings.areaLightSampler;
    lights.sceneSettings = sceneAsosSettings(scene.description().globals, settings.asos);
    const RayTracer tracer(scene, lights);
    const TileRenderOptions options = tileOptions(settings);

    TileRenderResult r;
    if (settings.method == RenderMethod::Asos) {
        const AsosTracer asos(tracer, camera,
                              sceneAsosSettings(scene.description().globals, settings.asos),
                              settings.seed, settings.patternEdges,
                              effectivePatternFilter(settings));
        // Per-thread buffers: no pixel allocates once they have grown.
        tbb::enumerable_thread_specific<AsosScratch> scratch;
        r = renderTiles(settings.width, settings.height, options,
                        [&](int x, int y, RenderCounters& c) {
                            return asos.tracePixel(x, y, scratch.local(), c);
                        });
    } else {
        r = renderClassic(tracer, camera, settings, options);
    }

    RenderOutput out;
    out.color = std::move(r.color);
    out.samples = std::move(r.samples);
    out.stats.method = methodName(settings.method);
    out.stats.width = settings.width;
    out.stats.height = settings.height;
    out.stats.threads = r.threads;
    out.stats.counters = r.counters;
    out.stats.times.renderSeconds = r.seconds;
    return out;
}

std::optional<RenderOutput> render(const SceneDescription& description,
                                   const RenderSettings& settings, Diagnostics& diagnostics) {
    if (std::string problems = checkRenderSettings(settings); !problems.empty())
        throw std::invalid_argument(problems);
    if (!checkRenderable(description, diagnostics)) return std::nullopt;
    warnTransparency(description, diagnostics);
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Scene> scene = Scene::build(description, diagnostics);
    const double buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!scene) return std::nullopt;
    RenderOutput out = render(*scene, settings);
    out.stats.times.buildSeconds = buildSeconds;
    return out;
}

}  // namespace asos
