#include "asos/render/area_light_shadow.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "asos/accel/cone_box.hpp"
#include "asos/geometry/beam.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/render/convex_lattice.hpp"
#include "asos/render/grid_light.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos {

namespace {

constexpr double kTolerance = kPovShadowTolerance;

// Where the rays of a beam start. At the shaded point (the paper), they count
// from POV-Ray's shadow tolerance on. From an apex behind the surface, a ray
// counts only beyond the tangent plane (paper, "Future Work": intersections
// between the new origin and the surface are ignored).
struct Origin {
    Vec3 apex{0.0};
    bool behind = false;
    Vec3 normal{0.0, 1.0, 0.0};  // the tangent plane's, toward the light's side
    double depth = 0.0;          // behind: the apex's distance below the tangent plane

    // Distance along unit `dir` at which a ray leaves the surface.
    double surfaceDistance(const Vec3& dir) const {
        if (!behind) return 0.0;
        const double c = glm::dot(dir, normal);
        return c > 0.0 ? depth / c : kInfinity;
    }
    // Bounds of surfaceDistance over the directions of a cone.
    double nearestSurface(const Cone& cone) const {
        if (!behind) return 0.0;
        const double psi = angleBetween(normal, cone.axis);
        return padDown(depth / std::cos(std::max(0.0, psi - cone.halfAngle)));
    }
    double farthestSurface(const Cone& cone) const {
        if (!behind) return 0.0;
        const double widest = angleBetween(normal, cone.axis) + cone.halfAngle;
        if (!(widest < 0.5 * kPi)) return kInfinity;
        return padUp(depth / std::cos(widest));
    }
    // The first distance at which a ray may meet an occluder.
    double rayStart(const Vec3& dir) const {
        return behind ? surfaceDistance(dir) + kTolerance : kTolerance;
    }
};

// Every direction of the piece's cone is at or below the tangent plane:
// nothing through it can light the point.
bool belowHorizon(const Vec3& normal, const LightPiece& piece) {
    if (piece.tanHalf >= 0.0) {
        // angle(normal, axis) >= pi/2 + halfAngle, i.e. cos <= -sin(halfAngle),
        // past the rounding of both (thousands of ulps of 1).
        const double t = piece.tanHalf;
        return glm::dot(normal, piece.cone.axis) < -t / std::sqrt(1.0 + t * t) - kThousandsOfUlps;
    }
    return angleBetween(normal, piece.cone.axis) - piece.cone.halfAngle >= 0.5 * kPi;
}

// Every direction of the piece's cone is above the tangent plane, past
// rounding: a convex or flat shaded surface cannot meet a ray through it.
bool aboveHorizon(const Vec3& normal, const LightPiece& piece) {
    if (piece.tanHalf >= 0.0) {
        const double t = piece.tanHalf;
        return glm::dot(normal, piece.cone.axis) > t / std::sqrt(1.0 + t * t) + kThousandsOfUlps;
    }
    return angleBetween(normal, piece.cone.axis) + piece.cone.halfAngle < 0.5 * kPi - kThousandsOfUlps;
}

// How the light of a piece's lit rays is gathered: POV-Ray's emitter counts
// their shares (the visible fraction); the paper's sums them as diffuse
// light (WeightedDiffuseSum) or keeps them as samples.
enum class Gather { Fraction, Diffuse, Samples };

// The edges of the square pyramid about a cone (its faces tangent to it), so
// that every direction of the cone is a non-negative combination of them
// (Primitive::raysLeave): written to out[], four, or none for a cone of a
// right angle or more.
int pyramidAbout(const Cone& cone, Vec3* out) {
    if (!(cone.halfAngle < 0.45 * kPi)) return 0;
    const Mat3 frame = frameAroundAxis(cone.axis);
    // Widened by 1e-9 of itself, far above the rounding of tan and the frame.
    const double t = std::tan(cone.halfAngle) * (1.0 + 1e-9);
    for (int k = 0; k < 4; ++k)
        out[k] = cone.axis + t * ((k & 1 ? 1.0 : -1.0) * frame[0] + (k & 2 ? 1.0 : -1.0) * frame[1]);
    return 4;
}

// The piece's cone prepared for the primitives, from the tangent of its
// half-angle where it has one (no trigonometry), widened as PreparedCone
// widens every cone (kConeAngleMargin), and the padding kConeAnglePad.
PreparedCone preparedCone(const LightPiece& piece, const Cone& cone) {
    if (!(piece.tanHalf >= 0.0 && piece.tanHalf < 1e6)) return PreparedCone(cone);
    PreparedCone p;
    p.apex = cone.apex;
    p.axis = cone.axis;
    p.tMin = std::max(cone.tMin, 0.0);
    p.tMax = cone.tMax;
    const double c = 1.0 / std::sqrt(1.0 + piece.tanHalf * piece.tanHalf), s = piece.tanHalf * c;
    // cos and sin of halfAngle + delta, delta far below 1e-6 (cos delta is
    // 1 in doubles, sin delta is delta).
    const double delta = 2.0 * kConeAnglePad + kConeAngleMargin * (1.0 + cone.halfAngle);
    p.cosHalf = c - s * delta;
    p.sinHalf = s + c * delta;
    return p;
}

// The shadow of one area light at one point: detection, then subdivision
// of the marginal sub-beams level by level. One instance per light form:
// the form is known once per shaded point, and nothing below asks it again.
// With POV-Ray's emitter it measures the share of the light that reaches
// the point (visible()): a lit piece counts its share, with no refinement,
// and nothing is left out for lying below the surface's horizon (the shaded
// object is an occluder there); with the paper's it makes the samples.
template <AreaLightForm Form>
class BeamShadow {
public:
    using Item = AreaLightScratch::Item;
    using Node = AreaBeamNode;
    using Beam = typename Form::Beam;

