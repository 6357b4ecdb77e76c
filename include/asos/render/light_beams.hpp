#pragma once
// The shadow beams from one point toward an area light, as the ASOS light
// shadows split them (paper: "Distributed Light Sources", Figure 5): the
// pyray to a rectangle's corners and its quarters, the triangle to a
// segment's ends and its halves, the cone tangent to a sphere and its
// equal-area pieces (the concentric images of square cells). These are the
// pieces of geometry/beam_rect.hpp, beam_segment.hpp and beam_sphere.hpp (the
// same regions, central rays, random rays and weights;
// tests/unit/light_beams_test.cpp compares them), made for speed: a piece is a small value, and its bounding cone is the
// cone about its central ray through its widest corner, one arctangent
// (the beams' smallest cones try every pair and triple of corners, forty).
// A cone about the central ray holds the piece because the piece's corner
// rays lie within it and the cone is convex (half-angle below pi/2); for a
// sphere piece, the corners of the polar rectangle that holds it, because the
// central ray lies within its angular range (docs/accel.md, "Sphere pieces").
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/beam_sphere.hpp"
#include "asos/render/light_model.hpp"

namespace asos {

// One piece of the light: its region in the light's coordinates, its
// level (its share of the light is share(level)), its position among the
// pieces of that level (for random numbers), its central ray and its cone.
struct LightPiece {
    // Rectangle: s in [a0, a1], t in [b0, b1]; segment: s in [a0, a1];
    // sphere: the concentric map's cell s in [a0, a1], t in [b0, b1].
    double a0 = 0.0, b0 = 0.0, a1 = 1.0, b1 = 1.0;
    int level = 0;
    std::uint64_t path = 0;
    BeamRay central;
    Cone cone;
    // The tangent of the cone's half-angle before its padding, when the cone
    // was made through its widest corner (rectangle pieces, sphere pieces
    // below level 0); NaN otherwise. Spares its users the trigonometry.
    double tanHalf = std::numeric_limits<double>::quiet_NaN();
};

// The pieces of a sphere light's apparent disc: the concentric images of the
// quadtree's cells of the unit square (geometry/beam_sphere.hpp). Their
// layout does not depend on the point, so the first levels are made once
// (discPieceTable()), with their central points and the cosines and sines of
// their polar bounds' angles; deeper pieces are made as they are needed.
class DiscPieceTable {
public:
    struct Trig {
        double c, s;
    };
    struct Piece {
        DiscCell cell;
        Vec2 centre;       // the image of the cell's centre on the unit disc,
        double rho2, rim;  // its |centre|^2 and sqrt(1 - |centre|^2)
        double r0, r1;     // the polar rectangle holding the image: radii,
        Trig at0, at1;   // and its angles' cosines and sines
    };
    static Piece piece(const DiscCell& cell);

    static constexpr int kLevels = 5;  // 1365 pieces
    DiscPieceTable();
    // The four children of piece `path` at `level`, or null past the table.
    const Piece* children(int level, std::uint64_t path) const {
        if (level + 1 > kLevels) return nullptr;
        return &pieces_[(((std::size_t(1) << (2 * (level + 1))) - 1) / 3) + 4 * path];
    }

private:
    std::vector<Piece> pieces_;  // level by level, each level in path order
};

// The one table, made on first use and constant after.
const DiscPieceTable& discPieceTable();

// Where a piece lies against the plane through the apex with a given normal
// (LightBeams::horizonSide): every direction above it, every direction at or
// below it, across it, or not known without rays.
enum class HorizonSide { Above, Below, Across, Unknown };

class LightBeams {
public:
    // Beams from `apex` toward an area light (model.isArea()); rays start at
    // distance tMin. `valid()` is false when the apex sees no beam: in the
    // rectangle's plane, on the segment's line, on or inside the sphere.
    LightBeams(const LightModel& model, const Vec3& apex, double tMin);

    bool valid() const { return valid_; }
    const Vec3& apex() const { return apex_; }
    LightShape shape() const { return shape_; }

