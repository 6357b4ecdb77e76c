#pragma once
// A bounding volume hierarchy over the scene's bounded objects (paper:
// "Detection Phase" needs, for a pyray's cone, the objects it may meet; the
// classic methods need nearest and any hits). Built by the binned surface area
// heuristic into a binary tree, then collapsed into four-wide nodes whose
// child boxes are floats rounded outward, so every box still holds what it
// bounds. Layout, build and the robustness argument: docs/accel.md.
//
// The tree knows items only by index and bounds; the caller supplies the
// per-item tests as callables, which the traversals (templates here) inline.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "asos/accel/cone_box.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"

namespace asos {

struct BvhBuildOptions {
    int maxLeafSize = 4;         // items per leaf, 1..15
    double traversalCost = 1.0;  // SAH cost of visiting a node, in item tests
    int binCount = 32;           // SAH bins per axis, 2..256
};

namespace bvh_detail {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

// Four children's boxes, structure of arrays: box[side][axis][child], side 0
// the low corner and 1 the high one. An unused slot has lo = +inf, hi = -inf.
struct alignas(64) Node {
    Float4 box[2][3];
    std::uint32_t child[4];
};

// A child reference: a node index, or (top bit set) a leaf holding `count`
// items from slot `first` of the item order.
inline constexpr std::uint32_t kLeafBit = 0x80000000u;
inline constexpr int kCountShift = 27;
inline constexpr std::uint32_t kFirstMask = (1u << kCountShift) - 1;
inline constexpr std::uint32_t kEmptyLeaf = kLeafBit;  // a leaf of no items

inline bool isLeaf(std::uint32_t ref) { return (ref & kLeafBit) != 0; }
inline std::uint32_t leafFirst(std::uint32_t ref) { return ref & kFirstMask; }
inline std::uint32_t leafCount(std::uint32_t ref) { return (ref >> kCountShift) & 15u; }

// The float after and before f; x rounded up and down to a float.
inline float nextFloatUp(float f) {
    if (std::isnan(f) || f == std::numeric_limits<float>::infinity()) return f;
    if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
    std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
    bits = f > 0.0f ? bits + 1 : bits - 1;
    return std::bit_cast<float>(bits);
}
inline float nextFloatDown(float f) { return -nextFloatUp(-f); }
inline float roundUpToFloat(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? nextFloatUp(f) : f;
}
inline float roundDownToFloat(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? nextFloatDown(f) : f;
}
// roundUpToFloat for the far limits of a search (x >= 0, or +inf): the float
// after a finite f >= 0 is the next bit pattern, so no special cases.
inline float roundUpToFloatNonNegative(double x) {
    if (!(x >= 0.0)) [[unlikely]] return roundUpToFloat(x);
    const float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) return std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) + 1);
    return f;
}

// The float slab test is made conservative for a double ray (docs/accel.md):
// the origin is moved a few float ulps toward the far side of each plane it is
// compared with (oNear, oFar), the t-range is rounded outward, and far
// distances are scaled up by kFarScale (folded into invFar), which exceeds the
// worst relative error of the float roundings in (plane - origin) * inverse.
inline constexpr double kFarScale = 1.0 + 0x1p-20;
// The least shift of a ray's origin (an origin coordinate of 0 still moves):
// a float far above the smallest normal one, far below any scene's sizes.
inline constexpr double kOriginShiftFloor = 1e-30;
// A direction component below this in magnitude drops its axis's constraint
// (RayPrep) or sends its ray through the single-ray loop (traversePacket):
// its inverse is out of the float test's range.
inline constexpr double kParallelComponent = 1e-30;

struct RayPrep {
    Float4 oNear[3];
    Float4 oFar[3];
    Float4 invNear[3];
    Float4 invFar[3];
    int nearSide[3];  // 0: the low plane is entered first (direction >= 0)
    Float4 tMin;
    Float4 tMax;      // scaled by kFarScale, like the far distances

    RayPrep(const Ray& ray, double tMinD, double tMaxD) {
        constexpr float inf = std::numeric_limits<float>::infinity();
        for (int i = 0; i < 3; ++i) {
            const double d = ray.dir[i];
            const double o = ray.origin[i];
            // Strictly beyond o on either side, after rounding to float.
            const double shift = std::abs(o) * 0x1p-22 + kOriginShiftFloor;
            const auto above = static_cast<float>(o + shift), below = static_cast<float>(o - shift);
            float nearInv, farInv, oN, oF;
            int side = std::signbit(d) ? 1 : 0;
            if (std::abs(d) >= kParallelComponent) [[likely]] {
                // One division: kFarScale * (1 / d) in double is within
                // 2^-52 of kFarScale / d, far below the margin kFarScale leaves.
                const double inv = 1.0 / d;
                nearInv = static_cast<float>(inv);
                farInv = static_cast<float>(kFarScale * inv);
                oN = side ? below : above;
                oF = side ? above : below;
            } else if (d == 0.0) {
                // Parallel: an infinite inverse gives -inf or +inf per plane;
                // 0 * inf (NaN) can only occur for a plane strictly outside,
                // where either answer is right.
                nearInv = farInv = side ? -inf : inf;
                oN = side ? below : above;
                oF = side ? above : below;
            } else {
                // 1/d overflows a float (or d is NaN): drop this axis's
                // constraint (conservative; a unit direction has another,
                // larger component that still culls).
                side = 0;
                nearInv = farInv = inf;
                oN = inf;
                oF = -inf;
            }
            nearSide[i] = side;
            oNear[i] = Float4{oN, oN, oN, oN};
            oFar[i] = Float4{oF, oF, oF, oF};
            invNear[i] = Float4{nearInv, nearInv, nearInv, nearInv};
            invFar[i] = Float4{farInv, farInv, farInv, farInv};
        }
        setRange(tMinD, tMaxD);
    }

