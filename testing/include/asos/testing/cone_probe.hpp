#pragma once
// Checks a cone classification against a dense set of rays of the cone: its
// axis, rings of rays at fractions of the half-angle, and the rim itself, each
// traced exactly. Used by the property tests (any contradiction fails) and by
// `asos bench intersect` (the spurious-marginal rate: a Marginal cone whose
// rays all hit or all miss).
#include <string>
#include <vector>

#include "asos/geometry/cone.hpp"
#include "asos/shapes/primitive.hpp"

namespace asos {

struct ProbeDensity {
    int rings = 5;        // rings at k/rings of the half-angle, k = 1..rings
    int raysPerRing = 6;  // ring k carries raysPerRing * k rays
    int rimRays = 48;     // extra rays on the rim
};

struct ProbeResult {
    int rays = 0;
    int hits = 0;
    int violations = 0;  // rays contradicting the classification
    std::string firstViolation;  // what the first contradicting ray saw

    bool allHit() const { return hits == rays; }
    bool allMiss() const { return hits == 0; }
};

// The unit directions of the probe's rays: the axis, the rings (the cone's
// half-angle as given, not widened), the rim.
std::vector<Vec3> probeDirections(const Cone& cone, const ProbeDensity& density = {});

// Rays are apex + t d for the directions d, traced over [max(tMin, 0),
// tMax]. Besides hit or miss and the depths, with `creases` (the answer was
// asked for them: PreparedCone::creases) a Full answer's creases: the rays
// of a cone it calls crease-free all see one part of the surface
// (SurfaceHit::part), and those of one with creases only the parts it names.
ProbeResult probeCone(const Primitive& primitive, const Cone& cone, const ConeClass& answer,
                      const ProbeDensity& density = {}, bool creases = false);

}  // namespace asos
