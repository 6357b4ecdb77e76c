// libFuzzer target: the conservative rule of the cone classification. The
// input chooses a primitive (each shape asos knows), a transform (translate,
// rotate, scale, a general matrix) and a cone (apex, axis, half-angle,
// t-range), all within the ranges a scene produces; the primitive's answer
// is checked against a dense set of the cone's rays traced exactly
// (probeCone, as the property tests do): Miss where a ray hits, Full where
// one misses or a depth outside the answer's interval, or a crease left
// out, aborts.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "asos/geometry/transform.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/shapes/shape_issue.hpp"
#include "asos/testing/cone_probe.hpp"

namespace {

using namespace asos;

double value(FuzzedDataProvider& in, double lo, double hi) { return in.ConsumeFloatingPointInRange(lo, hi); }
Vec3 point(FuzzedDataProvider& in, double extent) {
    return {value(in, -extent, extent), value(in, -extent, extent), value(in, -extent, extent)};
}
Vec3 direction(FuzzedDataProvider& in) {
    for (int tries = 0; tries < 4; ++tries) {
        const Vec3 d = point(in, 1.0);
        if (glm::length(d) > 1e-3) return glm::normalize(d);
    }
    return {0.0, 0.0, 1.0};
}

Shape shapeFrom(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange(0, 6)) {
        case 0: return SphereShape{point(in, 4.0), value(in, 1e-3, 4.0)};
        case 1: return BoxShape{point(in, 4.0), point(in, 4.0)};
        case 2: return ConeShape{point(in, 4.0), value(in, 0.0, 3.0), point(in, 4.0), value(in, 0.0, 3.0), in.ConsumeBool()};
        case 3: return CylinderShape{point(in, 4.0), point(in, 4.0), value(in, 1e-3, 3.0), in.ConsumeBool()};
        case 4: return DiscShape{point(in, 4.0), direction(in), value(in, 1e-3, 4.0), value(in, 0.0, 2.0)};
        case 5: {
            PolygonShape p;
            const int n = in.ConsumeIntegralInRange(3, 8);
            for (int i = 0; i < n; ++i) p.points.push_back({value(in, -4.0, 4.0), value(in, -4.0, 4.0), 0.0});
            p.points.push_back(p.points.front());
            return p;
        }
        default: return PlaneShape{direction(in), value(in, -4.0, 4.0)};
    }
}

Transform transformFrom(FuzzedDataProvider& in) {
    Transform t = Transform::translate(point(in, 5.0));
    switch (in.ConsumeIntegralInRange(0, 3)) {
        case 0: return t;
        case 1: return t * Transform::rotateDegrees(point(in, 180.0));
        case 2:
            return t * Transform::rotateDegrees(point(in, 180.0)) *
                   Transform::scale({value(in, 0.2, 5.0), value(in, 0.2, 5.0), value(in, 0.2, 5.0)});
        default: {
            double v[12];
            for (int i = 0; i < 9; ++i) v[i] = (i % 4 == 0 ? 1.0 : 0.0) + value(in, -0.6, 0.6);
            for (int i = 9; i < 12; ++i) v[i] = value(in, -5.0, 5.0);
            return Transform::fromPovMatrix(v);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const Shape shape = shapeFrom(in);
    if (!shapeIssues(shape).empty()) return 0;  // what the interpreter refuses
    const Transform transform = transformFrom(in);
    if (!(std::abs(glm::determinant(Mat3(transform.matrix()))) > 1e-3)) return 0;
    Cone cone;
    cone.apex = point(in, 10.0);
    cone.axis = direction(in);
    const double angle = in.ConsumeIntegralInRange(0, 3);
    cone.halfAngle = angle == 0 ? value(in, 0.0, 1e-6) : angle == 1 ? value(in, 0.0, 0.01) : value(in, 0.0, 1.5);
    cone.tMin = in.ConsumeBool() ? 0.0 : value(in, 0.0, 10.0);
    cone.tMax = in.ConsumeBool() ? kInfinity : cone.tMin + value(in, 0.0, 20.0);
    const bool creases = in.ConsumeBool();
    // A record shapeIssues passes is one Primitive::make lays out: a throw
    // here is a finding too.
    const Primitive primitive = Primitive::make(shape, transform);
    const ConeClass answer = primitive.classify(PreparedCone(cone, creases));
    const ProbeResult probe = probeCone(primitive, cone, answer, {}, creases);
    if (probe.violations > 0) {
        std::fprintf(stderr, "fuzz_cone: %s: %s\n", primitive.kindName(), probe.firstViolation.c_str());
        std::abort();
    }
    return 0;
}
