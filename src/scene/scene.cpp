#include "asos/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "asos/shapes/csg_clip.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

namespace {
bool finiteBounds(const Bounds3& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (!std::isfinite(b.lo[axis]) || !std::isfinite(b.hi[axis])) return false;
    return true;
}
}  // namespace

std::unique_ptr<Scene> Scene::build(SceneDescription description, Diagnostics& diagnostics) {
    std::unique_ptr<Scene> scene(new Scene());
    std::vector<Primitive> byObject;
    byObject.reserve(description.objects.size());
    std::vector<Bounds3> bounds;
    bool ok = true;
    CsgSolidCache solids;
    for (std::size_t i = 0; i < description.objects.size(); ++i) {
        const Object& object = description.objects[i];
        try {
            byObject.push_back(Primitive::make(object.shape, object.worldFromObject, solids));
        } catch (const std::invalid_argument& e) {
            diagnostics.error(object.loc, e.what());
            ok = false;
            continue;
        }
        const Primitive& p = byObject.back();
        const auto index = static_cast<std::uint32_t>(i);
        if (p.bounded() && !finiteBounds(p.worldBounds())) {
            // Finite numbers whose bounds overflow (a huge radius far away):
            // refused here, where the object's location is known.
            diagnostics.error(object.loc, "this object is too large: its bounding box is not finite (" +
                                              formatVector(p.worldBounds().lo) + " to " +
                                              formatVector(p.worldBounds().hi) + ")");
            ok = false;
            continue;
        }
        if (p.bounded()) {
            scene->bounded_.push_back(index);
            bounds.push_back(p.worldBounds());
        } else {
            scene->unbounded_.push_back(index);
        }
    }
    if (!ok) return nullptr;
    scene->bvh_ = Bvh::build(bounds);

    // Slots: unbounded objects, the BVH's items in leaf order, then any
    // item the BVH left out (empty bounds).
    const std::size_t n = byObject.size();
    scene->objectOf_.reserve(n);
    scene->objectOf_.insert(scene->objectOf_.end(), scene->unbounded_.begin(),
                            scene->unbounded_.end());
    std::vector<std::uint8_t> placed(scene->bounded_.size(), 0);
    for (const std::uint32_t item : scene->bvh_.itemOrder()) {
        placed[item] = 1;
        scene->objectOf_.push_back(scene->bounded_[item]);
    }
    for (std::size_t item = 0; item < placed.size(); ++item)
        if (!placed[item]) scene->objectOf_.push_back(scene->bounded_[item]);
    scene->slotOf_.assign(n, 0);
    scene->primitives_.reserve(n);
    scene->castsShadow_.reserve(n);
    for (std::size_t slot = 0; slot < n; ++slot) {
        const std::uint32_t object = scene->objectOf_[slot];
        scene->slotOf_[object] = static_cast<std::uint32_t>(slot);
        scene->primitives_.push_back(std::move(byObject[object]));
        scene->castsShadow_.push_back(
            description.objects[object].noShadow || mayBeTransparent(*description.objects[object].texture) ? 0 : 1);
    }
    const std::size_t treeSlots = scene->bvh_.itemOrder().size();
    scene->leafSpheres_.assign(treeSlots, TranslatedSphere{Vec3(0.0), -1.0});
    for (std::size_t i = 0; i < treeSlots; ++i) {
        const auto sphere = scene->primitives_[scene->unbounded_.size() + i].translatedSphere();
        if (sphere) scene->leafSpheres_[i] = *sphere;
    }
    scene->transparent_.reserve(n);
    for (const Object& o : description.objects) {
        scene->transparent_.push_back(mayBeTransparent(*o.texture) ? 1 : 0);
        scene->anyTransparent_ = scene->anyTransparent_ || scene->transparent_.back();
    }
    scene->description_ = std::move(description);
    return scene;
}

std::optional<LocalHit> Scene::intersectSlot(std::uint32_t slot, const Ray& ray, double tMin,
                                             double tMax) const {
    return primitives_[slot].intersectLocal(ray, tMin, tMax);
}

// One ray's nearest-hit search, shared by the single-ray and the packet
// search so that both do the same arithmetic. It keeps the nearest
// candidate's slot and local hit; the world record (Primitive::surfaceHit) is
// made for the winner only. A leaf sphere keeps only its t: its local hit is
// made once, at the end.
//
// Ties: a hit at the current far limit replaces the best one only from a
// higher slot, so the answer does not depend on the order in which the
// traversal reaches the leaves (the packet traversal reaches them in another
// order than a lone ray). Every primitive's hit is the nearest of its
// candidates at or after tMin, kept if at most tMax, so an item's answer
// does not depend on the far limit it is tested with either.
struct Scene::NearestSearch {
    const Scene* scene = nullptr;
    const Ray* ray = nullptr;
    double tMin = 0.0;
    double far = 0.0;
    std::int64_t bestSlot = -1;
    bool bestIsLeafSphere = false;
    LocalHit bestLocal;

    NearestSearch() = default;
    NearestSearch(const Scene& s, const Ray& r, double lo, double hi)
        : scene(&s), ray(&r), tMin(lo), far(hi) {}

    // t in [tMin, far] found at `slot` beats the best so far.
    bool wins(double t, std::uint32_t slot) const {
        return t >= tMin && t <= far && (t < far || static_cast<std::int64_t>(slot) > bestSlot);
    }

    void unbounded() {
        for (std::uint32_t slot = 0; slot < scene->unbounded_.size(); ++slot) {
            if (auto hit = scene->primitives_[slot].intersectLocal(*ray, tMin, far);
                hit && wins(hit->t, slot)) {
                far = hit->t;
                bestSlot = slot;
                bestLocal = *hit;
            }
        }
    }