    void setRange(double tMinD, double tMaxD) {
        const float lo = roundDownToFloat(tMinD > 0.0 ? tMinD : 0.0);
        const float hi = roundUpToFloat(tMaxD * kFarScale);
        tMin = Float4{lo, lo, lo, lo};
        tMax = Float4{hi, hi, hi, hi};
    }
};

inline unsigned moveMask(Int4 m) {
#if defined(__SSE__)
    using M128 = float __attribute__((vector_size(16)));
    return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<M128>(m)));
#else
    return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u);
#endif
}

inline Float4 sqrt4(Float4 x) {
#if defined(__SSE__)
    return __builtin_ia32_sqrtps(x);
#else
    return Float4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}

// A float prefilter of the cone traversal: the bounding sphere of each of a
// node's four child boxes against the cone, with ConeBoxTest's exact distance
// (test 4 in src/accel/cone_box.cpp) computed in float for the four at once,
// and a slack of 2^-12 times the magnitude of the coordinates involved, far
// above float rounding (a few dozen roundings of relative size 2^-24 in
// values bounded by that magnitude). A box it drops has no point in the cone;
// the boxes it keeps go on to the exact double test. Used only where the
// coordinates are below 1e15 (no float overflow in the squares).
struct ConePrefilter {
    Float4 apex[3], axis[3];
    Float4 cosHalf, sinHalf, tMin, tMax, apexScale;

    explicit ConePrefilter(const Cone& c) {
        const Vec3 w = glm::normalize(c.axis);
        for (int i = 0; i < 3; ++i) {
            const float a = static_cast<float>(c.apex[i]), d = static_cast<float>(w[i]);
            apex[i] = Float4{a, a, a, a};
            axis[i] = Float4{d, d, d, d};
        }
        const auto splat = [](double x) {
            const float f = static_cast<float>(x);
            return Float4{f, f, f, f};
        };
        cosHalf = splat(std::cos(c.halfAngle));
        sinHalf = splat(std::sin(c.halfAngle));
        tMin = splat(std::max(c.tMin, 0.0));
        tMax = splat(c.tMax);
        apexScale = splat(maxNorm(c.apex));
    }
    void setTMax(double t) {
        const float f = static_cast<float>(t);
        tMax = Float4{f, f, f, f};
    }

    // Bit k set unless child k's bounding sphere is certainly outside the cone.
    unsigned keep(const Node& node) const {
        const Float4 zero = {0, 0, 0, 0};
        const auto abs4 = [&](Float4 x) { return x < zero ? -x : x; };
        const auto max4 = [](Float4 x, Float4 y) { return x > y ? x : y; };
        Float4 v[3], e[3];
        Float4 centreScale = zero;
        for (int i = 0; i < 3; ++i) {
            const Float4 c = 0.5f * (node.box[0][i] + node.box[1][i]);
            e[i] = 0.5f * (node.box[1][i] - node.box[0][i]);
            v[i] = c - apex[i];
            centreScale = max4(centreScale, abs4(c));
        }
        const Float4 radius = sqrt4(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        const Float4 p = v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2];
        const Float4 x = v[1] * axis[2] - v[2] * axis[1];
        const Float4 y = v[2] * axis[0] - v[0] * axis[2];
        const Float4 z = v[0] * axis[1] - v[1] * axis[0];
        const Float4 q = sqrt4(x * x + y * y + z * z);
        const Float4 d = sqrt4(p * p + q * q);
        // Within the angular range: the radial distance to [tMin, tMax].
        const Float4 radial = max4(zero, max4(tMin - d, d - tMax));
        // Outside it: the distance to the boundary ray's segment.
        const Float4 s = p * cosHalf + q * sinHalf;
        const Float4 h = q * cosHalf - p * sinHalf;
        const Float4 clamped = s < tMin ? tMin : (s > tMax ? tMax : s);
        const Float4 along = s - clamped;
        const Float4 outside = sqrt4(h * h + along * along);
        const Float4 distance = p >= d * cosHalf ? radial : outside;
        const Float4 slack = (apexScale + centreScale + radius) * 0x1p-12f;
        return moveMask(distance <= radius + slack);
    }
};

