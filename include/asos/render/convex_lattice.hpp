#pragma once
// Which points of a small lattice lie in a convex set, from few membership
// tests: the shadow of one convex occluder on an area light's point samples
// (docs/lights.md, "Convex occluders").
//
// The lattice's points are an affine image of the integer points (i, j),
// 0 <= i < columns, 0 <= j < rows. A convex set K meets it in a set with
// these properties, which let most points be known without a test:
// - In every row the members are one run of consecutive columns, or none.
// - A lattice point on the segment between two members is a member. So in a
//   row between two rows with runs, every column between the interpolated
//   ends of the runs is a member: only the columns just past them are tested.
// - A lattice point p with a non-member r on the segment from a member q to
//   p is not a member. Row by row, with r the midpoint of q and p, this
//   bounds a row's run by the two rows before it (the ends of the runs move
//   at most linearly); and if row e has no member and a row r has a run
//   [l, h] with h - l >= |e - r| + 1, no row past e on the other side has a
//   member (the triangle of (l, r), (h, r) and such a member would cross row
//   e in an interval of length at least 1 within the columns).
//
// Every point is tested at most once, so the tests never exceed the points;
// a straight boundary across an 8 x 8 lattice takes about 18 of its 64
// (tests/unit/convex_lattice_test.cpp). A set with no point in the lattice
// takes every test: any untested point could be its one member. The answer
// is exact when the tests are exactly those of a convex set.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace asos {

class ConvexLattice {
public:
    static constexpr int kMaxSide = 16;

    // inside(i, j) -> bool: whether lattice point (i, j) lies in the set;
    // asked at most once per point. 1 <= columns, rows <= kMaxSide.
    template <class Inside>
    ConvexLattice(int columns, int rows, Inside&& inside) {
        // The search goes row by row, from a row with a member where a
        // corner shows one. Where the corners show a boundary from the left
        // side to the right (each row's corners alike, the rows unlike), or
        // the lattice is one column, it goes column by column instead: rows
        // wholly inside or outside cost more than the rows a boundary
        // crosses.
        bool corners[4] = {};
        if (columns > 1 && rows > 1) {
            corners[0] = inside(0, 0);
            corners[1] = inside(columns - 1, 0);
            corners[2] = inside(0, rows - 1);
            corners[3] = inside(columns - 1, rows - 1);
            tests_ = 4;
            transposed_ = corners[0] == corners[1] && corners[2] == corners[3] && corners[0] != corners[2];
        } else {
            transposed_ = columns == 1 && rows > 1;
        }
        columns_ = transposed_ ? rows : columns;
        rows_ = transposed_ ? columns : rows;
        if (columns > 1 && rows > 1) {
            // In this layout: (0, 0), (last, 0), (0, last), (last, last).
            const int c = columns_ - 1, r = rows_ - 1;
            mark(0, 0, corners[0]);
            mark(c, r, corners[3]);
            mark(transposed_ ? 0 : c, transposed_ ? r : 0, corners[1]);
            mark(transposed_ ? c : 0, transposed_ ? 0 : r, corners[2]);
        }
        if (transposed_) {
            auto swapped = [&](int i, int j) { return inside(j, i); };
            Solver<decltype(swapped)>{*this, swapped}.solve();
        } else {
            Solver<Inside>{*this, inside}.solve();
        }
    }

    bool member(int i, int j) const {
        if (transposed_) std::swap(i, j);
        return first_[j] <= i && i <= last_[j];
    }
    // How many points were tested.
    int tests() const { return tests_; }

private:
    void mark(int i, int j, bool in) { (in ? in_ : out_)[j] |= 1u << i; }

    // The search over rows (of the transposed lattice when transposed_).
    // Each row's known members and non-members are bit masks.
    template <class Inside>
    struct Solver {
        ConvexLattice& l;
        Inside& inside;

        static constexpr int kNoGuess = -1000;

        // Bits [lo, hi] (empty when lo > hi), 0 <= lo, hi < 32.
        static std::uint32_t bits(int lo, int hi) {
            return lo > hi ? 0u : ((2u << hi) - 1u) & ~((1u << lo) - 1u);
        }
        bool isKnown(int i, int j) const { return ((l.in_[j] | l.out_[j]) >> i) & 1u; }
        bool at(int i, int j) {
            const std::uint32_t bit = 1u << i;
            if (l.in_[j] & bit) return true;
            if (l.out_[j] & bit) return false;
            ++l.tests_;
            if (inside(i, j)) {
                l.in_[j] |= bit;
                return true;
            }
            l.out_[j] |= bit;
            return false;
        }
        bool empty(int j) const { return l.first_[j] > l.last_[j]; }
        void setRun(int j, int first, int last) {
            l.first_[j] = std::int8_t(first);
            l.last_[j] = std::int8_t(last);
            l.done_[j] = true;
        }
        void setEmpty(int j) { setRun(j, 0, -1); }

