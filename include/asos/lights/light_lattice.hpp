#pragma once
// The central points of the pieces `depth` levels below a piece of a
// rectangle or a segment (down to 4 levels), as a lattice: column i along
// the light's first edge, row j along its second (one row for a segment), an
// affine image of (i, j). ray(i, j) is that piece's central ray, bit for bit
// the beam's split()'s; place(m) is where the m-th of the beam's
// forEachDescendant pieces lies (Morton order for a rectangle: quarter
// q = i + 2 j at each level). A ray is made only when asked for.
//
// Every coordinate of a piece is a dyadic fraction of few bits, so
// a0 + (i + 1/2) ds is exactly the midpoint that repeated splits compute.
#include <array>
#include <bit>
#include <cstdint>

#include "asos/lights/beam_apex.hpp"
#include "asos/lights/light_piece.hpp"

namespace asos {

class LightLattice {
public:
    static constexpr int kMaxDepth = 4;

    // The lattice below `piece` of the rectangle corner + s edgeA + t edgeB,
    // 0 <= depth <= kMaxDepth.
    static LightLattice ofRectangle(const BeamApex& apex, const Vec3& corner, const Vec3& edgeA,
                                    const Vec3& edgeB, const LightPiece& piece, int depth) {
        LightLattice l(apex, depth);
        const double ds = step(piece.a0, piece.a1, depth), dt = step(piece.b0, piece.b1, depth);
        for (int k = 0; k < l.side_; ++k) {
            // The midpoint of a dyadic range, exactly: split()'s 0.5 (a0 + a1).
            l.columns_[k] = corner + (piece.a0 + (double(k) + 0.5) * ds) * edgeA;
            l.rows_[k] = (piece.b0 + (double(k) + 0.5) * dt) * edgeB;
        }
        return l;
    }
    // The lattice below `piece` of the segment corner + s edgeA.
    static LightLattice ofSegment(const BeamApex& apex, const Vec3& corner, const Vec3& edgeA,
                                  const LightPiece& piece, int depth) {
        LightLattice l(apex, depth);
        l.segment_ = true;
        const double ds = step(piece.a0, piece.a1, depth);
        for (int k = 0; k < l.side_; ++k) l.columns_[k] = corner + (piece.a0 + (double(k) + 0.5) * ds) * edgeA;
        return l;
    }

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
    __attribute__((always_inline)) BeamRay ray(int i, int j) const { return apex_.toward(point(i, j)); }
    // The light point at place (i, j) less the apex: ray(i, j)'s
    // direction, not normalised.
    Vec3 offset(int i, int j) const { return point(i, j) - apex_.point; }

private:
    LightLattice(const BeamApex& apex, int depth) : apex_(apex), side_(1 << depth) {}
    // The spacing of 2^depth equal steps from lo to hi, exactly (hi - lo) / 2^depth.
    static double step(double lo, double hi, int depth) {
        return (hi - lo) * std::bit_cast<double>(std::uint64_t(1023 - depth) << 52);
    }
    // The light point at place (i, j).
    __attribute__((always_inline)) Vec3 point(int i, int j) const {
        return segment_ ? columns_[i] : columns_[i] + rows_[j];
    }

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

    BeamApex apex_;
    bool segment_ = false;
    int side_ = 1;
    // The rectangle's point sum, its first two terms per column and its last
    // per row (the same operations in the same order); a segment's points.
    Vec3 columns_[16], rows_[16];
};

}  // namespace asos
