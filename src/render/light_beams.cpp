#include "asos/render/light_beams.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace asos {

LightBeams::LightBeams(const LightModel& model, const Vec3& apex, double tMin)
    : shape_(model.shape), apex_(apex), tMin_(tMin) {
    switch (shape_) {
        case LightShape::Rectangle: {
            corner_ = model.rectangle.corner;
            edgeA_ = model.rectangle.edgeA;
            edgeB_ = model.rectangle.edgeB;
            const Vec3 n = glm::cross(edgeA_, edgeB_);
            const double area = glm::length(n);
            if (!(area > 0.0)) return;
            normal_ = n / area;
            const Vec3 rel = apex_ - corner_;
            height_ = std::abs(glm::dot(rel, normal_));
            // As RectShadowPyray: below rounding, the apex is in the plane.
            const double scale = glm::length(edgeA_) + glm::length(edgeB_) + glm::length(rel);
            if (!(height_ > 1e-12 * scale)) return;
            rectangular_ = std::abs(glm::dot(edgeA_, edgeB_)) <=
                           1e-12 * glm::length(edgeA_) * glm::length(edgeB_);
            footS_ = glm::dot(rel, edgeA_) / glm::dot(edgeA_, edgeA_);
            footT_ = glm::dot(rel, edgeB_) / glm::dot(edgeB_, edgeB_);
            valid_ = true;
            return;
        }
        case LightShape::Segment: {
            corner_ = model.start;
            edgeA_ = model.end - model.start;
            const double length = glm::length(edgeA_);
            if (!(length > 0.0)) return;
            const double f = std::clamp(glm::dot(apex_ - corner_, edgeA_) / (length * length), 0.0, 1.0);
            const double offLine = glm::length(apex_ - (corner_ + f * edgeA_));
            if (!(offLine > 1e-12 * (length + glm::length(apex_ - corner_)))) return;
            footS_ = glm::dot(apex_ - corner_, edgeA_) / (length * length);
            valid_ = true;
            return;
        }
        case LightShape::Sphere: {
            const double radius = model.radius;
            if (!(radius > 0.0) || !(glm::length(model.position - apex_) > radius * (1.0 + 1e-12))) return;
            // SphereShadowCone's tangent cone, made alike: the same rays.
            tangent_ = TangentCone::make(apex_, model.position, radius);
            alpha_ = std::asin(tangent_.sinAlpha);
            valid_ = true;
            return;
        }
        case LightShape::Point: return;
    }
}

Cone LightBeams::coneAbout(const Vec3& axis, const Vec3* directions, int count, double farthest,
                           double& tanHalf) const {
    // The widest direction by the tangent of its angle, from directions of
    // any length (the tangent |d x axis| / (d . axis) does not depend on it):
    // no normalisation, one square root and one arctangent.
    double widest2 = 0.0;
    bool hemisphere = true;
    for (int i = 0; i < count; ++i) {
        const double along = glm::dot(directions[i], axis);
        // along > 1e-6 |d|: within a right angle of the axis, with margin.
        if (!(along > 0.0) || !(along * along > 1e-12 * glm::dot(directions[i], directions[i]))) {
            hemisphere = false;
            break;
        }
        const Vec3 off = glm::cross(directions[i], axis);
        widest2 = std::max(widest2, glm::dot(off, off) / (along * along));
    }
    // A piece reaching a right angle from its central ray has no convex cone
    // about it: the cone of all directions holds it.
    const double widest = std::sqrt(widest2);
    const double halfAngle = hemisphere ? std::atan(widest) + kConeAnglePad : kPi;
    tanHalf = hemisphere ? widest : std::numeric_limits<double>::quiet_NaN();
    return {apex_, axis, halfAngle, tMin_, farthest * (1.0 + 1e-12)};
}

