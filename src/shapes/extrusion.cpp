#include "asos/shapes/extrusion.hpp"

#include <algorithm>
#include <cmath>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/box.hpp"
#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

namespace {

double eval(const double* c, int degree, double s) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * s + c[i];
    return v;
}

// The roots of c[0] + c[1] s + ... (degree <= 3) where it changes sign
// (from <= 0 to > 0 or back) on [0, 1], each on a stretch where it is
// monotone, by bisection; at most 3. A sign change at s = 1 counts, one at
// s = 0 does not: a piece's end is its successor's start, so along a closed
// contour each sign change is counted once.
int signChanges(const double* c, int degree, double* roots) {
    double cuts[4];
    int n = 0;
    cuts[n++] = 0.0;
    if (degree == 2 && c[2] != 0.0) {
        const double s = -c[1] / (2.0 * c[2]);
        if (s > 0.0 && s < 1.0) cuts[n++] = s;
    } else if (degree == 3) {
        // 3 c3 s^2 + 2 c2 s + c1 = 0
        const double a = 3.0 * c[3], b = 2.0 * c[2], k = c[1];
        double r[2];
        int m = 0;
        if (a == 0.0) {
            if (b != 0.0) r[m++] = -k / b;
        } else {
            const double disc = b * b - 4.0 * a * k;
            if (disc > 0.0) {
                const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
                r[m++] = q / a;
                if (q != 0.0) r[m++] = k / q;
            }
        }
        if (m == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
        for (int i = 0; i < m; ++i)
            if (r[i] > 0.0 && r[i] < 1.0) cuts[n++] = r[i];
    }
    cuts[n++] = 1.0;
    int count = 0;
    for (int i = 0; i + 1 < n; ++i) {
        double a = cuts[i], b = cuts[i + 1];
        const bool above = eval(c, degree, a) > 0.0;
        if ((eval(c, degree, b) > 0.0) == above) continue;
        for (int k = 0; k < 80; ++k) {
            const double m = 0.5 * (a + b);
            if (m <= a || m >= b) break;
            if ((eval(c, degree, m) > 0.0) == above) a = m;
            else b = m;
        }
        roots[count++] = b;
    }
    return count;
}

double derivative(const double* c, int degree, double s) {
    double v = 0.0;
    for (int i = degree; i >= 1; --i) v = v * s + i * c[i];
    return v;
}

// Power-basis coefficients of a Bezier coordinate.
void powerBasis(const double* p, int degree, double* out) {
    switch (degree) {
    case 1:
        out[0] = p[0];
        out[1] = p[1] - p[0];
        break;
    case 2:
        out[0] = p[0];
        out[1] = 2.0 * (p[1] - p[0]);
        out[2] = p[0] - 2.0 * p[1] + p[2];
        break;
    default:
        out[0] = p[0];
        out[1] = 3.0 * (p[1] - p[0]);
        out[2] = 3.0 * (p[0] - 2.0 * p[1] + p[2]);
        out[3] = -p[0] + 3.0 * (p[1] - p[2]) + p[3];
        break;
    }
}

// Sign changes along a +x ray from (x, z) over some pieces.
int crossingsRight(const std::vector<Extrusion::Piece>& pieces, std::size_t from, std::size_t to, double x,
                   double z) {
    int count = 0;
    for (std::size_t i = from; i < to; ++i) {
        const Extrusion::Piece& p = pieces[i];
        if (p.hi[0] < x || p.lo[1] > z || p.hi[1] < z) continue;
        double c[4] = {p.az[0] - z, p.az[1], p.az[2], p.az[3]};
        double roots[3];
        const int n = signChanges(c, p.degree, roots);
        for (int k = 0; k < n; ++k)
            if (eval(p.ax, p.degree, roots[k]) > x) ++count;
    }
    return count;
}

}  // namespace