    BeamShadow(const Scene& scene, const LightModel& model, const Form& form, const Beam& beams,
               const AreaLightQuery& query, const Origin& origin, AreaLightScratch& scratch,
               RenderCounters& counters)
        : scene_(scene),
          model_(model),
          form_(form),
          q_(query),
          origin_(origin),
          beams_(beams),
          s_(scratch),
          c_(counters),
          povray_(model.emitter == LightEmitter::Povray) {
        jitterKey_ = mix64(query.key ^ mix64(0xa5ea11u + query.lightIndex));
    }

    // POV-Ray's emitter: the share of the light that reaches the point.
    double visible() const { return visible_; }

    void run() {
        const LightPiece root = beams_.root();
        if (!povray_ && belowHorizon(q_.normal, root)) return;
        if (model_.shadowless) {
            litPiece(root);
            return;
        }
        // The shaded object is left out where it cannot shadow itself (a
        // convex or flat surface, toward light above its horizon); with
        // POV-Ray's emitter, light below the horizon counts too: there a
        // flat shape still cannot meet a ray from its surface, a convex
        // solid meets those that enter it (selfClass), and any other object
        // is an occluder like the rest until a piece is wholly above (from
        // behind the surface, its tangent plane already cuts the rays).
        const bool selfSure = povray_ && !origin_.behind && !q_.shadedCanSelfShadow;
        const Primitive::SelfOcclusion self =
            selfSure ? scene_.primitive(q_.shadedObject).selfOcclusion() : Primitive::SelfOcclusion::Any;
        selfInterior_ = self == Primitive::SelfOcclusion::Interior;
        const bool shadedLeftOut = !povray_ || origin_.behind || self == Primitive::SelfOcclusion::None ||
                                   (!selfInterior_ && aboveHorizon(q_.normal, root));

        // Detection: the occluders of the whole beam.
        std::vector<Item>& rootItems = s_.items[0];
        rootItems.clear();
        const Cone rootCone = coneOf(root);
        const PreparedCone prepared = preparedCone(root, rootCone);
        // The beam ends at the light: an object beyond the light wherever the
        // beam's cone reaches it (within the cone's box) is no occluder
        // (docs/lights.md, "Where a beam ends"); nor is one outside the
        // cone's box, which the candidates of a wider cone may hold. Objects
        // beside the beam are left to the cone, so that a verdict changes
        // only where an object lies beyond the light. Made for the first
        // candidate.
        std::optional<BeamHull> hull;
        bool hullMade = false;
        const auto beyondLight = [&](const Primitive& primitive) {
            if (!hullMade) {
                hullMade = true;
                const Bounds3 reach = ConeBoxTest(rootCone).coneBounds();
                const std::optional<BeamHull> h = beams_.hull(kTolerance);
                if (h && std::isfinite(l1Norm(reach.lo) + l1Norm(reach.hi))) hull = h->beyondLight(reach);
            }
            return hull && primitive.outside(*hull);
        };
        if (s_.beamCandidates.size() <= q_.lightIndex) s_.beamCandidates.resize(q_.lightIndex + 1);
        s_.beamCandidates[q_.lightIndex].visit(scene_, rootCone, prepared, [&](std::uint32_t object) {
            if (scene_.object(object).noShadow || scene_.transparent(object)) return;  // transparent: areaLightSamples filters
            if (object == q_.shadedObject && !q_.shadedCanSelfShadow && shadedLeftOut) return;
            const Primitive& primitive = scene_.primitive(object);
            if (beyondLight(primitive)) return;
            ++c_.coneTests;
            const ConeClass k = selfInterior_ && object == q_.shadedObject ? selfClass(root)
                                                                           : primitive.classify(prepared);
            if (k.coverage != Coverage::Miss) rootItems.push_back({object, k});
        });
        // In object order, wherever the candidates came from.
        sortByObject(rootItems.data(), rootItems.data() + rootItems.size());
        c_.countShadowPyray(0);
        const auto rootCount = static_cast<std::uint32_t>(rootItems.size());
        switch (verdict(rootItems, 0, rootCount, root, rootCone)) {
            case Verdict::Lit: litPiece(root); return;
            case Verdict::Blocked: return;
            case Verdict::Marginal: break;
        }

        // Subdivision, all marginal sub-beams of a level together. A marginal
        // sub-beam's central ray is traced only when the stopping rule may
        // need it (docs/lights.md, "Central rays when they count").
        std::vector<Node>* nodes = s_.nodes;
        nodes[0].clear();
        nodes[0].push_back({root, 0, rootCount, false});
        const AsosSettings& settings = model_.asos;
        const bool halving = Beam::kSingleEdgeHalving;
        LightPiece children[Beam::kChildren];
        int cur = 0;
        for (int level = 0;; ++level) {
            std::vector<Node>& levelNodes = nodes[cur];
            const std::vector<Item>& items = s_.items[cur];
            std::vector<std::uint8_t>& hits = s_.hits[cur];
            const double share = beams_.share(level);

            // The tally, first without the central rays: each marginal
            // sub-beam counted for each of its occluders. Where even the
            // least bound this allows exceeds EPS, the rule cannot stop and
            // no central ray is needed; otherwise they are traced, marking
            // the occluders they meet, and the rule is the paper's.
            const auto tallyLevel = [&](const std::uint8_t* marks) {
                s_.tally.clear();
                for (const Node& n : levelNodes)
                    for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
                        s_.tally.add(items[i].object, marks && marks[i] != 0,
                                     halving && items[i].cls.coverage == Coverage::Marginal &&
                                         items[i].cls.singleEdge);
            };
            tallyLevel(nullptr);
            bool stop = level >= settings.maxLevel;
            bool traced = false;
            if (!stop && s_.tally.leastChangeBoundForShare(share) <= settings.eps) {
                hits.assign(items.size(), 0);
                for (Node& n : levelNodes)
                    n.blocked = rayBlocked(n.piece.central, items, n.first, n.count, hits.data());
                traced = true;
                tallyLevel(hits.data());
                stop = s_.tally.changeBoundForShare(share) <= settings.eps;
            }
            if (stop) {
                // Stop: each marginal sub-beam is decided by its central ray,
                // or at MAX with jitter by a random ray inside it.
                const bool jitter = settings.jitter && level >= settings.maxLevel;
                for (const Node& n : levelNodes) {
                    if (jitter) {
                        const BeamRay ray = beams_.sample(n.piece, randomPoint(n.piece));
                        if (!rayBlocked(ray, items, n.first, n.count, nullptr)) litRay(ray, share);
                    } else if (traced ? !n.blocked : !rayBlocked(n.piece.central, items, n.first, n.count, nullptr)) {
                        litRay(n.piece.central, share);
                    }
                }
                break;
            }

            const int childLevel = level + 1;
            const double childShare = beams_.share(childLevel);
            // MAX-beams need no detection: each is one point sample. Where
            // detection does not pay, the levels down to MAX are left
            // undetected too (docs/lights.md, "Detection where it pays").
            const int toMax = settings.maxLevel - level;
            if (toMax <= 1 || (toMax <= undetectedLevels() && !detectionMayStop(childShare, settings.eps))) {
                const double sampleShare = beams_.share(settings.maxLevel);
                for (const Node& n : levelNodes) {
                    const Item* occluders = items.data() + n.first;
                    if (settings.jitter) {
                        beams_.forEachDescendant(n.piece, toMax, [&](const LightPiece& piece) {
                            pointSample(piece, occluders, n.count, sampleShare);
                        });
                    } else {
                        sampleCentralRays(n.piece, toMax, occluders, n.count, sampleShare);
                    }
                }
                break;
            }

            const int next = 1 - cur;
            std::vector<Item>& childItems = s_.items[next];
            std::vector<Node>& childNodes = nodes[next];
            childItems.clear();
            childNodes.clear();
            for (const Node& n : levelNodes) {
                const int count = beams_.split(n.piece, children);
                for (int i = 0; i < count; ++i) {
                    const LightPiece& child = children[i];
                    if (!povray_ && belowHorizon(q_.normal, child)) continue;
                    c_.countShadowPyray(childLevel);
                    const auto first = static_cast<std::uint32_t>(childItems.size());
                    const Cone cone = coneOf(child);
                    const PreparedCone childPrepared = preparedCone(child, cone);
                    // The shaded object, an occluder below the horizon only.
                    const bool childAbove = povray_ && aboveHorizon(q_.normal, child);
                    for (std::uint32_t j = n.first; j < n.first + n.count; ++j) {
                        const bool shaded = items[j].object == q_.shadedObject && !q_.shadedCanSelfShadow;
                        if (childAbove && shaded && !selfInterior_) continue;
                        ++c_.coneTests;
                        const ConeClass k = selfInterior_ && shaded
                                                ? selfClass(child)
                                                : scene_.primitive(items[j].object).classify(childPrepared);
                        if (k.coverage != Coverage::Miss) childItems.push_back({items[j].object, k});
                    }
                    const auto found = static_cast<std::uint32_t>(childItems.size()) - first;
                    switch (verdict(childItems, first, found, child, cone)) {
                        case Verdict::Lit:
                            childItems.resize(first);
                            litPiece(child);
                            break;
                        case Verdict::Blocked: childItems.resize(first); break;
                        case Verdict::Marginal: childNodes.push_back({child, first, found, false}); break;
                    }
                }
            }
            if (childNodes.empty()) break;
            cur = next;
        }
    }

private:
    enum class Verdict { Lit, Blocked, Marginal };