struct StackEntry {
    std::uint32_t ref;
    float tNear;
};

// Orders stack[base, top) by tNear, farthest first, so that the pops come
// near first (an insertion sort: at most four entries).
template <class Entry>
inline void sortFarthestFirst(Entry* stack, int base, int top) {
    for (int i = base + 1; i < top; ++i) {
        const Entry e = stack[i];
        int j = i;
        while (j > base && stack[j - 1].tNear < e.tNear) {
            stack[j] = stack[j - 1];
            --j;
        }
        stack[j] = e;
    }
}

// Depth is bounded by the build (median splits past a depth limit), so a
// fixed stack suffices: at most three entries pushed per level.
inline constexpr int kMaxDepth = 96;
inline constexpr int kStackSize = 3 * kMaxDepth + 4;

// Packets of rays (Bvh::traversePacket; docs/accel.md, "Packet traversal"):
// up to kPacketSize rays of one direction octant, one lane each, in groups of
// four lanes. A lane holds a ray's set-up exactly as RayPrep has it. Lanes
// from `count` to the next multiple of four copy lane 0's origin and
// inverses (so that bounds over all lanes are bounds over the rays) with an
// empty t-range, so no box accepts them.
inline constexpr int kPacketSize = 64;
inline constexpr int kPacketGroups = kPacketSize / 4;

struct PacketPrep {
    Float4 oNear[3][kPacketGroups];
    Float4 oFar[3][kPacketGroups];
    Float4 invNear[3][kPacketGroups];
    Float4 invFar[3][kPacketGroups];
    Float4 tLo[kPacketGroups];
    Float4 tHi[kPacketGroups];  // scaled by kFarScale, like RayPrep::tMax
    std::uint32_t ray[kPacketSize];  // the caller's index of each lane's ray
    int count = 0;
};

// A lane's far limit: as the single-ray loop's, except that a NaN limit
// returned by a leaf (after which a lone ray pops nothing more) becomes -inf,
// which accepts nothing either and leaves the packet's greatest limit to the
// other lanes. (A ray whose search starts with a NaN limit goes alone.)
inline float laneFarLimit(double tMax) {
    const float f = roundUpToFloatNonNegative(tMax * kFarScale);
    return f == f ? f : -std::numeric_limits<float>::infinity();
}

// A box's planes as the lanes of one octant meet them: along axis a, the
// plane entered first and the plane left last.
struct PacketBox {
    float nearPlane[3];
    float farPlane[3];
};

// Bit l set for each lane l whose own box test (RayPrep's arithmetic, as
// traverseOctant does it, four lanes at once) accepts the box. (Eight or
// sixteen lanes at once with AVX2 or AVX-512, dispatched at run time, were no
// faster: docs/accel.md.)
inline std::uint64_t packetLanesHit(const PacketPrep& p, const PacketBox& b) {
    const int groups = (p.count + 3) / 4;
    const auto splat = [](float f) { return Float4{f, f, f, f}; };
    const auto min4 = [](Float4 x, Float4 y) { return x < y ? x : y; };
    const auto max4 = [](Float4 x, Float4 y) { return x > y ? x : y; };
    const Float4 near0 = splat(b.nearPlane[0]), far0 = splat(b.farPlane[0]);
    const Float4 near1 = splat(b.nearPlane[1]), far1 = splat(b.farPlane[1]);
    const Float4 near2 = splat(b.nearPlane[2]), far2 = splat(b.farPlane[2]);
    std::uint64_t mask = 0;
    for (int g = 0; g < groups; ++g) {
        const Float4 n0 = (near0 - p.oNear[0][g]) * p.invNear[0][g];
        const Float4 n1 = (near1 - p.oNear[1][g]) * p.invNear[1][g];
        const Float4 n2 = (near2 - p.oNear[2][g]) * p.invNear[2][g];
        const Float4 f0 = (far0 - p.oFar[0][g]) * p.invFar[0][g];
        const Float4 f1 = (far1 - p.oFar[1][g]) * p.invFar[1][g];
        const Float4 f2 = (far2 - p.oFar[2][g]) * p.invFar[2][g];
        const Float4 lo = max4(max4(n0, p.tLo[g]), max4(n1, n2));
        const Float4 hi = min4(min4(f0, p.tHi[g]), min4(f1, f2));
        mask |= static_cast<std::uint64_t>(moveMask(lo <= hi)) << (4 * g);
    }
    return mask;
}

struct PacketStackEntry {
    std::uint32_t ref;
    float tNear;
    std::uint32_t box;  // parent node * 4 + child slot: where the child's box is
};

template <class F, class... Args>
using ResultOf = std::invoke_result_t<F&, Args...>;

}  // namespace bvh_detail

class Bvh {
public:
    Bvh() = default;

