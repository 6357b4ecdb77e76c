#include "asos/shapes/box.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

namespace {

// The slab test: the interval of t over which the line o + t d is inside the
// box, and the axes through which it enters and leaves.
struct Slab {
    bool hit = false;
    double tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1, exitAxis = -1;
};

Slab slab(const Vec3& lo, const Vec3& hi, const Vec3& o, const Vec3& d) {
    Slab s;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (o[i] < lo[i] || o[i] > hi[i]) return s;
            continue;
        }
        const double inv = 1.0 / d[i];
        double t0 = (lo[i] - o[i]) * inv, t1 = (hi[i] - o[i]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > s.tEnter) {
            s.tEnter = t0;
            s.enterAxis = i;
        }
        if (t1 < s.tExit) {
            s.tExit = t1;
            s.exitAxis = i;
        }
    }
    s.hit = s.tEnter <= s.tExit;
    return s;
}

double sq(double x) { return x * x; }

// The part (SurfaceHit::part) of the face on side `hi` of axis i.
constexpr int facePart(int i, int hi) { return 2 * i + hi; }

// The edges seen from each of the 27 places of the apex (front[i] in
// {-1, 0, 1} per axis: below, within or above the slab), as pairs of corners
// (bit i of a corner: hi on axis i): the silhouette, between a face turned to
// the apex and one turned away, and the creases, between two faces turned to
// it (at most three), with the two faces' parts as bits. Tables, so that the
// passes over them have no branch on where the apex is.
struct EdgeTable {
    int silhouetteCount[27] = {};
    int silhouette[27][12][2] = {};
    int creaseCount[27] = {};
    int crease[27][3][2] = {};
    std::uint8_t creaseParts[27][3] = {};
};

constexpr EdgeTable makeEdgeTable() {
    EdgeTable t;
    for (int place = 0; place < 27; ++place) {
        const int front[3] = {place % 3 - 1, place / 3 % 3 - 1, place / 9 - 1};
        for (int k = 0; k < 3; ++k) {  // edges along axis k
            const int i = (k + 1) % 3, j = (k + 2) % 3;
            for (int si = 0; si < 2; ++si) {
                for (int sj = 0; sj < 2; ++sj) {
                    const bool frontI = front[i] == (si ? 1 : -1);
                    const bool frontJ = front[j] == (sj ? 1 : -1);
                    const int base = (si << i) | (sj << j);
                    if (frontI != frontJ) {
                        const int n = t.silhouetteCount[place]++;
                        t.silhouette[place][n][0] = base;
                        t.silhouette[place][n][1] = base | (1 << k);
                    } else if (frontI) {
                        const int n = t.creaseCount[place]++;
                        t.crease[place][n][0] = base;
                        t.crease[place][n][1] = base | (1 << k);
                        t.creaseParts[place][n] =
                            static_cast<std::uint8_t>((1 << facePart(i, si)) | (1 << facePart(j, sj)));
                    }
                }
            }
        }
    }
    return t;
}

constexpr EdgeTable kEdges = makeEdgeTable();

}  // namespace

Bounds3 Box::worldBounds(const Mat3& m, const Vec3& offset) const {
    Bounds3 b;
    for (int i = 0; i < 8; ++i) {
        const Vec3 c((i & 1) ? hi_.x : lo_.x, (i & 2) ? hi_.y : lo_.y, (i & 4) ? hi_.z : lo_.z);
        b.extend(m * c + offset);
    }
    return b;
}

std::optional<LocalHit> Box::intersect(const Ray& ray, double tMin, double tMax) const {
    const Slab s = slab(lo_, hi_, ray.origin, ray.dir);
    if (!s.hit) return std::nullopt;
    double t;
    int axis;
    double sign;
    if (s.tEnter >= tMin && s.tEnter <= tMax && s.enterAxis >= 0) {
        t = s.tEnter;
        axis = s.enterAxis;
        sign = ray.dir[axis] > 0.0 ? -1.0 : 1.0;
    } else if (s.tExit >= tMin && s.tExit <= tMax && s.exitAxis >= 0) {
        t = s.tExit;
        axis = s.exitAxis;
        sign = ray.dir[axis] > 0.0 ? 1.0 : -1.0;
    } else {
        return std::nullopt;
    }
    Vec3 n(0.0);
    n[axis] = sign;
    Vec3 p = ray.at(t);
    p[axis] = (sign > 0.0) ? hi_[axis] : lo_[axis];  // exactly on the face
    return LocalHit{t, p, n, static_cast<std::uint8_t>(2 * axis + (sign > 0.0 ? 1 : 0))};
}