    // The shaded object, a convex solid (Primitive::SelfOcclusion::Interior),
    // over a piece: its rays below the plane tangent at the point enter the
    // solid and leave it within the world box's diagonal, the others never
    // meet it. So the piece misses it wholly above that plane, is covered
    // wholly below it, and is marginal across it, where the plane is its one
    // straight edge unless the light lies within the diagonal. (A ray that
    // leaves the solid within the shadow tolerance, on a sphere within about
    // 1e-3 / radius of the plane, or near a box's edge, is not counted as the
    // ray test counts it: far below any EPS.)
    ConeClass selfClass(const LightPiece& piece) const {
        ConeClass k;
        if (aboveHorizon(q_.outward, piece)) return k;
        if (selfReach_ < 0.0) {
            const Bounds3 b = scene_.primitive(q_.shadedObject).worldBounds();
            selfReach_ = padUp(glm::length(b.hi - b.lo)) + kTolerance;
        }
        k.tNear = 0.0;
        k.tFar = selfReach_;
        if (belowHorizon(q_.outward, piece)) {
            k.coverage = Coverage::Full;
        } else {
            k.coverage = Coverage::Marginal;
            k.singleEdge = selfReach_ < beams_.nearestLightDistance(piece) - kTolerance;
        }
        return k;
    }

