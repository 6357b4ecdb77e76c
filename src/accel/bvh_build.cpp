// Building the BVH: binned SAH into a binary tree (subtrees in parallel), then
// a collapse into four-wide nodes laid out depth first. The result depends on
// the input only: subtrees are independent, and the final layout is written
// by one depth-first walk after the parallel part.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include <tbb/parallel_invoke.h>

#include "asos/accel/bvh.hpp"
#include "asos/geometry/margins.hpp"

namespace asos {

// Internal to this file; a named namespace because BvhBuilder, a friend of
// Bvh, holds a BinaryBuilder.
namespace bvh_build {

using bvh_detail::roundDownToFloat;
using bvh_detail::roundUpToFloat;

// An item during the build: its bounds as floats rounded outward (exactly
// what the nodes will hold) and its index.
struct PrimRef {
    float lo[3];
    std::uint32_t index;
    float hi[3];
    float centre(int axis) const { return 0.5f * (lo[axis] + hi[axis]); }
};

struct FloatBox {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};
    void extend(const float l[3], const float h[3]) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], l[i]);
            hi[i] = std::max(hi[i], h[i]);
        }
    }
    void extend(const FloatBox& b) { extend(b.lo, b.hi); }
    void extendPoint(float x, float y, float z) {
        const float p[3] = {x, y, z};
        extend(p, p);
    }
    bool empty() const { return lo[0] > hi[0]; }
    double area() const {
        if (empty()) return 0.0;
        const double dx = double(hi[0]) - lo[0], dy = double(hi[1]) - lo[1],
                     dz = double(hi[2]) - lo[2];
        return 2.0 * (dx * dy + dy * dz + dz * dx);
    }
};

// A binary node: a leaf (count > 0) over prims [first, first + count), or an
// inner node with two children.
struct BinaryNode {
    FloatBox box;
    std::uint32_t left = 0, right = 0;
    std::uint32_t first = 0, count = 0;
};

// Past this depth, splits are object medians, which halve the item count, so
// the depth stays below kMaxDepth for any input up to 2^27 items.
constexpr int kMedianDepth = bvh_detail::kMaxDepth - 28;
constexpr std::uint32_t kParallelThreshold = 4096;

class BinaryBuilder {
public:
    BinaryBuilder(std::vector<PrimRef>& prims, const BvhBuildOptions& options)
        : prims_(prims), options_(options), nodes_(2 * prims.size()) {}

    std::uint32_t build() {
        FloatBox box, centres;
        for (const PrimRef& p : prims_) {
            box.extend(p.lo, p.hi);
            centres.extendPoint(p.centre(0), p.centre(1), p.centre(2));
        }
        return buildRange(0, static_cast<std::uint32_t>(prims_.size()), 0, box, centres);
    }

    const BinaryNode& node(std::uint32_t i) const { return nodes_[i]; }

private:
    // Plain data (no default initialisation): findSplit sets only the bins
    // it uses.
    struct Bin {
        float lo[3], hi[3];
        std::uint32_t count;
    };
    static constexpr int kMaxBins = 256;

    std::uint32_t makeLeaf(std::uint32_t first, std::uint32_t count, const FloatBox& box) {
        const std::uint32_t id = next_.fetch_add(1, std::memory_order_relaxed);
        BinaryNode& n = nodes_[id];
        n.box = box;
        n.first = first;
        n.count = count;
        return id;
    }

    static void bounds(const PrimRef* begin, const PrimRef* end, FloatBox& box, FloatBox& centres) {
        for (const PrimRef* p = begin; p != end; ++p) {
            box.extend(p->lo, p->hi);
            centres.extendPoint(p->centre(0), p->centre(1), p->centre(2));
        }
    }

