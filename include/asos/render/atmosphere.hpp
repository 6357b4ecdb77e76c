#pragma once
// What a ray meets besides objects, with POV-Ray 3.7's arithmetic
// (core/render/trace.cpp, ComputeSky and ComputeFog): the sky_sphere over
// the background for a ray that hits nothing, and the fogs along every eye
// and reflected ray, a missing ray's length being POV-Ray's BOUND_HUGE.
// docs/manual/global-settings.md, "sky_sphere" and "fog".
#include <vector>

#include "asos/geometry/ray.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// POV-Ray's BOUND_HUGE: the depth of a ray that hits nothing, through which
// it is fogged.
inline constexpr double kPovBoundHuge = 2.0e10;

class Atmosphere {
public:
    explicit Atmosphere(const SceneDescription& scene);

    // The colour of a ray (unit direction) that hits nothing: the sky and
    // background, then the fogs over kPovBoundHuge.
    Vec3 miss(const Ray& ray) const { return fogged(sky(ray.dir), ray, kPovBoundHuge); }
    // The sky_sphere's pigments over the background along a unit direction
    // (the background alone where there is no sky_sphere).
    Vec3 sky(const Vec3& unitDirection) const;
    // `colour` seen through the fogs over `depth` along `ray`.
    Vec3 fogged(const Vec3& colour, const Ray& ray, double depth) const;

    bool hasFog() const { return !fogs_.empty(); }
    // Whether a missing ray's colour may change with its direction (a
    // patterned sky pigment or a ground fog).
    bool skyVaries() const { return skyVaries_; }

private:
    const SceneDescription& scene_;
    std::vector<Fog> fogs_;  // those with a distance (POV-Ray skips the others)
    Vec3 background_;
    bool skyVaries_ = false;
};

// One fog's transmittance over [0, depth] along `ray` (POV-Ray's
// ComputeConstantFogColour and ComputeGroundFogColour, before the minimum
// its colour's transmit sets): `generator` is the scene's noise generator.
double fogTransmittance(const Fog& fog, const Ray& ray, double depth, int generator);

}  // namespace asos
