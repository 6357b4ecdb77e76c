#pragma once
// The forms a light takes, one type each in its own file, in the manner of
// pbrt-v4's lights.h: a point (lights/point_light.hpp), a rectangle
// (rectangle_light.hpp), a segment (segment_light.hpp) and a sphere
// (sphere_light.hpp). Every area form answers the same questions: its beam
// from a point and how a piece of it splits (for the ASOS shadow beams,
// render/area_light_shadow.hpp), its grid's points seen from a point (for
// the classic grid, render/grid_light.hpp), its emitted radiance (its size
// and its weighting along a direction). The concepts below name those
// answers and a static_assert checks every alternative of LightForm against
// them, so that a form lacking one is a compile error, not a default.
//
// The renderer turns a light into its concrete form once per shaded point
// (withAreaForm), never per ray or per sample: its tracers are templates
// over the form.
#include <concepts>
#include <optional>
#include <utility>
#include <variant>

#include "asos/geometry/bounds.hpp"
#include "asos/lights/light_lattice.hpp"
#include "asos/lights/light_piece.hpp"
#include "asos/lights/point_light.hpp"
#include "asos/lights/rectangle_light.hpp"
#include "asos/lights/segment_light.hpp"
#include "asos/lights/sphere_light.hpp"

namespace asos {

// A function of a piece, for the concept's forEachDescendant.
struct LightPieceSink {
    void operator()(const LightPiece&) const {}
};

// The beam of an area light from one point (its apex): its pieces, how
// they split, their rays, shares and bounds.
template <class B>
concept AreaLightBeam = requires(const B& beam, const LightPiece& piece, LightPiece* out, const Vec2& xi,
                                 const Vec3& direction, BeamRay* rays, int level) {
    // How many pieces one split makes (a fixed number per form).
    { B::kChildren } -> std::convertible_to<int>;
    // Whether the paper's "Proximity to One Edge" halving holds for its splits.
    { B::kSingleEdgeHalving } -> std::convertible_to<bool>;
    { beam.root() } -> std::same_as<LightPiece>;
    { beam.split(piece, out, true) } -> std::same_as<int>;
    beam.forEachDescendant(piece, level, LightPieceSink{});
    { beam.lattice(piece, level) } -> std::same_as<std::optional<LightLattice>>;
    { beam.sample(piece, xi) } -> std::same_as<BeamRay>;
    { beam.share(level) } -> std::same_as<double>;
    { beam.nearestLightDistance(piece) } -> std::same_as<double>;
    { beam.probeRays(piece, rays) } -> std::same_as<int>;
    { beam.ruleWeights(piece) } -> std::same_as<std::pair<double, double>>;
    { beam.horizonSide(piece, direction) } -> std::same_as<HorizonSide>;
    { beam.emission(direction) } -> std::same_as<double>;
};

// The grid of an area light seen from one point: the ray toward the light's
// point (s, t) in [0, 1]^2, and the emitter's weighting along a direction.
template <class G>
concept AreaLightGridPoints = requires(const G& grid, double s, const Vec3& direction) {
    { grid.toward(s, s) } -> std::same_as<BeamRay>;
    { grid.emission(direction) } -> std::same_as<double>;
};

// What every light form answers: its name (as the docs and statistics call
// it) and its size (area, length, disc area; 0 for a point).
template <class L>
concept LightFormBasics = requires(const L& light) {
    { L::kName } -> std::convertible_to<const char*>;
    { light.size() } -> std::same_as<double>;
};

// What an area light form answers besides.
template <class L>
concept AreaLightForm = LightFormBasics<L> && AreaLightBeam<typename L::Beam> &&
                        AreaLightGridPoints<typename L::GridPoints> &&
                        requires(const L& light, const Vec3& point, double tMin) {
    { light.beamFrom(point, tMin) } -> std::same_as<std::optional<typename L::Beam>>;
    { light.gridFrom(point) } -> std::same_as<std::optional<typename L::GridPoints>>;
    { light.beamHolds(point, point) } -> std::same_as<bool>;
    { light.halfWidth() } -> std::same_as<double>;
    { light.bounds() } -> std::same_as<Bounds3>;
};

using LightForm = std::variant<PointLight, RectangleLight, SegmentLight, SphereLight>;

namespace detail {
template <class... L>
constexpr bool everyFormAnswers(const std::variant<L...>*) {
    return ((LightFormBasics<L> && (std::same_as<L, PointLight> || AreaLightForm<L>)) && ...);
}
}  // namespace detail
// The point light is the one form without an area; every other form
// answers all an area light answers.
static_assert(detail::everyFormAnswers(static_cast<const LightForm*>(nullptr)),
              "a light form lacks an answer of AreaLightForm (lights/light_form.hpp)");

// f(form) with the light's concrete area form; nothing for a point light.
template <class F>
void withAreaForm(const LightForm& form, F&& f) {
    std::visit(
        [&]<class L>(const L& light) {
            if constexpr (!std::same_as<L, PointLight>) f(light);
        },
        form);
}

// "point", "rectangular", "linear" or "spherical".
inline const char* lightFormName(const LightForm& form) {
    return std::visit([](const auto& light) -> const char* { return std::decay_t<decltype(light)>::kName; }, form);
}

}  // namespace asos