    // A MAX-beam: one point sample, its central ray or with jitter a random
    // ray inside it, decided against its parent's occluders. A ray below
    // the surface's horizon would light nothing: it is not traced.
    void pointSample(const LightPiece& piece, const Item* occluders, std::uint32_t count, double share) {
        c_.countShadowPyray(piece.level);
        const BeamRay ray = model_.asos.jitter ? beams_.sample(piece, randomPoint(piece)) : piece.central;
        sampleRay(ray, occluders, count, share);
    }
    // The MAX-beams `depth` levels below `piece` without jitter: their
    // central rays (of the beam's lattice where it has one), each decided as
    // pointSample decides it, with the occluders' primitives looked up once
    // and the counters kept here (the inner loop of a penumbra).
    void sampleCentralRays(const LightPiece& piece, int depth, const Item* occluders, std::uint32_t count,
                           double share) {
        // An occluder whose every ray toward the point samples leaves it
        // (Primitive::raysLeave) blocks none and is left out: from a
        // lattice's corner points (rectangles, segments), which span the
        // rest, or else from the pyramid about the piece's cone (a sphere's
        // pieces). Detection cannot tell so where the point lies next to the
        // occluder (a box or cone standing on the ground), nor from the
        // piece's cone, which reaches past a lattice's samples. So is an
        // occluder outside the hull of the point and the lattice's corner
        // points (BeamHull), where the samples' rays run: beside the piece
        // within its cone (a circle about an oblong piece holds twice its
        // area), or beyond the light.
        const std::optional<LightLattice> lattice = beams_.lattice(piece, depth);
        const bool latticed = lattice.has_value();
        Vec3 corners[4];
        int cornerCount = 0;
        if (latticed) {
            const int i1 = lattice->columns() - 1, j1 = lattice->rows() - 1;
            corners[cornerCount++] = lattice->offset(0, 0);
            corners[cornerCount++] = lattice->offset(i1, 0);
            if (j1 > 0) {
                corners[cornerCount++] = lattice->offset(0, j1);
                corners[cornerCount++] = lattice->offset(i1, j1);
            }
        } else {
            cornerCount = pyramidAbout(piece.cone, corners);
        }
        std::optional<BeamHull> hull;
        bool hullMade = !latticed;
        const auto outsideHull = [&](const Primitive& primitive) {
            if (!hullMade) {
                hullMade = true;
                // The corner points in order around the lattice.
                const Vec3& a = origin_.apex;
                const Vec3 base[4] = {a + corners[0], a + corners[1], a + corners[cornerCount - 1],
                                      a + corners[cornerCount - 2]};
                double reach2 = 0.0;
                for (int k = 0; k < cornerCount; ++k) reach2 = std::max(reach2, dot3(corners[k], corners[k]));
                hull = BeamHull::over(a, base, cornerCount, padUp(std::sqrt(reach2)), kTolerance);
            }
            return hull && primitive.outside(*hull);
        };
        std::vector<AreaLightScratch::SampleOccluder>& list = s_.sampleOccluders;
        list.clear();
        for (std::uint32_t i = 0; i < count; ++i) {
            const Primitive& primitive = scene_.primitive(occluders[i].object);
            if (cornerCount > 0 && primitive.raysLeave(origin_.apex, corners, cornerCount)) continue;
            if (outsideHull(primitive)) continue;
            list.push_back({&primitive, primitive.originToLocal(origin_.apex)});
        }
        count = static_cast<std::uint32_t>(list.size());
        const AreaLightScratch::SampleOccluder* first = list.data();
        std::uint64_t pieces = 0, rays = 0, tests = 0;
        // Diffuse only, from the shaded point (no surface distance to take
        // off), the lit samples' sum is kept in locals: emitAbove's and
        // WeightedDiffuseSum::add's operations in their order, written back
        // once per lattice.
        const Gather gather = povray_ ? Gather::Fraction
                              : q_.diffuseOnly && !origin_.behind ? Gather::Diffuse
                                                                  : Gather::Samples;
        WeightedDiffuseSum& out = s_.diffuseSum;
        double sumX = out.sum.x, sumY = out.sum.y, sumZ = out.sum.z, sumDistance = out.distance,
               total = out.total;
        std::size_t emitted = out.count;
        std::uint64_t litCount = 0;
        // A lit sample's light (above the horizon with the paper's emitter).
        const auto lit = [&](const BeamRay& ray, auto gatherHere) __attribute__((always_inline)) {
            const Vec3& dir = ray.ray.dir;
            if constexpr (decltype(gatherHere)::value == Gather::Fraction) {
                ++litCount;
            } else if constexpr (decltype(gatherHere)::value == Gather::Diffuse) {
                const double k = share * beams_.emission(dir);
                const double distance = std::max(ray.distance, 0.0);
                sumX += k * dir.x;
                sumY += k * dir.y;
                sumZ += k * dir.z;
                sumDistance += k * distance;
                total += k;
                if (emitted++ == 0) {
                    out.firstDirection = dir;
                    out.firstDistance = distance;
                    out.firstWeight = k;
                }
            } else {
                emitAbove(ray, share);
            }
        };
        // The lattice's loop with `blocked(dir, t0, t1)` inlined (the central
        // rays of forEachDescendant's pieces, in its order, bit for bit).
        const auto sample = [&](auto&& blocked, auto gatherHere) {
            const auto each = [&](const BeamRay& ray) __attribute__((always_inline)) {
                ++pieces;
                const Vec3& dir = ray.ray.dir;
                if (!povray_ && dot3(q_.normal, dir) < kPovEpsilon) return;
                ++rays;
                const double t0 = origin_.rayStart(dir);
                const double t1 = ray.distance - kTolerance;
                if (!(t0 < t1)) {
                    if (origin_.behind) return;
                } else if (blocked(dir, t0, t1)) {
                    return;
                }
                lit(ray, gatherHere);
            };
            if (!latticed) {
                beams_.forEachDescendant(piece, depth, [&](const LightPiece& p) { each(p.central); });
                return;
            }
            for (int m = 0; m < lattice->count(); ++m) {
                const LightLattice::Place at = lattice->place(m);
                each(lattice->ray(at.i, at.j));
            }
        };
        // One convex occluder clear of the rays' ends (convexShadow): its
        // shadow on the lattice is a convex set's points, found with few
        // tests (ConvexLattice); then the lit samples in the lattice's order.
        const auto sampleConvex = [&](auto&& blocked, auto gatherHere) {
            const ConvexLattice shadow(lattice->columns(), lattice->rows(), [&](int i, int j) {
                const BeamRay ray = lattice->ray(i, j);
                const double t1 = ray.distance - kTolerance;
                return kTolerance < t1 && blocked(ray.ray.dir, kTolerance, t1);
            });
            for (int m = 0; m < lattice->count(); ++m) {
                const LightLattice::Place at = lattice->place(m);
                if (shadow.member(at.i, at.j)) continue;
                const BeamRay ray = lattice->ray(at.i, at.j);
                if (!povray_ && dot3(q_.normal, ray.ray.dir) < kPovEpsilon) continue;
                lit(ray, gatherHere);
            }
            pieces += std::uint64_t(lattice->count());
            rays += std::uint64_t(shadow.tests());
        };
        // One of the three gatherings, resolved at compile time.
        const auto withGather = [&](auto&& f) __attribute__((always_inline)) {
            switch (gather) {
                case Gather::Fraction: f(std::integral_constant<Gather, Gather::Fraction>{}); break;
                case Gather::Diffuse: f(std::integral_constant<Gather, Gather::Diffuse>{}); break;
                case Gather::Samples: f(std::integral_constant<Gather, Gather::Samples>{}); break;
            }
        };
        // sample(blocked) with the sum kept in locals where it may be.
        const auto sampleAll = [&](auto&& blocked) __attribute__((always_inline)) {
            withGather([&](auto gatherHere) { sample(blocked, gatherHere); });
        };
        if (count == 1) {
            // One occluder (the common case): its shape's test is resolved
            // once for the whole lattice, with what does not depend on the
            // direction computed once (Primitive::withAnyTestFrom).
            const bool convex = latticed && convexShadow(*first[0].primitive);
            first[0].primitive->withAnyTestFrom(origin_.apex, [&](const auto& test) {
                const auto blocked = [&](const Vec3& dir, double t0, double t1) __attribute__((always_inline)) {
                    ++tests;
                    return test(dir, t0, t1);
                };
                if (!convex) sampleAll(blocked);
                else withGather([&](auto gatherHere) { sampleConvex(blocked, gatherHere); });
            });
        } else if (count == 0) {
            // Every occluder left out: every sample is lit, without a ray.
            sampleAll([](const Vec3&, double, double) { return false; });
            rays = 0;
        } else {
            sampleAll([&](const Vec3& dir, double t0, double t1) __attribute__((always_inline)) {
                for (std::uint32_t i = 0; i < count; ++i) {
                    ++tests;
                    if (first[i].primitive->intersectAnyFrom(first[i].origin, dir, t0, t1)) return true;
                }
                return false;
            });
        }
        if (gather == Gather::Diffuse) {
            out.sum = Vec3(sumX, sumY, sumZ);
            out.distance = sumDistance;
            out.total = total;
            out.count = emitted;
        }
        visible_ += double(litCount) * share;
        c_.countShadowPyrays(piece.level + depth, pieces);
        c_.shadowRays += rays;
        c_.rayTests += tests;
    }
    // Whether one occluder's shadow on a lattice of MAX-pieces (the beam's
    // lattice below a piece) is the lattice's points in a convex set, so that
    // ConvexLattice may find it: a convex occluder (Primitive::convex); rays
    // from the shaded point, each tested from the shadow tolerance to the
    // tolerance before the light; the occluder farther than twice the
    // tolerance from the point and from the light's box. A lattice ray then
    // meets the occluder's surface within that range iff the segment from
    // the point to the ray's light point meets the occluder, and the light
    // points for which it does are a convex set's (docs/lights.md, "Convex
    // occluders").
    bool convexShadow(const Primitive& occluder) const {
        if (origin_.behind || !occluder.bounded() || !occluder.convex()) return false;
        const Bounds3 b = occluder.worldBounds();
        const double margin = 2.0 * kTolerance;
        const Vec3& a = origin_.apex;
        const Vec3 gap = glm::max(glm::max(b.lo - a, a - b.hi), Vec3(0.0));
        if (!(glm::dot(gap, gap) > margin * margin)) return false;
        const Bounds3 light = form_.bounds();
        for (int axis = 0; axis < 3; ++axis)
            if (b.lo[axis] > light.hi[axis] + margin || b.hi[axis] < light.lo[axis] - margin) return true;
        return false;
    }