bool Box::intersectAny(const Ray& ray, double tMin, double tMax) const {
    const Slab s = slab(lo_, hi_, ray.origin, ray.dir);
    return s.hit && ((s.tEnter >= tMin && s.tEnter <= tMax && s.enterAxis >= 0) ||
                     (s.tExit >= tMin && s.tExit <= tMax && s.exitAxis >= 0));
}

ConeClass Box::classify(const LocalCone& cone) const {
    return classifyWith(cone, [] {}, LocalFinish{cone});
}

ConeClass Box::classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
    return classifyWith(cone, [&] { cone.setRange(t0, t1, cone.absTol); }, back);
}

// `finish` is LocalFinish (the cone's range is set) or RigidBounds (it is
// not, until setRange): the fast path's range tests and answers go through
// it, the rest sets the range and hands its answer to it.
template <class SetRange, class Finish>
ConeClass Box::classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const {
    const Vec3& p = cone.apex;
    const Vec3& a = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    // Positional tolerance: within it the apex counts as on the surface.
    const double tol =
        kTensOfUlps * ((std::abs(p.x) + std::abs(p.y) + std::abs(p.z)) + cornerAbsSum_) + cone.absTol;
    bool outside = false, inside = true;
    double far2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        // Flags, not branches: where the apex lies is as good as random.
        outside |= (p[i] < lo_[i] - tol) | (p[i] > hi_[i] + tol);
        inside &= (p[i] > lo_[i] + tol) & (p[i] < hi_[i] - tol);
        far2 += std::max(sq(p[i] - lo_[i]), sq(p[i] - hi_[i]));
    }
    if (outside && c > 0.0) {
        // Fast path. Up to the farthest corner, dFar, the cone lies within
        // r = dFar sin(theta) of its axis: if the axis misses the box grown
        // by r, so does the cone, and no hit is nearer than the grown box.
        // If the footprint on the face the axis enters through lies inside
        // that face, every ray enters there.
        const double dFar = std::sqrt(far2);
        const double r = dFar * s + tol;
        double enter = -kInfinity, exit = kInfinity, grownEnter = -kInfinity, grownExit = kInfinity;
        int enterAxis = -1;
        bool hits = true;
        // The three reciprocals, named apart from the branches below (an
        // a[i] == 0 gives an infinity that is never used). GCC still places
        // each in its iteration; this build measured ~0.7 ns faster with
        // them named here than without (docs/geometry.md, Box).
        const double invA[3] = {1.0 / a.x, 1.0 / a.y, 1.0 / a.z};
        for (int i = 0; i < 3; ++i) {
            if (a[i] == 0.0) {
                if (p[i] < lo_[i] - r || p[i] > hi_[i] + r) return missClass();
                hits = hits && p[i] >= lo_[i] && p[i] <= hi_[i];
                continue;
            }
            const double inv = invA[i];
            const double tLo = (lo_[i] - p[i]) * inv, tHi = (hi_[i] - p[i]) * inv;
            const double t0 = std::min(tLo, tHi), t1 = std::max(tLo, tHi);  // no branch
            const double spread = r * std::abs(inv);
            grownEnter = std::max(grownEnter, t0 - spread);
            grownExit = std::min(grownExit, t1 + spread);
            // Selected, not branched to: which face the axis enters through
            // is as good as random from one cone to the next.
            enterAxis += (i - enterAxis) * static_cast<int>(t0 > enter);
            enter = std::max(enter, t0);
            exit = std::min(exit, t1);
        }
        if ((grownEnter > grownExit) | (grownExit < 0.0) | (grownEnter > dFar) |
            finish.surelyAfter(std::max(0.0, grownEnter)) | finish.surelyBefore(dFar))
            return missClass();
        if (hits & (enterAxis >= 0) & (enter <= exit) & (enter >= 0.0)) {
            // Indexed by the entry axis, which is as good as random: plain
            // arrays (a vector's operator[] with a variable index is a
            // chain of branches on it).
            const double pa[3] = {p.x, p.y, p.z}, aa[3] = {a.x, a.y, a.z};
            const double loa[3] = {lo_.x, lo_.y, lo_.z}, hia[3] = {hi_.x, hi_.y, hi_.z};
            constexpr int kNext[3] = {1, 2, 0}, kAfter[3] = {2, 0, 1};
            const int e = enterAxis, j = kNext[e], k = kAfter[e];
            const double an = std::abs(aa[e]);
            const double g2 = aa[j] * aa[j] + aa[k] * aa[k];
            const double kk = c * c - g2;
            const bool above = pa[e] > hia[e];
            const double face = (above ? hia : loa)[e];
            if ((kk > kFootprintMinK) & (above | (pa[e] < loa[e]))) {
                // The footprint ellipse lies within `radius` of the axis'
                // entry point (see Polygon::classify).
                const double depth = std::abs(face - pa[e]);
                const double g = std::sqrt(g2);
                const auto [tNear, tFar] = planeDepthsWithG(depth, an, g2, g, c, s);
                // Both sides times kk an > 0: no division.
                const double scale = kk * an;
                const double reach = padUp(depth * s * (c * an + g * s)) + tol * scale;
                const double qj = pa[j] + enter * aa[j], qk = pa[k] + enter * aa[k];
                if (((qj - loa[j]) * scale > reach) & ((hia[j] - qj) * scale > reach) &
                    ((qk - loa[k]) * scale > reach) & ((hia[k] - qk) * scale > reach)) {
                    if (finish.surelyWithin(tNear, tFar)) return finish.full(tNear, tFar);
                    if (finish.surelyAfter(tNear)) return missClass();
                    return finish.marginal(tNear, finish.startsWithin(tNear) ? tFar : dFar);
                }
            }
        }
        setRange();
        return finish(classifyOutside(cone));
    }
    setRange();
    const BoundingSphere ball = boundingSphere();
    if (ballOutside(cone, ball.center, ball.radius)) return missClass();
    if (outside) return finish(classifyOutside(cone));
    if (inside) return finish(classifyInside(cone));
    return finish(classifyOnSurface(cone, tol));
}

