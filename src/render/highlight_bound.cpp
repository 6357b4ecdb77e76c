#include "asos/render/highlight_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "asos/lights/light_model.hpp"
#include "asos/render/map_pattern.hpp"
#include "asos/render/shading.hpp"

namespace asos {

namespace {

// The angle between two unit vectors, accurate near 0 and pi.
double unitAngle(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double largestComponent(const Vec3& c) {
    return std::max(std::abs(c.x), std::max(std::abs(c.y), std::abs(c.z)));
}

}  // namespace

SurfaceSpread SurfaceSpread::over(const EyePyray& pyray, const SurfaceHit& centre,
                                  const Primitive& object) {
    SurfaceSpread s;
    s.position = centre.position;
    s.viewDir = glm::normalize(pyray.centralRay().dir);
    s.normal = facingNormal(centre.normal, s.viewDir);
    s.view = pyray.cone().halfAngle;
    for (const Ray& corner : pyray.cornerRays()) {
        const Ray ray{corner.origin, glm::normalize(corner.dir)};
        const std::optional<SurfaceHit> hit = object.intersect(ray, kPovMinIsectDepth, kInfinity);
        if (!hit || hit->part != centre.part) {
            s.turn = kPi;
            s.radius = kInfinity;
            return s;
        }
        s.turn = std::max(s.turn, unitAngle(s.normal, facingNormal(hit->normal, ray.dir)));
        s.radius = std::max(s.radius, glm::length(hit->position - s.position));
    }
    s.turn = std::min(kPi, kMargin * s.turn);
    s.radius *= kMargin;
    return s;
}

namespace {

// One highlight term, weight cos^exponent(theta) with theta in
// [angle - spread, angle + spread] (0 where theta passes a right angle).
struct HighlightTerm {
    double weight = 0.0, exponent = 0.0, angle = 0.0, spread = 0.0;
    // POV-Ray drops phong's cosines of at most 0.0008 for sizes from 60 on.
    bool cutSmallCosines = false;

