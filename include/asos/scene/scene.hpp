#pragma once
// A scene ready to render: the description's objects as world-space
// primitives and a BVH over the bounded ones (planes are kept aside and
// tested always). Built once; every query is const and thread-safe.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "asos/accel/bvh.hpp"
#include "asos/diag/diagnostics.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/primitive.hpp"

namespace asos {

class Scene {
public:
    // Reports every object that cannot be built (a meaningless shape) to
    // `diagnostics` with its source location, and returns null then.
    static std::unique_ptr<Scene> build(SceneDescription description, Diagnostics& diagnostics);

    const SceneDescription& description() const { return description_; }
    std::uint32_t objectCount() const { return static_cast<std::uint32_t>(primitives_.size()); }
    const Primitive& primitive(std::uint32_t object) const { return primitives_[slotOf_[object]]; }
    const Object& object(std::uint32_t object) const { return description_.objects[object]; }
    const Bvh& bvh() const { return bvh_; }
    // Whether the object may let light through (mayBeTransparent of its
    // texture): rays go on through it, and it filters the shadows it casts
    // rather than blocking them.
    bool transparent(std::uint32_t object) const { return transparent_[object] != 0; }
    bool anyTransparent() const { return anyTransparent_; }

    // The nearest hit in [tMin, tMax], with objectIndex set. Of hits at the
    // same distance, the one of the object stored last wins (an order of the
    // objects fixed at build), whatever order the search tests them in.
    std::optional<SurfaceHit> intersect(const Ray& ray, double tMin, double tMax) const;
    // hits[i] = intersect(rays[i], tMin, tMax), bit for bit, for many rays at
    // once (hits.size() == rays.size()): coherent rays, such as a pixel tile
    // of a pinhole camera, share the BVH traversal (Bvh::traversePacket).
    void intersect(std::span<const Ray> rays, double tMin, double tMax,
                   std::span<std::optional<SurfaceHit>> hits) const;
    // Whether an opaque object that casts shadows (not `no_shadow`, not
    // transparent) is hit in [tMin, tMax].
    bool occluded(const Ray& ray, double tMin, double tMax) const;
    // Calls visit(object) for every object whose bounds the cone may touch,
    // unbounded ones included: a superset of the objects the cone meets.
    template <class Visit>
    void coneCandidates(const Cone& cone, Visit&& visit) const {
        for (std::uint32_t i : unbounded_) visit(i);
        bvh_.cone(cone, [&](std::uint32_t item) { visit(bounded_[item]); });
    }

private:
    struct NearestSearch;
    Scene() = default;
    // The generic item test of the ray search, out of line: the traversal
    // loop inlines only the compact tests.
    [[gnu::noinline]] std::optional<LocalHit> intersectSlot(std::uint32_t slot, const Ray& ray,
                                                            double tMin, double tMax) const;

    SceneDescription description_;
    // The primitives are stored by slot: the unbounded ones first, then the
    // bounded ones in the BVH's leaf order, so that a ray's item tests read
    // neighbouring memory (a Primitive is a few hundred bytes).
    std::vector<Primitive> primitives_;        // by slot
    std::vector<std::uint8_t> castsShadow_;    // by slot
    std::vector<std::uint8_t> transparent_;    // by object
    bool anyTransparent_ = false;
    std::vector<std::uint32_t> objectOf_;      // slot -> object
    std::vector<std::uint32_t> slotOf_;        // object -> slot
    std::vector<std::uint32_t> bounded_;       // BVH item -> object
    std::vector<std::uint32_t> unbounded_;     // objects outside the BVH
    // By BVH leaf slot (slot - unbounded count): the item's local offset and
    // radius when it is a translated sphere (TranslatedSphere), else radius
    // -1. The ray searches test such spheres from this array (32 bytes an
    // item, in the order the traversal reaches them), the rest through their
    // Primitive.
    std::vector<TranslatedSphere> leafSpheres_;
    Bvh bvh_;
};

}  // namespace asos