Extrusion::Extrusion(const std::vector<OutlineContour>& contours, double y0, double y1, bool open)
    : y0_(y0), y1_(y1), open_(open) {
    std::vector<std::size_t> starts;
    std::vector<double> areas;
    double lx = kInfinity, lz = kInfinity, hx = -kInfinity, hz = -kInfinity;
    for (const OutlineContour& contour : contours) {
        starts.push_back(pieces_.size());
        double area = 0.0;
        for (const OutlinePiece& op : contour.pieces) {
            Piece p;
            p.degree = std::clamp(op.degree, 1, 3);
            for (int i = 0; i <= p.degree; ++i) {
                p.px[i] = op.p[2 * i];
                p.pz[i] = op.p[2 * i + 1];
            }
            powerBasis(p.px, p.degree, p.ax);
            powerBasis(p.pz, p.degree, p.az);
            p.lo[0] = *std::min_element(p.px, p.px + p.degree + 1);
            p.hi[0] = *std::max_element(p.px, p.px + p.degree + 1);
            p.lo[1] = *std::min_element(p.pz, p.pz + p.degree + 1);
            p.hi[1] = *std::max_element(p.pz, p.pz + p.degree + 1);
            for (int i = 0; i < p.degree; ++i) area += p.px[i] * p.pz[i + 1] - p.px[i + 1] * p.pz[i];
            lx = std::min(lx, p.lo[0]);
            hx = std::max(hx, p.hi[0]);
            lz = std::min(lz, p.lo[1]);
            hz = std::max(hz, p.hi[1]);
            pieces_.push_back(p);
        }
        areas.push_back(area);
    }
    starts.push_back(pieces_.size());
    // The region lies just inside a contour iff an even number of the other
    // contours hold it; its outward normal then points away from the
    // contour's interior (the right of a counterclockwise contour).
    for (std::size_t c = 0; c + 1 < starts.size(); ++c) {
        if (starts[c] == starts[c + 1]) continue;
        const Piece& first = pieces_[starts[c]];
        int depth = 0;
        for (std::size_t o = 0; o + 1 < starts.size(); ++o)
            if (o != c && crossingsRight(pieces_, starts[o], starts[o + 1], first.px[0], first.pz[0]) % 2 == 1)
                ++depth;
        const double sign = (areas[c] >= 0.0 ? 1.0 : -1.0) * (depth % 2 == 0 ? 1.0 : -1.0);
        for (std::size_t i = starts[c]; i < starts[c + 1]; ++i) pieces_[i].outward = sign;
    }
    if (pieces_.empty()) lx = lz = hx = hz = 0.0;
    lo_ = Vec3(lx, y0, lz);
    hi_ = Vec3(hx, y1, hz);
    center_ = 0.5 * (lo_ + hi_);
    radius_ = padUp(0.5 * glm::length(hi_ - lo_));
}

Bounds3 Extrusion::worldBounds(const Mat3& m, const Vec3& offset) const {
    return Box(lo_, hi_).worldBounds(m, offset);
}

bool Extrusion::insideOutline(double x, double z) const {
    return crossingsRight(pieces_, 0, pieces_.size(), x, z) % 2 == 1;
}

bool Extrusion::inside(const Vec3& p) const {
    return p.y >= y0_ && p.y <= y1_ && insideOutline(p.x, p.z);
}