LightPiece LightBeams::make(double a0, double b0, double a1, double b1, int level, std::uint64_t path,
                            bool cone) const {
    LightPiece p{a0, b0, a1, b1, level, path, {}, {}};
    switch (shape_) {
        case LightShape::Rectangle: {
            p.central = toward(rectPoint(0.5 * (a0 + a1), 0.5 * (b0 + b1)));
            if (!cone) break;
            const Vec3 dirs[4] = {rectPoint(a0, b0) - apex_, rectPoint(a1, b0) - apex_, rectPoint(a1, b1) - apex_,
                                  rectPoint(a0, b1) - apex_};
            double farthest2 = 0.0;
            for (const Vec3& d : dirs) farthest2 = std::max(farthest2, glm::dot(d, d));
            p.cone = coneAbout(p.central.ray.dir, dirs, 4, std::sqrt(farthest2), p.tanHalf);
            break;
        }
        case LightShape::Segment: {
            p.central = toward(corner_ + 0.5 * (a0 + a1) * edgeA_);
            if (!cone) break;
            const Vec3 d0 = corner_ + a0 * edgeA_ - apex_, d1 = corner_ + a1 * edgeA_ - apex_;
            const double l0 = glm::length(d0), l1 = glm::length(d1);
            const Vec3 u = d0 / l0, v = d1 / l1;
            // The bisector of the two end rays: the smallest cone of the
            // triangle. For unit u and v, tan(angle / 2) = |u - v| / |u + v|:
            // one arctangent, and the tangent spares the cone's users theirs.
            const Vec3 sum = u + v;
            const double sumLength = glm::length(sum);
            p.tanHalf = glm::length(u - v) / sumLength;
            p.cone = {apex_, sum / sumLength, std::atan(p.tanHalf) + kConeAnglePad, tMin_,
                      std::max(l0, l1) * (1.0 + 1e-12)};
            break;
        }
        case LightShape::Sphere: {
            if (level > 0) return makeDiscPiece(DiscPieceTable::piece(DiscCell{a0, a1, b0, b1}), level, path, cone);
            // The whole disc: the tangent cone.
            p.central = tangent_.ray(apex_, 0.0, 0.0, 0.0, 1.0);
            p.cone = {apex_, tangent_.frame.w, alpha_ + kConeAnglePad, tMin_,
                      tangent_.distanceAtRadius(1.0, 1.0) * (1.0 + 1e-12)};
            break;
        }
        case LightShape::Point: break;
    }
    return p;
}

DiscPieceTable::Piece DiscPieceTable::piece(const DiscCell& cell) {
    const PolarBounds b = polarBounds(cell);
    const Vec2 centre = concentricDisc(0.5 * (cell.s0 + cell.s1), 0.5 * (cell.t0 + cell.t1));
    const TangentCone::Radial radial = TangentCone::radial(centre);
    return {cell,
            centre,
            radial.rho2,
            radial.rim,
            b.r0,
            b.r1,
            {std::cos(b.phi0), std::sin(b.phi0)},
            {std::cos(b.phi1), std::sin(b.phi1)}};
}

DiscPieceTable::DiscPieceTable() {
    pieces_.push_back(piece(DiscCell{}));
    for (int level = 0; level < kLevels; ++level) {
        const std::size_t first = ((std::size_t(1) << (2 * level)) - 1) / 3;
        const std::size_t count = std::size_t(1) << (2 * level);
        for (std::size_t i = first; i < first + count; ++i) {
            const DiscCell c = pieces_[i].cell;
            const double s[3] = {c.s0, 0.5 * (c.s0 + c.s1), c.s1}, t[3] = {c.t0, 0.5 * (c.t0 + c.t1), c.t1};
            for (int q = 0; q < 4; ++q) {
                const int u = q & 1, v = q >> 1;
                pieces_.push_back(piece(DiscCell{s[u], s[u + 1], t[v], t[v + 1]}));
            }
        }
    }
}

const DiscPieceTable& discPieceTable() {
    static const DiscPieceTable table;
    return table;
}

Vec3 LightBeams::discOffset(double r, const DiscPieceTable::Trig& t) const {
    const double k = tangent_.tanAlpha * r;
    return tangent_.frame.toWorld(k * t.c, k * t.s, 1.0);
}

