// prism { … }: POV-Ray 3.7's prism with linear_sweep (core/shape/prism.cpp),
// an ExtrusionShape whose outline is the spline's segments, each written
// exactly as a Bezier piece:
//   linear_spline     P[i] to P[i+1], a line;
//   quadratic_spline  P[i+1] to P[i+2], the segment of POV-Ray's B t^2 +
//                     C t + D: control point P[i+1] + (P[i+2] - P[i]) / 4;
//   cubic_spline      P[i+1] to P[i+2], a Catmull-Rom segment: control
//                     points P[i+1] + (P[i+2] - P[i]) / 6 and
//                     P[i+2] - (P[i+3] - P[i+1]) / 6;
//   bezier_spline     P[i] … P[i+3], four points of its own per segment.
// A sub-prism closes where a segment ends on its first point (the second
// one written, for quadratic and cubic splines, whose first is a control
// point; a cubic's sub-prism has a control point after its last too), and
// the next starts with the points after, as POV-Ray's Compute_Prism steps.
#include <cmath>
#include <string>

#include "asos/diag/format_number.hpp"
#include "asos/scene/pov_tolerances.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

enum class Spline { Linear, Quadratic, Cubic, Bezier };

struct Point2 {
    double x = 0.0, z = 0.0;
};
Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.z + b.z}; }
Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.z - b.z}; }
Point2 operator*(double k, Point2 a) { return {k * a.x, k * a.z}; }

// POV-Ray's test for a sub-prism's closing point.
bool samePoint(Point2 a, Point2 b) {
    return std::fabs(a.x - b.x) < kPovEpsilon && std::fabs(a.z - b.z) < kPovEpsilon;
}

OutlinePiece piece(std::initializer_list<Point2> points) {
    OutlinePiece p;
    p.degree = static_cast<int>(points.size()) - 1;
    std::size_t k = 0;
    for (const Point2& q : points) {
        p.p[k++] = q.x;
        p.p[k++] = q.z;
    }
    return p;
}

// The contour closed exactly: its last piece ends where its first starts
// (POV-Ray calls them equal within its epsilon).
void closeContour(OutlineContour& c) {
    OutlinePiece& last = c.pieces.back();
    last.p[static_cast<std::size_t>(2 * last.degree)] = c.pieces.front().p[0];
    last.p[static_cast<std::size_t>(2 * last.degree + 1)] = c.pieces.front().p[1];
}

const char* splineName(Spline s) {
    switch (s) {
    case Spline::Linear: return "linear_spline";
    case Spline::Quadratic: return "quadratic_spline";
    case Spline::Cubic: return "cubic_spline";
    case Spline::Bezier: return "bezier_spline";
    }
    return "";
}

}  // namespace