    // Builds over the items' bounds (item i has bounds itemBounds[i]). Items
    // with empty bounds are left out: no ray or cone can touch them. Throws
    // std::invalid_argument on NaN or infinite bounds or bad options, and
    // std::length_error past 2^27 - 1 items.
    static Bvh build(std::span<const Bounds3> itemBounds, const BvhBuildOptions& options = {});

    bool empty() const { return nodes_.empty(); }
    std::size_t itemCount() const { return order_.size(); }
    std::size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }
    const Bounds3& bounds() const { return bounds_; }
    // The items in leaf order (a caller may lay out its data this way).
    std::span<const std::uint32_t> itemOrder() const { return order_; }

    // The nearest hit in [tMin, tMax] (0 <= tMin). The callable
    //   f(std::uint32_t item, const Ray& ray, double tMin, double tMax) -> std::optional<H>
    // returns the item's nearest hit in the range, where H has a member `t`;
    // the range it is given shrinks as nearer hits are found.
    template <class Intersect>
    auto nearest(const Ray& ray, double tMin, double tMax, Intersect&& f) const
        -> bvh_detail::ResultOf<Intersect, std::uint32_t, const Ray&, double, double>;

    // Whether some item is hit in [tMin, tMax] (0 <= tMin), stopping at the
    // first: f(std::uint32_t item, const Ray& ray, double tMin, double tMax) -> bool.
    template <class Test>
    bool any(const Ray& ray, double tMin, double tMax, Test&& f) const;

    // Visits every item in a leaf whose box the cone may touch (a superset of
    // the items whose bounds it touches: ConeBoxTest), boxes nearer the apex
    // first. f(std::uint32_t item) may return
    //   void:   visit all;
    //   bool:   false stops the traversal;
    //   double: a new far limit for the cone (e.g. the far depth of an item
    //           that blocks the whole cone): boxes wholly beyond it are skipped.
    template <class Visit>
    void cone(const Cone& cone, Visit&& f) const;

    // The ray traversal under nearest and any, for a caller that keeps its
    // item data in leaf order (itemOrder()): leaf(first, count) tests the
    // items in leaf slots [first, first + count) and returns the far limit of
    // the search from then on (the current one, or nearer), or a negative
    // number to stop. Ordered: children nearest first, as a nearest-hit
    // search wants; an any-hit search does not need the order.
    template <bool Ordered, class Leaf>
    void traverse(const Ray& ray, double tMin, double tMax, Leaf&& leaf) const;

    // The traversal of `traverse<true>` for many rays at once, for a caller
    // whose rays are coherent (pixel tiles of a pinhole camera). Ray i is
    // searched over [tMin, tMax[i]] (0 <= tMin); leaf(i, first, count) tests
    // the items in leaf slots [first, first + count) for ray i and returns
    // its far limit from then on (the current one, or nearer). Every leaf
    // whose box ray i's own traversal would accept at its current far limit
    // is handed to ray i (possibly with others, in another order), so a
    // nearest-hit search whose answer does not depend on the order of its
    // item tests gives each ray the answer of traverse<true>. Rays are taken
    // kPacketSize at a time and grouped by direction octant; a ray with a
    // direction component below kParallelComponent in magnitude, or a
    // far-off origin, is traversed alone.
    template <class Leaf>
    void traversePacket(std::span<const Ray> rays, double tMin, std::span<const double> tMax,
                        Leaf&& leaf) const;

private:
    friend struct BvhBuilder;
    // The traversal for one octant of ray directions (SX, SY, SZ: 1 where the
    // direction's component is negative), so that which plane of a box is
    // entered first is known at compile time.
    template <int SX, int SY, int SZ, bool Ordered, class Leaf>
    void traverseOctant(const bvh_detail::RayPrep& prep, Leaf& leaf) const;

    // The packet traversal for one octant (all lanes' directions in it).
    template <int SX, int SY, int SZ, class Leaf>
    void traversePacketOctant(bvh_detail::PacketPrep& packet, Leaf& leaf) const;

    std::vector<bvh_detail::Node> nodes_;  // nodes_[0] is the root
    std::vector<std::uint32_t> order_;     // item index per leaf slot
    Bounds3 bounds_;
    int depth_ = 0;
};

template <bool Ordered, class Leaf>
void Bvh::traverse(const Ray& ray, double tMin, double tMax, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    const bvh_detail::RayPrep prep(ray, tMin, tMax);
    switch (prep.nearSide[0] | prep.nearSide[1] << 1 | prep.nearSide[2] << 2) {
    case 0: traverseOctant<0, 0, 0, Ordered>(prep, leaf); break;
    case 1: traverseOctant<1, 0, 0, Ordered>(prep, leaf); break;
    case 2: traverseOctant<0, 1, 0, Ordered>(prep, leaf); break;
    case 3: traverseOctant<1, 1, 0, Ordered>(prep, leaf); break;
    case 4: traverseOctant<0, 0, 1, Ordered>(prep, leaf); break;
    case 5: traverseOctant<1, 0, 1, Ordered>(prep, leaf); break;
    case 6: traverseOctant<0, 1, 1, Ordered>(prep, leaf); break;
    default: traverseOctant<1, 1, 1, Ordered>(prep, leaf); break;
    }
}

