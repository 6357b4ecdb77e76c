#include "asos/scene/scene.hpp"

#include <stdexcept>

namespace asos {

std::unique_ptr<Scene> Scene::build(SceneDescription description, Diagnostics& diagnostics) {
    std::unique_ptr<Scene> scene(new Scene());
    scene->primitives_.reserve(description.objects.size());
    std::vector<Bounds3> bounds;
    bool ok = true;
    for (std::size_t i = 0; i < description.objects.size(); ++i) {
        const Object& object = description.objects[i];
        try {
            scene->primitives_.push_back(Primitive::make(object.shape, object.worldFromObject));
        } catch (const std::invalid_argument& e) {
            diagnostics.error(object.loc, e.what());
            ok = false;
            continue;
        }
        const Primitive& p = scene->primitives_.back();
        const auto index = static_cast<std::uint32_t>(i);
        scene->castsShadow_.push_back(object.noShadow ? 0 : 1);
        if (p.bounded()) {
            scene->bounded_.push_back(index);
            bounds.push_back(p.worldBounds());
        } else {
            scene->unbounded_.push_back(index);
        }
    }
    if (!ok) return nullptr;
    scene->bvh_ = Bvh::build(bounds);
    scene->description_ = std::move(description);
    return scene;
}

std::optional<SurfaceHit> Scene::intersect(const Ray& ray, double tMin, double tMax) const {
    std::optional<SurfaceHit> best;
    for (std::uint32_t i : unbounded_) {
        if (auto hit = primitives_[i].intersect(ray, tMin, tMax)) {
            hit->objectIndex = static_cast<int>(i);
            tMax = hit->t;
            best = hit;
        }
    }
    auto hit = bvh_.nearest(ray, tMin, tMax,
                            [&](std::uint32_t item, const Ray& r, double lo, double hi) {
                                const std::uint32_t object = bounded_[item];
                                auto h = primitives_[object].intersect(r, lo, hi);
                                if (h) h->objectIndex = static_cast<int>(object);
                                return h;
                            });
    return hit ? hit : best;
}

bool Scene::occluded(const Ray& ray, double tMin, double tMax) const {
    for (std::uint32_t i : unbounded_)
        if (castsShadow_[i] && primitives_[i].intersectAny(ray, tMin, tMax)) return true;
    return bvh_.any(ray, tMin, tMax, [&](std::uint32_t item, const Ray& r, double lo, double hi) {
        const std::uint32_t object = bounded_[item];
        return castsShadow_[object] && primitives_[object].intersectAny(r, lo, hi);
    });
}

}  // namespace asos
