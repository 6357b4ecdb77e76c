#include "asos/geometry/beam_hull.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"

namespace asos {

namespace {

double largestMagnitude(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }
double largestMagnitude(const Bounds3& b) { return std::max(largestMagnitude(b.lo), largestMagnitude(b.hi)); }

// The corners of the polygon where the plane through `point` with unit
// `normal` crosses the box: where it crosses the box's edges (corners on
// the plane counted once per edge), written to out[] (at most 24); returns
// how many, none where it misses the box.
int planeInBox(const Vec3& normal, const Vec3& point, const Bounds3& box, Vec3* out) {
    double heights[8];
    for (int i = 0; i < 8; ++i) heights[i] = glm::dot(normal, box.corner(i) - point);
    int n = 0;
    for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            const int j = i | (1 << axis);
            if (j == i) continue;
            const double hi = heights[i], hj = heights[j];
            if ((hi > 0.0 && hj > 0.0) || (hi < 0.0 && hj < 0.0)) continue;
            const Vec3 a = box.corner(i), b = box.corner(j);
            if (hi == hj) {  // both on the plane
                out[n++] = a;
                out[n++] = b;
            } else {
                out[n++] = a + (hi / (hi - hj)) * (b - a);
            }
        }
    return n;
}

}  // namespace

std::optional<BeamHull> BeamHull::over(const Vec3& apex, const Vec3* base, int count, double reach,
                                       double endGap) {
    if (count < 2 || count > kMaxBase || !(reach > 0.0)) return std::nullopt;
    const double keep = 1.0 - endGap / reach;
    if (!(keep > 0.0)) return std::nullopt;
    BeamHull h;
    h.points_[0] = apex;
    h.count_ = count + 1;
    for (int i = 0; i < count; ++i) h.points_[std::size_t(i + 1)] = apex + keep * (base[i] - apex);
    h.box_ = Bounds3::of(apex);
    for (int i = 0; i < h.count_; ++i) {
        h.box_.extend(h.points_[std::size_t(i)]);
        h.scale_ = std::max(h.scale_, largestMagnitude(h.points_[std::size_t(i)]));
    }
    const Vec3* b = h.points_.data() + 1;
    // Below this a normal's length is rounding: the apex lies in the base's
    // plane or on its line (the products are of differences of coordinates
    // up to scale_).
    const double degenerate = kThousandsOfUlps * h.scale_ * h.scale_;
    if (count == 2) {
        // A triangle: its edge at the light first (square to the triangle),
        // then its other edges' outward normals within its plane, and both
        // sides of the plane.
        const Vec3 t = glm::cross(b[0] - apex, b[1] - apex);
        const double area = glm::length(t);
        if (!(area > degenerate)) return std::nullopt;
        h.triangle_ = true;
        h.across_ = t / area;
        // The edge at the light's with a unit normal: planes through the
        // segment are turned from it (beyondLight).
        const Vec3 corners[3] = {b[0], b[1], apex};
        for (int i = 0; i < 3; ++i) {
            const Vec3& p = corners[i];
            const Vec3& q = corners[(i + 1) % 3];
            const Vec3& r = corners[(i + 2) % 3];
            const Vec3 n = glm::cross(q - p, t);
            h.addFace((glm::dot(n, r - p) > 0.0 ? -n : n) / (i == 0 ? glm::length(n) : 1.0));
        }
        h.addFace(t);
        h.addFace(-t);
        return h;
    }
    // A pyramid: the base's face, and a side through the apex and each edge.
    const Vec3 n = count == 3 ? glm::cross(b[1] - b[0], b[2] - b[0]) : glm::cross(b[2] - b[0], b[3] - b[1]);
    const double length = glm::length(n);
    if (!(length > degenerate) || !(std::abs(glm::dot(n / length, b[0] - apex)) > kThousandsOfUlps * h.scale_))
        return std::nullopt;
    h.addFace(glm::dot(n, b[0] - apex) > 0.0 ? n : -n);
    Vec3 centroid(0.0);
    for (int i = 0; i < count; ++i) centroid += b[i];
    centroid /= double(count);
    for (int i = 0; i < count; ++i) {
        const Vec3 side = glm::cross(b[i] - apex, b[(i + 1) % count] - apex);
        h.addFace(glm::dot(side, centroid - apex) > 0.0 ? -side : side);
    }
    return h;
}

