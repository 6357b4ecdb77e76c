#pragma once
// The insides a ray travels through, and what an interior does to the rays
// that cross its surface (docs/rendering.md, "Refraction"): POV-Ray 3.7's
// bookkeeping (trace.cpp, ComputeRefraction), its refraction by Heckbert's
// method (TraceRefractionRay) and its fade (ComputeLightedTexture,
// ComputeShadowTexture).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "asos/geometry/vec.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// The interiors a ray is inside, innermost last, each by its identity (the
// shared Interior of a CSG's members, or the object for one without its own
// interior) and its ior. At most kCapacity deep; deeper ones are not kept
// (a ray inside nine nested objects at once refracts at the ninth as if it
// came from the eighth).
class InteriorList {
public:
    static constexpr std::size_t kCapacity = 8;
    struct Entry {
        const void* key = nullptr;
        double ior = 1.0;
        double dispersion = 1.0;
        int dispersionSamples = 7;
    };

    bool empty() const { return count_ == 0; }
    std::size_t size() const { return count_; }
    const Entry& back() const { return entries_[count_ - 1]; }
    bool contains(const void* key) const {
        for (std::size_t i = 0; i < count_; ++i)
            if (entries_[i].key == key) return true;
        return false;
    }
    void push(const void* key, const Interior& interior) {
        if (count_ < kCapacity) entries_[count_++] = {key, interior.ior, interior.dispersion, interior.dispersionSamples};
    }
    // Removes `key` (its innermost entry); whether it was there.
    bool remove(const void* key) {
        for (std::size_t i = count_; i-- > 0;)
            if (entries_[i].key == key) {
                for (std::size_t j = i + 1; j < count_; ++j) entries_[j - 1] = entries_[j];
                --count_;
                return true;
            }
        return false;
    }

private:
    std::array<Entry, kCapacity> entries_{};
    std::size_t count_ = 0;
};

// An object's interior (POV-Ray's default one where it has none) and the
// identity the list keeps for it.
inline const Interior& interiorOf(const Object& o) {
    static const Interior kDefault{};
    return o.interior ? *o.interior : kDefault;
}
inline const void* interiorKey(const Object& o) {
    return o.interior ? static_cast<const void*>(o.interior.get()) : static_cast<const void*>(&o);
}

// A ray crossing the surface of `o`: the list of the ray beyond the surface
// and the ratio of the iors (POV-Ray's `ior`, the one before over the one
// after), as ComputeRefraction keeps them: entering from outside everything,
// leaving the innermost interior (into the next one out, or the air),
// leaving one of two overlapping ones (ratio 1), or entering a new one
// inside another.
// The dispersions' ratio and the number of bands a dispersive crossing
// splits a ray into go the same way (the larger of the two interiors'
// numbers of bands when leaving one for another).
struct Crossing {
    InteriorList beyond;
    double iorRatio = 1.0;
    double dispersionRatio = 1.0;
    int bands = 7;
};
inline Crossing cross(const InteriorList& inside, const Object& o) {
    const Interior& interior = interiorOf(o);
    const void* key = interiorKey(o);
    Crossing c{inside, 1.0, 1.0, interior.dispersionSamples};
    if (inside.empty()) {
        c.beyond.push(key, interior);
        c.iorRatio = 1.0 / interior.ior;
        c.dispersionRatio = 1.0 / interior.dispersion;
    } else if (inside.back().key == key) {
        c.beyond.remove(key);
        if (c.beyond.empty()) {
            c.iorRatio = interior.ior;
            c.dispersionRatio = interior.dispersion;
        } else {
            c.iorRatio = interior.ior / c.beyond.back().ior;
            c.dispersionRatio = interior.dispersion / c.beyond.back().dispersion;
            c.bands = std::max(c.bands, c.beyond.back().dispersionSamples);
        }
    } else if (c.beyond.remove(key)) {
        c.iorRatio = 1.0;
    } else {
        c.iorRatio = inside.back().ior / interior.ior;
        c.dispersionRatio = inside.back().dispersion / interior.dispersion;
        c.beyond.push(key, interior);
    }
    return c;
}

// The ior ratio a Fresnel reflection off the surface of `o` uses (POV-Ray's
// ComputeRelativeIOR): the object's over the air's or the ray's innermost
// interior's when the ray comes from outside it; from inside, the air's (or
// the innermost one's) over the object's.
inline double reflectionIor(const InteriorList& inside, const Object& o) {
    const double ior = interiorOf(o).ior;
    if (inside.empty()) return ior;
    if (inside.contains(interiorKey(o))) return (inside.size() == 1 ? 1.0 : inside.back().ior) / ior;
    return ior / inside.back().ior;
}

// The refracted direction of unit direction `d` at a surface of unit normal
// `normal` (either side) for the ior ratio `ior` (POV-Ray's
// TraceRefractionRay, Heckbert's method); none on total internal reflection.
inline std::optional<Vec3> refractedDirection(const Vec3& d, const Vec3& normal, double ior) {
    double n = glm::dot(d, normal);
    Vec3 local = normal;
    if (n <= 0.0) {
        n = -n;
    } else {
        local = -normal;
    }
    const double t = 1.0 + ior * ior * (n * n - 1.0);
    if (t < 0.0) return std::nullopt;
    return ior * d + (ior * n - std::sqrt(t)) * local;
}

// What the inside of `interior` lets through of a ray that travelled
// `distance` within it (POV-Ray's attenuation by fade_distance, fade_power
// and fade_color): 1 without a fade distance. `eyeRay`: as
// ComputeLightedTexture computes it (for eye, reflected and refracted rays:
// a fade power of 0 still fades); otherwise as ComputeShadowTexture (shadow
// rays: only with a positive fade power).
inline Vec3 fadeThrough(const Interior& interior, double distance, bool eyeRay) {
    if (!(std::fabs(interior.fadeDistance) > 1e-10)) return Vec3(1.0);
    if (!eyeRay && !(interior.fadePower > 0.0)) return Vec3(1.0);
    const double depth = distance / interior.fadeDistance;
    if (interior.fadePower >= 1000.0) {
        const Vec3 k = -(Vec3(1.0) - interior.fadeColor) * depth;
        return Vec3(std::exp(k.x), std::exp(k.y), std::exp(k.z));
    }
    const double att = 1.0 + std::pow(depth, interior.fadePower);
    return interior.fadeColor + (Vec3(1.0) - interior.fadeColor) / att;
}

}  // namespace asos