template <int SX, int SY, int SZ, bool Ordered, class Leaf>
__attribute__((always_inline)) inline void Bvh::traverseOctant(const bvh_detail::RayPrep& prep, Leaf& leaf) const {
    using namespace bvh_detail;
    // Locals, so that the loop keeps them in registers.
    const Float4 oNear0 = prep.oNear[0], oNear1 = prep.oNear[1], oNear2 = prep.oNear[2];
    const Float4 oFar0 = prep.oFar[0], oFar1 = prep.oFar[1], oFar2 = prep.oFar[2];
    const Float4 nInv0 = prep.invNear[0], nInv1 = prep.invNear[1], nInv2 = prep.invNear[2];
    const Float4 fInv0 = prep.invFar[0], fInv1 = prep.invFar[1], fInv2 = prep.invFar[2];
    const Float4 tLo = prep.tMin;
    Float4 tHi = prep.tMax;
    float farLimit = tHi[0];
    const Node* const nodes = nodes_.data();

    StackEntry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;
    for (;;) {
        while (!isLeaf(ref)) {
            const Node& node = nodes[ref];
            const Float4 n0 = (node.box[SX][0] - oNear0) * nInv0;
            const Float4 n1 = (node.box[SY][1] - oNear1) * nInv1;
            const Float4 n2 = (node.box[SZ][2] - oNear2) * nInv2;
            const Float4 f0 = (node.box[1 - SX][0] - oFar0) * fInv0;
            const Float4 f1 = (node.box[1 - SY][1] - oFar1) * fInv1;
            const Float4 f2 = (node.box[1 - SZ][2] - oFar2) * fInv2;
            const Float4 a = n0 > tLo ? n0 : tLo, b = n2 > n1 ? n2 : n1;
            const Float4 lo = a > b ? a : b;
            const Float4 c = f0 < tHi ? f0 : tHi, d = f2 < f1 ? f2 : f1;
            const Float4 hi = c < d ? c : d;
            unsigned mask = moveMask(lo <= hi);
            if (mask == 0) goto pop;
            {
                const int first = std::countr_zero(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    ref = node.child[first];
                    continue;
                }
                const int second = std::countr_zero(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    // Two children, the common case: nearer one next.
                    const bool swap = Ordered && lo[second] < lo[first];
                    const int nearK = swap ? second : first, farK = swap ? first : second;
                    stack[top++] = {node.child[farK], lo[farK]};
                    ref = node.child[nearK];
                    continue;
                }
                // Three or four: push all, sort the pushed entries farthest first.
                const int base = top;
                stack[top++] = {node.child[first], lo[first]};
                stack[top++] = {node.child[second], lo[second]};
                while (mask != 0) {
                    const int k = std::countr_zero(mask);
                    mask &= mask - 1;
                    stack[top++] = {node.child[k], lo[k]};
                }
                if constexpr (Ordered) sortFarthestFirst(stack, base, top);
                ref = stack[--top].ref;
            }
        }
        {
            const double next = leaf(leafFirst(ref), leafCount(ref));
            if (next < 0.0) return;
            const float hiF = roundUpToFloatNonNegative(next * kFarScale);
            tHi = Float4{hiF, hiF, hiF, hiF};
            farLimit = hiF;
        }
    pop:
        for (;;) {
            if (top == 0) return;
            const StackEntry& e = stack[--top];
            if (e.tNear <= farLimit) {
                ref = e.ref;
                break;
            }
        }
    }
}