    void sampleRay(const BeamRay& ray, const Item* occluders, std::uint32_t count, double share) {
        if (!povray_ && glm::dot(q_.normal, ray.ray.dir) < kPovEpsilon) return;
        if (!sampleBlocked(ray, occluders, count)) litRay(ray, share);
    }

    // rayBlocked without marks, for point samples: stops at the first
    // occluder met.
    bool sampleBlocked(const BeamRay& ray, const Item* occluders, std::uint32_t count) {
        ++c_.shadowRays;
        const double t0 = origin_.rayStart(ray.ray.dir);
        const double t1 = ray.distance - kTolerance;
        if (!(t0 < t1)) return origin_.behind;
        for (std::uint32_t i = 0; i < count; ++i) {
            ++c_.rayTests;
            if (scene_.primitive(occluders[i].object).intersectAny(ray.ray, t0, t1)) return true;
        }
        return false;
    }

    // How many levels above MAX a marginal beam's descendants may be left
    // undetected: three for quarters (64 MAX-beams) and four for halves (16),
    // whose point samples cost about as much as the detection of the levels
    // between costs in cone classifications and the samples of the marginal
    // pieces it leaves (docs/lights.md, "Detection where it pays": with the
    // cheaper samples of FrustumFromOrigin, three for quarters took less time
    // than two).
    static constexpr int undetectedLevels() { return Beam::kChildren == 2 ? 4 : 3; }