    // The whole light: the level-0 piece.
    LightPiece root() const;
    // The pieces of the next level, written to out[]: four (rectangle,
    // sphere) or two (segment). Returns how many. Without `cones` the
    // pieces' cones are left empty (pieces that are only sampled by rays).
    int split(const LightPiece& piece, LightPiece* out, bool cones = true) const;
    static constexpr int kMaxChildren = 4;
    // The pieces `depth` levels below `piece`, without cones, each passed
    // to f(const LightPiece&) in the order repeated split()s give them, with
    // the same regions, paths and central rays (bit for bit). Rectangles
    // and segments make only those pieces, none of the levels between (point
    // samples at MAX: docs/lights.md, "Speed").
    template <class F>
    void forEachDescendant(const LightPiece& piece, int depth, F&& f) const {
        switch (shape_) {
            case LightShape::Rectangle:
                descendRectangle(piece.a0, piece.b0, piece.a1, piece.b1, piece.level, piece.path, depth, f);
                return;
            case LightShape::Segment:
                descendSegment(piece.a0, piece.a1, piece.level, piece.path, depth, f);
                return;
            case LightShape::Sphere:
                if (depth > 0 && discPieceTable().children(piece.level + depth - 1, 0)) {
                    descendDisc(discPieceTable(), piece.level, piece.path, depth, f);
                    return;
                }
                [[fallthrough]];
            default: {
                if (depth == 0) {
                    f(piece);
                    return;
                }
                LightPiece children[kMaxChildren];
                const int count = split(piece, children, false);
                for (int i = 0; i < count; ++i) forEachDescendant(children[i], depth - 1, f);
                return;
            }
        }
    }

    // The central rays of the pieces forEachDescendant would give, in the
    // same order and bit for bit, without the pieces. A rectangle's are
    // made straight from the lattice of their centres: every coordinate of
    // a piece is a dyadic fraction of few bits, so a0 + (i + 1/2) ds is
    // exactly the midpoint that repeated splits compute; the order is
    // forEachDescendant's (quarter q = i + 2 j at each level: Morton order).
    template <class F>
    void forEachCentralRay(const LightPiece& piece, int depth, F&& f) const {
        if (shape_ != LightShape::Rectangle || depth > 4) {
            forEachDescendant(piece, depth, [&](const LightPiece& p) { f(p.central); });
            return;
        }
        const Lattice l = lattice(piece, depth);
        for (int m = 0; m < l.count(); ++m) {
            const Lattice::Place at = l.place(m);
            f(l.ray(at.i, at.j));
        }
    }

    // The central points of the pieces `depth` levels below a piece as a
    // lattice, for a rectangle or a segment down to 4 levels (hasLattice):
    // column i along the light's first edge, row j along its second (one
    // row for a segment), an affine image of (i, j). ray(i, j) is that
    // piece's central ray, bit for bit split()'s; place(m) is where the m-th
    // of forEachCentralRay's rays lies. A ray is made only when asked for.
    class Lattice {
    public:
        struct Place {
            int i, j;
        };
        int columns() const { return side_; }
        int rows() const { return segment_ ? 1 : side_; }
        int count() const { return columns() * rows(); }
        __attribute__((always_inline)) Place place(int m) const {
            if (segment_) return {m, 0};
            const std::uint8_t ij = kMorton[std::size_t(m)];
            return {int(ij & 15u), int(ij >> 4)};
        }
        __attribute__((always_inline)) BeamRay ray(int i, int j) const { return beams_->toward(point(i, j)); }
        // The light point at place (i, j) less the apex: ray(i, j)'s
        // direction, not normalised.
        Vec3 offset(int i, int j) const { return point(i, j) - beams_->apex_; }

    private:
        // The light point at place (i, j).
        __attribute__((always_inline)) Vec3 point(int i, int j) const {
            return segment_ ? columns_[i] : columns_[i] + rows_[j];
        }
        friend class LightBeams;
        const LightBeams* beams_ = nullptr;
        bool segment_ = false;
        int side_ = 1;
        // rectPoint's sum, its first two terms per column and its last per
        // row (the same operations in the same order); a segment's points.
        Vec3 columns_[16], rows_[16];
    };
    bool hasLattice(int depth) const {
        return (shape_ == LightShape::Rectangle || shape_ == LightShape::Segment) && depth >= 0 && depth <= 4;
    }
    Lattice lattice(const LightPiece& piece, int depth) const {
        Lattice l;
        l.beams_ = this;
        l.segment_ = shape_ == LightShape::Segment;
        l.side_ = 1 << depth;
        const double scale = std::bit_cast<double>(std::uint64_t(1023 - depth) << 52);  // 2^-depth
        const double ds = (piece.a1 - piece.a0) * scale, dt = (piece.b1 - piece.b0) * scale;
        for (int k = 0; k < l.side_; ++k) {
            // The midpoint of a dyadic range, exactly: split()'s 0.5 (a0 + a1).
            l.columns_[k] = corner_ + (piece.a0 + (double(k) + 0.5) * ds) * edgeA_;
            if (!l.segment_) l.rows_[k] = (piece.b0 + (double(k) + 0.5) * dt) * edgeB_;
        }
        return l;
    }
    // The box that holds a rectangle's or segment's points.
    Bounds3 lightBounds() const {
        Bounds3 b = Bounds3::of(corner_);
        b.extend(corner_ + edgeA_);
        b.extend(corner_ + edgeB_);
        b.extend(corner_ + edgeA_ + edgeB_);
        return b;
    }