template <class Leaf>
void Bvh::traversePacket(std::span<const Ray> rays, double tMin, std::span<const double> tMax,
                         Leaf&& leaf) const {
    using namespace bvh_detail;
    if (nodes_.empty()) return;
    constexpr float kMaxFloat = std::numeric_limits<float>::max();
    const float tLo = roundDownToFloat(tMin > 0.0 ? tMin : 0.0);
    // `all` holds the chunk's rays in order, one lane each; when they do not
    // share one octant, `part` gathers each octant's lanes in turn.
    PacketPrep all, part;
    const auto run = [&](PacketPrep& packet, int octant) {
        const int count = packet.count;
        for (int lane = count; lane % 4 != 0; ++lane) {
            const int g = lane / 4, l = lane % 4;
            for (int a = 0; a < 3; ++a) {
                packet.oNear[a][g][l] = packet.oNear[a][0][0];
                packet.oFar[a][g][l] = packet.oFar[a][0][0];
                packet.invNear[a][g][l] = packet.invNear[a][0][0];
                packet.invFar[a][g][l] = packet.invFar[a][0][0];
            }
            packet.tLo[g][l] = std::numeric_limits<float>::infinity();
            packet.tHi[g][l] = -std::numeric_limits<float>::infinity();
        }
        switch (octant) {
        case 0: traversePacketOctant<0, 0, 0>(packet, leaf); break;
        case 1: traversePacketOctant<1, 0, 0>(packet, leaf); break;
        case 2: traversePacketOctant<0, 1, 0>(packet, leaf); break;
        case 3: traversePacketOctant<1, 1, 0>(packet, leaf); break;
        case 4: traversePacketOctant<0, 0, 1>(packet, leaf); break;
        case 5: traversePacketOctant<1, 0, 1>(packet, leaf); break;
        case 6: traversePacketOctant<0, 1, 1>(packet, leaf); break;
        default: traversePacketOctant<1, 1, 1>(packet, leaf); break;
        }
    };
    for (std::size_t start = 0; start < rays.size(); start += kPacketSize) {
        const int n = static_cast<int>(std::min<std::size_t>(kPacketSize, rays.size() - start));
        std::int8_t octant[kPacketSize];
        unsigned present = 0;
        bool anyAlone = false;
        for (int i = 0; i < n; ++i) {
            // RayPrep's values for a component of at least
            // kParallelComponent, written straight into the lanes (a returned
            // struct would be assembled and reloaded through memory).
            const Ray& ray = rays[start + i];
            const int g = i / 4, l = i % 4;
            bool alone = false;
            int oct = 0;
            for (int a = 0; a < 3; ++a) {
                const double d = ray.dir[a], o = ray.origin[a];
                const double shift = std::abs(o) * 0x1p-22 + kOriginShiftFloor;
                const auto above = static_cast<float>(o + shift), below = static_cast<float>(o - shift);
                const bool negative = std::signbit(d);
                const double inv = 1.0 / d;
                const auto nearInv = static_cast<float>(inv), farInv = static_cast<float>(kFarScale * inv);
                all.oNear[a][g][l] = negative ? below : above;
                all.oFar[a][g][l] = negative ? above : below;
                all.invNear[a][g][l] = nearInv;
                all.invFar[a][g][l] = farInv;
                // The interval bounds need finite origins and finite,
                // non-zero inverses; RayPrep's special cases go alone.
                alone = alone || !(std::abs(d) >= kParallelComponent) ||
                        !(std::abs(above) <= kMaxFloat) || !(std::abs(below) <= kMaxFloat) ||
                        nearInv == 0.0f || farInv == 0.0f || !(std::abs(farInv) <= kMaxFloat);
                oct |= static_cast<int>(negative) << a;
            }
            const auto index = static_cast<std::uint32_t>(start + i);
            alone = alone || std::isnan(tMax[index]);
            all.ray[i] = index;
            all.tLo[g][l] = tLo;
            all.tHi[g][l] = laneFarLimit(tMax[index]);
            octant[i] = static_cast<std::int8_t>(alone ? -1 : oct);
            anyAlone = anyAlone || alone;
            if (!alone) present |= 1u << oct;
        }
        if (!anyAlone && std::has_single_bit(present)) {
            // One octant, no ray alone: the common case of a pixel tile.
            all.count = n;
            run(all, std::countr_zero(present));
            continue;
        }
        for (int i = 0; i < n; ++i) {
            if (octant[i] >= 0) continue;
            const auto index = static_cast<std::uint32_t>(start + i);
            traverse<true>(rays[index], tMin, tMax[index], [&](std::uint32_t first, std::uint32_t count) {
                return leaf(index, first, count);
            });
        }
        while (present != 0) {
            const int o = std::countr_zero(present);
            present &= present - 1;
            int lanes = 0;
            for (int i = 0; i < n; ++i) {
                if (octant[i] != o) continue;
                const int g = i / 4, l = i % 4, pg = lanes / 4, pl = lanes % 4;
                for (int a = 0; a < 3; ++a) {
                    part.oNear[a][pg][pl] = all.oNear[a][g][l];
                    part.oFar[a][pg][pl] = all.oFar[a][g][l];
                    part.invNear[a][pg][pl] = all.invNear[a][g][l];
                    part.invFar[a][pg][pl] = all.invFar[a][g][l];
                }
                part.tLo[pg][pl] = all.tLo[g][l];
                part.tHi[pg][pl] = all.tHi[g][l];
                part.ray[lanes] = all.ray[i];
                ++lanes;
            }
            part.count = lanes;
            run(part, o);
        }
    }
}