    // Whether the stopping rule could stop at the next level (of pieces each
    // `childShare` of the light) if the children of this level's marginal
    // beams were taken as marginal without detection: each counted for each
    // occluder of its parent, without the single-edge halving. With n such
    // children on an occluder, max(in, out) >= ceil(n / 2) whatever their
    // central rays say. s_.tally holds this level's tally (in + out: the
    // beams listing each occluder).
    bool detectionMayStop(double childShare, double eps) const {
        const int perSplit = Beam::kChildren;
        double least = 0.0;
        for (const SubdivisionTally::Entry& e : s_.tally.entries()) {
            const int n = perSplit * (e.in + e.out);
            least += double((n + 1) / 2) * childShare;
        }
        return least <= eps;
    }

    // The piece's cone, its near end moved to the surface for an apex behind it.
    Cone coneOf(const LightPiece& piece) const {
        Cone cone = piece.cone;
        if (origin_.behind) cone.tMin = origin_.nearestSurface(cone);
        return cone;
    }

    // No occluder: lit. A Full occluder wholly between the surface and the
    // nearest point of the light blocks the whole beam. Otherwise (an edge in
    // the beam, or an object that may lie behind the light for some rays or
    // before the surface) it is marginal.
    Verdict verdict(const std::vector<Item>& items, std::uint32_t first, std::uint32_t count,
                    const LightPiece& piece, const Cone& cone) const {
        if (count == 0) return Verdict::Lit;
        double nearestLight = -1.0, farthestSurface = 0.0;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const ConeClass& k = items[i].cls;
            if (k.coverage != Coverage::Full) continue;
            if (nearestLight < 0.0) {
                nearestLight = beams_.nearestLightDistance(piece) - kTolerance;
                farthestSurface = origin_.farthestSurface(cone) + kTolerance;
            }
            if (k.tFar < nearestLight && (!origin_.behind || k.tNear > farthestSurface)) return Verdict::Blocked;
        }
        return Verdict::Marginal;
    }

