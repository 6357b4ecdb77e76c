#include <catch2/catch.hpp>

#include "asos/render/subdivision_criterion.hpp"

using namespace asos;

namespace {
SubdivisionTally tally(int in, int out, bool singleEdge, std::uint32_t object = 0) {
    SubdivisionTally t;
    for (int i = 0; i < in; ++i) t.add(object, true, singleEdge);
    for (int i = 0; i < out; ++i) t.add(object, false, singleEdge);
    return t;
}
}  // namespace

TEST_CASE("The paper's Table 1: a polygon inside a pixel, EPS = 1/16", "[criterion]") {
    // K, in, out, L/2^(2K) as printed in the paper.
    struct Row { int k, in, out; double bound; bool stop; };
    const Row rows[] = {{1, 0, 3, 0.7500, false},
                        {2, 0, 5, 0.3125, false},
                        {3, 4, 8, 0.1250, false},
                        {4, 13, 15, 0.0586, true}};
    for (const Row& r : rows) {
        const SubdivisionTally t = tally(r.in, r.out, false);
        CHECK(t.changeBound(r.k) == Approx(r.bound).margin(5e-5));
        CHECK(stopSubdividing(t, r.k, 1.0 / 16, 8) == r.stop);
    }
}

TEST_CASE("The paper's Table 2: one edge, EPS = 1/16, stops at level 3", "[criterion]") {
    struct Row { int k, in, out; double bound; bool stop; };
    const Row rows[] = {{1, 1, 2, 0.2500, false}, {2, 3, 3, 0.0938, false}, {3, 6, 7, 0.0547, true}};
    for (const Row& r : rows) {
        const SubdivisionTally t = tally(r.in, r.out, true);
        CHECK(t.changeBound(r.k) == Approx(r.bound).margin(5e-5));
        CHECK(stopSubdividing(t, r.k, 1.0 / 16, 8) == r.stop);
    }
}

TEST_CASE("One edge: the paper's bound K >= log2(1/EPS) - 1 always stops", "[criterion]") {
    // A single edge crosses at most 2^K of the 4^K K-pyrays, so L <= 2^K.
    for (int e = 2; e <= 10; ++e) {
        const double eps = std::ldexp(1.0, -e);
        const int k = e - 1;
        const SubdivisionTally worst = tally(1 << k, 0, true);
        CHECK(stopSubdividing(worst, k, eps, 16));
    }
}

TEST_CASE("Several objects: the per-object terms add up", "[criterion]") {
    SubdivisionTally t;
    t.add(7, true, false);
    t.add(7, false, false);
    t.add(7, false, false);  // object 7: L = 2
    t.add(9, true, true);    // object 9: L = 1, single edge: halved
    CHECK(t.changeBound(1) == Approx((2.0 + 0.5) / 4.0));
    // A pyray marginal on two objects counts for both; one object alone reduces to the paper.
    CHECK(tally(5, 3, false, 7).changeBound(2) == Approx(5.0 / 16.0));
}

TEST_CASE("MAX always stops, whatever the bound", "[criterion]") {
    const SubdivisionTally t = tally(100, 100, false);
    CHECK_FALSE(stopSubdividing(t, 3, 1e-9, 4));
    CHECK(stopSubdividing(t, 4, 1e-9, 4));
    CHECK(stopSubdividing(SubdivisionTally{}, 0, 1.0 / 64, 4));
}

TEST_CASE("The least bound: what the bound is at least, whatever the central rays say", "[criterion]") {
    // For every split of n pyrays into in + out, the bound is at least the
    // least bound of the same pyrays, which one split reaches.
    for (int n = 1; n <= 9; ++n)
        for (const bool single : {false, true}) {
            const double least = tally(0, n, single).leastChangeBoundForShare(1.0 / 16.0);
            double smallest = 1e300;
            for (int in = 0; in <= n; ++in) {
                const SubdivisionTally t = tally(in, n - in, single);
                CHECK(t.leastChangeBoundForShare(1.0 / 16.0) == least);
                CHECK(t.changeBoundForShare(1.0 / 16.0) >= least);
                smallest = std::min(smallest, t.changeBoundForShare(1.0 / 16.0));
            }
            CHECK(smallest == least);
        }
    // Several objects add up.
    SubdivisionTally t;
    t.add(7, true, false);
    t.add(7, false, false);
    t.add(7, false, false);  // object 7: at least 2 of 3
    t.add(9, true, true);    // object 9: at least 1, halved
    CHECK(t.leastChangeBoundForShare(0.25) == Approx((2.0 + 0.5) / 4.0));
}

TEST_CASE("Creases: two parts beside one edge are the paper's edge, parts count half, a tip whole",
          "[criterion]") {
    // One straight crease between parts 1 and 4 of object 3 across 13
    // pyrays, 6 K-rays on part 1: exactly Table 2's level 3 (in 6, out 7).
    SubdivisionTally two;
    for (int i = 0; i < 13; ++i) {
        two.addPart(3, 1, i < 6, true);
        two.addPart(3, 4, i >= 6, true);
    }
    CHECK(two.changeBound(3) == Approx(tally(6, 7, true).changeBound(3)));
    // Three parts about a corner, not single: half of each part's term.
    SubdivisionTally three;
    const int seen[] = {1, 1, 3, 4, 4, 4};
    for (int part : {1, 3, 4})
        for (int k : seen) three.addPart(3, static_cast<std::uint8_t>(part), k == part, false);
    CHECK(three.changeBound(1) == Approx(0.5 * (4 + 5 + 3) / 4.0));
    // Beside the object's own outline, in entries of their own; a tip
    // counts its pyrays whole.
    SubdivisionTally both;
    both.add(3, true, false);
    both.addPart(3, 0, true, false);
    both.addPart(3, 2, false, false);
    both.addTip(3);
    both.addTip(3);
    CHECK(both.entries().size() == 4);
    CHECK(both.changeBound(0) == Approx(1.0 + 0.5 + 0.5 + 2.0));
}
