#pragma once
// The objects a cone may meet, from the scene's BVH, remembered for the
// cones that follow: neighbouring pixels' pyrays, and the shadow pyrays of
// neighbouring footprints toward one light, lie inside one slightly wider
// cone with the same apex. Each thread keeps one cache per kind of cone; a
// cone inside the remembered wider one takes its list (a superset of its own
// candidates, which the caller classifies anyway) without a traversal.
//
// What a pixel renders never depends on the cache: the caller keeps the
// objects its classification does not call Miss and puts them in object order
// (sortByObject), so the same pixel gets the same list whatever cone was
// remembered before it, on any thread and in any tile.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "asos/geometry/cone.hpp"
#include "asos/render/stats.hpp"
#include "asos/scene/scene.hpp"

namespace asos {

class ConeCandidateCache {
public:
    // The remembered cone is `widen` times as wide as the cone that missed
    // (and reaches `deepen` times as far); a wider cone holding more than
    // `maxObjects` objects is not remembered, so that dense scenes do not
    // trade traversals for long lists.
    explicit ConeCandidateCache(double widen = 4.0, double deepen = 1.25, std::size_t maxObjects = 48)
        : widen_(widen), deepen_(deepen), maxObjects_(maxObjects) {}

    // Calls visit(object) for a superset of the objects the cone may meet
    // (Scene::coneCandidates).
    template <class Visit>
    void visit(const Scene& scene, const Cone& cone, Visit&& visit) {
        if (skip_ > 0) {
            --skip_;
            scene.coneCandidates(cone, visit);
            return;
        }
        if (!holds(cone)) remember(scene, cone);
        if (valid_) {
            for (std::uint32_t object : objects_) visit(object);
        } else {
            skip_ = kSkipAfterMiss;
            scene.coneCandidates(cone, visit);
        }
    }

    void clear() { valid_ = false; }

private:
    static constexpr int kSkipAfterMiss = 15;
    bool holds(const Cone& cone) const;
    void remember(const Scene& scene, const Cone& cone);

    double widen_, deepen_;
    std::size_t maxObjects_;
    bool valid_ = false;
    Cone wide_;
    int skip_ = 0;  // cones to query directly after a wide cone held too much
    std::vector<std::uint32_t> objects_;
};

// Puts items in increasing order of their `object` field (insertion sort:
// the lists are short).
template <class Item>
void sortByObject(Item* first, Item* last) {
    for (Item* i = first + 1; i < last; ++i) {
        Item item = *i;
        Item* j = i;
        for (; j > first && (j - 1)->object > item.object; --j) *j = *(j - 1);
        *j = item;
    }
}

}  // namespace asos
