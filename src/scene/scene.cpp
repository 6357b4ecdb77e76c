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
    const std::size_t treeSlots = scene->bvh_.itemOrder().size();
    scene->leafSpheres_.assign(treeSlots, TranslatedSphere{Vec3(0.0), -1.0});
    for (std::size_t i = 0; i < treeSlots; ++i) {
        const auto sphere = scene->primitives_[scene->unbounded_.size() + i].translatedSphere();
        if (sphere) scene->leafSpheres_[i] = *sphere;
    }
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
    // The BVH's items sit at slots base + leaf slot (Scene::build).
    const auto base = static_cast<std::uint32_t>(unbounded_.size());
    double far = tMax;
    bvh_.traverse<true>(ray, tMin, tMax, [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t k = first; k < first + count; ++k) {
            const TranslatedSphere& sphere = leafSpheres_[k];
            std::optional<LocalHit> hit;
            if (sphere.radius >= 0.0) {
                hit = Sphere::intersect(Ray{ray.origin + sphere.localOffset, ray.dir},
                                        sphere.radius, tMin, far);
            } else {
                hit = primitives_[base + k].intersectLocal(ray, tMin, far);
            }
            if (hit && hit->t >= tMin && hit->t <= far) {
                far = hit->t;
                best = Candidate{hit->t, base + k, *hit};
            }
        }
        return far;
    });
    if (!best) return std::nullopt;
    SurfaceHit hit = primitives_[best->slot].surfaceHit(ray, best->local);
    hit.objectIndex = static_cast<int>(objectOf_[best->slot]);
    return hit;
}

bool Scene::occluded(const Ray& ray, double tMin, double tMax) const {
    for (std::uint32_t slot = 0; slot < unbounded_.size(); ++slot)
        if (castsShadow_[slot] && primitives_[slot].intersectAny(ray, tMin, tMax)) return true;
    const auto base = static_cast<std::uint32_t>(unbounded_.size());
    bool found = false;
    bvh_.traverse<false>(ray, tMin, tMax, [&](std::uint32_t first, std::uint32_t count) {
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
    });
    return found;
}

}  // namespace asos
