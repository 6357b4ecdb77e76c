// `asos-bench intersect`: the paper's Table 3 ("Cone vs. ray intersection")
// on this machine. For each primitive: nanoseconds per nearest-hit ray test,
// per cone classification, and their ratio; then how the cones were
// classified and the spurious-marginal rate (a Marginal cone whose probe rays
// all hit or all miss, judged by cone_probe's dense rays).
//
// Each round visits the queries in a fresh order, and the bench consumes the
// answers without a branch of its own (reshuffle, keep): what is timed is
// the tests as they run on questions never seen before.
//
// The queries imitate what the tracer issues after its BVH: rays and cones
// aimed into the object's bounding box, from eyes 3 to 30 object sizes away;
// the cones are mostly pixel-sized (1e-3 rad and its subdivisions down to
// level 4), some are shadow cones to an area light beyond the object (a cut
// t-range), a few are wide. Each ray is its cone's axis with the same range.
// Objects vary (16 of each kind) and sit under translations (60%),
// rotations (30%) and non-uniform scales (10%).
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "asos/testing/cone_probe.hpp"
#include "asos/testing/rng.hpp"
#include "asos/shapes/primitive.hpp"
#include "benchmarks.hpp"

namespace asos::bench {
namespace {

struct Kind {
    const char* name;
    double paperRatio;  // Table 3; 0 where the paper has no row
    Shape (*make)(Rng&);
};

Shape makeSphere(Rng& rng) { return SphereShape{Vec3(0.0), rng.uniform(0.5, 1.5)}; }

Shape makePolygon(Rng& rng) {
    const double pick = rng.uniform();
    const int n = pick < 0.5 ? 3 : pick < 0.8 ? 4 : 5 + static_cast<int>(rng.uniform(0.0, 4.0));
    std::vector<Vec3> points;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * kPi * (i + rng.uniform(0.0, 0.5)) / n;
        const double r = n > 4 && i % 2 ? rng.uniform(0.4, 0.8) : 1.0;
        points.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
    }
    return PolygonShape{points};
}

Shape makeDisc(Rng& rng) {
    return DiscShape{Vec3(0.0), Vec3(0, 1, 0), 1.0, rng.chance(0.3) ? rng.uniform(0.2, 0.5) : 0.0};
}

Shape makeBox(Rng& rng) {
    const Vec3 half(rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0));
    return BoxShape{-half, half};
}

Shape makeCone(Rng& rng) {
    return ConeShape{Vec3(0, -1, 0), 1.0, Vec3(0, 1, 0), rng.chance(0.5) ? 0.0 : 0.4,
                     rng.chance(0.2)};
}

Shape makeCylinder(Rng& rng) {
    return CylinderShape{Vec3(0, -1, 0), Vec3(0, 1, 0), rng.uniform(0.4, 1.0), rng.chance(0.2)};
}

Shape makePlane(Rng& rng) { return PlaneShape{rng.unitVector(), rng.uniform(-1.0, 1.0)}; }

const Kind kKinds[] = {
    {"sphere", 1.01, makeSphere},     {"polygon", 1.42, makePolygon}, {"disc", 1.01, makeDisc},
    {"box", 1.19, makeBox},           {"cone", 2.40, makeCone},       {"cylinder", 5.40, makeCylinder},
    {"plane", 0.0, makePlane},
};

// mix: "mixed" (60% translate, 30% rotate, 10% non-uniform scale), or all
// "translate", all "rotate" or all "scale".
Transform randomPlacement(Rng& rng, const std::string& mix) {
    const Vec3 offset(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10));
    const Vec3 angles(rng.uniform(-180, 180), rng.uniform(-180, 180), rng.uniform(-180, 180));
    const double pick = mix == "translate" ? 0.0
                        : mix == "rotate"  ? 0.7
                        : mix == "scale"   ? 0.95
                                           : rng.uniform();
    if (pick < 0.6) return Transform::translate(offset);
    if (pick < 0.9) return Transform::translate(offset) * Transform::rotateDegrees(angles);
    return Transform::translate(offset) * Transform::rotateDegrees(angles) *
           Transform::scale(Vec3(rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0)));
}

