#include "asos/shapes/csg_clip.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <memory>

namespace asos {

namespace {

// The record whose surface bounds a leaf's inside (CsgClip::regions); none
// for a polygon or a mesh's face, which have no inside.
std::optional<Shape> regionRecord(const Shape& leaf) {
    if (std::holds_alternative<PolygonShape>(leaf) || std::holds_alternative<TriangleShape>(leaf)) return std::nullopt;
    if (const auto* disc = std::get_if<DiscShape>(&leaf)) {
        const Vec3 n = glm::normalize(disc->normal);
        return Shape{PlaneShape{disc->normal, glm::dot(n, disc->center)}};
    }
    if (const auto* cone = std::get_if<ConeShape>(&leaf)) {
        ConeShape capped = *cone;
        capped.open = false;
        return Shape{capped};
    }
    if (const auto* cylinder = std::get_if<CylinderShape>(&leaf)) {
        CylinderShape capped = *cylinder;
        capped.open = false;
        return Shape{capped};
    }
    return leaf;
}

Bounds3 intersectionOf(const Bounds3& a, const Bounds3& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

const Bounds3 kEverywhere{Vec3(-kInfinity), Vec3(kInfinity)};

// Builds the solid from the description's tree: the inversions pushed down
// (each node's parity), every node's inside rule, box and parent.
class SolidBuilder {
public:
    SolidBuilder(CsgSolid& solid) : solid_(solid) {}

    // `parity`: the inversions above the node; `extra`: the node is a
    // difference's member after the first (inverted by the difference).
    void visit(std::uint32_t index, bool parity, bool extra) {
        const CsgTree& tree = *solid_.tree;
        const CsgTree::Node& node = tree.nodes.at(index);
        const bool odd = parity != (node.inverse != extra);
        CsgSolid::Node& out = solid_.nodes[index];
        out.odd = odd;
        if (node.op == CsgTree::Op::Leaf) {
            out.leaf = true;
            out.flip = odd;
            const CsgTree::Leaf& leaf = tree.leaves.at(node.leaf);
            if (const std::optional<Shape> region = regionRecord(leaf.shape)) {
                out.region = static_cast<int>(solid_.regions.size());
                solid_.regions.push_back(
                    Primitive::make(*region, csgLeafTransform(solid_.worldFromObject, leaf.worldFromObject)));
                const Primitive& p = solid_.regions.back();
                if (!odd && p.bounded()) out.box = p.worldBounds();
            } else {
                out.box = Bounds3{};  // never inside: holds nothing
            }
            return;
        }
        // POV-Ray's rule for the node with its parity: an intersection (a
        // difference) or an inverted union or merge needs every child.
        const bool intersection = node.op == CsgTree::Op::Intersection || node.op == CsgTree::Op::Difference;
        out.all = intersection != odd;
        out.children = node.children;
        Bounds3 box = out.all ? kEverywhere : Bounds3{};
        for (std::size_t i = 0; i < node.children.size(); ++i) {
            const std::uint32_t c = node.children[i];
            solid_.nodes.at(c).parent = index;
            visit(c, odd, node.op == CsgTree::Op::Difference && i > 0);
            const Bounds3& child = solid_.nodes[c].box;
            box = solid_.nodes[index].all ? intersectionOf(box, child) : unionOf(box, child);
        }
        // An inverted subtree's inside is unbounded.
        solid_.nodes[index].box = box;
    }

private:
    CsgSolid& solid_;
};

}  // namespace

Transform csgLeafTransform(const Transform& worldFromObject, const Transform& leaf) {
    if (worldFromObject.isIdentity()) return leaf;
    if (leaf.isIdentity()) return worldFromObject;
    return worldFromObject * leaf;
}

bool CsgSolid::inside(std::uint32_t index, const Vec3& worldPoint) const {
    const Node& node = nodes[index];
    if (node.leaf) return node.region >= 0 && regions[static_cast<std::size_t>(node.region)].inside(worldPoint) != node.flip;
    for (std::uint32_t c : node.children)
        if (inside(c, worldPoint) != node.all) return !node.all;
    return node.all;
}

bool CsgClip::keeps(const Vec3& worldPoint) const {
    for (const Test& t : tests)
        for (std::uint32_t c : solid->nodes[t.node].children)
            if (c != t.except && solid->inside(c, worldPoint) != t.wanted) return false;
    return true;
}

CsgSolid::Side CsgSolid::side(std::uint32_t index, const PreparedCone& cone) const {
    const Node& node = nodes[index];
    if (node.leaf) {
        if (node.region < 0) return Side::Out;
        const Primitive& region = regions[static_cast<std::size_t>(node.region)];
        // A box around the cone's points within a bounded range (their
        // depth along the axis lies in [tMin cos, tMax], their distance from
        // it below tMax sin): every region is a convex solid or a
        // half-space, so holding the box's corners holds the box, and a
        // bounded region clear of the box is clear of the cone.
        if (std::isfinite(cone.tMax) && cone.cosHalf > 0.0) {
            const Vec3 a = cone.apex + cone.tMin * cone.cosHalf * cone.axis, b = cone.apex + cone.tMax * cone.axis;
            const Vec3 grow(cone.tMax * cone.sinHalf * (1.0 + kThousandsOfUlps) + kPositionTolerance * l1Norm(b));
            const Bounds3 box{glm::min(a, b) - grow, glm::max(a, b) + grow};
            const Bounds3 clear = region.worldBounds();
            if (region.bounded() && (box.lo.x > clear.hi.x || box.hi.x < clear.lo.x || box.lo.y > clear.hi.y ||
                                     box.hi.y < clear.lo.y || box.lo.z > clear.hi.z || box.hi.z < clear.lo.z))
                return node.flip ? Side::In : Side::Out;
            bool all = true;
            for (int i = 0; i < 8 && all; ++i) all = region.inside(box.corner(i));
            if (all) return node.flip ? Side::Out : Side::In;
        }
        if (region.classify(cone).coverage != Coverage::Miss) return Side::Both;
        // The cone's part in range does not cross the region's surface, so it
        // lies on the side of any of its points: one on the axis away from
        // the apex, which may lie on the surface (to rounding) and be
        // counted on either side.
        const double t = std::isfinite(cone.tMax) ? 0.5 * (cone.tMin + cone.tMax)
                                                  : cone.tMin + 1.0 + l1Norm(cone.apex);
        const Vec3 point = cone.apex + t * cone.axis;
        return region.inside(point) != node.flip ? Side::In : Side::Out;
    }
    // Every child's inside: Out if one is Out, In if all are In; any
    // child's: the same with In and Out swapped.
    const Side decisive = node.all ? Side::Out : Side::In;
    bool mixed = false;
    for (std::uint32_t c : node.children) {
        const Side s = side(c, cone);
        if (s == decisive) return decisive;
        mixed |= s == Side::Both;
    }
    if (mixed) return Side::Both;
    return node.all ? Side::In : Side::Out;
}

ConeClass CsgClip::restrict(const ConeClass& own, const ConeClass& second, const PreparedCone& cone,
                           FunctionRef<ConeClass(const PreparedCone&)> ownClass) const {
    if (own.coverage == Coverage::Miss) return own;
    const Verdict first = verdict(own.tNear, own.tFar, cone, ownClass, kSpanSplits);
    // Every nearest crossing kept: the leaf's own answer.
    if (first == Verdict::Kept) return own;
    const Verdict later = second.coverage == Coverage::Miss
                              ? Verdict::None
                              : verdict(second.tNear, second.tFar, cone, ownClass, kSpanSplits);
    const bool firstDropped = first == Verdict::Dropped || first == Verdict::None;
    const bool laterDropped = later == Verdict::Dropped || later == Verdict::None;
    if (firstDropped && laterDropped) return {};
    ConeClass out = own;
    out.coverage = Coverage::Marginal;
    out.singleEdge = false;
    out.creaseParts = 0;
    if (firstDropped) out.tNear = second.tNear;
    if (!laterDropped) out.tFar = firstDropped ? second.tFar : std::max(own.tFar, second.tFar);
    return out;
}

CsgClip::Verdict CsgClip::verdict(double t0, double t1, const PreparedCone& cone,
                                  FunctionRef<ConeClass(const PreparedCone&)> ownClass, int splits) const {
    PreparedCone span = cone;
    span.tMin = std::max(cone.tMin, t0);
    span.tMax = std::min(cone.tMax, t1);
    Verdict v = Verdict::Kept;
    for (const Test& t : tests)
        for (std::uint32_t c : solid->nodes[t.node].children) {
            if (c == t.except) continue;
            const Side s = solid->side(c, span);
            if (s == Side::Both) v = Verdict::Unsure;
            else if ((s == Side::In) != t.wanted) return Verdict::Dropped;
        }
    // Unsure over the whole span: its halves' boxes are smaller (the box
    // around a span grows with its length), and a half the leaf's surface
    // does not cross holds no crossing to keep or drop.
    if (v != Verdict::Unsure || splits == 0 || !(span.tMax > span.tMin) || !std::isfinite(span.tMax)) return v;
    const double mid = 0.5 * (span.tMin + span.tMax);
    Verdict joined = Verdict::None;
    for (const auto& [a, b] : {std::pair{span.tMin, mid}, std::pair{mid, span.tMax}}) {
        PreparedCone half = span;
        half.tMin = a;
        half.tMax = b;
        const ConeClass k = ownClass(half);
        if (k.coverage == Coverage::Miss) continue;
        const Verdict h = verdict(std::max(a, k.tNear), std::min(b, k.tFar), cone, ownClass, splits - 1);
        if (h == Verdict::Unsure) return h;
        if (h == Verdict::None) continue;
        if (joined != Verdict::None && joined != h) return Verdict::Unsure;
        joined = h;
    }
    return joined;
}

std::shared_ptr<const CsgSolid> makeCsgSolid(const CsgShape& shape, const Transform& worldFromObject) {
    std::vector<ShapeIssue> issues = validate(shape);
    if (!issues.empty()) throw std::invalid_argument(std::move(issues.front().message));
    auto solid = std::make_shared<CsgSolid>();
    solid->tree = shape.tree;
    solid->worldFromObject = worldFromObject;
    solid->nodes.resize(shape.tree->nodes.size());
    SolidBuilder(*solid).visit(0, false, false);
    return solid;
}

std::shared_ptr<const CsgSolid> CsgSolidCache::solidFor(const CsgShape& shape, const Transform& worldFromObject) {
    if (!last_ || last_->tree != shape.tree || !(last_->worldFromObject == worldFromObject))
        last_ = makeCsgSolid(shape, worldFromObject);
    return last_;
}

CsgClip makeCsgClip(const CsgShape& shape, std::shared_ptr<const CsgSolid> solid) {
    CsgClip clip;
    const CsgTree& tree = *shape.tree;
    const std::uint32_t leafNode = tree.leaves.at(shape.leaf).node;
    // The tests, from the leaf up: at each compound above it, the rule the
    // node applies with its parity (see csg_clip.hpp).
    clip.leafNode = leafNode;
    clip.inverted = solid->nodes[leafNode].odd;
    for (std::uint32_t child = leafNode, node = solid->nodes[leafNode].parent; node != CsgSolid::kNoNode;
         child = node, node = solid->nodes[node].parent) {
        const CsgTree::Op op = tree.nodes[node].op;
        const bool odd = solid->nodes[node].odd;
        // Union: none (odd: an intersection); intersection and difference:
        // inside the others (odd: a merge); merge: outside the others (odd:
        // an intersection).
        const bool intersection = op == CsgTree::Op::Union || op == CsgTree::Op::Merge ? odd : !odd;
        const bool merge = op == CsgTree::Op::Merge ? !odd : op != CsgTree::Op::Union && odd;
        if (!intersection && !merge) continue;
        if (tree.nodes[node].children.size() < 2) continue;
        clip.tests.push_back({node, child, intersection});
        if (intersection)
            for (std::uint32_t sibling : tree.nodes[node].children)
                if (sibling != child) clip.keptBounds = intersectionOf(clip.keptBounds, solid->nodes[sibling].box);
    }
    clip.solid = std::move(solid);
    return clip;
}

std::vector<ShapeIssue> validate(const CsgShape& record) {
    IssueList issues;
    if (!record.tree || record.tree->nodes.empty()) {
        issues.add(0, "a CSG leaf needs its tree");
        return issues.take();
    }
    const CsgTree& tree = *record.tree;
    if (record.leaf >= tree.leaves.size()) {
        issues.add(0, "a CSG leaf's index is past its tree's " + std::to_string(tree.leaves.size()) + " leaves");
        return issues.take();
    }
    // Every node reached once from the root, leaves and their nodes paired.
    std::vector<int> seen(tree.nodes.size(), 0);
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        if (n >= tree.nodes.size() || seen[n]++) {
            issues.add(0, "a CSG tree's nodes do not form a tree");
            return issues.take();
        }
        const CsgTree::Node& node = tree.nodes[n];
        if (node.op == CsgTree::Op::Leaf) {
            if (node.leaf >= tree.leaves.size() || tree.leaves[node.leaf].node != n) {
                issues.add(0, "a CSG tree's leaf node and leaf do not match");
                return issues.take();
            }
        } else {
            stack.insert(stack.end(), node.children.begin(), node.children.end());
        }
    }
    for (const CsgTree::Leaf& leaf : tree.leaves) {
        if (leaf.node >= tree.nodes.size() || !seen[leaf.node]) {
            issues.add(0, "a CSG tree's leaf is not in the tree");
            return issues.take();
        }
        if (std::holds_alternative<CsgShape>(leaf.shape)) {
            issues.add(0, "a CSG tree's leaf is a CSG leaf itself");
            return issues.take();
        }
        for (ShapeIssue& issue : shapeIssues(leaf.shape)) issues.add(0, std::move(issue.message));
    }
    return issues.take();
}

}  // namespace asos
