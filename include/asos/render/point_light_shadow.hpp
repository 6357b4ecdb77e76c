#pragma once
// Antialiased point light sources (paper: "Antialiased Point Light Sources",
// Figure 4). When an eye (sub)pyray hits a surface, the light reaching it is
// not decided by one shadow ray from the hit point: a shadow pyray from the
// light encloses the pyray's footprint on the surface, is tested against the
// objects in its way like an eye pyray, and is subdivided where it is
// marginal, down to the light's MAX, giving the fraction of the footprint that
// the light reaches. The shadow pyray starts at the level of the eye pyray:
// its quarters are the footprints of the eye pyray's quarters, so a shadow
// pyray at level K covers 1/2^(2K) of the pixel like an eye K-pyray, and the
// stopping rule (render/subdivision_criterion.hpp) measures the change of the
// pixel in the same units with the light's EPS.
//
// docs/algorithm.md, "Point lights", has the rules for footprints, occluders
// and the plain shadow ray used when nothing is marginal.
#include <array>
#include <cstdint>
#include <vector>

#include "asos/geometry/beam_eye.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/scene/asos_settings.hpp"
#include "asos/render/camera.hpp"
#include "asos/render/cone_candidates.hpp"
#include "asos/render/sampling.hpp"
#include "asos/render/stats.hpp"
#include "asos/render/subdivision_criterion.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

// The part of a surface that an eye pyray sees around the point it hit,
// approximated by the tangent plane there: the image point (u, v) of the
// pyray's square maps to where its camera ray meets that plane. When the
// plane is seen too obliquely for that (a corner ray meets it nearer than half
// or farther than twice the hit's depth, or not at all), the footprint is the
// pyray's cross-section at the hit's depth instead, so that a grazing pixel
// never stretches its footprint toward the horizon.
class Footprint {
public:
    // `depth`: the distance along the shaded ray to `point` (its t).
    Footprint(const CameraModel& camera, const ImageSquare& square, const Vec3& point,
              const Vec3& normal, double depth);

    // The footprint point of image point (u, v) (image coordinates).
    Vec3 at(double u, double v) const;
    const ImageSquare& square() const { return square_; }
    // The footprint points of the square's corners (u0,v0), (u1,v0),
    // (u1,v1), (u0,v1), and of its centre.
    const std::array<Vec3, 4>& corners() const { return corners_; }
    const Vec3& centre() const { return centre_; }
    // False when the cross-section replaced the tangent plane.
    bool onTangentPlane() const { return tangentPlane_; }
    const Vec3& point() const { return point_; }

private:
    double planeDistance(const Ray& ray) const;

    const CameraModel* camera_;
    ImageSquare square_;
    Vec3 point_;
    Vec3 normal_;
    double depth_;
    bool tangentPlane_ = true;
    std::array<Vec3, 4> corners_;
    Vec3 centre_;
};

// Per-thread buffers, so that shadow pyrays allocate nothing per pixel.
struct ShadowScratch {
    struct Item {
        std::uint32_t object;
        ConeClass cls;
    };
    struct Node {
        ImageSquare square;
        int level;
        std::uint32_t ix, iy;  // position among the 2^level x 2^level squares of the pixel
        std::uint32_t first, count;  // its occluders in items[]
        bool blocked;                // its central ray is blocked
    };
    std::vector<Item> items[2];
    std::vector<std::uint8_t> hits[2];  // per item: the node's central ray hits it
    std::vector<Node> nodes[2];
    SubdivisionTally tally;
    std::vector<ConeCandidateCache> candidates;  // per light: shadow cones share its position
};

// One question: how much of a footprint does a point light reach?
struct PointShadowQuery {
    Vec3 lightPosition{0.0};
    std::size_t lightIndex = 0;  // which of the scratch's candidate caches serves it
    AsosSettings settings;  // the light's eps, max and jitter
    // The object the footprint lies on. Convex closed shapes (and flat ones)
    // cannot shadow themselves where they face the light, so they are left
    // out of the occluders; `shadedCanSelfShadow` (the inner side of a shape
    // that can shadow itself, Primitive::canShadowItself) keeps it in, asked
    // only about the part of the cone before the footprint.
    std::uint32_t shadedObject = 0;
    bool shadedCanSelfShadow = false;
    int level = 0;             // the eye pyray's level: the shadow pyray starts there
    std::uint32_t ix = 0, iy = 0;  // the eye pyray's position within the pixel at that level
    // Jittered MAX-rays draw from rng's ShadowJitter stream at indices made
    // of jitterKey (the light) and the sub-position.
    PixelRandom rng{0, 0, 0};
    std::uint64_t jitterKey = 0;
};

// The fraction of the footprint the light reaches, in [0, 1].
double pointLightLitFraction(const Scene& scene, const Footprint& footprint,
                             const PointShadowQuery& query, ShadowScratch& scratch,
                             RenderCounters& counters);

}  // namespace asos
