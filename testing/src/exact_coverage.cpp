#include "asos/testing/exact_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace asos {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

double signedArea(const std::vector<Vec2>& p) {
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) twice += cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * twice;
}

std::vector<Vec2> counterClockwise(std::vector<Vec2> p) {
    if (signedArea(p) < 0.0) std::reverse(p.begin(), p.end());
    return p;
}

// The part of convex `p` where side * cross(b - a, x - a) >= 0 (Sutherland
// and Hodgman's clip against one line).
std::vector<Vec2> clip(const std::vector<Vec2>& p, const Vec2& a, const Vec2& b, double side) {
    std::vector<Vec2> out;
    const auto f = [&](const Vec2& x) { return side * cross(b - a, x - a); };
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2& u = p[i];
        const Vec2& v = p[(i + 1) % p.size()];
        const double fu = f(u), fv = f(v);
        if (fu >= 0.0) out.push_back(u);
        if ((fu >= 0.0) != (fv >= 0.0)) out.push_back(u + (v - u) * (fu / (fu - fv)));
    }
    return out.size() >= 3 ? out : std::vector<Vec2>{};
}

// Convex p inside convex counter-clockwise s.
std::vector<Vec2> intersect(std::vector<Vec2> p, const std::vector<Vec2>& s) {
    for (std::size_t i = 0; i < s.size() && !p.empty(); ++i) p = clip(p, s[i], s[(i + 1) % s.size()], 1.0);
    return p;
}

// Convex p less convex counter-clockwise s, as disjoint convex pieces: the
// part outside each edge of s and inside the edges before it.
std::vector<std::vector<Vec2>> subtract(std::vector<Vec2> p, const std::vector<Vec2>& s) {
    std::vector<std::vector<Vec2>> pieces;
    for (std::size_t i = 0; i < s.size() && !p.empty(); ++i) {
        const Vec2& a = s[i];
        const Vec2& b = s[(i + 1) % s.size()];
        if (std::vector<Vec2> outside = clip(p, a, b, -1.0); convexArea(outside) > 0.0)
            pieces.push_back(std::move(outside));
        p = clip(p, a, b, 1.0);
    }
    return pieces;
}

// The signed area of the unit disc within the triangle (0, a, b): along the
// edge a-b, straight pieces inside the circle add their triangle, pieces
// outside add the circular sector they subtend.
double discTriangleArea(const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double qa = glm::dot(d, d);
    if (qa == 0.0) return 0.0;
    const double qb = glm::dot(a, d), qc = glm::dot(a, a) - 1.0;
    std::vector<double> ts{0.0};
    if (const double disc = qb * qb - qa * qc; disc > 0.0) {
        const double s = std::sqrt(disc);
        for (const double t : {(-qb - s) / qa, (-qb + s) / qa})
            if (t > 0.0 && t < 1.0) ts.push_back(t);
    }
    ts.push_back(1.0);
    double area = 0.0;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
        const Vec2 p = a + ts[i] * d, q = a + ts[i + 1] * d;
        const Vec2 mid = a + 0.5 * (ts[i] + ts[i + 1]) * d;
        area += glm::dot(mid, mid) <= 1.0 ? 0.5 * cross(p, q) : 0.5 * std::atan2(cross(p, q), glm::dot(p, q));
    }
    return area;
}

double ellipseAreaIn(const ImageEllipse& e, const std::vector<std::vector<Vec2>>& pieces) {
    double sum = 0.0;
    for (const auto& p : pieces) sum += ellipseAreaIn(e, p);
    return sum;
}

// Everything of a scene's object the exact image needs.
struct FlatShape {
    ImageShape image;
    Vec3 planePoint{0.0}, planeNormal{0.0};
    Vec2 lo{0.0}, hi{0.0};  // the image bounds
};

struct Projector {
    Vec3 location{0.0}, direction{0.0}, right{0.0}, up{0.0};
    Mat3 fromWorld{1.0};  // world offset -> (a, b, w) on (right, up, direction)
    double width = 0.0, height = 0.0;

    // Image coordinates as render/camera.hpp defines them: u = a / w = x / width - 0.5, v = b / w = 0.5 - y / height.
    glm::dmat3 homogeneous() const {
        // (a, b, w) -> (x w, y w, w)
        glm::dmat3 k(0.0);
        k[0][0] = width;          // column 0 (a) -> x
        k[2][0] = 0.5 * width;    // column 2 (w) -> x
        k[1][1] = -height;        // column 1 (b) -> y
        k[2][1] = 0.5 * height;   // column 2 (w) -> y
        k[2][2] = 1.0;
        return k * fromWorld;
    }
    Vec2 project(const Vec3& p, const std::string& what) const {
        const Vec3 q = fromWorld * (p - location);
        if (!(q.z > 0.0)) throw std::invalid_argument(what + " reaches behind the camera");
        return {(q.x / q.z + 0.5) * width, (0.5 - q.y / q.z) * height};
    }
    Vec3 ray(double x, double y) const {
        return direction + (x / width - 0.5) * right + (0.5 - y / height) * up;
    }
};