    // The BVH's items sit at slots base + leaf slot (Scene::build). Inlined
    // into the traversal loop: an out-of-line call there would save and
    // restore the loop's vector registers at every leaf.
    __attribute__((always_inline)) double leaf(std::uint32_t first, std::uint32_t count) {
        const auto base = static_cast<std::uint32_t>(scene->unbounded_.size());
        for (std::uint32_t k = first; k < first + count; ++k) {
            const TranslatedSphere& sphere = scene->leafSpheres_[k];
            if (sphere.radius >= 0.0) {
                const double t = Sphere::nearestRoot(Ray{ray->origin + sphere.localOffset, ray->dir},
                                                     sphere.radius, tMin, far);
                if (wins(t, base + k)) {
                    far = t;
                    bestSlot = base + k;
                    bestIsLeafSphere = true;
                }
            } else if (const auto hit = scene->intersectSlot(base + k, *ray, tMin, far);
                       hit && wins(hit->t, base + k)) {
                far = hit->t;
                bestSlot = base + k;
                bestIsLeafSphere = false;
                bestLocal = *hit;
            }
        }
        return far;
    }

    // The winner's local hit, for a leaf sphere made now (bestSlot >= 0).
    void finishLocal() {
        if (bestIsLeafSphere) {
            // Sphere::intersect's hit, from the same ray and t.
            const auto base = static_cast<std::uint32_t>(scene->unbounded_.size());
            const auto slot = static_cast<std::uint32_t>(bestSlot);
            const Ray local{ray->origin + scene->leafSpheres_[slot - base].localOffset, ray->dir};
            const Vec3 p = local.at(far);
            bestLocal = LocalHit{far, p, p};
        }
    }

    std::optional<SurfaceHit> result() {
        if (bestSlot < 0) return std::nullopt;
        const auto slot = static_cast<std::uint32_t>(bestSlot);
        finishLocal();
        SurfaceHit hit = scene->primitives_[slot].surfaceHit(*ray, bestLocal);
        hit.objectIndex = static_cast<int>(scene->objectOf_[slot]);
        return hit;
    }

    // The same, written into `out` (the packet search: no temporary to copy).
    void writeResult(std::optional<SurfaceHit>& out) {
        if (bestSlot < 0) {
            out.reset();
            return;
        }
        const auto slot = static_cast<std::uint32_t>(bestSlot);
        finishLocal();
        SurfaceHit& hit = out.emplace(scene->primitives_[slot].surfaceHit(*ray, bestLocal));
        hit.objectIndex = static_cast<int>(scene->objectOf_[slot]);
    }
};

std::optional<SurfaceHit> Scene::intersect(const Ray& ray, double tMin, double tMax) const {
    NearestSearch search(*this, ray, tMin, tMax);
    search.unbounded();
    bvh_.traverse<true>(ray, tMin, search.far,
                        [&](std::uint32_t first, std::uint32_t count) __attribute__((always_inline)) {
                            return search.leaf(first, count);
                        });
    return search.result();
}

void Scene::intersect(std::span<const Ray> rays, double tMin, double tMax,
                      std::span<std::optional<SurfaceHit>> hits) const {
    if (hits.size() != rays.size())
        throw std::invalid_argument("Scene::intersect: as many hits as rays are needed");
    constexpr std::size_t kChunk = bvh_detail::kPacketSize;
    for (std::size_t start = 0; start < rays.size(); start += kChunk) {
        const std::size_t n = std::min(kChunk, rays.size() - start);
        // Left uninitialised, each search made in place (default-made ones
        // would cost clearing 6.6 KB a packet); trivially destructible.
        union Searches {
            Searches() {}
            NearestSearch at[kChunk];
        } searches;
        double far[kChunk];
        for (std::size_t i = 0; i < n; ++i) {
            NearestSearch* s = std::construct_at(&searches.at[i], *this, rays[start + i], tMin, tMax);
            s->unbounded();
            far[i] = s->far;
        }
        bvh_.traversePacket(rays.subspan(start, n), tMin, std::span<const double>(far, n),
                            [&](std::uint32_t i, std::uint32_t first, std::uint32_t count)
                                __attribute__((always_inline)) { return searches.at[i].leaf(first, count); });
        for (std::size_t i = 0; i < n; ++i) searches.at[i].writeResult(hits[start + i]);
    }
}

bool Scene::occluded(const Ray& ray, double tMin, double tMax) const {
    for (std::uint32_t slot = 0; slot < unbounded_.size(); ++slot)
        if (castsShadow_[slot] && primitives_[slot].intersectAny(ray, tMin, tMax)) return true;
    const auto base = static_cast<std::uint32_t>(unbounded_.size());
    bool found = false;
    const auto leaf = [&](std::uint32_t first, std::uint32_t count) __attribute__((always_inline)) {
        for (std::uint32_t k = first; k < first + count; ++k) {
            if (!castsShadow_[base + k]) continue;
            const TranslatedSphere& sphere = leafSpheres_[k];
            const bool hit = sphere.radius >= 0.0
                                 ? Sphere::intersectAny(Ray{ray.origin + sphere.localOffset, ray.dir},
                                                        sphere.radius, tMin, tMax)
                                 : primitives_[base + k].intersectAny(ray, tMin, tMax);
            if (hit) {
                found = true;
                return -1.0;
            }
        }
        return tMax;
    };
    bvh_.traverse<false>(ray, tMin, tMax, leaf);
    return found;
}

}  // namespace asos