// A cone as the tracer would test it against this object; its ray is the axis.
Cone randomQuery(Rng& rng, const Primitive& prim) {
    Bounds3 box = prim.bounded() ? prim.worldBounds() : Bounds3{Vec3(-3.0), Vec3(3.0)};
    const Vec3 pad = 0.1 * box.diagonal();
    box = {box.lo - pad, box.hi + pad};
    const double size = glm::length(box.diagonal());
    const Vec3 target(rng.uniform(box.lo.x, box.hi.x), rng.uniform(box.lo.y, box.hi.y),
                      rng.uniform(box.lo.z, box.hi.z));
    Cone cone;
    const double pick = rng.uniform();
    if (pick < 0.85) {
        // An eye cone: a pixel's (1e-3 rad), or one of its subpyrays' (levels 1-4).
        cone.apex = target + rng.unitVector() * size * rng.uniform(3.0, 30.0);
        cone.halfAngle = 1e-3 / static_cast<double>(1 << static_cast<int>(rng.uniform(0.0, 5.0)));
    } else if (pick < 0.95) {
        // A shadow cone from a nearby surface point to an area light behind the object.
        cone.apex = target + rng.unitVector() * size * rng.uniform(1.0, 3.0);
        cone.halfAngle = rng.uniform(0.01, 0.1);
        cone.tMin = 1e-6 * size;
        cone.tMax = glm::length(target - cone.apex) * rng.uniform(1.5, 3.0);
    } else {
        cone.apex = target + rng.unitVector() * size * rng.uniform(3.0, 30.0);
        cone.halfAngle = rng.uniform(0.02, 0.3);
    }
    cone.axis = glm::normalize(target - cone.apex);
    return cone;
}

struct Timing {
    double rayNs, coneNs, coneTrigNs;
};

// The queries of one primitive kind, in compact arrays.
struct Queries {
    struct RayQuery {
        Ray ray;
        double tMin, tMax;
        std::uint32_t object;
    };
    struct ConeQuery {
        PreparedCone cone;
        std::uint32_t object;
    };
    struct RawCone {
        Cone cone;
        std::uint32_t object;
    };
    std::vector<RayQuery> rays;
    std::vector<ConeQuery> cones;
    std::vector<RawCone> raw;
};

// CPU time of this thread: a share of the 2 cores going to other work does
// not count (cache and frequency effects still do).
double threadNanoseconds() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

// Makes a result observable to the compiler without consuming it by code of
// its own (the idiom of Google Benchmark's DoNotOptimize): a branch on the
// answer here would be timed with the test, and mispredicted as often as the
// answers are mixed.
template <class T>
inline void keep(const T& value) {
    asm volatile("" : : "r"(&value) : "memory");
}

// Each round visits the queries in a fresh order (shuffled outside the
// timed loop). Over the same sequence again and again a branch predictor
// learns the answers of thousands of queries: on a Zen 4 core 8192 queries
// in a fixed order ran the disc's cones at 24 ns, in a new order each round
// at 37 ns. The tracer asks fresh questions, so the bench does too. The
// objects keep their cycle (query i asks object i mod 16, a predictable
// sequence, as a BVH leaf's objects come one after the other): queries are
// shuffled among those of the same object.
template <class T>
void reshuffle(std::vector<T>& items, std::size_t objects, std::mt19937_64& order) {
    for (std::size_t first = 0; first < objects && first < items.size(); ++first) {
        const std::size_t count = (items.size() - first + objects - 1) / objects;
        for (std::size_t i = count - 1; i > 0; --i) {
            const std::size_t j = std::uniform_int_distribution<std::size_t>(0, i)(order);
            std::swap(items[first + i * objects], items[first + j * objects]);
        }
    }
}

// One round: `repeat` passes over the items in a fresh order, in ns per item.
template <class Item, class Body>
double timeRound(std::vector<Item>& items, std::size_t objects, int repeat, std::mt19937_64& order,
                 Body&& body) {
    reshuffle(items, objects, order);
    const double start = threadNanoseconds();
    for (int r = 0; r < repeat; ++r)
        for (const Item& item : items) body(item);
    return (threadNanoseconds() - start) /
           (static_cast<double>(repeat) * static_cast<double>(items.size()));
}

