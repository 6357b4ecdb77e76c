#pragma once
// POV-Ray's CSG (difference, intersection, merge, and a union inside one of
// those) as clips on its leaves. Each leaf of a CSG tree is an object of its
// own (its own texture, as POV-Ray's leaves keep theirs): the leaf's surface,
// of which only the crossings that bound the tree's solid are kept. POV-Ray
// keeps a hit of a member of an intersection when it is inside every other
// member, of a merge when it is inside none, and of a union always; a
// difference is the intersection of its first member and the others
// inverted, and inverting a union makes it the intersection of its inverted
// members, inverting an intersection the merge of its inverted members (so
// an `inverse` changes which rule each node above the leaf applies). A
// leaf's clip is the list of those tests from its ancestors: a sibling
// subtree whose inside (POV-Ray's, with the inversions above it) the hit must
// be in, or out of. See docs/geometry.md, "CSG".
#include <cstdint>
#include <memory>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/shapes/shape_issue.hpp"
#include "asos/util/function_ref.hpp"

namespace asos {

// A CSG object's tree as its inside tests see it, placed: made once per
// object and shared by its leaves' clips (each leaf's clip holding the whole
// tree would take memory growing with the square of its members).
struct CsgSolid {
    // A node of the tree as its inside tests see it (the inversions pushed
    // down to the leaves, as POV-Ray does): a leaf inside its region (xor
    // its inversion), or every child's inside (all) or any child's.
    struct Node {
        std::vector<std::uint32_t> children;  // a compound's
        std::uint32_t parent = kNoNode;       // kNoNode for the root
        bool leaf = false;
        bool all = false;   // a compound: every child's inside, not any
        int region = -1;    // a leaf: index into regions; -1 for a polygon (never inside)
        bool flip = false;  // a leaf: inverted an odd number of times (with its ancestors)
        bool odd = false;   // the node's inversions, its own and its ancestors'
        // A box holding the node's inside (POV-Ray's, with its parity).
        Bounds3 box{Vec3(-kInfinity), Vec3(kInfinity)};
    };
    // Where a cone's points lie against a node's inside.
    enum class Side : std::uint8_t { In, Out, Both };
    static constexpr std::uint32_t kNoNode = ~std::uint32_t{0};

    std::shared_ptr<const CsgTree> tree;
    Transform worldFromObject;
    std::vector<Node> nodes;
    // The solid leaves' regions, each the surface that bounds the leaf's
    // inside: the leaf itself for a closed shape or a plane, the capped
    // solid for an open cylinder or cone, the plane of a disc.
    std::vector<Primitive> regions;

    bool inside(std::uint32_t node, const Vec3& worldPoint) const;
    // Where the points of the cone (within its range) lie against node's
    // inside: one side when the node's regions, missed by the cone or
    // combined, show it; Both otherwise.
    Side side(std::uint32_t node, const PreparedCone& cone) const;
};

// The solid of a CSG leaf's object, its regions placed by worldFromObject
// after each leaf's own transform. Throws std::invalid_argument as
// Primitive::make for a tree that is not one.
std::shared_ptr<const CsgSolid> makeCsgSolid(const CsgShape& shape, const Transform& worldFromObject);

// The solid last made, handed to the next leaf of the same object (the
// interpreter makes an object's leaves one after another).
class CsgSolidCache {
public:
    std::shared_ptr<const CsgSolid> solidFor(const CsgShape& shape, const Transform& worldFromObject);

private:
    std::shared_ptr<const CsgSolid> last_;
};

struct CsgClip {
    using Side = CsgSolid::Side;
    // A hit is kept iff inside(child) == wanted for every child of node
    // but `except` (the one holding the leaf), for every test.
    struct Test {
        std::uint32_t node;
        std::uint32_t except;
        bool wanted;
    };

    std::shared_ptr<const CsgSolid> solid;
    std::uint32_t leafNode = 0;  // the leaf's node in the solid
    std::vector<Test> tests;     // one per ancestor that clips
    // The leaf meets a line at most once (a flat shape): its nearest hit is
    // its only one.
    bool flat = false;
    // The leaf is inverted an odd number of times: a curved one's kept part
    // (a hole's wall) can shadow itself.
    bool inverted = false;
    // A box holding the points every test can keep: the intersection of the
    // boxes of the subtrees a hit must be inside (those not inverted).
    Bounds3 keptBounds{Vec3(-kInfinity), Vec3(kInfinity)};

    // Whether a hit at the point is kept.
    bool keeps(const Vec3& worldPoint) const;
    // The leaf's own answer for the cone restricted to the kept part, from
    // the tests asked over the depths of its nearest crossings (own's) and
    // of its later ones (`second`: the leaf classified past own.tFar; Miss
    // for a flat leaf): the own answer where every nearest crossing is
    // kept, Miss where every crossing is dropped, else Marginal over the
    // depths whose crossings may be kept. ownClass is the leaf's own
    // classification (without the clip) of a part of the cone.
    ConeClass restrict(const ConeClass& own, const ConeClass& second, const PreparedCone& cone,
                       FunctionRef<ConeClass(const PreparedCone&)> ownClass) const;

    // What the tests say of the leaf's crossings within a span of depth:
    // all kept, all dropped, not known, or none there.
    enum class Verdict : std::uint8_t { Kept, Dropped, Unsure, None };
    // A span the tests leave unsure is split in halves, `splits` deep.
    static constexpr int kSpanSplits = 3;
    // The tests asked over the cone's depths [t0, t1] (within its range):
    // a span they leave unsure is split in halves, `splits` deep, a half
    // the leaf's own answer (ownClass) does not cross left out.
    Verdict verdict(double t0, double t1, const PreparedCone& cone,
                    FunctionRef<ConeClass(const PreparedCone&)> ownClass, int splits) const;
};

// A leaf's world transform: worldFromObject (the Object's) after the
// leaf's own (an identity left out, so that no -0 turns into 0).
Transform csgLeafTransform(const Transform& worldFromObject, const Transform& leaf);

// The clip of a CSG leaf of the solid (makeCsgSolid's, of the same shape).
CsgClip makeCsgClip(const CsgShape& shape, std::shared_ptr<const CsgSolid> solid);

// A CSG leaf record's issues: a tree and a leaf index that fit, the leaves'
// own records' issues.
std::vector<ShapeIssue> validate(const CsgShape& record);

}  // namespace asos