Vec3 flatColor(const Object& o, const SceneDescription& scene, const std::string& what) {
    const Texture& t = *o.texture;
    const Finish& f = t.finish;
    if (!t.above.empty() || t.pigment.kind != Pigment::Kind::Solid || t.pigment.color1.filter != 0.0 ||
        t.pigment.color1.transmit != 0.0)
        throw std::invalid_argument(what + ": not one opaque solid colour");
    if (f.diffuse != 0.0 || f.phong != 0.0 || f.specular != 0.0 || f.reflection != Vec3(0.0))
        throw std::invalid_argument(what + ": not lit by ambient only (diffuse, phong, specular, reflection 0)");
    return t.pigment.color1.rgb * f.ambient * scene.globals.ambientLight;
}

bool convex(const std::vector<Vec2>& p) {
    bool positive = false, negative = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double c = cross(p[(i + 1) % p.size()] - p[i], p[(i + 2) % p.size()] - p[(i + 1) % p.size()]);
        positive = positive || c > 0.0;
        negative = negative || c < 0.0;
    }
    return !(positive && negative);
}

FlatShape polygonShape(const PolygonShape& s, const Object& o, const Projector& cam, const std::string& what) {
    std::vector<Vec3> world;
    for (const Vec3& p : s.points) world.push_back(o.worldFromObject.point(p));
    if (world.size() > 3 && world.back() == world.front()) world.pop_back();
    if (std::find(world.begin() + 1, world.end(), world.front()) != world.end())
        throw std::invalid_argument(what + ": a polygon of several sub-polygons");
    FlatShape f;
    for (const Vec3& p : world) f.image.polygon.push_back(cam.project(p, what));
    if (!convex(f.image.polygon)) throw std::invalid_argument(what + ": not convex");
    f.image.polygon = counterClockwise(f.image.polygon);
    f.planePoint = world[0];
    for (std::size_t i = 2; i < world.size() && glm::length(f.planeNormal) == 0.0; ++i)
        f.planeNormal = glm::cross(world[1] - world[0], world[i] - world[0]);
    f.lo = f.hi = f.image.polygon[0];
    for (const Vec2& p : f.image.polygon) {
        f.lo = glm::min(f.lo, p);
        f.hi = glm::max(f.hi, p);
    }
    return f;
}

// The disc's circle c + s U + t V (s^2 + t^2 <= 1) is the conic diag(1, 1, -1)
// in (s, t, 1); through the homography H from (s, t, 1) to the image's
// homogeneous coordinates it is H^-T diag(1, 1, -1) H^-1.
FlatShape discShape(const DiscShape& s, const Object& o, const Projector& cam, const std::string& what) {
    if (s.holeRadius != 0.0) throw std::invalid_argument(what + ": a disc with a hole");
    const Vec3 n = glm::normalize(s.normal);
    const Vec3 e1 = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
    const Vec3 e2 = glm::cross(n, e1);
    const Vec3 c = o.worldFromObject.point(s.center);
    const Vec3 u = o.worldFromObject.vector(s.radius * e1), v = o.worldFromObject.vector(s.radius * e2);
    // In front of the camera: the circle's nearest point along the view has w > 0.
    const Vec3 cw = cam.fromWorld * (c - cam.location);
    const double reach = std::hypot((cam.fromWorld * u).z, (cam.fromWorld * v).z);
    if (!(cw.z - reach > 0.0)) throw std::invalid_argument(what + " reaches behind the camera");
    const glm::dmat3 h = cam.homogeneous() * glm::dmat3(u, v, c - cam.location);
    const glm::dmat3 hi = glm::inverse(h);
    const glm::dmat3 conic = glm::transpose(hi) * glm::dmat3(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1)) * hi;
    const glm::dmat2 q(conic[0][0], conic[0][1], conic[1][0], conic[1][1]);
    const Vec2 b(conic[2][0], conic[2][1]);
    const double f0 = conic[2][2];
    const glm::dmat2 qi = glm::inverse(q);
    const Vec2 centre = -(qi * b);
    const double k = glm::dot(b, qi * b) - f0;
    const glm::dmat2 m = q / k;  // (x - centre)^T m (x - centre) <= 1
    if (!(m[0][0] > 0.0 && glm::determinant(m) > 0.0))
        throw std::invalid_argument(what + ": its image is not an ellipse");
    // Cholesky: m = L L^T, and toUnit = L^T.
    const double l00 = std::sqrt(m[0][0]), l10 = m[0][1] / l00, l11 = std::sqrt(m[1][1] - l10 * l10);
    FlatShape out;
    ImageEllipse e;
    e.centre = centre;
    e.toUnit = glm::dmat2(l00, 0.0, l10, l11);  // columns: (l00, 0), (l10, l11), i.e. rows (l00, l10), (0, l11)
    out.image.ellipse = e;
    const glm::dmat2 back = glm::inverse(e.toUnit);
    const Vec2 extent(std::hypot(back[0][0], back[1][0]), std::hypot(back[0][1], back[1][1]));
    out.lo = centre - extent;
    out.hi = centre + extent;
    out.planePoint = c;
    out.planeNormal = o.worldFromObject.normal(n);
    return out;
}

}  // namespace