        // Row j's run, given that columns [lo, hi] are members, with guesses
        // of its first and last columns (kNoGuess: halving only).
        void runThrough(int j, int lo, int hi, int guessFirst, int guessLast) {
            // The nearest known non-members on either side; known members
            // between widen [lo, hi] (the run is contiguous).
            const std::uint32_t left = l.out_[j] & bits(0, lo - 1);
            int a = left ? 31 - __builtin_clz(left) : -1;
            if (const std::uint32_t in = l.in_[j] & bits(a + 1, lo - 1)) lo = __builtin_ctz(in);
            const std::uint32_t right = l.out_[j] & bits(hi + 1, l.columns_ - 1);
            int b = right ? __builtin_ctz(right) : l.columns_;
            if (const std::uint32_t in = l.in_[j] & bits(hi + 1, b - 1)) hi = 31 - __builtin_clz(in);
            // The first member in (a, lo]: the guessed boundary (the column
            // outside it, then the one inside), then halving.
            for (int probe = 0; lo - a > 1; ++probe) {
                int p = a + (lo - a) / 2;
                if (guessFirst != kNoGuess && probe < 2) p = std::clamp(guessFirst - 1 + probe, a + 1, lo - 1);
                (at(p, j) ? lo : a) = p;
            }
            for (int probe = 0; b - hi > 1; ++probe) {
                int p = hi + (b - hi) / 2;
                if (guessLast != kNoGuess && probe < 2) p = std::clamp(guessLast + 1 - probe, hi + 1, b - 1);
                (at(p, j) ? hi : b) = p;
            }
            setRun(j, lo, hi);
        }

        // Row j's run, found by testing the columns not known outward from
        // `hint` until one is a member.
        void search(int j, int hint, int guessFirst, int guessLast) {
            if (const std::uint32_t in = l.in_[j]) {
                runThrough(j, __builtin_ctz(in), __builtin_ctz(in), guessFirst, guessLast);
                return;
            }
            const std::uint32_t all = bits(0, l.columns_ - 1);
            hint = std::clamp(hint, 0, l.columns_ - 1);
            for (int d = 0; (l.out_[j] & all) != all && d < l.columns_; ++d) {
                const int side[2] = {hint + d, hint - d};
                for (int k = 0; k < (d == 0 ? 1 : 2); ++k) {
                    const int i = side[k];
                    if (i >= 0 && i < l.columns_ && at(i, j)) {
                        runThrough(j, i, i, guessFirst, guessLast);
                        return;
                    }
                }
            }
            setEmpty(j);
        }

        // Whether empty row e shows that the rows past it (one `step` on,
        // and on) are empty: a done row r on the other side has a run
        // [l, h] with h - l >= |e - r| + 1.
        bool emptiesBeyond(int e, int step) const {
            for (int r = e - step, distance = 1; r >= 0 && r < l.rows_; r -= step, ++distance)
                if (l.done_[r] && l.last_[r] - l.first_[r] >= distance + 1) return true;
            return false;
        }

        // The columns of row j known to be outside from the done rows
        // before it (p next to j, then a, a - step, ...): column c is outside
        // when the segment from c to a member q of a row a crosses row p at a
        // column outside p's run. With a d rows from j, the crossing is the
        // integer (q + (d - 1) c) / d when q = c (mod d), and it grows with
        // q: only the first and last such q of a's run count. Next to a row
        // with a run, only the row before it is used (d = 2, the midpoints);
        // next to an empty row, all of them.
        void boundFrom(int j, int p, int step) {
            const int n = l.columns_;
            for (int a = p - step, d = 2; a >= 0 && a < l.rows_ && l.done_[a]; a -= step, ++d) {
                if (!empty(p) && d > 2) return;
                if (empty(a)) continue;
                const int la = l.first_[a], ha = l.last_[a];
                // (c - la) mod d and (ha - c) mod d, kept as c steps on.
                int up = ((-la) % d + d) % d, down = ha % d;
                for (int c = 0; c < n; ++c) {
                    if (!isKnown(c, j)) {
                        const int qFirst = la + up, qLast = ha - down;
                        if (qFirst <= qLast) {
                            const int xFirst = (qFirst + (d - 1) * c) / d, xLast = (qLast + (d - 1) * c) / d;
                            if (empty(p) || xFirst < l.first_[p] || xLast > l.last_[p]) l.out_[j] |= 1u << c;
                        }
                    }
                    if (++up == d) up = 0;
                    if (--down < 0) down = d - 1;
                }
            }
        }

