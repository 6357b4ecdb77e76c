#pragma once
// The forms a light takes, one type each in its own file, in the manner of
// pbrt-v4's lights.h: a point (lights/point_light.hpp), a rectangle
// (rectangle_light.hpp), a segment (segment_light.hpp), POV-Ray's oriented
// disc (oriented_disc_light.hpp) and the paper's sphere (sphere_light.hpp). Every area form answers the same questions: its beam
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

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/lights/light_lattice.hpp"
#include "asos/lights/light_piece.hpp"
#include "asos/lights/oriented_disc_light.hpp"
#include "asos/lights/point_light.hpp"
#include "asos/lights/rectangle_light.hpp"
#include "asos/lights/segment_light.hpp"
#include "asos/lights/sphere_light.hpp"

namespace asos {

// A function of a piece, for the concept's forEachDescendant.
struct LightPieceSink {
    void operator()(const LightPiece&) const {}
};

// The beam of an area light from one point (its apex), as the ASOS shadow
// tracer asks it (render/area_light_shadow.cpp). Every answer about a piece
// is about a piece the beam made.
template <class B>
concept AreaLightBeam = requires(const B& beam, const LightPiece& piece, LightPiece* out, const Vec2& xi,
                                 const Vec3& direction, BeamRay* rays, int level, double gap) {
    // How many pieces one split makes.
    { B::kChildren } -> std::convertible_to<int>;
    // Whether the paper's "Proximity to One Edge" halving holds for a split.
    { B::kSingleEdgeHalving } -> std::convertible_to<bool>;
    // The whole light: the level-0 piece, with its cone.
    { beam.root() } -> std::same_as<LightPiece>;
    // The pieces of the next level, written to out[]; returns how many.
    // Without cones (false) their cones are left empty: pieces only
    // sampled by rays.
    { beam.split(piece, out, true) } -> std::same_as<int>;
    // f(const LightPiece&) for each piece `level` levels below `piece`,
    // without cones, in the order repeated split()s give them, with the same
    // regions, paths and central rays, bit for bit (point samples at MAX:
    // docs/lights.md, "Speed").
    beam.forEachDescendant(piece, level, LightPieceSink{});
    // The central points of those pieces as a lattice, where the form has
    // one (down to LightLattice::kMaxDepth levels).
    { beam.lattice(piece, level) } -> std::same_as<std::optional<LightLattice>>;
    // A ray inside the piece from two numbers in [0, 1), uniform over it.
    { beam.sample(piece, xi) } -> std::same_as<BeamRay>;
    // The region its rays run through, each stopping this far before the
    // light (BeamHull; none where it is degenerate).
    { beam.hull(gap) } -> std::same_as<std::optional<BeamHull>>;
    // A piece's share of the light at a level, exactly. Inline: it is asked
    // for every sample.
    { beam.share(level) } -> std::same_as<double>;
    // No ray of the piece reaches the light nearer than this.
    { beam.nearestLightDistance(piece) } -> std::same_as<double>;
    // Pairs of rays across the piece through its central point, one pair
    // per coordinate, written to rays[] (at most four); returns how many.
    // Their means less the central value are the piece's second differences.
    { beam.probeRays(piece, rays) } -> std::same_as<int>;
    // The central ray's and each probe ray's weight in a rule exact for
    // quadratics over the piece; they sum to 1.
    { beam.ruleWeights(piece) } -> std::same_as<std::pair<double, double>>;
    // Where the piece lies against the plane through the apex with this
    // normal: Unknown where only rays can tell.
    { beam.horizonSide(piece, direction) } -> std::same_as<HorizonSide>;
    // The paper's emitter's weighting along a direction (POV-Ray's points
    // are isotropic). Inline: it is asked for every sample.
    { beam.emission(direction) } -> std::same_as<double>;
};

// The grid of an area light seen from one point (render/grid_light.hpp).
template <class G>
concept AreaLightGridPoints = requires(const G& grid, double s, const Vec3& direction) {
    // The ray toward the light's point (s, t) and the distance to it: for
    // s, t in [0, 1] the light's square (rectangle, segment, POV-Ray's
    // lattice's square) or its map's (the sphere's disc); beyond it, the
    // rectangle's or segment's plane or line continued (POV-Ray's jitter).
    { grid.toward(s, s) } -> std::same_as<BeamRay>;
    // The paper's emitter's weighting along a direction.
    { grid.emission(direction) } -> std::same_as<double>;
};

// What every light form answers.
template <class L>
concept LightFormBasics = requires(const L& light) {
    // Its name, as the docs and the scene call it.
    { L::kName } -> std::convertible_to<const char*>;
    // The size its power is spread over (area, length, disc area; 0 for a
    // point): its intensity is colour / size.
    { light.size() } -> std::same_as<double>;
};

// What an area light form answers besides.
template <class L>
concept AreaLightForm = LightFormBasics<L> && AreaLightBeam<typename L::Beam> &&
                        AreaLightGridPoints<typename L::GridPoints> &&
                        requires(const L& light, const Vec3& point, double tMin) {
    // Its beam from a point, rays starting at distance tMin; none where the
    // point sees no beam (in the light's plane, on its line, inside it).
    { light.beamFrom(point, tMin) } -> std::same_as<std::optional<typename L::Beam>>;
    // Its grid's points as seen from a point; none where the point sees none.
    { light.gridFrom(point) } -> std::same_as<std::optional<typename L::GridPoints>>;
    // Whether the beam from an apex toward the light holds a point (the
    // apex behind the surface, render/area_light_shadow.hpp).
    { light.beamHolds(point, point) } -> std::same_as<bool>;
    // Half its width: the scale its beam's cross-section grows toward.
    { light.halfWidth() } -> std::same_as<double>;
    // A box that holds it.
    { light.bounds() } -> std::same_as<Bounds3>;
};

using LightForm = std::variant<PointLight, RectangleLight, SegmentLight, OrientedDiscLight, SphereLight>;

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

// "point", "rectangular", "linear", "oriented disc" or "spherical".
inline const char* lightFormName(const LightForm& form) {
    return std::visit([](const auto& light) -> const char* { return std::decay_t<decltype(light)>::kName; }, form);
}

}  // namespace asos
