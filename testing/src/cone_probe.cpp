#include "asos/testing/cone_probe.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "asos/geometry/frame.hpp"

namespace asos {

namespace {

const char* coverageName(Coverage c) {
    switch (c) {
        case Coverage::Miss: return "Miss";
        case Coverage::Full: return "Full";
        case Coverage::Marginal: return "Marginal";
    }
    return "?";
}

}  // namespace

std::vector<Vec3> probeDirections(const Cone& cone, const ProbeDensity& density) {
    const Vec3 axis = glm::normalize(cone.axis);
    const Mat3 basis = frameAroundAxis(axis);
    const double theta = std::min(cone.halfAngle, kPi);
    std::vector<Vec3> out{axis};
    if (theta > 0.0) {
        constexpr double kGolden = 2.39996322972865332;
        for (int k = 1; k <= density.rings; ++k) {
            const int n = density.raysPerRing * k + (k == density.rings ? density.rimRays : 0);
            const double phi = theta * k / density.rings;
            for (int j = 0; j < n; ++j) {
                const double psi = kGolden * k + 2.0 * kPi * j / n;
                out.push_back(glm::normalize(std::cos(phi) * axis + std::sin(phi) * (std::cos(psi) * basis[0] +
                                                                                    std::sin(psi) * basis[1])));
            }
        }
    }
    return out;
}

ProbeResult probeCone(const Primitive& primitive, const Cone& cone, const ConeClass& answer,
                      const ProbeDensity& density, bool creases) {
    ProbeResult out;
    const double tMin = std::max(cone.tMin, 0.0);
    int firstPart = -1;  // the part the first hit sees
    for (const Vec3& d : probeDirections(cone, density)) {
        const std::optional<SurfaceHit> hit = primitive.intersect({cone.apex, d}, tMin, cone.tMax);
        ++out.rays;
        if (hit) ++out.hits;
        const char* wrong = nullptr;
        if (answer.coverage == Coverage::Miss && hit) wrong = "a ray hits a Miss cone";
        else if (answer.coverage == Coverage::Full && !hit) wrong = "a ray misses a Full cone";
        else if (hit) {
            // The ray test itself is only accurate to ~1e-8 of the size near
            // tangency; a wrong bound is off by far more.
            const double tol = 1e-7 * hit->t + 1e-12;
            if (hit->t < answer.tNear - tol || hit->t > answer.tFar + tol)
                wrong = "a hit lies outside [tNear, tFar]";
            else if (creases && answer.coverage == Coverage::Full && answer.creaseParts == 0 && firstPart >= 0 &&
                     hit->part != firstPart)
                wrong = "a crease-free Full cone's rays see two parts";
            else if (creases && answer.coverage == Coverage::Full && answer.creaseParts != 0 &&
                     !(answer.creaseParts & (1u << hit->part)))
                wrong = "a ray of a creased Full cone sees a part it does not name";
            if (firstPart < 0) firstPart = hit->part;
        }
        if (wrong && out.violations++ == 0) {
            std::ostringstream s;
            s.precision(17);
            s << wrong << ": class " << coverageName(answer.coverage) << " [" << answer.tNear
              << ", " << answer.tFar << "] creaseParts " << int(answer.creaseParts) << ", ray dir ("
              << d.x << ", " << d.y << ", " << d.z << ")";
            if (hit) s << " hit t " << hit->t << " part " << int(hit->part);
            out.firstViolation = s.str();
        }
    }
    return out;
}

}  // namespace asos
