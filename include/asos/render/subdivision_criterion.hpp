#pragma once
// The paper's stopping rule for subdivision ("Subdivision Phase" and
// "Proximity to One Edge"), generalised to several objects in a pixel.
//
// At level K every marginal K-pyray is tallied against each object it is
// marginal on: `in` when its K-ray hits that object, `out` otherwise. For one
// object, L = max(in, out) and subdivision stops when L / 2^(2K) <= EPS, or
// L / 2^(2K+1) <= EPS when every marginal pyray is near a single edge of it.
// With several objects the bound is the sum of the per-object terms: the
// projected coverage of object o can change only inside the pyrays marginal on
// o, its in-pyrays can only lose coverage and its out-pyrays only gain, so
// |Δcoverage(o)| <= max(in_o, out_o) · 4^-K (halved when all of o's marginal
// pyrays are near one straight edge), and the change of a pixel intensity in
// [0,1] is at most the sum of the coverage changes. With a single object the
// sum is exactly the paper's criterion.
//
// A crease inside an object (a box's edge between two visible faces) is an
// edge between parts of its surface: in a pyray the object covers, each part
// the rays may see is tallied, in when the K-ray sees it. The parts' coverages
// add up to the pyray, so their changes add up to zero, and a pixel value
// sum_p c_p cov_p with c_p in [0,1] changes by sum_p (c_p - 1/2) Δcov_p, at
// most half the sum of |Δcov_p|: each part counts half (for two parts, one
// edge, exactly the paper's term). A tip, around which the normal turns all
// round, counts its pyrays whole. A pyray whose shading (a highlight) may
// change by up to `range` over it, though one object covers it without a
// crease, counts as a pyray that may change by `range` times its area.
// docs/algorithm.md has the argument.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace asos {

class SubdivisionTally {
public:
    // The part of an entry for an object's outline (or its pattern, or its
    // order against another object), and for a tip.
    static constexpr std::uint8_t kWhole = 0xff, kTip = 0xfe, kShading = 0xfd;

    // One marginal pyray's verdict on one object.
    void add(std::uint32_t object, bool centralRayHits, bool singleEdge) {
        count(entry(object, kWhole, 1.0), centralRayHits, singleEdge);
    }
    // One pyray's verdict on one part of an object beside a crease inside
    // it (SurfaceHit::part): in when its K-ray sees that part. Counts half.
    void addPart(std::uint32_t object, std::uint8_t part, bool centralRaySees, bool singleEdge) {
        count(entry(object, part, 0.5), centralRaySees, singleEdge);
    }
    // A pyray that may hold a tip of the object: counted whole.
    void addTip(std::uint32_t object) { count(entry(object, kTip, 1.0), true, false); }
    // A pyray the object covers whose shading may change by up to `range`
    // inside it (render/highlight_bound.hpp): the entry's weight is the
    // largest range of its pyrays, so the bound holds for each.
    void addShading(std::uint32_t object, double range) {
        Entry& e = entry(object, kShading, range);
        e.weight = std::max(e.weight, range);
        count(e, true, false);
    }

    // The paper's estimate of the largest change of the pixel intensity that
    // subdividing all marginal K-pyrays could produce, in units of the pixel.
    double changeBound(int level) const;
    // The same for pieces that are each `pieceShare` of the whole (a beam
    // split in two at each level, as a linear light's: 2^-K).
    double changeBoundForShare(double pieceShare) const;
    // The least value changeBoundForShare can take with the same pyrays,
    // whatever their central rays say: for each object max(in, out) >=
    // ceil((in + out) / 2). When it exceeds EPS the rule cannot stop, and
    // the central rays need not be traced to know it.
    double leastChangeBoundForShare(double pieceShare) const;

    bool empty() const { return entries_.empty(); }
    void clear() { entries_.clear(); }

    struct Entry {
        std::uint32_t object = 0;
        std::uint8_t part = kWhole;
        int in = 0;
        int out = 0;
        bool allSingleEdge = true;
        double weight = 1.0;  // 1/2 for a part beside a crease, the range for shading
    };
    const std::vector<Entry>& entries() const { return entries_; }

private:
    Entry& entry(std::uint32_t object, std::uint8_t part, double weight);
    static void count(Entry& e, bool in, bool singleEdge) {
        (in ? e.in : e.out) += 1;
        e.allSingleEdge = e.allSingleEdge && singleEdge;
    }
    std::vector<Entry> entries_;  // few objects per pixel: a flat vector beats a map
};

// Stop subdividing at `level` when the bound is within eps, or at maxLevel.
inline bool stopSubdividing(const SubdivisionTally& tally, int level, double eps, int maxLevel) {
    return level >= maxLevel || tally.changeBound(level) <= eps;
}

}  // namespace asos