    // A ray inside the piece from two numbers in [0, 1) (a segment uses the
    // first), uniform over the piece's area (length, disc area).
    BeamRay sample(const LightPiece& piece, const Vec2& xi) const;
    // The piece's share of the light: 4^-level (2^-level for a segment).
    // Inline and without a library call: it is asked for every sample.
    double share(int level) const {
        const int exponent = shape_ == LightShape::Segment ? level : 2 * level;
        return exponent < 1000 ? std::bit_cast<double>(std::uint64_t(1023 - exponent) << 52) : 0.0;
    }
    // No ray of the piece reaches the light nearer than this.
    double nearestLightDistance(const LightPiece& piece) const;
    // Pairs of rays across the piece through its central point, one pair per
    // coordinate: toward the midpoints of opposite edges (a segment's two
    // ends; for the whole sphere, opposite points of its rim). Their means
    // less the central value are the piece's second differences. Returns
    // how many rays (2 or 4).
    int probeRays(const LightPiece& piece, BeamRay* out) const;
    // The weights of a rule exact for quadratics (cubics) over the piece:
    // the central ray's, and each probe ray's; they sum to 1. Square pieces
    // (rectangle quarters, the sphere's pieces in their equal-area
    // coordinates) 1/3 and 1/6; the whole disc 1/2 and 1/8; a segment
    // (Simpson's rule) 2/3 and 1/6.
    std::pair<double, double> ruleWeights(const LightPiece& piece) const;
    // Whether the plane through the apex with this normal crosses the piece,
    // exactly up to rounding (Across where it is in doubt): the height of a
    // rectangle's or segment's point above the plane is affine in its
    // coordinates, so its range over the piece is at the piece's corners.
    // Sphere pieces: Unknown.
    HorizonSide horizonSide(const LightPiece& piece, const Vec3& normal) const {
        if (shape_ != LightShape::Rectangle && shape_ != LightShape::Segment) return HorizonSide::Unknown;
        const double h0 = glm::dot(normal, corner_ - apex_), hA = glm::dot(normal, edgeA_);
        const double hB = shape_ == LightShape::Rectangle ? glm::dot(normal, edgeB_) : 0.0;
        const double lo = h0 + std::min(piece.a0 * hA, piece.a1 * hA) + std::min(piece.b0 * hB, piece.b1 * hB);
        const double hi = h0 + std::max(piece.a0 * hA, piece.a1 * hA) + std::max(piece.b0 * hB, piece.b1 * hB);
        const double margin = 1e-12 * (std::abs(h0) + std::abs(hA) + std::abs(hB));
        if (lo > margin) return HorizonSide::Above;
        if (hi < -margin) return HorizonSide::Below;
        return HorizonSide::Across;
    }
    // The emitter's weighting along a direction: |cos theta| between the
    // rectangle's normal and the direction; 1 for segments and spheres.
    // Inline: it is asked for every sample.
    double emission(const Vec3& dir) const {
        return shape_ == LightShape::Rectangle ? std::abs(dot3(normal_, dir)) : 1.0;
    }
    // Whether the paper's "Proximity to One Edge" halving holds for this
    // split: for quarters of a rectangle and halves of a segment (a straight
    // occluder edge is a straight line in the light's plane); not for the
    // sphere's equal-area pieces, whose central rays are not placed
    // symmetrically about their parent's.
    bool singleEdgeHalving() const { return shape_ != LightShape::Sphere; }

private:
    // The even bits of a Morton index (at most 8 bits) in the low four bits,
    // its odd bits in the high four: the column and the row.
    static constexpr std::array<std::uint8_t, 256> kMorton = [] {
        std::array<std::uint8_t, 256> table{};
        const auto compact = [](std::uint32_t x) {
            x &= 0x55u;
            x = (x | (x >> 1)) & 0x33u;
            return (x | (x >> 2)) & 0x0fu;
        };
        for (std::uint32_t m = 0; m < 256; ++m) table[m] = std::uint8_t(compact(m) | compact(m >> 1) << 4);
        return table;
    }();