ConeClass Box::classifyOutside(const LocalCone& cone) const {
    const Vec3& p = cone.apex;
    // Depths: the nearest point of the box, the farthest corner, and the
    // farthest point of the faces turned to the apex (where rays enter).
    Vec3 gap, far2;
    int front[3];  // +1: the hi face of this axis faces the apex, -1: the lo face, 0: neither
    for (int i = 0; i < 3; ++i) {
        front[i] = int(p[i] > hi_[i]) - int(p[i] < lo_[i]);
        gap[i] = std::max({lo_[i] - p[i], 0.0, p[i] - hi_[i]});
        far2[i] = std::max(sq(p[i] - lo_[i]), sq(p[i] - hi_[i]));
    }
    const double dNear = glm::length(gap);
    const double dFar = std::sqrt(far2.x + far2.y + far2.z);
    if (cone.surelyAfter(dNear) || cone.surelyBefore(dFar)) return missClass();
    double frontFar2 = 0.0;
    for (int i = 0; i < 3; ++i)
        if (front[i] != 0)
            frontFar2 = std::max(frontFar2, sq(gap[i]) + far2[(i + 1) % 3] + far2[(i + 2) % 3]);
    const double frontFar = std::sqrt(frontFar2);
    const double firstFar = dNear >= cone.tMinInner ? frontFar : dFar;

    const Slab axisSlab = slab(lo_, hi_, p, cone.axis);
    const bool axisHits = axisSlab.hit && axisSlab.tExit >= 0.0;

    // The silhouette: edges between a face turned to the apex and one turned
    // away (paper: "Detection Phase"; the boundary seen from the apex).
    const Vec3* bounds[2] = {&lo_, &hi_};
    auto cornerPoint = [&](int c) {
        return Vec3(bounds[c & 1]->x, bounds[(c >> 1) & 1]->y, bounds[(c >> 2) & 1]->z);
    };
    ConePoint corner[8];
    unsigned known = 0;  // corners computed so far (only silhouette ends are needed)
    auto cornerAt = [&](int c) -> const ConePoint& {
        if (!(known & (1u << c))) {
            corner[c] = conePoint(cone, cornerPoint(c) - p);
            known |= 1u << c;
        }
        return corner[c];
    };
    // Up to the farthest corner, a cone narrower than a hemisphere lies
    // within `reach` of its axis line: an edge farther from that line is
    // out of it, which is cheaper to see than the exact test.
    const Vec3& a = cone.axis;
    const double reach = padUp(dFar * cone.sinHalf) + 2.0 * cone.absTol + kThousandsOfUlps * dFar;
    // The edges are along the box's axes, so their squared distance to the
    // axis line is a quadratic in the place along the edge, with
    // coefficients from per-axis sums: each corner's depth along the axis
    // (sigma) and squared distance from the apex are sums of one term per
    // axis, and an edge along axis k has |e|^2 (1 - a_k^2) for its leading
    // coefficient. The minimum is compared multiplied through (no
    // division). Plain arrays: the corner and the edge's axis are indices
    // as good as random. The quadratic's rounding (a few ulps of
    // dFar^2, from |w|^2 - sigma^2) is covered by `slack`.
    const double pa[3] = {p.x, p.y, p.z}, aa[3] = {a.x, a.y, a.z};
    const double loa[3] = {lo_.x, lo_.y, lo_.z}, hia[3] = {hi_.x, hi_.y, hi_.z};
    double rel[3][2], relSq[3][2], relA[3][2], len[3], lead[3];
    double len2Sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        rel[i][0] = loa[i] - pa[i];
        rel[i][1] = hia[i] - pa[i];
        relSq[i][0] = rel[i][0] * rel[i][0];
        relSq[i][1] = rel[i][1] * rel[i][1];
        relA[i][0] = rel[i][0] * aa[i];
        relA[i][1] = rel[i][1] * aa[i];
        len[i] = hia[i] - loa[i];
        lead[i] = len[i] * len[i] * std::max(0.0, 1.0 - aa[i] * aa[i]);
        len2Sum += len[i] * len[i];
    }
    const double slack = kHundredsOfUlps * (dFar * dFar + len2Sum);
    const double reach2 = cone.cosHalf > 0.0 ? reach * reach + slack : kInfinity;
    auto farFromAxis = [&](int c0, int c1) {
        // c1 is c0 with bit k set: the edge runs from c0 along +k.
        const int bits = c0 ^ c1, k = ((bits >> 1) & 1) + 2 * ((bits >> 2) & 1);
        const int x = c0 & 1, y = (c0 >> 1) & 1, z = (c0 >> 2) & 1;
        const double sigma = relA[0][x] + relA[1][y] + relA[2][z];
        const double w2 = relSq[0][x] + relSq[1][y] + relSq[2][z];
        // f(u) = A + 2 B u + C u^2, u in [0, 1] along the edge.
        const double qa = w2 - sigma * sigma;
        const double qb = len[k] * (rel[k][0] - sigma * aa[k]);
        const double qc = lead[k];
        // No branch: the nearest point's place is as good as random. The
        // minimum over [0, 1] exceeds reach2 when both ends do and the
        // vertex -B/C is outside (0, 1) or its value A - B^2/C does.
        const bool ends = (qa > reach2) & (qa + 2.0 * qb + qc > reach2);
        const bool vertex = (qb >= 0.0) | (-qb >= qc) | ((qa - reach2) * qc > qb * qb);
        return ends & vertex;
    };
    // Whether the edge between two corners meets the cone, and whether an
    // end of it lies inside.
    struct EdgeMeeting {
        bool meets = false, endInside = false;
    };
    auto edgeMeeting = [&](const int (&edge)[2]) {
        if (farFromAxis(edge[0], edge[1])) return EdgeMeeting{};
        const ConePoint& from = cornerAt(edge[0]);
        const ConePoint& to = cornerAt(edge[1]);
        return EdgeMeeting{segmentMeetsCone(cone, from, to), from.inside || to.inside};
    };
    const int place = (front[0] + 1) + 3 * (front[1] + 1) + 9 * (front[2] + 1);
    int meeting = 0;
    bool endpointInside = false;
    for (int n = 0; n < kEdges.silhouetteCount[place] && meeting < 2; ++n) {  // two meeting settle it
        const EdgeMeeting m = edgeMeeting(kEdges.silhouette[place][n]);
        if (m.meets) {
            ++meeting;
            endpointInside = endpointInside || m.endInside;
        }
    }
    if (meeting > 0) {
        const bool single = meeting == 1 && !endpointInside && cone.surelyWithin(dNear, dFar);
        return marginalClass(cone, dNear, firstFar, single);
    }
    // No silhouette in the cone: every ray hits or none does, as the axis.
    if (!axisHits) return missClass();
    if (!cone.surelyWithin(dNear, frontFar)) return marginalClass(cone, dNear, firstFar);
    // Full: the creases, edges between two faces turned to the apex, the
    // cone may hold (the rays may see both faces of each).
    ConeClass out = fullClass(dNear, frontFar);
    if (!cone.creases) return out;
    int creases = 0;
    for (int n = 0; n < kEdges.creaseCount[place]; ++n) {
        const EdgeMeeting m = edgeMeeting(kEdges.crease[place][n]);
        if (m.meets) {
            ++creases;
            out.creaseParts |= kEdges.creaseParts[place][n];
            endpointInside = endpointInside || m.endInside;
        }
    }
    // The face the axis enters by: a ray on another face passed, on its way
    // from the axis within the cone, a crease found above (one found to
    // rounding only may have none beside it).
    if (creases > 0 && axisSlab.enterAxis >= 0) {
        const int e = axisSlab.enterAxis;
        out.creaseParts |= static_cast<std::uint8_t>(1 << facePart(e, cone.axis[e] > 0.0 ? 0 : 1));
    }
    out.singleEdge = creases == 1 && !endpointInside;
    return out;
}