// A cone query (prepared or raw) classified, its answer kept.
template <class ConeQuery>
void classifyKept(const std::vector<Primitive>& objects, const ConeQuery& c) {
    const ConeClass k = objects[c.object].classify(c.cone);
    keep(k);
}

Timing timeKind(const std::vector<Primitive>& objects, Queries& q, int repeat, std::mt19937_64& order) {
    const auto ray = [&](const Queries::RayQuery& r) {
        const auto hit = objects[r.object].intersect(r.ray, r.tMin, r.tMax);
        keep(hit);
    };
    const auto cone = [&](const auto& c) { classifyKept(objects, c); };
    // Short rounds, interleaved, the best of each kept.
    Timing t{kInfinity, kInfinity, kInfinity};
    for (int i = 0; i < 40; ++i) {
        t.rayNs = std::min(t.rayNs, timeRound(q.rays, objects.size(), repeat, order, ray));
        t.coneNs = std::min(t.coneNs, timeRound(q.cones, objects.size(), repeat, order, cone));
        t.coneTrigNs = std::min(t.coneTrigNs, timeRound(q.raw, objects.size(), repeat, order, cone));
    }
    return t;
}

// ns per classification over a subset of the cones (the best of 40 rounds).
double timeCones(const std::vector<Primitive>& objects, std::vector<Queries::ConeQuery>& cones,
                 int repeat, std::mt19937_64& order) {
    if (cones.empty()) return 0.0;
    const auto cone = [&](const Queries::ConeQuery& c) { classifyKept(objects, c); };
    double best = kInfinity;
    for (int round = 0; round < 40; ++round)
        best = std::min(best, timeRound(cones, objects.size(), repeat, order, cone));
    return best;
}