void Interpreter::evalPrism(const Node& block, ObjectTree& t) {
    const auto args = block.children();
    Spline spline = Spline::Linear;
    for (const Node& option : args[0].children()) {
        switch (option.word) {
        case Word::LinearSweep: break;
        case Word::ConicSweep:
            fail(option, "'conic_sweep' is not supported by asos (a prism's linear_sweep is)");
        case Word::LinearSpline: spline = Spline::Linear; break;
        case Word::QuadraticSpline: spline = Spline::Quadratic; break;
        case Word::CubicSpline: spline = Spline::Cubic; break;
        case Word::BezierSpline: spline = Spline::Bezier; break;
        default: fail(option, "expected linear_sweep, conic_sweep or a spline of the prism");
        }
    }
    double h1 = evalFloat(args[1]), h2 = evalFloat(args[2]);
    if (!(std::isfinite(h1) && std::isfinite(h2)))
        fail(args[1], "the heights of a prism must be finite, not " + formatNumber(h1) + " and " + formatNumber(h2));
    if (h1 > h2) std::swap(h1, h2);  // as POV-Ray
    if (!(h1 < h2)) fail(args[1], "the heights of a prism must differ, not both " + formatNumber(h1));

    // POV-Ray takes the count's integer part.
    const double countValue = evalFloat(args[3]);
    if (!(std::isfinite(countValue) && std::fabs(countValue) < 1e9))
        fail(args[3], "the number of points of a prism must be finite, not " + formatNumber(countValue));
    const int n = static_cast<int>(countValue);
    const char* name = splineName(spline);
    const int least = spline == Spline::Linear ? 3 : spline == Spline::Quadratic ? 5 : spline == Spline::Cubic ? 6 : 4;
    if (n < least)
        fail(args[3], std::string("a prism with ") + name + " needs at least " + std::to_string(least) +
                          " points, not " + std::to_string(n));
    if (spline == Spline::Bezier && n % 4 != 0)
        fail(args[3], "a prism with bezier_spline needs four points per segment, not " + std::to_string(n) +
                          " points");
    const auto nodes = args[4].children();
    if (static_cast<int>(nodes.size()) != n)
        fail(args[3], "the prism announces " + std::to_string(n) + " points but lists " +
                          std::to_string(nodes.size()));
    std::vector<Point2> P;
    P.reserve(nodes.size() + 1);
    for (const Node& node : nodes) {
        const Vec3 v = evalVector(node);
        if (!(std::isfinite(v.x) && std::isfinite(v.y))) fail(node, "a point of a prism must be finite");
        P.push_back({v.x, v.y});
    }

    // POV-Ray's check that the last sub-prism is closed (its Parse_Prism).
    if (spline != Spline::Bezier) {
        int i = spline == Spline::Linear ? 1 : 2;
        Point2 first = spline == Spline::Linear ? P[0] : P[1];
        bool closed = false;
        for (; i < n; ++i) {
            closed = false;
            if (samePoint(first, P[static_cast<std::size_t>(i)])) {
                i += spline == Spline::Linear ? 1 : spline == Spline::Quadratic ? 2 : 3;
                if (i < n) first = P[static_cast<std::size_t>(i)];
                closed = true;
            }
        }
        if (!closed) {
            if (spline == Spline::Linear) {
                report(Severity::Warning, block,
                       "this linear_spline prism is not closed: asos closes it, as POV-Ray does");
                P.push_back(first);
            } else {
                fail(args[4], std::string("this ") + name +
                                  " prism is not closed: its last sub-prism must end on its second point "
                                  "(POV-Ray stops with \"Too few points in prism\")");
            }
        }
    }

    // The segments, as POV-Ray's Compute_Prism steps through the points.
    const int count = static_cast<int>(P.size());
    auto contours = std::make_shared<std::vector<OutlineContour>>();
    OutlineContour current;
    auto finish = [&] {
        closeContour(current);
        contours->push_back(std::move(current));
        current = OutlineContour{};
    };
    auto at = [&](int i) { return P[static_cast<std::size_t>(i)]; };
    Point2 first = spline == Spline::Linear ? P[0] : P[1];
    for (int i = 0; i < count - 1; ++i) {
        switch (spline) {
        case Spline::Linear:
            current.pieces.push_back(piece({at(i), at(i + 1)}));
            if (samePoint(at(i + 1), first)) {
                finish();
                ++i;
                if (i + 1 < count) first = at(i + 1);
            }
            break;
        case Spline::Quadratic:
            if (i + 2 >= count) fail(args[4], "too few points in this quadratic_spline prism (as POV-Ray says)");
            current.pieces.push_back(piece({at(i + 1), at(i + 1) + 0.25 * (at(i + 2) - at(i)), at(i + 2)}));
            if (samePoint(at(i + 2), first)) {
                finish();
                i += 2;
                if (i + 2 < count) first = at(i + 2);
            }
            break;
        case Spline::Cubic:
            if (i + 3 >= count) fail(args[4], "too few points in this cubic_spline prism (as POV-Ray says)");
            current.pieces.push_back(piece({at(i + 1), at(i + 1) + (1.0 / 6.0) * (at(i + 2) - at(i)),
                                            at(i + 2) - (1.0 / 6.0) * (at(i + 3) - at(i + 1)), at(i + 2)}));
            if (samePoint(at(i + 2), first)) {
                finish();
                i += 3;
                if (i + 2 < count) first = at(i + 2);
            }
            break;
        case Spline::Bezier: {
            // Each segment starts where the one before it ends, and a
            // sub-prism closes where a segment ends on its start.
            const Point2 start = at(i), end = at(i + 3);
            if (!current.pieces.empty()) {
                const OutlinePiece& last = current.pieces.back();
                if (!samePoint(start, {last.p[6], last.p[7]}))
                    fail(nodes[static_cast<std::size_t>(i)],
                         "this bezier_spline segment does not start where the one before it ends: the "
                         "prism is not closed (POV-Ray ignores such a prism) ");
            }
            current.pieces.push_back(piece({start, at(i + 1), at(i + 2), end}));
            if (samePoint(end, {current.pieces.front().p[0], current.pieces.front().p[1]})) finish();
            i += 3;
            break;
        }
        }
    }
    if (!current.pieces.empty())
        fail(args[4], std::string("this ") + name +
                          " prism is not closed: its last sub-prism does not end where it started (POV-Ray "
                          "ignores such a prism)");
    if (contours->empty()) fail(args[4], "this prism has no closed outline");
    ExtrusionShape shape;
    shape.outline = std::move(contours);
    shape.y0 = h1;
    shape.y1 = h2;
    shape.keyword = "prism";
    t.shape = std::move(shape);
}

}  // namespace asos::lang