BeamHull BeamHull::beyondLight(const Bounds3& reach) const {
    BeamHull h = *this;
    // Widened past rounding, so that a plane through one of its corners
    // (the apex may be one) is seen to cross it.
    const Vec3 pad(kThousandsOfUlps * (largestMagnitude(reach) + largestMagnitude(reach.diagonal())));
    h.reach_ = Bounds3{reach.lo - pad, reach.hi + pad};
    return h;
}

void BeamHull::addFace(const Vec3& normal) {
    Face f{normal, -kInfinity, l1Norm(normal)};
    if (!(f.size > 0.0)) return;
    for (int i = 0; i < count_; ++i) f.offset = std::max(f.offset, glm::dot(f.normal, points_[std::size_t(i)]));
    faces_[std::size_t(faceCount_++)] = f;
}

double BeamHull::margin(double magnitude) const {
    // Dot products of unit normals with coordinates up to scale_ +
    // magnitude, and a plane's crossings of a box's edges: a few ulps of it
    // each, far within the margin.
    return kThousandsOfUlps * (scale_ + magnitude);
}

bool BeamHull::beyondLight(const Vec3* points, int count, double magnitude) const {
    const Face& f = faces_[0];
    const double pad = margin(magnitude);
    if (!triangle_) {
        for (int i = 0; i < count; ++i)
            if (!(glm::dot(f.normal, points[i]) > f.offset + pad * f.size)) return false;
        return true;
    }
    // The planes through the segment (as the gap leaves it: parallel to the
    // light, every point of it at f's offset) with normals (f + s across) /
    // sqrt(1 + s^2), |s| <= tan 60 degrees: a point x lies beyond one when
    // dot(f, x) - offset + s dot(across, x - base) > 0, linear in s. The
    // points' bounds on s leave an interval, whose middle is tried.
    const Vec3& base = points_[1];
    const double limit = std::sqrt(3.0);
    double lo = -limit, hi = limit;
    for (int i = 0; i < count && lo < hi; ++i) {
        const double along = glm::dot(f.normal, points[i]) - f.offset, aside = glm::dot(across_, points[i] - base);
        if (aside > 0.0) lo = std::max(lo, -along / aside);
        else if (aside < 0.0) hi = std::min(hi, -along / aside);
        else if (!(along > 0.0)) return false;
    }
    if (!(lo < hi)) return false;
    // Checked as computed, past the margin: the bounds only chose the plane.
    const double s = 0.5 * (lo + hi);
    const Vec3 normal = (f.normal + s * across_) / std::sqrt(1.0 + s * s);
    const double offset = glm::dot(normal, base);
    for (int i = 0; i < count_; ++i)
        if (glm::dot(normal, points_[std::size_t(i)]) > offset + pad) return false;
    for (int i = 0; i < count; ++i)
        if (!(glm::dot(normal, points[i]) > offset + pad)) return false;
    return true;
}

bool BeamHull::missesBox(const Bounds3& box) const {
    Bounds3 b = box;
    if (reach_) {
        b.lo = glm::max(b.lo, reach_->lo);
        b.hi = glm::min(b.hi, reach_->hi);
    }
    if (b.empty()) return true;
    const double magnitude = largestMagnitude(b);
    if (reach_) {
        Vec3 corners[8];
        for (int i = 0; i < 8; ++i) corners[i] = b.corner(i);
        return beyondLight(corners, 8, magnitude);
    }
    const double pad = margin(magnitude);
    for (int axis = 0; axis < 3; ++axis)
        if (b.lo[axis] > box_.hi[axis] + pad || b.hi[axis] < box_.lo[axis] - pad) return true;
    const Vec3 centre = b.center(), half = 0.5 * b.diagonal();
    for (int i = 0; i < faceCount_; ++i) {
        const Face& f = faces_[std::size_t(i)];
        if (glm::dot(f.normal, centre) - glm::dot(glm::abs(f.normal), half) > f.offset + pad * f.size) return true;
    }
    return false;
}

bool BeamHull::missesPlane(const Vec3& normal, const Vec3& point) const {
    if (reach_) {
        Vec3 crossings[24];
        const int n = planeInBox(normal, point, *reach_, crossings);
        return beyondLight(crossings, n, std::max(largestMagnitude(*reach_), largestMagnitude(point)));
    }
    const double pad = margin(largestMagnitude(point));
    bool above = true, below = true;
    for (int i = 0; i < count_; ++i) {
        const double height = glm::dot(normal, points_[std::size_t(i)] - point);
        above = above && height > pad;
        below = below && height < -pad;
    }
    return above || below;
}

}  // namespace asos