    // Whether the ray toward the light meets one of the occluders; marks
    // each one it meets (all are asked then).
    bool rayBlocked(const BeamRay& ray, const std::vector<Item>& items, std::uint32_t first,
                    std::uint32_t count, std::uint8_t* marks) {
        ++c_.shadowRays;
        const double t0 = origin_.rayStart(ray.ray.dir);
        const double t1 = ray.distance - kTolerance;
        if (!(t0 < t1)) {
            // From behind the surface, a ray that never leaves it (the light
            // point is below the tangent plane) reaches nothing.
            if (marks)
                for (std::uint32_t i = first; i < first + count; ++i) marks[i] = 0;
            return origin_.behind;
        }
        bool blocked = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (blocked && !marks) break;
            ++c_.rayTests;
            const bool hit = scene_.primitive(items[i].object).intersectAny(ray.ray, t0, t1);
            if (marks) marks[i] = hit;
            blocked = blocked || hit;
        }
        return blocked;
    }

    // A piece no occluder touches: its share (POV-Ray's emitter), or its
    // light integrated to EPS (the paper's).
    void litPiece(const LightPiece& piece) {
        if (povray_) visible_ += beams_.share(piece.level);
        else refineLit(piece);
    }
    // A ray of `share` of the light that no occluder blocks: its share
    // (POV-Ray's emitter, wherever it points), or its light (the paper's).
    void litRay(const BeamRay& ray, double share) {
        if (povray_) visible_ += share;
        else emit(ray, share);
    }

    // The light a sub-beam of `share` of the light carries along `ray`:
    // I A cos(theta) = colour x share x cos(theta) (rectangle), I A (sphere),
    // I L (segment).
    void emit(const BeamRay& ray, double share) {
        if (glm::dot(q_.normal, ray.ray.dir) < kPovEpsilon) return;  // it would light nothing
        emitAbove(ray, share);
    }
    // emit, for a ray known to be above the horizon.
    void emitAbove(const BeamRay& ray, double share) {
        const Vec3& dir = ray.ray.dir;
        const double distance = ray.distance - origin_.surfaceDistance(dir);
        add(dir, distance, share * beams_.emission(dir));
    }

    // A sub-beam that reaches the light unobstructed (no ray needed). The
    // one-ray midpoint rule's error on it is about a third of the sum of its
    // second differences along each coordinate (exactly so for a quadratic
    // on a square), measured with two pairs of probe rays across it. Where
    // that error is negligible (below EPS / 64 of the piece's share) the
    // central ray alone carries the piece; where half the sum is within EPS,
    // a rule exact for quadratics: the central ray and the probes
    // (the beam's ruleWeights); otherwise the pieces are refined alike,
    // down to MAX.
    //
    // The tangent plane (the horizon) through a piece is the exception: the
    // clamped cosine has a kink along it, which second differences do not
    // bound (a rule through probes on both sides overestimates a convex kink,
    // by 1.2 EPS on a segment in the tests), so neither rule is trusted
    // across it: such a piece is refined to MAX, where its central ray alone
    // carries it, as a grid point would. Rectangles and segments know exactly
    // and without rays whether the horizon crosses a piece
    // (the beam's horizonSide); sphere pieces find it from their five
    // directions.
    void refineLit(const LightPiece& piece) {
        const bool deepest = piece.level >= model_.asos.maxLevel;
        switch (beams_.horizonSide(piece, q_.normal)) {
            case HorizonSide::Below: return;  // it would light nothing
            case HorizonSide::Across:
                if (deepest) emit(piece.central, beams_.share(piece.level));
                else refineChildren(piece);
                return;
            case HorizonSide::Above:
            case HorizonSide::Unknown: break;
        }
        BeamRay probes[4];
        const int n = beams_.probeRays(piece, probes);
        // Each direction's emitter weight and cosine of incidence, computed
        // once: the criterion and the samples both use them.
        double weight[5], cosine[5];
        const auto measure = [&](int i, const Vec3& dir) {
            weight[i] = beams_.emission(dir);
            cosine[i] = glm::dot(q_.normal, dir);
            return weight[i] * std::max(0.0, cosine[i]);
        };
        const double centre = measure(4, piece.central.ray.dir);
        double differences = 0.0;
        for (int i = 0; i < n; i += 2)
            differences += std::abs(0.5 * (measure(i, probes[i].ray.dir) + measure(i + 1, probes[i + 1].ray.dir)) - centre);
        const double share = beams_.share(piece.level);
        bool above = cosine[4] >= kPovEpsilon, below = !above;
        for (int i = 0; i < n; ++i) (cosine[i] >= kPovEpsilon ? above : below) = true;
        if (above && below) {
            if (deepest) emitMeasured(piece.central, share, weight[4], cosine[4]);
            else refineChildren(piece);
            return;
        }
        if (differences / 3.0 <= model_.asos.eps / 64.0) {
            emitMeasured(piece.central, share, weight[4], cosine[4]);
            return;
        }
        if (!deepest && 0.5 * differences > model_.asos.eps) {
            refineChildren(piece);
            return;
        }
        const auto [centreWeight, probeWeight] = beams_.ruleWeights(piece);
        emitMeasured(piece.central, share * centreWeight, weight[4], cosine[4]);
        for (int i = 0; i < n; ++i) emitMeasured(probes[i], share * probeWeight, weight[i], cosine[i]);
    }

    // refineLit over the piece's children. No cones: nothing is classified
    // here. A child wholly below the horizon carries nothing, as if it had
    // been left out.
    void refineChildren(const LightPiece& piece) {
        LightPiece children[Beam::kChildren];
        const int count = beams_.split(piece, children, false);
        for (int i = 0; i < count; ++i) refineLit(children[i]);
    }

    // emit, with the direction's emitter weight and cosine of incidence
    // already known (the same values emit would compute).
    void emitMeasured(const BeamRay& ray, double share, double emission, double cosine) {
        if (cosine < kPovEpsilon) return;  // it would light nothing
        const Vec3& dir = ray.ray.dir;
        const double distance = ray.distance - origin_.surfaceDistance(dir);
        add(dir, distance, share * emission);
    }
    // The sample of the light's colour times k along `dir`. Diffuse only:
    // summed as made (WeightedDiffuseSum, mergeDiffuse's sample).
    void add(const Vec3& dir, double distance, double k) {
        if (q_.diffuseOnly) s_.diffuseSum.add(dir, std::max(distance, 0.0), k);
        else s_.samples.push_back({dir, std::max(distance, 0.0), model_.color * k});
    }

    // Two numbers in [0, 1) for a piece: its level and position decide them.
    Vec2 randomPoint(const LightPiece& piece) const {
        return q_.rng.uniform2(SampleStream::LightJitter,
                               mix64(jitterKey_ ^ (std::uint64_t(piece.level) << 44 | piece.path)));
    }

    const Scene& scene_;
    const LightModel& model_;
    const Form& form_;
    const AreaLightQuery& q_;
    const Origin& origin_;
    Beam beams_;
    AreaLightScratch& s_;
    RenderCounters& c_;
    const bool povray_;  // POV-Ray's emitter: the visible fraction
    double visible_ = 0.0;
    std::uint64_t jitterKey_ = 0;
    bool selfInterior_ = false;      // the shaded object is classified by selfClass
    mutable double selfReach_ = -1.0;  // selfClass's reach, made on first use
};

