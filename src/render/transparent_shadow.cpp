#include "asos/render/transparent_shadow.hpp"

#include <algorithm>
#include <cmath>

#include "asos/render/interiors.hpp"
#include "asos/render/shading.hpp"

namespace asos {

Vec3 transparentShadowFilter(const Scene& scene, const Vec3& point, const Vec3& lightPoint,
                             RenderCounters& counters, const InteriorList& startInside) {
    if (!scene.anyTransparent()) return Vec3(1.0);
    const Vec3 d = lightPoint - point;
    const double distance = glm::length(d);
    if (!(distance > 2.0 * kPovShadowTolerance)) return Vec3(1.0);
    ++counters.shadowRays;
    const Ray ray{point, d / distance};
    const double tMax = distance - kPovShadowTolerance;
    Vec3 through(1.0);
    double tMin = kPovShadowTolerance;
    // The insides the shadow ray is in, entered at its hits, and where it
    // last crossed a surface.
    InteriorList inside = startInside;
    double last = 0.0;
    // Hit by hit toward the light. The bound stops a ray that would not move
    // on past a hit (a degenerate surface hit again at the same distance).
    for (int k = 0; k < 4096; ++k) {
        const std::optional<SurfaceHit> hit = scene.intersect(ray, tMin, tMax);
        if (!hit) return through;
        const auto index = static_cast<std::uint32_t>(hit->objectIndex);
        const Object& object = scene.object(index);
        if (scene.transparent(index) && !object.noShadow) {
            through *= shadowTransmittance(*object.texture, hit->position);
            const Interior& interior = interiorOf(object);
            // POV-Ray's faked caustics (ComputeShadowTexture): each layer
            // multiplies by 1 + |cos|^caustics, with the surface's normal.
            if (interior.caustics != 0.0) {
                const double gain = 1.0 + std::pow(std::fabs(glm::dot(hit->normal, ray.dir)), interior.caustics);
                through *= std::pow(gain, double(1 + object.texture->above.size()));
            }
            // Leaving an inside: its fade over the way through it.
            const void* key = interiorKey(object);
            if (inside.remove(key)) through *= fadeThrough(interior, hit->t - last, false);
            else inside.push(key, interior);
            last = hit->t;
            if (through == Vec3(0.0)) return through;
        }
        // As POV-Ray, the next search starts past the hit (MIN_ISECT_DEPTH).
        tMin = std::max(hit->t + kPovMinIsectDepth, std::nextafter(tMin, kInfinity));
    }
    return Vec3(0.0);
}

}  // namespace asos