template <int SX, int SY, int SZ, class Leaf>
void Bvh::traversePacketOctant(bvh_detail::PacketPrep& packet, Leaf& leaf) const {
    using namespace bvh_detail;
    const int groups = (packet.count + 3) / 4;
    const auto splat = [](float f) { return Float4{f, f, f, f}; };
    const auto min4 = [](Float4 a, Float4 b) { return a < b ? a : b; };
    const auto max4 = [](Float4 a, Float4 b) { return a > b ? a : b; };
    const auto hmin = [](Float4 v) { return std::min(std::min(v[0], v[1]), std::min(v[2], v[3])); };
    const auto hmax = [](Float4 v) { return std::max(std::max(v[0], v[1]), std::max(v[2], v[3])); };

    // Bounds over the packet (docs/accel.md): for axis a, every lane's entry
    // distance (plane - oNear) * invNear is at least the least of the
    // products of the extreme origin on the entry side with the two extreme
    // inverses, and its exit distance at most the greatest such product on
    // the exit side (float subtraction and multiplication are monotonic).
    Float4 entryOrigin[3], exitOrigin[3], nearInvA[3], nearInvB[3], farInvA[3], farInvB[3];
    const int sides[3] = {SX, SY, SZ};
    Float4 tLoMin = packet.tLo[0], tHiMax = packet.tHi[0];
    for (int g = 1; g < groups; ++g) {
        tLoMin = min4(tLoMin, packet.tLo[g]);
        tHiMax = max4(tHiMax, packet.tHi[g]);
    }
    for (int a = 0; a < 3; ++a) {
        Float4 oNearLo = packet.oNear[a][0], oNearHi = oNearLo;
        Float4 oFarLo = packet.oFar[a][0], oFarHi = oFarLo;
        Float4 nLo = packet.invNear[a][0], nHi = nLo, fLo = packet.invFar[a][0], fHi = fLo;
        for (int g = 1; g < groups; ++g) {
            oNearLo = min4(oNearLo, packet.oNear[a][g]);
            oNearHi = max4(oNearHi, packet.oNear[a][g]);
            oFarLo = min4(oFarLo, packet.oFar[a][g]);
            oFarHi = max4(oFarHi, packet.oFar[a][g]);
            nLo = min4(nLo, packet.invNear[a][g]);
            nHi = max4(nHi, packet.invNear[a][g]);
            fLo = min4(fLo, packet.invFar[a][g]);
            fHi = max4(fHi, packet.invFar[a][g]);
        }
        // Positive direction: the entry distance grows with the plane minus
        // the origin, so its least value has the greatest origin; negative:
        // the least origin. The exit distance the other way round.
        entryOrigin[a] = splat(sides[a] ? hmin(oNearLo) : hmax(oNearHi));
        exitOrigin[a] = splat(sides[a] ? hmax(oFarHi) : hmin(oFarLo));
        nearInvA[a] = splat(hmin(nLo));
        nearInvB[a] = splat(hmax(nHi));
        farInvA[a] = splat(hmin(fLo));
        farInvB[a] = splat(hmax(fHi));
    }
    const Float4 tLo = splat(hmin(tLoMin));
    float farLimit = hmax(tHiMax);
    Float4 tHi = splat(farLimit);
    const Node* const nodes = nodes_.data();

    PacketStackEntry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0, box = 0;
    for (;;) {
        while (!isLeaf(ref)) {
            const Node& node = nodes[ref];
            const std::uint32_t at = ref * 4;
            const auto entry = [&](int a, const Float4& plane) {
                const Float4 d = plane - entryOrigin[a];
                return min4(d * nearInvA[a], d * nearInvB[a]);
            };
            const auto exit = [&](int a, const Float4& plane) {
                const Float4 d = plane - exitOrigin[a];
                return max4(d * farInvA[a], d * farInvB[a]);
            };
            const Float4 n0 = entry(0, node.box[SX][0]);
            const Float4 n1 = entry(1, node.box[SY][1]);
            const Float4 n2 = entry(2, node.box[SZ][2]);
            const Float4 f0 = exit(0, node.box[1 - SX][0]);
            const Float4 f1 = exit(1, node.box[1 - SY][1]);
            const Float4 f2 = exit(2, node.box[1 - SZ][2]);
            const Float4 lo = max4(max4(n0, tLo), max4(n1, n2));
            const Float4 hi = min4(min4(f0, tHi), min4(f1, f2));
            unsigned mask = moveMask(lo <= hi);
            if (mask == 0) goto pop;
            {
                const int first = std::countr_zero(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    ref = node.child[first];
                    box = at + first;
                    continue;
                }
                const int second = std::countr_zero(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    const bool swap = lo[second] < lo[first];
                    const int nearK = swap ? second : first, farK = swap ? first : second;
                    stack[top++] = {node.child[farK], lo[farK], at + farK};
                    ref = node.child[nearK];
                    box = at + nearK;
                    continue;
                }
                const int base = top;
                stack[top++] = {node.child[first], lo[first], at + first};
                stack[top++] = {node.child[second], lo[second], at + second};
                while (mask != 0) {
                    const int k = std::countr_zero(mask);
                    mask &= mask - 1;
                    stack[top++] = {node.child[k], lo[k], at + k};
                }
                sortFarthestFirst(stack, base, top);
                --top;
                ref = stack[top].ref;
                box = stack[top].box;
            }
        }
        if (const std::uint32_t count = leafCount(ref); count != 0) {
            // Each lane's own box test decides which rays test the leaf's items.
            const Node& parent = nodes[box / 4];
            const int k = static_cast<int>(box % 4);
            const PacketBox planes{{parent.box[SX][0][k], parent.box[SY][1][k], parent.box[SZ][2][k]},
                                   {parent.box[1 - SX][0][k], parent.box[1 - SY][1][k],
                                    parent.box[1 - SZ][2][k]}};
            const std::uint32_t first = leafFirst(ref);
            std::uint64_t lanes = packetLanesHit(packet, planes);
            const bool changed = lanes != 0;
            while (lanes != 0) {
                const int l = std::countr_zero(lanes);
                lanes &= lanes - 1;
                const double next = leaf(packet.ray[l], first, count);
                packet.tHi[l / 4][l % 4] = laneFarLimit(next);
            }
            if (changed) {
                Float4 m = packet.tHi[0];
                for (int g = 1; g < groups; ++g) m = max4(m, packet.tHi[g]);
                farLimit = hmax(m);
                tHi = splat(farLimit);
            }
        }
    pop:
        for (;;) {
            if (top == 0) return;
            const PacketStackEntry& e = stack[--top];
            if (e.tNear <= farLimit) {
                ref = e.ref;
                box = e.box;
                break;
            }
        }
    }
}