    std::uint32_t buildRange(std::uint32_t first, std::uint32_t end, int depth, const FloatBox& box,
                             const FloatBox& centres) {
        const std::uint32_t count = end - first;
        const auto maxLeaf = static_cast<std::uint32_t>(options_.maxLeafSize);
        if (count == 1) return makeLeaf(first, count, box);

        PrimRef* const begin = prims_.data() + first;
        std::uint32_t mid = first;
        if (depth < kMedianDepth) {
            const Split split = findSplit(begin, count, centres);
            const double leafCost = static_cast<double>(count);
            const double splitCost =
                options_.traversalCost + split.cost / std::max(box.area(), kPositiveFloor);
            if (count <= maxLeaf && (!split.found || leafCost <= splitCost)) {
                return makeLeaf(first, count, box);
            }
            if (split.found) {
                const float lo = centres.lo[split.axis];
                const int bins = binsFor(count);
                const float scale = binScale(centres, split.axis, bins);
                PrimRef* m = std::partition(begin, begin + count, [&](const PrimRef& p) {
                    return binOf(p.centre(split.axis), lo, scale, bins) < split.bin;
                });
                mid = first + static_cast<std::uint32_t>(m - begin);
            }
        } else if (count <= maxLeaf) {
            return makeLeaf(first, count, box);
        }
        if (mid == first || mid == end) {
            // No useful SAH split (all centres equal, or too deep): the
            // object median along the widest centre extent.
            int axis = 0;
            for (int i = 1; i < 3; ++i) {
                if (centres.hi[i] - centres.lo[i] > centres.hi[axis] - centres.lo[axis]) axis = i;
            }
            mid = first + count / 2;
            std::nth_element(begin, prims_.data() + mid, begin + count,
                             [axis](const PrimRef& a, const PrimRef& b) {
                                 return a.centre(axis) < b.centre(axis);
                             });
        }

        FloatBox leftBox, leftCentres, rightBox, rightCentres;
        bounds(prims_.data() + first, prims_.data() + mid, leftBox, leftCentres);
        bounds(prims_.data() + mid, prims_.data() + end, rightBox, rightCentres);
        const std::uint32_t id = next_.fetch_add(1, std::memory_order_relaxed);
        std::uint32_t left = 0, right = 0;
        if (count >= kParallelThreshold) {
            tbb::parallel_invoke(
                [&] { left = buildRange(first, mid, depth + 1, leftBox, leftCentres); },
                [&] { right = buildRange(mid, end, depth + 1, rightBox, rightCentres); });
        } else {
            left = buildRange(first, mid, depth + 1, leftBox, leftCentres);
            right = buildRange(mid, end, depth + 1, rightBox, rightCentres);
        }
        BinaryNode& n = nodes_[id];
        n.box = box;
        n.left = left;
        n.right = right;
        return id;
    }

    struct Split {
        bool found = false;
        int axis = 0;
        int bin = 0;        // items in bins < bin go left
        double cost = 0.0;  // area-weighted item count of both sides
    };

    // Small ranges use fewer bins: the sweep's cost then follows the item
    // count (most ranges in a big tree are small), and with as many bins as
    // items the split is nearly the exact SAH one anyway.
    int binsFor(std::uint32_t count) const {
        return static_cast<int>(std::min<std::uint32_t>(options_.binCount, std::max(4u, count)));
    }
    // Shrunk by a millionth so that the highest centre maps inside the last
    // bin (binOf clamps as well).
    static float binScale(const FloatBox& centres, int axis, int bins) {
        const float extent = centres.hi[axis] - centres.lo[axis];
        return extent > 0.0f ? static_cast<float>(bins) * (1.0f - 1e-6f) / extent : 0.0f;
    }
    static int binOf(float c, float lo, float scale, int bins) {
        const int b = static_cast<int>((c - lo) * scale);
        return std::clamp(b, 0, bins - 1);
    }

