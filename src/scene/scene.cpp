#include "asos/scene/scene.hpp"

#include <stdexcept>

namespace asos {

std::unique_ptr<Scene> Scene::build(SceneDescription description, Diagnostics& diagnostics) {
    std::unique_ptr<Scene> scene(new Scene());
    std::vector<Primitive> byObject;
    byObject.reserve(description.objects.size());
    std::vector<Bounds3> bounds;
    bool ok = true;
    for (std::size_t i = 0; i < description.objects.size(); ++i) {
        const Object& object = description.objects[i];
        try {
            byObject.push_back(Primitive::make(object.shape, object.worldFromObject));
        } catch (const std::invalid_argument& e) {
            diagnostics.error(object.loc, e.what());
            ok = false;
            continue;
        }
        const Primitive& p = byObject.back();
        const auto index = static_cast<std::uint32_t>(i);
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
        scene->castsShadow_.push_back(description.objects[object].noShadow ? 0 : 1);
    }
    scene->itemSlot_.resize(scene->bounded_.size());
    for (std::size_t item = 0; item < scene->bounded_.size(); ++item)
        scene->itemSlot_[item] = scene->slotOf_[scene->bounded_[item]];
    scene->description_ = std::move(description);
    return scene;
}

namespace {
// A candidate of the nearest-hit search: the world record is made for the
// winner only (Primitive::surfaceHit), not for every hit it replaces.
struct Candidate {
    double t;
    std::uint32_t slot;
    LocalHit local;
};
}  // namespace

std::optional<SurfaceHit> Scene::intersect(const Ray& ray, double tMin, double tMax) const {
    std::optional<Candidate> best;
    for (std::uint32_t slot = 0; slot < unbounded_.size(); ++slot) {
        if (auto hit = primitives_[slot].intersectLocal(ray, tMin, tMax)) {
            tMax = hit->t;
            best = Candidate{hit->t, slot, *hit};
        }
    }
    const std::optional<Candidate> nearest =
        bvh_.nearest(ray, tMin, tMax,
                     [&](std::uint32_t item, const Ray& r, double lo,
                         double hi) -> std::optional<Candidate> {
                         const std::uint32_t slot = itemSlot_[item];
                         auto h = primitives_[slot].intersectLocal(r, lo, hi);
                         if (!h) return std::nullopt;
                         return Candidate{h->t, slot, *h};
                     });
    if (nearest) best = nearest;
    if (!best) return std::nullopt;
    SurfaceHit hit = primitives_[best->slot].surfaceHit(ray, best->local);
    hit.objectIndex = static_cast<int>(objectOf_[best->slot]);
    return hit;
}

bool Scene::occluded(const Ray& ray, double tMin, double tMax) const {
    for (std::uint32_t slot = 0; slot < unbounded_.size(); ++slot)
        if (castsShadow_[slot] && primitives_[slot].intersectAny(ray, tMin, tMax)) return true;
    return bvh_.any(ray, tMin, tMax, [&](std::uint32_t item, const Ray& r, double lo, double hi) {
        const std::uint32_t slot = itemSlot_[item];
        return castsShadow_[slot] && primitives_[slot].intersectAny(r, lo, hi);
    });
}

}  // namespace asos