    // forEachDescendant's: the midpoints of dyadic ranges are exact, and the
    // central rays are made by the same expressions as split()'s.
    template <class F>
    void descendRectangle(double a0, double b0, double a1, double b1, int level, std::uint64_t path, int depth,
                          F& f) const {
        if (depth == 0) {
            LightPiece p{a0, b0, a1, b1, level, path, {}, {}};
            p.central = toward(rectPoint(0.5 * (a0 + a1), 0.5 * (b0 + b1)));
            f(std::as_const(p));
            return;
        }
        const double s[3] = {a0, 0.5 * (a0 + a1), a1};
        const double t[3] = {b0, 0.5 * (b0 + b1), b1};
        for (int q = 0; q < 4; ++q) {
            const int i = q & 1, j = q >> 1;
            descendRectangle(s[i], t[j], s[i + 1], t[j + 1], level + 1, 4 * path + std::uint64_t(q), depth - 1, f);
        }
    }
    // Sphere pieces whose layouts are all in the table: made from it.
    template <class F>
    void descendDisc(const DiscPieceTable& table, int level, std::uint64_t path, int depth, F& f) const {
        const DiscPieceTable::Piece* d = table.children(level, path);
        for (int q = 0; q < 4; ++q) {
            const std::uint64_t child = 4 * path + std::uint64_t(q);
            if (depth == 1) {
                const LightPiece piece = makeDiscPiece(d[q], level + 1, child, false);
                f(piece);
            } else {
                descendDisc(table, level + 1, child, depth - 1, f);
            }
        }
    }
    template <class F>
    void descendSegment(double a0, double a1, int level, std::uint64_t path, int depth, F& f) const {
        if (depth == 0) {
            LightPiece p{a0, 0.0, a1, 1.0, level, path, {}, {}};
            p.central = toward(corner_ + 0.5 * (a0 + a1) * edgeA_);
            f(std::as_const(p));
            return;
        }
        const double mid = 0.5 * (a0 + a1);
        descendSegment(a0, mid, level + 1, 2 * path, depth - 1, f);
        descendSegment(mid, a1, level + 1, 2 * path + 1, depth - 1, f);
    }

    LightPiece make(double a0, double b0, double a1, double b1, int level, std::uint64_t path,
                    bool cone = true) const;
    int splitRectangle(const LightPiece& piece, LightPiece* out, bool cones) const;
    Vec3 rectPoint(double s, double t) const { return corner_ + s * edgeA_ + t * edgeB_; }
    // The offset (not normalised) through the disc's point of radius r at
    // the angle of t.
    Vec3 discOffset(double r, const DiscPieceTable::Trig& t) const;
    LightPiece makeDiscPiece(const DiscPieceTable::Piece& d, int level, std::uint64_t path, bool cone) const;
    // Inline: forEachDescendant makes one per point sample.
    __attribute__((always_inline)) BeamRay toward(const Vec3& target) const {
        const Vec3 offset = target - apex_;
        // glm::length's sqrt(dot) written out: GCC left glm::length a call.
        const double distance = std::sqrt(dot3(offset, offset));
        return {Ray{apex_, offset / distance}, distance};
    }
    // The cone about unit `axis` through the widest of `directions` (of any
    // length), reaching `farthest`.
    Cone coneAbout(const Vec3& axis, const Vec3* directions, int count, double farthest,
                   double& tanHalf) const;

    LightShape shape_ = LightShape::Point;
    Vec3 apex_{0.0};
    double tMin_ = 0.0;
    bool valid_ = false;
    // Rectangle (corner + s edgeA + t edgeB) and segment (corner + s edgeA).
    Vec3 corner_{0.0}, edgeA_{0.0}, edgeB_{0.0}, normal_{0.0};
    bool rectangular_ = false;  // edges at right angles: nearest points by clamping
    double footS_ = 0.0, footT_ = 0.0, height_ = 0.0;
    // Sphere.
    double alpha_ = 0.0;
    TangentCone tangent_;
};

}  // namespace asos