    Split findSplit(const PrimRef* prims, std::uint32_t count, const FloatBox& centres) const {
        const int bins = binsFor(count);
        Split best;
        Bin binArray[3][kMaxBins];
        float lo[3], scale[3];
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = centres.lo[axis];
            scale[axis] = binScale(centres, axis, bins);
            const FloatBox empty;
            for (int i = 0; i < bins; ++i) {
                Bin& b = binArray[axis][i];
                for (int k = 0; k < 3; ++k) {
                    b.lo[k] = empty.lo[k];
                    b.hi[k] = empty.hi[k];
                }
                b.count = 0;
            }
        }
        for (std::uint32_t i = 0; i < count; ++i) {
            const PrimRef& p = prims[i];
            for (int axis = 0; axis < 3; ++axis) {
                Bin& bin = binArray[axis][binOf(p.centre(axis), lo[axis], scale[axis], bins)];
                for (int k = 0; k < 3; ++k) {
                    bin.lo[k] = std::min(bin.lo[k], p.lo[k]);
                    bin.hi[k] = std::max(bin.hi[k], p.hi[k]);
                }
                ++bin.count;
            }
        }
        double rightArea[kMaxBins];
        std::uint32_t rightCount[kMaxBins];
        for (int axis = 0; axis < 3; ++axis) {
            if (scale[axis] == 0.0f) continue;
            const Bin* b = binArray[axis];
            FloatBox acc;
            std::uint32_t n = 0;
            for (int i = bins - 1; i > 0; --i) {
                acc.extend(b[i].lo, b[i].hi);
                n += b[i].count;
                rightArea[i] = acc.area();
                rightCount[i] = n;
            }
            FloatBox leftAcc;
            std::uint32_t leftN = 0;
            for (int i = 1; i < bins; ++i) {
                leftAcc.extend(b[i - 1].lo, b[i - 1].hi);
                leftN += b[i - 1].count;
                if (leftN == 0 || rightCount[i] == 0) continue;
                const double cost = leftAcc.area() * leftN + rightArea[i] * rightCount[i];
                if (!best.found || cost < best.cost) {
                    best = {true, axis, i, cost};
                }
            }
        }
        return best;
    }

    std::vector<PrimRef>& prims_;
    const BvhBuildOptions& options_;
    std::vector<BinaryNode> nodes_;
    std::atomic<std::uint32_t> next_{0};
};

}  // namespace bvh_build

using bvh_build::BinaryBuilder;
using bvh_build::BinaryNode;
using bvh_build::PrimRef;
using bvh_detail::roundDownToFloat;
using bvh_detail::roundUpToFloat;

// Collapses the binary tree into four-wide nodes, depth first.
struct BvhBuilder {
    const BinaryBuilder& binary;
    Bvh& bvh;

    std::uint32_t leafRef(const BinaryNode& n) const {
        return bvh_detail::kLeafBit | (n.count << bvh_detail::kCountShift) | n.first;
    }

    std::uint32_t emit(std::uint32_t id, int depth) {
        bvh.depth_ = std::max(bvh.depth_, depth);
        // Open the largest inner child until there are four children.
        std::uint32_t children[4] = {binary.node(id).left, binary.node(id).right, 0, 0};
        int count = 2;
        while (count < 4) {
            int widest = -1;
            double widestArea = -1.0;
            for (int k = 0; k < count; ++k) {
                const BinaryNode& c = binary.node(children[k]);
                if (c.count == 0 && c.box.area() > widestArea) {
                    widest = k;
                    widestArea = c.box.area();
                }
            }
            if (widest < 0) break;
            const BinaryNode& opened = binary.node(children[widest]);
            children[widest] = opened.left;
            children[count++] = opened.right;
        }
        const auto index = static_cast<std::uint32_t>(bvh.nodes_.size());
        bvh.nodes_.emplace_back();
        std::uint32_t refs[4];
        for (int k = 0; k < 4; ++k) {
            if (k >= count) {
                refs[k] = bvh_detail::kEmptyLeaf;
                continue;
            }
            const BinaryNode& c = binary.node(children[k]);
            refs[k] = c.count > 0 ? leafRef(c) : emit(children[k], depth + 1);
        }
        bvh_detail::Node& node = bvh.nodes_[index];
        const float inf = std::numeric_limits<float>::infinity();
        for (int k = 0; k < 4; ++k) {
            node.child[k] = refs[k];
            for (int axis = 0; axis < 3; ++axis) {
                node.box[0][axis][k] = k < count ? binary.node(children[k]).box.lo[axis] : inf;
                node.box[1][axis][k] = k < count ? binary.node(children[k]).box.hi[axis] : -inf;
            }
        }
        return index;
    }
};