ConeClass Box::withEveryCrease(const LocalCone& cone, ConeClass full) const {
    if (!cone.creases) return full;
    const Vec3* bounds[2] = {&lo_, &hi_};
    ConePoint corner[8];
    for (int c = 0; c < 8; ++c)
        corner[c] = conePoint(cone, Vec3(bounds[c & 1]->x, bounds[(c >> 1) & 1]->y, bounds[(c >> 2) & 1]->z) -
                                        cone.apex);
    int creases = 0;
    bool endpointInside = false;
    for (int k = 0; k < 3; ++k) {  // the edges along axis k, from the corners without bit k
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (int c0 = 0; c0 < 8; ++c0) {
            if (c0 & (1 << k)) continue;
            const int c1 = c0 | (1 << k);
            if (!segmentMeetsCone(cone, corner[c0], corner[c1])) continue;
            ++creases;
            full.creaseParts |= static_cast<std::uint8_t>((1 << facePart(i, (c0 >> i) & 1)) |
                                                          (1 << facePart(j, (c0 >> j) & 1)));
            endpointInside = endpointInside || corner[c0].inside || corner[c1].inside;
        }
    }
    // The face the axis leaves by, as above.
    if (creases > 0)
        if (const std::optional<LocalHit> hit = intersect(Ray{cone.apex, cone.axis}, cone.tMin, cone.tMax))
            full.creaseParts |= static_cast<std::uint8_t>(1 << hit->part);
    full.singleEdge = creases == 1 && !endpointInside;
    return full;
}

