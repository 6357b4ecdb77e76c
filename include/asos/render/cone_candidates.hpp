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
#include "asos/shapes/local_cone.hpp"

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

// The same for the shadow beams of area lights (render/area_light_shadow.hpp):
// their apexes are the shaded points, which differ from one beam to the next,
// but neighbouring points' beams toward one light lie inside one wider cone
// whose apex is set back behind them. A beam inside the remembered cone takes
// its list, each object first tested against the beam's own cone by its
// bounding sphere (a few multiplications); one outside it makes a new one.
// The list is a superset of the beam's candidates that the caller classifies
// exactly, so what a point renders does not depend on the cache (the caller
// puts the objects it keeps in object order). One cache per light per thread.
class BeamCandidateCache {
public:
    // Calls visit(object) for a superset of the objects that `cone` (as
    // `prepared`, its trigonometry done) may meet.
    template <class Visit>
    void visit(const Scene& scene, const Cone& cone, const PreparedCone& prepared, Visit&& visit) {
        if (skip_ > 0) {
            --skip_;
            scene.coneCandidates(cone, visit);
            return;
        }
        if (&scene != scene_ || !holds(cone, prepared)) remember(scene, cone);
        if (!valid_) {
            skip_ = kSkipAfterMiss;
            scene.coneCandidates(cone, visit);
            return;
        }
        for (const Entry& e : entries_)
            if (!e.bounded || sphereMayMeet(prepared, e.center, e.radius)) visit(e.object);
    }

    void clear() { valid_ = false; }

    // Whether the sphere may meet the cone's solid (false only when it
    // certainly does not). Exposed for tests.
    static bool sphereMayMeet(const PreparedCone& cone, const Vec3& center, double radius);

private:
    static constexpr int kSkipAfterMiss = 15;
    static constexpr std::size_t kMaxObjects = 48;
    struct Entry {
        std::uint32_t object;
        bool bounded;
        Vec3 center;  // the bounds' centre and half diagonal: a sphere holding the object
        double radius;
    };
    bool holds(const Cone& cone, const PreparedCone& prepared) const;
    void remember(const Scene& scene, const Cone& cone);

    bool valid_ = false;
    const Scene* scene_ = nullptr;  // whose objects entries_ lists
    // The remembered cone: apex, unit axis, the cosine and sine of its
    // half-angle and its reach, as tested (the BVH was asked for a slightly
    // larger one).
    Vec3 apex_{0.0}, axis_{0.0, 0.0, 1.0};
    double cos_ = 1.0, sin_ = 0.0, reach_ = 0.0;
    int skip_ = 0;
    std::vector<Entry> entries_;
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