    double at(double theta) const {
        theta = std::abs(theta);
        if (!(theta < 0.5 * kPi)) return 0.0;
        const double c = std::cos(theta);
        if (cutSmallCosines && !(c > 0.0008)) return 0.0;
        return weight * std::pow(c, exponent);
    }
    // The value is monotone in |theta|.
    double hi() const { return at(std::max(0.0, angle - spread)); }
    double lo() const { return at(angle + spread); }
    // How far the term strays from its tangent at the centre over the
    // spread: at both ends and at the peak (theta = 0) where it lies inside.
    double curvature() const {
        const double c = std::cos(angle), s = std::sin(angle);
        const double slope =
            angle < 0.5 * kPi && c > 0.0 ? -weight * exponent * std::pow(c, exponent - 1.0) * s : 0.0;
        const double centre = at(angle);
        auto stray = [&](double t) { return std::abs(at(angle + t) - centre - slope * t); };
        double d = std::max(stray(-spread), stray(spread));
        if (angle < spread) d = std::max(d, stray(-angle));
        return d;
    }
};

// Light and spread as the terms see them.
struct LightView {
    double beta = kPi;       // how far the light direction turns over the footprint
    double fadeLo = 0.0, fadeHi = 0.0;
    bool mayBeCut = true;    // N.L may fall below kPovEpsilon somewhere
    bool dark = false;       // N.L below kPovEpsilon everywhere
    bool beamVaries = false; // a spotlight's or cylinder's factor changes over the footprint
    Vec3 direction{0.0};     // unit, at the centre
};

// The range of a spotlight's or cylinder light's factor over the
// footprint: the direction from the light turns by at most `beta` (a
// spotlight's factor falls with the angle from its axis, a cylinder's with
// the distance from it, when tightness is not negative).
std::pair<double, double> beamRange(const Light& light, const SurfaceSpread& s, double beta) {
    if (light.type == LightType::Point) return {1.0, 1.0};
    const LightBeam beam = LightBeam::of(light);
    if (light.tightness < 0.0) return {0.0, 1e300};
    if (light.type == LightType::Spot) {
        if (beam.parallel) return {0.0, 1.0};
        const Vec3 fromLight = s.position - light.position;
        const double length = glm::length(fromLight);
        if (!(length > 0.0) || !(glm::length(beam.axis) > 0.0)) return {0.0, 1.0};
        const double theta = unitAngle(glm::normalize(beam.axis), fromLight / length);
        const auto at = [&](double angle) {
            return spotlightFactor(std::cos(std::clamp(angle, 0.0, kPi)), beam.radius, beam.falloff, beam.tightness);
        };
        return {at(theta + beta), at(theta - beta)};
    }
    const Vec3 v = s.position - light.position;
    const double k = glm::dot(v, beam.axis);
    const double d = glm::length(v - k * beam.axis);
    const double lo = k - s.radius > 0.0 ? cylinderFactor(d + s.radius, beam.radius, beam.falloff, beam.tightness) : 0.0;
    return {lo, cylinderFactor(std::max(0.0, d - s.radius), beam.radius, beam.falloff, beam.tightness)};
}

LightView viewOf(const Light& light, const SurfaceSpread& s) {
    LightView v;
    // A parallel light stands where its beam enters for the centre.
    const std::optional<LightBeam::Source> source = lightSourceFor(light, s.position);
    const Vec3 toLight = (source ? source->position : s.position + s.normal) - s.position;
    const double distance = glm::length(toLight);
    const double extent =
        light.area ? 0.5 * (glm::length(light.area->axis1) + glm::length(light.area->axis2)) : 0.0;
    const double reach = s.radius + extent;
    const bool engulfed = !(reach < distance);
    v.beta = engulfed ? kPi : std::asin(reach / distance);
    v.direction = distance > 0.0 ? toLight / distance : s.normal;
    // Light fade falls with distance.
    v.fadeHi = lightFade(light.fadeDistance, light.fadePower, std::max(distance - reach, 1e-6 * distance + kPovEpsilon));
    v.fadeLo = engulfed ? 0.0 : lightFade(light.fadeDistance, light.fadePower, distance + reach);
    // A spotlight's cone or a cylinder's beam narrows it.
    const auto [beamLo, beamHi] = beamRange(light, s, v.beta);
    v.fadeLo *= beamLo;
    v.fadeHi *= beamHi;
    v.beamVaries = beamLo != beamHi;
    if (!source || source->unshadowed) v.fadeLo = 0.0;
    // directLight gives nothing where N.L < kPovEpsilon.
    const double incidence = unitAngle(s.normal, v.direction);
    const double gate = std::acos(kPovEpsilon);
    v.dark = incidence - s.turn - v.beta > gate;
    v.mayBeCut = incidence + s.turn + v.beta >= gate ||
                 !(largestComponent(light.color) * v.fadeLo > kPovEpsilon);
    return v;
}

// The highlight at a footprint point is phong cos^n(R, L) + specular
// cos^e(H, N), with R the view direction mirrored about the normal and H the
// halfway vector of L and the reversed view direction. Over the spread the
// view direction turns by at most `view`, the normal by `turn` and, the
// point moving by at most `radius` (and over an area light's extent),
// the light direction by beta; a mirror about a normal turned by an angle
// is turned by twice it, so R turns by at most view + 2 turn + beta. The
// halfway vector (a + b) / |a + b| of unit a, b moves by |da + db| / |a + b|
// at most, and |a + b| = 2 cos(phi / 2) for their angle phi, which stays
// below phi0 + view + beta. Each cosine power is monotone in its angle, so
// the angle's range gives the term's.
std::array<HighlightTerm, 2> termsOf(const Finish& finish, const SurfaceSpread& s, const LightView& v) {
    std::array<HighlightTerm, 2> terms{};
    if (finish.phong > 0.0) {
        const Vec3 mirror = s.viewDir - 2.0 * glm::dot(s.viewDir, s.normal) * s.normal;
        terms[0] = {finish.phong, finish.phongSize, unitAngle(glm::normalize(mirror), v.direction),
                    s.view + 2.0 * s.turn + v.beta, finish.phongSize >= 60.0};
    }
    if (finish.specular > 0.0) {
        const Vec3 sum = v.direction - s.viewDir;
        const double phiMax = unitAngle(v.direction, -s.viewDir) + s.view + v.beta;
        const bool defined = phiMax < kPi && glm::length(sum) > 0.0;
        const double halfTurn = defined ? (s.view + v.beta) / (2.0 * std::cos(0.5 * phiMax)) : kPi;
        terms[1] = {finish.specular, finish.roughness != 0.0 ? 1.0 / finish.roughness : 0.0,
                    defined ? unitAngle(glm::normalize(sum), s.normal) : 0.0, halfTurn + s.turn,
                    false};
    }
    return terms;
}

}  // namespace

ValueRange highlightRange(const Finish& finish, const Light& light, const SurfaceSpread& s) {
    if (light.shadowless || !hasHighlights(finish)) return {};
    const LightView v = viewOf(light, s);
    if (v.dark) return {};
    double lo = 0.0, hi = 0.0;
    for (const HighlightTerm& t : termsOf(finish, s, v)) {
        lo += t.lo();
        hi += t.hi();
    }
    return {v.mayBeCut ? 0.0 : lo * v.fadeLo, hi * v.fadeHi};
}

double highlightError(const Finish& finish, const Light& light, const SurfaceSpread& s) {
    if (light.shadowless || !hasHighlights(finish)) return 0.0;
    const LightView v = viewOf(light, s);
    if (v.dark) return 0.0;
    const ValueRange range = highlightRange(finish, light, s);
    // Where N.L may be cut, the highlight may end abruptly: the whole range.
    if (v.mayBeCut || v.beamVaries) return range.width();
    double stray = 0.0;
    for (const HighlightTerm& t : termsOf(finish, s, v)) stray += t.curvature();
    // The fade changes slowly, as the diffuse term does: it scales.
    return std::min(range.width(), stray * v.fadeHi);
}

double highlightVariation(const Finish& finish, std::span<const Light> lights, const SurfaceSpread& spread) {
    double variation = 0.0;
    for (const Light& light : lights) {
        double error = 0.0;
        if (!light.area) {
            error = highlightError(finish, light, spread);
        } else {
            // Each point of an area light shades as a point light with its
            // share of the colour (docs/lights.md), so the light's error is
            // the mean of its points' errors: estimated on a 3 x 3 grid of
            // them.
            Light point = light;
            point.area.reset();
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    point.position = light.position + 0.5 * (double(i) * light.area->axis1 + double(j) * light.area->axis2);
                    error += highlightError(finish, point, spread) / 9.0;
                }
        }
        variation += error * largestComponent(light.color);
    }
    return variation;
}

bool hasHighlights(const Texture& t) {
    return hasHighlights(t.finish) ||
           std::any_of(t.above.begin(), t.above.end(), [](const TextureLayer& l) { return hasHighlights(l.finish); });
}

namespace {
// The most any colour of the pigment lets through, in any channel.
double mostLetThrough(const Pigment& pigment) {
    auto most = [](const Color& c) { return largestComponent(layerTransmittance(c)); };
    if (pigment.pigmentMap) {
        double m = 0.0;
        for (const PigmentMapEntry& e : *pigment.pigmentMap) m = std::max(m, mostLetThrough(*e.pigment));
        return m;
    }
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return most(pigment.color1);
        case Pigment::Kind::Checker: case Pigment::Kind::Brick:
            return std::max(most(pigment.color1), most(pigment.color2));
        default: {
            double m = 0.0;
            for (const ColourMapEntry& e : colourMapOf(pigment)) m = std::max(m, most(e.color));
            return m;
        }
    }
}
}  // namespace

double highlightVariation(const Texture& texture, std::span<const Light> lights, const SurfaceSpread& spread) {
    double total = 0.0;
    double through = 1.0;  // the most the layers above let through
    for (std::size_t i = texture.above.size() + 1; i-- > 0 && through > 0.0;) {
        const TextureLayer& layer = i == 0 ? static_cast<const TextureLayer&>(texture) : texture.above[i - 1];
        if (hasHighlights(layer.finish)) total += through * highlightVariation(layer.finish, lights, spread);
        through *= mostLetThrough(layer.pigment);
    }
    return total;
}

}  // namespace asos