int run(int queries, int repeat, int probes, std::uint64_t seed, const std::string& only,
        const std::string& mix) {
    std::printf("asos-bench intersect: %d queries per primitive, best of 40 interleaved rounds of %d "
                "pass%s, each round in a fresh order; %d probed cones per primitive; %s placements\n\n",
                queries, repeat, repeat == 1 ? "" : "es", probes, mix.c_str());
    std::printf("%-9s %9s %9s %12s %7s %7s\n", "primitive", "ray_ns", "cone_ns", "cone+trig_ns",
                "paper", "ratio");
    struct Stats {
        const char* name;
        int miss = 0, full = 0, marginal = 0, spurious = 0, single = 0;
        double missNs = 0.0, fullNs = 0.0, marginalNs = 0.0;
    };
    std::vector<Stats> stats;
    for (const Kind& kind : kKinds) {
        if (!only.empty() && only != kind.name) continue;
        Rng rng(seed ^ std::hash<std::string>{}(kind.name));
        std::vector<Primitive> objects;
        for (int i = 0; i < 16; ++i) objects.push_back(Primitive::make(kind.make(rng), randomPlacement(rng, mix)));
        Queries q;
        for (int i = 0; i < queries; ++i) {
            const std::uint32_t object = static_cast<std::uint32_t>(i % objects.size());
            const Cone cone = randomQuery(rng, objects[object]);
            q.rays.push_back({{cone.apex, cone.axis}, cone.tMin, cone.tMax, object});
            q.cones.push_back({PreparedCone(cone), object});
            q.raw.push_back({cone, object});
        }
        std::mt19937_64 order(seed + 1);
        const Timing t = timeKind(objects, q, repeat, order);
        char paper[16] = "-";
        if (kind.paperRatio > 0.0) std::snprintf(paper, sizeof paper, "%.2f", kind.paperRatio);
        std::printf("%-9s %9.2f %9.2f %12.2f %7s %7.2f\n", kind.name, t.rayNs, t.coneNs,
                    t.coneTrigNs, paper, t.coneNs / t.rayNs);

        Stats s{kind.name};
        {
            // The time of each answer apart.
            std::vector<Queries::ConeQuery> byClass[3];
            for (const auto& c : q.cones)
                byClass[static_cast<int>(objects[c.object].classify(c.cone).coverage)].push_back(c);
            s.missNs = timeCones(objects, byClass[0], repeat, order);
            s.fullNs = timeCones(objects, byClass[1], repeat, order);
            s.marginalNs = timeCones(objects, byClass[2], repeat, order);
        }
        for (int i = 0; i < probes && i < queries; ++i) {
            const Queries::RawCone& c = q.raw[static_cast<std::size_t>(i)];
            const Primitive& prim = objects[c.object];
            const ConeClass k = prim.classify(c.cone);
            if (k.coverage == Coverage::Miss) {
                ++s.miss;
            } else if (k.coverage == Coverage::Full) {
                ++s.full;
            } else {
                ++s.marginal;
                if (k.singleEdge) ++s.single;
                // Denser than the tests' probe: the rate is judged by these rays.
                const ProbeResult p = probeCone(prim, c.cone, k, ProbeDensity{16, 8, 256});
                if (p.allHit() || p.allMiss()) ++s.spurious;
            }
        }
        stats.push_back(s);
    }
    std::printf("\n(ratio = cone_ns / ray_ns with the cone's sine and cosine computed once per "
                "cone, as the tracer does for its many objects; cone+trig_ns computes them per "
                "call)\n\n");
    if (probes == 0) {  // nothing to count the classes over
        return 0;
    }
    std::printf("%-9s %7s %7s %9s %8s %8s %8s %11s %14s %16s\n", "primitive", "miss%", "full%",
                "marginal%", "miss_ns", "full_ns", "marg_ns", "singleEdge%", "spurious/marg%",
                "spurious/cones%");
    for (std::size_t i = 0; i < stats.size(); ++i) {
        const Stats& s = stats[i];
        const double n = s.miss + s.full + s.marginal;
        const double m = std::max(1, s.marginal);
        std::printf("%-9s %7.2f %7.2f %9.2f %8.1f %8.1f %8.1f %11.2f %14.2f %16.3f\n", s.name,
                    100.0 * s.miss / n, 100.0 * s.full / n, 100.0 * s.marginal / n, s.missNs,
                    s.fullNs, s.marginalNs, 100.0 * s.single / m, 100.0 * s.spurious / m,
                    100.0 * s.spurious / n);
    }
    std::printf("\n(class %% over the probed cones; *_ns: classification time of the cones "
                "answered so, apart)\n(spurious: a Marginal cone whose ~1350 probe rays - axis, 16 rings, rim - all hit "
                "or all miss; a boundary passing between the probe rays counts too, so this is an "
                "upper bound)\n");
    return 0;
}

}  // namespace

void addIntersectBenchmark(CLI::App& app, CommandResult& result) {
    CLI::App* cmd = app.add_subcommand(
        "intersect", "Ray test vs cone classification per primitive (the paper's Table 3)");
    struct Options {
        int queries = 8192;
        int repeat = 1;
        int probes = 8192;
        std::uint64_t seed = 1993;
        std::string only;
        std::string transforms = "mixed";
    };
    auto options = std::make_shared<Options>();
    cmd->add_option("--queries", options->queries, "rays and cones per primitive")
        ->check(CLI::Range(1, 1 << 24));
    cmd->add_option("--repeat", options->repeat,
                    "timed passes over them per round (each round in a fresh order; passes after "
                    "the first repeat it, which a branch predictor may learn)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--probes", options->probes, "cones checked with dense rays per primitive")
        ->check(CLI::Range(0, 1 << 24));
    cmd->add_option("--seed", options->seed, "random seed");
    cmd->add_option("--transforms", options->transforms,
                    "object placements: mixed (60% translate, 30% rotate, 10% non-uniform "
                    "scale), translate, rotate or scale")
        ->check(CLI::IsMember({"mixed", "translate", "rotate", "scale"}));
    cmd->add_option("--only", options->only, "one primitive (sphere, polygon, disc, box, cone, "
                                              "cylinder, plane)")
        ->check(CLI::IsMember({"sphere", "polygon", "disc", "box", "cone", "cylinder", "plane"}));
    cmd->callback([options, &result] {
        result.exitCode =
            run(options->queries, options->repeat, options->probes, options->seed, options->only,
                options->transforms);
    });
}

}  // namespace asos::bench