std::optional<LocalHit> Extrusion::intersect(const Ray& ray, double tMin, double tMax) const {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.dir;
    // The bounding box first.
    double lo = tMin, hi = tMax;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < lo_[a] || o[a] > hi_[a]) return std::nullopt;
            continue;
        }
        double t0 = (lo_[a] - o[a]) / d[a], t1 = (hi_[a] - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        // Widened a little: the caps' and sides' hits lie on the box.
        lo = std::max(lo, t0 - 1e-9 * (std::abs(t0) + 1.0));
        hi = std::min(hi, t1 + 1e-9 * (std::abs(t1) + 1.0));
        if (lo > hi) return std::nullopt;
    }
    std::optional<LocalHit> best;
    double tBest = tMax;
    if (d.y != 0.0 && !open_) {
        for (int cap = 0; cap < 2; ++cap) {
            const double y = cap == 0 ? y0_ : y1_;
            const double t = (y - o.y) / d.y;
            if (!(t >= tMin && t <= tBest)) continue;
            const double x = o.x + t * d.x, z = o.z + t * d.z;
            if (!insideOutline(x, z)) continue;
            tBest = t;
            best = LocalHit{t, Vec3(x, y, z), Vec3(0.0, cap == 0 ? -1.0 : 1.0, 0.0), std::uint8_t(cap)};
        }
    }
    const double dd = d.x * d.x + d.z * d.z;
    if (dd == 0.0) return best;
    // The line's normal in the plane: a piece meets it where n . (B(s) - o) changes sign.
    const double nx = -d.z, nz = d.x;
    const double no = nx * o.x + nz * o.z;
    for (const Piece& p : pieces_) {
        bool below = false, above = false;
        for (int i = 0; i <= p.degree; ++i) {
            const double v = nx * p.px[i] + nz * p.pz[i] - no;
            below |= v <= 0.0;
            above |= v >= 0.0;
        }
        if (!below || !above) continue;
        double c[4] = {nx * p.ax[0] + nz * p.az[0] - no, 0.0, 0.0, 0.0};
        for (int i = 1; i <= p.degree; ++i) c[i] = nx * p.ax[i] + nz * p.az[i];
        double roots[3];
        const int n = signChanges(c, p.degree, roots);
        for (int k = 0; k < n; ++k) {
            const double s = roots[k];
            const double x = eval(p.ax, p.degree, s), z = eval(p.az, p.degree, s);
            const double t = ((x - o.x) * d.x + (z - o.z) * d.z) / dd;
            if (!(t >= tMin && t <= tBest)) continue;
            const double y = o.y + t * d.y;
            if (y < y0_ || y > y1_) continue;
            double tx = derivative(p.ax, p.degree, s), tz = derivative(p.az, p.degree, s);
            if (tx == 0.0 && tz == 0.0) {
                tx = p.px[p.degree] - p.px[0];
                tz = p.pz[p.degree] - p.pz[0];
            }
            tBest = t;
            best = LocalHit{t, Vec3(x, y, z), p.outward * Vec3(tz, 0.0, -tx), std::uint8_t(2)};
        }
    }
    return best;
}

ConeClass Extrusion::classify(const LocalCone& cone) const {
    if (ballOutsideAngular(cone, center_, radius_)) return missClass();
    const double dist = glm::length(center_ - cone.apex);
    const double nearest = std::max(0.0, padDown(dist - radius_) - cone.absTol);
    const double farthest = padUp(dist + radius_) + cone.absTol;
    if (cone.surelyAfter(nearest) || cone.surelyBefore(farthest)) return missClass();
    return marginalClass(cone, nearest, farthest);
}

double Extrusion::support(const Vec3& dir) const {
    double s = 0.0;
    for (int a = 0; a < 3; ++a) s += std::max(dir[a] * lo_[a], dir[a] * hi_[a]);
    return s;
}

bool Extrusion::raysLeave(const LocalRays& rays) const {
    const Vec3 w = rays.origin - center_;
    return glm::dot(w, w) >= radius_ * radius_ && rays.awayFrom(w);
}

std::vector<ShapeIssue> validate(const ExtrusionShape& record) {
    IssueList issues;
    const char* what = record.keyword;
    if (!(std::isfinite(record.y0) && std::isfinite(record.y1)) || !(record.y0 < record.y1))
        issues.add(0, std::string("the heights of a ") + what + " must be finite and differ, not " +
                          formatNumber(record.y0) + " and " + formatNumber(record.y1));
    if (!record.outline || record.outline->empty()) {
        issues.add(0, std::string("a ") + what + " needs at least one closed outline");
        return issues.take();
    }
    for (const OutlineContour& c : *record.outline) {
        if (c.pieces.empty()) {
            issues.add(0, std::string("a ") + what + " has an empty outline");
            continue;
        }
        for (std::size_t i = 0; i < c.pieces.size(); ++i) {
            const OutlinePiece& p = c.pieces[i];
            const OutlinePiece& next = c.pieces[(i + 1) % c.pieces.size()];
            for (int k = 0; k <= 2 * p.degree + 1; ++k)
                if (!std::isfinite(p.p[k])) {
                    issues.add(0, std::string("a ") + what + " has a point that is not finite");
                    return issues.take();
                }
            if (p.p[2 * p.degree] != next.p[0] || p.p[2 * p.degree + 1] != next.p[1]) {
                issues.add(0, std::string("an outline of a ") + what + " is not closed");
                return issues.take();
            }
        }
    }
    return issues.take();
}

Placed<Extrusion> place(const ExtrusionShape& record, const Transform& worldFromObject) {
    return {Extrusion(*record.outline, record.y0, record.y1, record.open),
            LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), record.keyword};
}

}  // namespace asos