Bvh Bvh::build(std::span<const Bounds3> itemBounds, const BvhBuildOptions& options) {
    if (options.maxLeafSize < 1 || options.maxLeafSize > 15)
        throw std::invalid_argument("BVH: maxLeafSize must be in 1..15");
    if (options.binCount < 2 || options.binCount > 256)
        throw std::invalid_argument("BVH: binCount must be in 2..256");
    if (!(options.traversalCost >= 0.0) || !std::isfinite(options.traversalCost))
        throw std::invalid_argument("BVH: traversalCost must be finite and >= 0");
    if (itemBounds.size() > bvh_detail::kFirstMask)
        throw std::length_error("BVH: more than 2^27 - 1 items");

    Bvh bvh;
    std::vector<PrimRef> prims;
    prims.reserve(itemBounds.size());
    for (std::size_t i = 0; i < itemBounds.size(); ++i) {
        const Bounds3& b = itemBounds[i];
        const auto bad = [&](auto test) {
            return test(b.lo.x) || test(b.lo.y) || test(b.lo.z) || test(b.hi.x) ||
                   test(b.hi.y) || test(b.hi.z);
        };
        if (bad([](double x) { return std::isnan(x); }))
            throw std::invalid_argument("BVH: item " + std::to_string(i) + " has NaN bounds");
        if (b.empty()) continue;  // (the default Bounds3 is empty: +inf/-inf)
        if (bad([](double x) { return std::isinf(x); }))
            throw std::invalid_argument("BVH: item " + std::to_string(i) +
                                        " has infinite bounds (unbounded items stay outside the BVH)");
        PrimRef p;
        for (int axis = 0; axis < 3; ++axis) {
            p.lo[axis] = roundDownToFloat(b.lo[axis]);
            p.hi[axis] = roundUpToFloat(b.hi[axis]);
        }
        p.index = static_cast<std::uint32_t>(i);
        prims.push_back(p);
        bvh.bounds_.extend(b);
    }
    if (prims.empty()) return bvh;

    BinaryBuilder binary(prims, options);
    const std::uint32_t root = binary.build();
    BvhBuilder collapse{binary, bvh};
    const BinaryNode& r = binary.node(root);
    if (r.count > 0) {
        // A single leaf: a root node with one child.
        bvh.nodes_.emplace_back();
        bvh_detail::Node& node = bvh.nodes_[0];
        const float inf = std::numeric_limits<float>::infinity();
        for (int k = 0; k < 4; ++k) {
            node.child[k] = k == 0 ? collapse.leafRef(r) : bvh_detail::kEmptyLeaf;
            for (int axis = 0; axis < 3; ++axis) {
                node.box[0][axis][k] = k == 0 ? r.box.lo[axis] : inf;
                node.box[1][axis][k] = k == 0 ? r.box.hi[axis] : -inf;
            }
        }
        bvh.depth_ = 1;
    } else {
        bvh.nodes_.reserve(prims.size() / 2 + 1);
        collapse.emit(root, 1);
    }
    bvh.order_.resize(prims.size());
    for (std::size_t i = 0; i < prims.size(); ++i) bvh.order_[i] = prims[i].index;
    return bvh;
}

}  // namespace asos