        // Rows a < j < b, where a and b are done and nothing between.
        void fill(int a, int b) {
            if (b - a < 2) return;
            if (!empty(a) && !empty(b)) {
                const int j = a + (b - a) / 2;
                interpolate(j, a, b);
                fill(a, j);
                fill(j, b);
            } else if (!empty(a)) {
                sweep(a, b, +1);
            } else if (!empty(b)) {
                sweep(b, a, -1);
            } else {
                const int j = a + (b - a) / 2;
                search(j, l.columns_ / 2, kNoGuess, kNoGuess);
                fill(a, j);
                fill(j, b);
            }
        }

        // Row j between done rows a and b with runs: the columns between the
        // interpolated ends are members (the segments from (first_a, a) to
        // (first_b, b) and from (last_a, a) to (last_b, b) lie in the set).
        void interpolate(int j, int a, int b) {
            const int span = b - a, u = j - a, v = b - j;
            // The ceiling and floor of (x_a v + x_b u) / span, all terms >= 0.
            const int lo = (l.first_[a] * v + l.first_[b] * u + span - 1) / span;
            const int hi = (l.last_[a] * v + l.last_[b] * u) / span;
            if (lo <= hi) {
                l.in_[j] |= bits(lo, hi);
                runThrough(j, lo, hi, lo, hi);
            } else {
                search(j, (lo + hi) / 2, lo, hi);
            }
        }

        // The rows from `from` (done, with a run) on by `step`, up to `to`
        // (excluded), each bounded and guessed from the rows before it.
        void sweep(int from, int to, int step) {
            for (int j = from + step; j != to; j += step) {
                const int p = j - step, pp = j - 2 * step;
                if (empty(p) && emptiesBeyond(p, step)) {
                    for (; j != to; j += step) setEmpty(j);
                    return;
                }
                boundFrom(j, p, step);
                if (empty(p)) {
                    search(j, l.columns_ / 2, kNoGuess, kNoGuess);
                    continue;
                }
                // The run's ends, extrapolated from the two rows before.
                int guessFirst = l.first_[p], guessLast = l.last_[p];
                if (pp >= 0 && pp < l.rows_ && l.done_[pp] && !empty(pp)) {
                    guessFirst = 2 * guessFirst - l.first_[pp];
                    guessLast = 2 * guessLast - l.last_[pp];
                }
                const int lo = std::max(guessFirst, 0), hi = std::min(guessLast, l.columns_ - 1);
                search(j, lo <= hi ? lo + (hi - lo) / 2 : (l.first_[p] + l.last_[p]) / 2, guessFirst, guessLast);
            }
        }

        void solve() {
            const int n = l.columns_, last = l.rows_ - 1;
            if (l.rows_ == 1) {
                search(0, n / 2, kNoGuess, kNoGuess);
                return;
            }
            // The corners are known: start from a row with a member among
            // them, the top row unless only the bottom row has one.
            const bool top = (l.in_[0] & bits(0, n - 1)) != 0, bottom = (l.in_[last] & bits(0, n - 1)) != 0;
            const bool fromBottom = !top && bottom;
            const int start = fromBottom ? last : 0, end = fromBottom ? 0 : last, step = fromBottom ? -1 : 1;
            const bool endMember = fromBottom ? top : bottom;
            search(start, n / 2, kNoGuess, kNoGuess);
            if (endMember || empty(start)) {
                // Both ends searched, then the rows between.
                search(end, n / 2, kNoGuess, kNoGuess);
                fill(0, last);
            } else {
                sweep(start, end + step, step);
            }
        }
    };

    int columns_ = 0, rows_ = 0;
    bool transposed_ = false;
    int tests_ = 0;
    std::array<std::uint32_t, kMaxSide> in_{}, out_{};  // per row: known members, known non-members
    std::array<std::int8_t, kMaxSide> first_{}, last_{};
    std::array<bool, kMaxSide> done_{};
};

}  // namespace asos
