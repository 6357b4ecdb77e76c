#include "asos/lights/light_model.hpp"

#include <cmath>

#include "asos/scene/pov_tolerances.hpp"

namespace asos {

namespace {

bool active(const Vec3& axis, int count) { return count > 1 && glm::length(axis) > 0.0; }

}  // namespace

double lightFade(double fadeDistance, double fadePower, double distance) {
    if (!(fadePower > 0.0)) return 1.0;
    if (std::fabs(fadeDistance) >= kPovEpsilon) return 2.0 / (1.0 + std::pow(distance / fadeDistance, fadePower));
    return std::pow(distance, -fadePower);
}

LightModel makeLightModel(const Light& light, const AsosSettings& sceneSettings,
                          std::optional<int> samples) {
    LightModel m;
    m.position = light.position;
    m.color = light.color;
    m.shadowless = light.shadowless;
    m.emitter = light.asos.emitter.value_or(LightEmitter::Povray);
    m.areaIllumination = light.areaIllumination;
    m.fadeDistance = light.fadeDistance;
    m.fadePower = light.fadePower;
    if (light.type != LightType::Point) m.beam = LightBeam::of(light);
    m.asos = sceneSettings.refinedBy(light.asos);
    if (!light.area) return m;
    const AreaLight& a = *light.area;
    m.adaptive = a.adaptive;
    m.jitter = a.jitter;
    // A 1 x 1 array is one point light at the centre, as in POV-Ray.
    if (a.size1 <= 1 && a.size2 <= 1) return m;

    const auto counts = [&](int n1, int n2) {
        m.count1 = samples ? *samples : n1;
        m.count2 = samples ? *samples : n2;
    };
    if (a.orient) {
        // POV-Ray's oriented disc: circular, facing the point, of the first
        // axis's length; the paper's sphere of that diameter with its
        // emitter ("Spherical Light Sources"). checkLight refused a count of
        // 1 along one axis.
        const double radius = 0.5 * glm::length(a.axis1);
        if (!(radius > 0.0)) return m;
        if (m.emitter == LightEmitter::Panel) m.form = SphereLight{{light.position, radius}};
        else m.form = OrientedDiscLight{{light.position, radius}};
        counts(a.size1, a.size2);
        return m;
    }
    const bool first = active(a.axis1, a.size1), second = active(a.axis2, a.size2);
    if (first && second) {
        m.form = RectangleLight{light.position - 0.5 * a.axis1 - 0.5 * a.axis2, a.axis1, a.axis2};
        counts(a.size1, a.size2);
    } else if (first || second) {
        const Vec3& axis = first ? a.axis1 : a.axis2;
        m.form = SegmentLight{light.position - 0.5 * axis, light.position + 0.5 * axis, glm::length(axis)};
        m.count1 = samples ? *samples : (first ? a.size1 : a.size2);
        m.count2 = 1;
    }
    return m;
}

bool checkLight(const Light& light, Diagnostics& diagnostics) {
    if (!light.area) return true;
    if (light.parallel || light.type == LightType::Cylinder) {
        // POV-Ray turns each point of a parallel area light's array toward
        // point_at on its own: a fan of parallel beams asos does not render.
        diagnostics.error(light.loc, std::string(light.type == LightType::Cylinder ? "cylinder" : "parallel") +
                                         " area lights are not rendered by asos: drop area_light, or " +
                                         (light.type == LightType::Cylinder ? "use a spotlight" : "drop parallel"));
        return false;
    }
    const AreaLight& a = *light.area;
    bool ok = true;
    auto error = [&](const std::string& message) {
        diagnostics.error(light.loc, message);
        ok = false;
    };
    if (a.size1 < 1 || a.size2 < 1 || a.size1 > kMaxLightSamplesPerSide ||
        a.size2 > kMaxLightSamplesPerSide)
        error("area_light counts must be between 1 and " + std::to_string(kMaxLightSamplesPerSide) +
              ", not " + std::to_string(a.size1) + " and " + std::to_string(a.size2));
    if (a.adaptive && *a.adaptive < 0)
        error("adaptive must not be negative, not " + std::to_string(*a.adaptive));
    // POV-Ray drops circular where a count is 1 (with a warning).
    const bool oneAlong = a.size1 <= 1 || a.size2 <= 1;
    if (a.orient) {
        if (!a.circular)
            diagnostics.warning(light.loc,
                                "orient is used with circular area lights only (as in POV-Ray): this "
                                "area light is circular");
        const double l1 = glm::length(a.axis1), l2 = glm::length(a.axis2);
        if (std::abs(l1 - l2) > kPovEpsilon)  // as POV-Ray's parser calls them equal
            diagnostics.warning(light.loc,
                                "with orient the two axes of an area light should be of equal "
                                "length: the first axis's length is the disc's diameter");
        if (a.size1 != a.size2)
            diagnostics.warning(light.loc,
                                "with orient the two counts of an area light should be equal (as "
                                "POV-Ray warns)");
        if (oneAlong && (a.size1 > 1 || a.size2 > 1))
            error("a circular orient area light needs more than one point along each axis: with a "
                  "count of 1, POV-Ray drops circular and turns a line toward each point, which "
                  "asos does not render");
        else if (oneAlong)
            diagnostics.warning(light.loc,
                                "circular area lights must have more than one sample along each axis "
                                "(as POV-Ray warns): this one is a point light");
    } else if (a.circular && oneAlong) {
        diagnostics.warning(light.loc,
                            "circular area lights must have more than one sample along each axis (as "
                            "POV-Ray warns): this one is not circular");
    } else if (a.circular) {
        error("circular area lights without orient (flat discs) are not rendered by asos: add "
              "orient for a spherical light, or drop circular for a rectangular one");
    } else if (active(a.axis1, a.size1) && active(a.axis2, a.size2) &&
               !(glm::length(glm::cross(a.axis1, a.axis2)) > 0.0)) {
        error("the axes of this area_light are parallel: it has no area (make one axis zero, or "
              "one count 1, for a linear light)");
    }
    return ok;
}

}  // namespace asos