// behindApex, for the light's form: `centre`, the light's position.
template <AreaLightForm Form>
std::optional<Vec3> behindApexOf(const Form& light, const Vec3& centre, const Vec3& point, const Vec3& normal,
                                 const Footprint& footprint) {
    if (!footprint.onTangentPlane()) return std::nullopt;
    const Vec3 toLight = centre - point;
    const double distance = glm::length(toLight);
    if (!(distance > 0.0)) return std::nullopt;
    const Vec3 axis = toLight / distance;
    // A light near the horizon would put the apex far along the surface.
    if (!(glm::dot(axis, normal) > 0.05)) return std::nullopt;
    const std::array<Vec3, 4>& corners = footprint.corners();
    double reach = 0.0;
    for (const Vec3& c : corners) reach = std::max(reach, glm::length(c - point));
    if (!(reach > 0.0)) return std::nullopt;
    const auto holds = [&](double h) {
        const Vec3 apex = point - h * axis;
        return std::all_of(corners.begin(), corners.end(), [&](const Vec3& c) { return light.beamHolds(apex, c); });
    };
    // The beam's cross-section at the surface grows with the distance behind
    // it, toward the light's own size: start from the similar-triangles
    // estimate, double until it holds, then halve the bracket.
    const double lightRadius = light.halfWidth();
    double hi = reach * distance / std::max(lightRadius - reach, 0.125 * lightRadius);
    const double farthest = 1e3 * distance;
    while (!holds(hi)) {
        hi *= 2.0;
        if (hi > farthest) return std::nullopt;
    }
    double lo = 0.0;
    for (int i = 0; i < 12; ++i) {
        const double mid = 0.5 * (lo + hi);
        (holds(mid) ? hi : lo) = mid;
    }
    return point - hi * axis;
}

// Where the beams toward area light `light` (the model's form) start: the
// shaded point, or with ShadowApex::Behind a point behind the surface.
template <AreaLightForm Form>
Origin beamOrigin(const Form& light, const LightModel& model, ShadowApex apex, const AreaLightQuery& query) {
    Origin origin;
    origin.apex = query.point;
    if (apex == ShadowApex::Behind && query.footprint) {
        if (const std::optional<Vec3> a =
                behindApexOf(light, model.position, query.point, query.normal, *query.footprint)) {
            origin.apex = *a;
            origin.behind = true;
            origin.normal = query.normal;
            origin.depth = glm::dot(query.point - *a, query.normal);
            if (!(origin.depth > 0.0)) origin = Origin{query.point};
        }
    }
    return origin;
}

// The beam of area light `light` from `origin`: none where the point lies in
// the light (its plane, its line, inside it).
template <AreaLightForm Form>
std::optional<typename Form::Beam> beamOf(const Form& light, const Origin& origin) {
    return light.beamFrom(origin.apex, origin.behind ? 0.0 : kTolerance);
}

// The ASOS samples of area light `light` (the model's form), into the
// scratch's samples or its diffuse sum.
template <AreaLightForm Form>
void beamSamples(const Form& light, const Scene& scene, const LightModel& model, ShadowApex apex,
                 const AreaLightQuery& query, AreaLightScratch& scratch, RenderCounters& counters) {
    const Origin origin = beamOrigin(light, model, apex, query);
    if (const std::optional<typename Form::Beam> beams = beamOf(light, origin))
        BeamShadow<Form>(scene, model, light, *beams, query, origin, scratch, counters).run();
}

// The share of area light `light` (the model's form, POV-Ray's emitter) that
// reaches the point; none where the point sees no beam.
template <AreaLightForm Form>
std::optional<double> beamFraction(const Form& light, const Scene& scene, const LightModel& model, ShadowApex apex,
                                   const AreaLightQuery& query, AreaLightScratch& scratch, RenderCounters& counters) {
    const Origin origin = beamOrigin(light, model, apex, query);
    const std::optional<typename Form::Beam> beams = beamOf(light, origin);
    if (!beams) return std::nullopt;
    BeamShadow<Form> shadow(scene, model, light, *beams, query, origin, scratch, counters);
    shadow.run();
    return shadow.visible();
}

}  // namespace

std::optional<Vec3> behindApex(const LightModel& model, const Vec3& point, const Vec3& normal,
                               const Footprint& footprint) {
    std::optional<Vec3> apex;
    withAreaForm(model.form,
                 [&](const auto& light) { apex = behindApexOf(light, model.position, point, normal, footprint); });
    return apex;
}

double asosVisibleFraction(const Scene& scene, const LightModel& model, ShadowApex apex,
                           const AreaLightQuery& query, AreaLightScratch& scratch, RenderCounters& counters) {
    std::optional<double> visible;
    withAreaForm(model.form, [&](const auto& light) {
        visible = beamFraction(light, scene, model, apex, query, scratch, counters);
    });
    // A point in the light's plane or on its line sees no beam, but POV-Ray's
    // isotropic points still light it (edge on): its grid answers.
    return visible ? *visible : gridVisibleFraction(scene, model, query, scratch, counters);
}

std::span<const LightSample> asosAreaLightSamples(const Scene& scene, const LightModel& model,
                                                  ShadowApex apex, const AreaLightQuery& query,
                                                  AreaLightScratch& scratch, RenderCounters& counters) {
    scratch.samples.clear();
    scratch.diffuseSum.clear();
    withAreaForm(model.form, [&](const auto& light) {
        beamSamples(light, scene, model, apex, query, scratch, counters);
    });
    if (!query.diffuseOnly) return scratch.samples;
    // The samples were summed as they were made (BeamShadow::add): the one
    // sample that lights the point as all of them (mergeDiffuse), or none
    // when they carry no light.
    if (scratch.diffuseSum.count == 0) return scratch.samples;
    const std::optional<LightSample> merged = scratch.diffuseSum.merged(model.color);
    if (!merged) return scratch.samples;
    scratch.merged = *merged;
    return {&scratch.merged, 1};
}

}  // namespace asos
