#include "asos/render/transparent_shadow.hpp"

#include <algorithm>
#include <cmath>

#include "asos/render/shading.hpp"

namespace asos {

Vec3 transparentShadowFilter(const Scene& scene, const Vec3& point, const Vec3& lightPoint,
                             RenderCounters& counters) {
    if (!scene.anyTransparent()) return Vec3(1.0);
    const Vec3 d = lightPoint - point;
    const double distance = glm::length(d);
    if (!(distance > 2.0 * kPovShadowTolerance)) return Vec3(1.0);
    ++counters.shadowRays;
    const Ray ray{point, d / distance};
    const double tMax = distance - kPovShadowTolerance;
    Vec3 through(1.0);
    double tMin = kPovShadowTolerance;
    // Hit by hit toward the light. The bound stops a ray that would not move
    // on past a hit (a degenerate surface hit again at the same distance).
    for (int k = 0; k < 4096; ++k) {
        const std::optional<SurfaceHit> hit = scene.intersect(ray, tMin, tMax);
        if (!hit) return through;
        const auto index = static_cast<std::uint32_t>(hit->objectIndex);
        if (scene.transparent(index) && !scene.object(index).noShadow) {
            through *= shadowTransmittance(*scene.object(index).texture, hit->position);
            if (through == Vec3(0.0)) return through;
        }
        // As POV-Ray, the next search starts past the hit (MIN_ISECT_DEPTH).
        tMin = std::max(hit->t + kPovMinIsectDepth, std::nextafter(tMin, kInfinity));
    }
    return Vec3(0.0);
}

}  // namespace asos