ConeClass Box::classifyInside(const LocalCone& cone) const {
    // Every ray leaves: no sooner than the nearest face plane, no later than
    // the farthest corner.
    const Vec3& p = cone.apex;
    double exitNear = kInfinity, far2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        exitNear = std::min({exitNear, p[i] - lo_[i], hi_[i] - p[i]});
        far2 += std::max(sq(p[i] - lo_[i]), sq(p[i] - hi_[i]));
    }
    const double exitFar = std::sqrt(far2);
    if (cone.surelyAfter(exitNear) || cone.surelyBefore(exitFar)) return missClass();
    if (cone.surelyWithin(exitNear, exitFar)) return withEveryCrease(cone, fullClass(exitNear, exitFar));
    return marginalClass(cone, exitNear, exitFar);
}

ConeClass Box::classifyOnSurface(const LocalCone& cone, double tol) const {
    // The apex is on the surface (to rounding). The box lies behind each face
    // plane: rays leaving through a face the apex is on meet the box again
    // only within t <= tol / (n.d).
    const Vec3& p = cone.apex;
    double far2 = 0.0;
    for (int i = 0; i < 3; ++i) far2 += std::max(sq(p[i] - lo_[i]), sq(p[i] - hi_[i]));
    const double dFar = std::sqrt(far2) + tol;
    // Rays turned into the box through every face the apex is on have
    // entered by entryFar and leave no sooner than the nearest other face.
    bool allInward = true;
    double exitNear = kInfinity, entryFar = 0.0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const double g = std::sqrt(sq(cone.axis[j]) + sq(cone.axis[k]));
        for (int side = 0; side < 2; ++side) {
            const double sign = side ? 1.0 : -1.0;
            const double gapOut = side ? p[i] - hi_[i] : lo_[i] - p[i];  // > 0 outside
            if (std::abs(gapOut) > tol) {
                exitNear = std::min(exitNear, -gapOut);
                continue;
            }
            const DotRange r = dotRange(cone, sign * cone.axis[i], g);
            if (r.lo > 0.0) {
                const double tHit = (tol + std::max(0.0, -gapOut)) / r.lo;
                if (cone.surelyBefore(tHit)) return missClass();
            }
            if (r.hi < 0.0) entryFar = std::max(entryFar, (tol + std::max(0.0, gapOut)) / -r.hi);
            else allInward = false;
        }
    }
    if (cone.surelyBefore(dFar)) return missClass();
    if (allInward && entryFar < 0.5 * exitNear && cone.surelyWithin(exitNear, dFar)) {
        // Rays from a point of the surface: which face each sees first is up
        // to rounding at its start; any of them.
        ConeClass out = fullClass(cone.tMin, dFar);
        if (cone.creases) out.creaseParts = 0x3f;
        return out;
    }
    return marginalClass(cone, cone.tMin, dFar);
}

