#include "asos/render/pattern_filter.hpp"

#include <array>
#include <cmath>

#include "asos/render/brick_pattern.hpp"
#include "asos/render/checker_pattern.hpp"

namespace asos {

namespace {

// A footprint is clipped exactly when its pattern-space bounds hold at most
// this many cells of the edge planes; otherwise it is quartered, at most
// kMaxQuarterings times, before the closed form takes over. Past 64 cells a
// footprint's mean is within a few per cent of the pattern's mean anyway.
constexpr int kMaxPieces = 64;
constexpr int kMaxQuarterings = 2;

// A convex polygon in image coordinates. Clipping a convex polygon along a
// line adds at most one vertex to either side, and a piece is cut at most
// twice along each of the three axes: 4 + 6 vertices at most.
struct ImagePolygon {
    static constexpr int kCapacity = 16;
    std::array<Vec2, kCapacity> v;
    int n = 0;

    void add(const Vec2& p) {
        if (n < kCapacity) v[n++] = p;
    }
    double area() const {
        double twice = 0.0;
        for (int i = 0; i < n; ++i) {
            const Vec2& p = v[i];
            const Vec2& q = v[(i + 1) % n];
            twice += p.x * q.y - q.x * p.y;
        }
        return 0.5 * std::fabs(twice);
    }
    // A point inside (the vertices' mean).
    Vec2 inner() const {
        Vec2 sum(0.0);
        for (int i = 0; i < n; ++i) sum += v[i];
        return sum / double(n);
    }
};

template <class Pattern>
class ShareOf {
public:
    ShareOf(const Pattern& pattern, const PatternFootprint& footprint)
        : pattern_(pattern), footprint_(footprint),
          planes_{pattern.planes(0), pattern.planes(1), pattern.planes(2)} {}

    double of(const ImageSquare& square, int quarterings) {
        Vec3 lo(kInfinity), hi(-kInfinity);
        const double us[2] = {square.u0, square.u1}, vs[2] = {square.v0, square.v1};
        for (double u : us)
            for (double v : vs) {
                const Vec3 p = footprint_.at(u, v);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        // The footprint is the projective image of the square, convex, with
        // the images of the square's corners as its corners: inside [lo, hi].
        int pieces = 1;
        for (int axis = 0; axis < 3 && pieces <= kMaxPieces; ++axis)
            pieces *= planes_[axis].countInside(lo[axis], hi[axis], kMaxPieces) + 1;
        if (pieces > kMaxPieces) {
            if (quarterings >= kMaxQuarterings) return pattern_.boxShare(lo, hi);
            double sum = 0.0;
            for (int q = 0; q < 4; ++q) sum += of(square.quarter(q), quarterings + 1);
            return 0.25 * sum;
        }
        ImagePolygon whole;
        whole.add({square.u0, square.v0});
        whole.add({square.u1, square.v0});
        whole.add({square.u1, square.v1});
        whole.add({square.u0, square.v1});
        area_ = share_ = 0.0;
        slice(whole, 0);
        return area_ > 0.0 ? share_ / area_ : double(pattern_.value(footprint_.at(square.uMid(), square.vMid())));
    }

private:
    // Cuts `piece` along the planes of `axis` it spans, and each part along
    // the next axes; a part cut along all three lies in one cell.
    void slice(const ImagePolygon& piece, int axis) {
        if (piece.n < 3) return;
        if (axis == 3) {
            const double area = piece.area();
            const Vec2 inner = piece.inner();
            area_ += area;
            if (pattern_.value(footprint_.at(inner.x, inner.y)) == 1) share_ += area;
            return;
        }
        double lo = kInfinity, hi = -kInfinity;
        for (int i = 0; i < piece.n; ++i) {
            const double p = footprint_.at(piece.v[i].x, piece.v[i].y)[axis];
            lo = std::min(lo, p);
            hi = std::max(hi, p);
        }
        ImagePolygon rest = piece;
        planes_[axis].forEachInside(lo, hi, [&](double plane) {
            ImagePolygon below, above;
            split(rest, axis, plane, below, above);
            slice(below, axis + 1);
            rest = above;
        });
        slice(rest, axis + 1);
    }

    // The parts of `piece` below and above the plane p[axis] = plane, along
    // its image line H[axis] - plane H.w = 0 (H.w > 0: the sign tells the
    // side).
    void split(const ImagePolygon& piece, int axis, double plane, ImagePolygon& below,
               ImagePolygon& above) const {
        std::array<double, ImagePolygon::kCapacity> side;
        for (int i = 0; i < piece.n; ++i) {
            const Vec4 h = footprint_.homogeneous(piece.v[i].x, piece.v[i].y);
            side[i] = h[axis] - plane * h.w;
        }
        for (int i = 0; i < piece.n; ++i) {
            const int j = (i + 1) % piece.n;
            const double s = side[i], t = side[j];
            if (s <= 0.0) below.add(piece.v[i]);
            if (s >= 0.0) above.add(piece.v[i]);
            if ((s < 0.0 && t > 0.0) || (s > 0.0 && t < 0.0)) {
                const Vec2 cut = piece.v[i] + (s / (s - t)) * (piece.v[j] - piece.v[i]);
                below.add(cut);
                above.add(cut);
            }
        }
    }

    const Pattern& pattern_;
    const PatternFootprint& footprint_;
    std::array<PatternPlanes, 3> planes_;
    double area_ = 0.0, share_ = 0.0;
};

template <class Pattern>
double shareOf(const Pattern& pattern, const PatternFootprint& footprint) {
    return ShareOf<Pattern>(pattern, footprint).of(footprint.square(), 0);
}

}  // namespace

double patternShare(const Pigment& pigment, const PatternFootprint& footprint) {
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return 0.0;
        case Pigment::Kind::Checker: return shareOf(CheckerPattern(), footprint);
        case Pigment::Kind::Brick:
            return shareOf(BrickPattern(pigment.brickSize, pigment.mortar), footprint);
        default: return 0.0;  // the map patterns are not filtered (hasPattern is false)
    }
}

Color filteredPigment(const Pigment& pigment, const PatternFootprint& footprint) {
    const double share = patternShare(pigment, footprint);
    if (share <= 0.0) return pigment.color1;
    if (share >= 1.0) return pigment.color2;
    const Color& a = pigment.color1;
    const Color& b = pigment.color2;
    return {a.rgb + share * (b.rgb - a.rgb), a.filter + share * (b.filter - a.filter),
            a.transmit + share * (b.transmit - a.transmit)};
}

}  // namespace asos