LightPiece LightBeams::makeDiscPiece(const DiscPieceTable::Piece& d, int level, std::uint64_t path, bool cone) const {
    LightPiece p{d.cell.s0, d.cell.t0, d.cell.s1, d.cell.t1, level, path, {}, {}};
    p.central = tangent_.ray(apex_, d.centre.x, d.centre.y, d.rho2, d.rim);
    const Vec3& dir = p.central.ray.dir;
    if (!cone) return p;
    // Unnormalised: coneAbout needs no unit directions.
    const Vec3 corners[4] = {discOffset(d.r0, d.at0), discOffset(d.r0, d.at1), discOffset(d.r1, d.at0),
                             discOffset(d.r1, d.at1)};
    p.cone = coneAbout(dir, corners, 4, tangent_.distanceAtRadius(d.r1, 1.0), p.tanHalf);
    return p;
}

LightPiece LightBeams::root() const {
    return make(0.0, 0.0, 1.0, 1.0, 0, 0);
}

int LightBeams::splitRectangle(const LightPiece& p, LightPiece* out, bool cones) const {
    // The quarters share the nine points of a 3 x 3 lattice over the piece:
    // each is made once (unnormalised: coneAbout needs no unit directions).
    const double s[3] = {p.a0, 0.5 * (p.a0 + p.a1), p.a1};
    const double t[3] = {p.b0, 0.5 * (p.b0 + p.b1), p.b1};
    Vec3 dirs[3][3];
    double lengths2[3][3];
    if (cones)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                dirs[j][i] = rectPoint(s[i], t[j]) - apex_;
                lengths2[j][i] = glm::dot(dirs[j][i], dirs[j][i]);
            }
    for (int q = 0; q < 4; ++q) {
        const int i = q & 1, j = q >> 1;
        LightPiece& c = out[q];
        c = LightPiece{s[i], t[j], s[i + 1], t[j + 1], p.level + 1, 4 * p.path + std::uint64_t(q), {}, {}};
        c.central = toward(rectPoint(0.5 * (s[i] + s[i + 1]), 0.5 * (t[j] + t[j + 1])));
        if (!cones) continue;
        const Vec3 corners[4] = {dirs[j][i], dirs[j][i + 1], dirs[j + 1][i + 1], dirs[j + 1][i]};
        const double farthest2 = std::max(std::max(lengths2[j][i], lengths2[j][i + 1]),
                                          std::max(lengths2[j + 1][i + 1], lengths2[j + 1][i]));
        c.cone = coneAbout(c.central.ray.dir, corners, 4, std::sqrt(farthest2), c.tanHalf);
    }
    return 4;
}

int LightBeams::split(const LightPiece& p, LightPiece* out, bool cones) const {
    const int level = p.level + 1;
    switch (shape_) {
        case LightShape::Rectangle: return splitRectangle(p, out, cones);
        case LightShape::Segment: {
            const double mid = 0.5 * (p.a0 + p.a1);
            out[0] = make(p.a0, 0.0, mid, 1.0, level, 2 * p.path, cones);
            out[1] = make(mid, 0.0, p.a1, 1.0, level, 2 * p.path + 1, cones);
            return 2;
        }
        case LightShape::Sphere: {
            // The layout of the disc's pieces does not depend on the apex:
            // the first levels are made once (discPieceTable).
            const DiscPieceTable& table = discPieceTable();
            if (const DiscPieceTable::Piece* d = table.children(p.level, p.path)) {
                for (int q = 0; q < 4; ++q)
                    out[q] = makeDiscPiece(d[q], level, 4 * p.path + std::uint64_t(q), cones);
                return 4;
            }
            // Deeper: the cell's quarters, as in the table.
            const double s[3] = {p.a0, 0.5 * (p.a0 + p.a1), p.a1}, t[3] = {p.b0, 0.5 * (p.b0 + p.b1), p.b1};
            for (int q = 0; q < 4; ++q) {
                const int i = q & 1, j = q >> 1;
                out[q] = makeDiscPiece(DiscPieceTable::piece(DiscCell{s[i], s[i + 1], t[j], t[j + 1]}), level,
                                       4 * p.path + std::uint64_t(q), cones);
            }
            return 4;
        }
        case LightShape::Point: break;
    }
    return 0;
}