double convexArea(const std::vector<Vec2>& polygon) {
    return polygon.size() < 3 ? 0.0 : std::abs(signedArea(polygon));
}

double ellipseAreaIn(const ImageEllipse& e, const std::vector<Vec2>& polygon) {
    if (polygon.size() < 3) return 0.0;
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        area += discTriangleArea(e.toUnit * (polygon[i] - e.centre),
                                 e.toUnit * (polygon[(i + 1) % polygon.size()] - e.centre));
    return std::abs(area) / std::abs(glm::determinant(e.toUnit));
}

std::vector<double> visibleAreas(const std::vector<ImageShape>& frontToBack, const std::vector<Vec2>& region) {
    std::vector<std::vector<Vec2>> open{counterClockwise(region)};  // the part no polygon in front covers
    std::vector<const ImageEllipse*> ellipses;                     // the ellipses in front
    std::vector<double> areas;
    for (const ImageShape& s : frontToBack) {
        if (s.ellipse) {
            const double a = ellipseAreaIn(*s.ellipse, open);
            if (a > 0.0)
                for (const ImageEllipse* e : ellipses)
                    if (ellipseAreaIn(*e, open) > 0.0)
                        throw std::invalid_argument("two discs in one pixel: their overlap has no closed form here");
            areas.push_back(a);
            if (a > 0.0) ellipses.push_back(&*s.ellipse);
            continue;
        }
        const std::vector<Vec2> polygon = counterClockwise(s.polygon);
        std::vector<std::vector<Vec2>> covered, rest;
        for (const auto& p : open) {
            if (std::vector<Vec2> in = intersect(p, polygon); !in.empty()) covered.push_back(std::move(in));
            for (auto& piece : subtract(p, polygon)) rest.push_back(std::move(piece));
        }
        double a = 0.0;
        for (const auto& p : covered) a += convexArea(p);
        for (const ImageEllipse* e : ellipses) a -= ellipseAreaIn(*e, covered);
        areas.push_back(std::max(a, 0.0));
        open = std::move(rest);
    }
    double uncovered = 0.0;
    for (const auto& p : open) uncovered += convexArea(p);
    for (const ImageEllipse* e : ellipses) uncovered -= ellipseAreaIn(*e, open);
    areas.push_back(std::max(uncovered, 0.0));
    return areas;
}

Image exactCoverageImage(const SceneDescription& scene, int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("exactCoverageImage: a positive size");
    const Camera& c = scene.camera;
    if (c.projection != Camera::Projection::Perspective)
        throw std::invalid_argument("exactCoverageImage: a perspective camera only");
    Projector cam;
    cam.location = c.location;
    cam.direction = c.direction;
    cam.right = c.right;
    cam.up = c.up;
    cam.fromWorld = glm::inverse(Mat3(c.right, c.up, c.direction));
    cam.width = width;
    cam.height = height;
    if (scene.background.transmit != 0.0) throw std::invalid_argument("exactCoverageImage: a transparent background");

    std::vector<FlatShape> shapes;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const std::string what = "object " + std::to_string(i + 1) + " (line " + std::to_string(o.loc.line) + ")";
        FlatShape f;
        if (const auto* p = std::get_if<PolygonShape>(&o.shape)) f = polygonShape(*p, o, cam, what);
        else if (const auto* d = std::get_if<DiscShape>(&o.shape)) f = discShape(*d, o, cam, what);
        else throw std::invalid_argument(what + ": only polygons and discs are flat shapes here");
        f.image.color = flatColor(o, scene, what);
        shapes.push_back(std::move(f));
    }

    Image out = Image::rgb(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Vec3 ray = cam.ray(x + 0.5, y + 0.5);
            std::vector<std::pair<double, const FlatShape*>> here;
            for (const FlatShape& s : shapes)
                if (s.lo.x < x + 1 && s.hi.x > x && s.lo.y < y + 1 && s.hi.y > y) {
                    const double facing = glm::dot(s.planeNormal, ray);
                    // Edge-on to the centre ray: seen edge-on, its depth here does not matter.
                    const double depth = facing != 0.0 ? glm::dot(s.planeNormal, s.planePoint - cam.location) / facing : 0.0;
                    here.emplace_back(depth, &s);
                }
            std::stable_sort(here.begin(), here.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            std::vector<ImageShape> ordered;
            for (const auto& [depth, s] : here) ordered.push_back(s->image);
            const std::vector<Vec2> square{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
            const std::vector<double> areas = visibleAreas(ordered, square);
            Vec3 color = areas.back() * scene.background.rgb;
            for (std::size_t k = 0; k < ordered.size(); ++k) color += areas[k] * ordered[k].color;
            out.setRgb(x, y, color);
        }
    return out;
}

}  // namespace asos