template <class Intersect>
auto Bvh::nearest(const Ray& ray, double tMin, double tMax, Intersect&& f) const
    -> bvh_detail::ResultOf<Intersect, std::uint32_t, const Ray&, double, double> {
    using Result = bvh_detail::ResultOf<Intersect, std::uint32_t, const Ray&, double, double>;
    Result best;
    double far = tMax;
    traverse<true>(ray, tMin, tMax, [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t k = 0; k < count; ++k) {
            Result hit = f(order_[first + k], ray, tMin, far);
            if (hit && hit->t >= tMin && hit->t <= far) {
                far = hit->t;
                best = std::move(hit);
            }
        }
        return far;
    });
    return best;
}

template <class Test>
bool Bvh::any(const Ray& ray, double tMin, double tMax, Test&& f) const {
    bool found = false;
    traverse<false>(ray, tMin, tMax, [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t k = 0; k < count; ++k) {
            if (f(order_[first + k], ray, tMin, tMax)) {
                found = true;
                return -1.0;
            }
        }
        return tMax;
    });
    return found;
}

template <class Visit>
void Bvh::cone(const Cone& cone, Visit&& f) const {
    using namespace bvh_detail;
    using Result = ResultOf<Visit, std::uint32_t>;
    if (nodes_.empty()) return;
    ConeBoxTest test(cone);
    double far = test.cone().tMax;
    ConePrefilter prefilter(test.cone());
    const double magnitude =
        std::max({std::abs(bounds_.lo.x), std::abs(bounds_.lo.y), std::abs(bounds_.lo.z),
                  std::abs(bounds_.hi.x), std::abs(bounds_.hi.y), std::abs(bounds_.hi.z),
                  std::abs(cone.apex.x), std::abs(cone.apex.y), std::abs(cone.apex.z)});
    const bool usePrefilter = magnitude < 1e15;
    struct Entry {
        std::uint32_t ref;
        double distance;
    };
    Entry stack[kStackSize];
    int top = 0;
    stack[top++] = {0u, 0.0};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.distance > far) continue;
        if (isLeaf(e.ref)) {
            const std::uint32_t first = leafFirst(e.ref);
            const std::uint32_t count = leafCount(e.ref);
            for (std::uint32_t k = 0; k < count; ++k) {
                const std::uint32_t item = order_[first + k];
                if constexpr (std::is_void_v<Result>) {
                    f(item);
                } else if constexpr (std::is_same_v<Result, bool>) {
                    if (!f(item)) return;
                } else {
                    static_assert(std::is_floating_point_v<Result>,
                                  "a cone visitor returns void, bool or a new far limit");
                    const double limit = static_cast<double>(f(item));
                    if (limit < far) {
                        far = limit;
                        test.setTMax(far);
                        // Past the float rounding of the prefilter's limit (2^-24).
                        prefilter.setTMax(far * (1.0 + 1e-6));
                    }
                }
            }
            continue;
        }
        const Node& node = nodes_[e.ref];
        Entry hits[4];
        int count = 0;
        unsigned kept = usePrefilter ? prefilter.keep(node) : 15u;
        while (kept != 0) {
            const int k = std::countr_zero(kept);
            kept &= kept - 1;
            Bounds3 box;
            for (int axis = 0; axis < 3; ++axis) {
                box.lo[axis] = node.box[0][axis][k];
                box.hi[axis] = node.box[1][axis][k];
            }
            const double distance = test.entryDistance(box);
            if (distance == kInfinity || distance > far) continue;
            Entry h{node.child[k], distance};
            int j = count++;
            while (j > 0 && hits[j - 1].distance < h.distance) {
                hits[j] = hits[j - 1];
                --j;
            }
            hits[j] = h;
        }
        for (int j = 0; j < count; ++j) stack[top++] = hits[j];
    }
}

}  // namespace asos