BeamRay LightBeams::sample(const LightPiece& p, const Vec2& xi) const {
    switch (shape_) {
        case LightShape::Rectangle:
            return toward(rectPoint(p.a0 + xi.x * (p.a1 - p.a0), p.b0 + xi.y * (p.b1 - p.b0)));
        case LightShape::Segment: return toward(corner_ + (p.a0 + xi.x * (p.a1 - p.a0)) * edgeA_);
        case LightShape::Sphere: {
            return tangent_.ray(apex_, concentricDisc(p.a0 + xi.x * (p.a1 - p.a0), p.b0 + xi.y * (p.b1 - p.b0)));
        }
        case LightShape::Point: break;
    }
    return p.central;
}

double LightBeams::nearestLightDistance(const LightPiece& p) const {
    switch (shape_) {
        case LightShape::Rectangle: {
            // Rectangles: the nearest point is the foot of the apex clamped
            // to the piece. Other parallelograms: the height above the plane,
            // a lower bound.
            if (!rectangular_) return height_;
            const Vec3 nearest = rectPoint(std::clamp(footS_, p.a0, p.a1), std::clamp(footT_, p.b0, p.b1));
            return std::max(height_, glm::length(nearest - apex_) * (1.0 - 1e-12));
        }
        case LightShape::Segment: {
            const Vec3 nearest = corner_ + std::clamp(footS_, p.a0, p.a1) * edgeA_;
            return glm::length(nearest - apex_) * (1.0 - 1e-12);
        }
        case LightShape::Sphere:
            return tangent_.distanceAtRadius(innerRadius(DiscCell{p.a0, p.a1, p.b0, p.b1}), -1.0) * (1.0 - 1e-12);
        case LightShape::Point: break;
    }
    return 0.0;
}

int LightBeams::probeRays(const LightPiece& p, BeamRay* out) const {
    const auto disc = [&](const Vec2& point) {
        return tangent_.ray(apex_, point);
    };
    switch (shape_) {
        case LightShape::Rectangle: {
            const double sm = 0.5 * (p.a0 + p.a1), tm = 0.5 * (p.b0 + p.b1);
            out[0] = toward(rectPoint(p.a0, tm));
            out[1] = toward(rectPoint(p.a1, tm));
            out[2] = toward(rectPoint(sm, p.b0));
            out[3] = toward(rectPoint(sm, p.b1));
            return 4;
        }
        case LightShape::Segment:
            out[0] = toward(corner_ + p.a0 * edgeA_);
            out[1] = toward(corner_ + p.a1 * edgeA_);
            return 2;
        case LightShape::Sphere: {
            if (p.level == 0) {
                // Opposite points of the rim: angles 0 and pi, pi/2 and 3 pi/2.
                for (int i = 0; i < 4; ++i) {
                    const double phi = 0.5 * kPi * ((i & 1) * 2 + (i >> 1));
                    out[i] = disc(Vec2(std::cos(phi), std::sin(phi)));
                }
                return 4;
            }
            // The images of the cell's edges' midpoints.
            const double sm = 0.5 * (p.a0 + p.a1), tm = 0.5 * (p.b0 + p.b1);
            out[0] = disc(concentricDisc(p.a0, tm));
            out[1] = disc(concentricDisc(p.a1, tm));
            out[2] = disc(concentricDisc(sm, p.b0));
            out[3] = disc(concentricDisc(sm, p.b1));
            return 4;
        }
        case LightShape::Point: break;
    }
    return 0;
}

std::pair<double, double> LightBeams::ruleWeights(const LightPiece& p) const {
    if (shape_ == LightShape::Segment) return {2.0 / 3.0, 1.0 / 6.0};
    if (shape_ == LightShape::Sphere && p.level == 0) return {0.5, 0.125};
    return {1.0 / 3.0, 1.0 / 6.0};
}

}  // namespace asos