HoldingPlanes Box::holdingPlanes(const Vec3& point) const {
    HoldingPlanes h;
    // A box of no thickness along an axis is flat: that axis' planes first.
    int first = 0;
    for (int i = 2; i >= 0; --i)
        if (lo_[i] == hi_[i]) first = i;
    h.flat = lo_[first] == hi_[first];
    for (int n = 0; n < 3; ++n) {
        const int i = (first + n) % 3;
        Vec3 e(0.0);
        e[i] = 1.0;
        h.add(e, hi_[i]);
        h.add(-e, -lo_[i]);
    }
    // Outside (beyond the positional tolerance that classify uses), every
    // face on a plane that holds the box on the point's side faces away.
    const double tol = kTensOfUlps * (l1Norm(point) + cornerAbsSum_);
    bool outside = false;
    for (int i = 0; i < 3; ++i) outside = outside || point[i] < lo_[i] - tol || point[i] > hi_[i] + tol;
    h.thinContact = !h.flat && outside;
    return h;
}

bool Box::raysLeave(const LocalRays& rays) const {
    const Vec3& a = rays.origin;
    for (int i = 0; i < 3; ++i) {
        Vec3 n(0.0);
        n[i] = 1.0;
        if (a[i] <= lo_[i] && rays.awayFrom(-n)) return true;
        if (a[i] >= hi_[i] && rays.awayFrom(n)) return true;
    }
    return false;
}

std::vector<ShapeIssue> validate(const BoxShape& record) {
    IssueList issues;
    issues.finite(0, record.corner1, "the first corner of a box");
    issues.finite(1, record.corner2, "the second corner of a box");
    return issues.take();
}

Placed<Box> place(const BoxShape& record, const Transform& worldFromObject) {
    return {Box(record.corner1, record.corner2), LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)),
            Box::kName};
}

}  // namespace asos
