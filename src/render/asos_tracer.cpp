#include "asos/render/asos_tracer.hpp"

#include <algorithm>
#include <cmath>

#include "asos/shapes/local_cone.hpp"

namespace asos {

namespace {

using Item = AsosScratch::Item;

// Drops, in place and in order, the objects of items[first, end) that lie
// wholly behind a Full object (their nearest depth beyond its farthest): no
// ray of the pyray can see them. Returns how many are left; items is cut to
// first + that.
std::uint32_t pruneHidden(std::vector<Item>& items, std::uint32_t first) {
    double front = kInfinity;
    for (std::size_t i = first; i < items.size(); ++i)
        if (items[i].cls.coverage == Coverage::Full) front = std::min(front, items[i].cls.tFar);
    std::size_t kept = first;
    for (std::size_t i = first; i < items.size(); ++i)
        if (items[i].cls.tNear <= front) items[kept++] = items[i];
    items.resize(kept);
    return static_cast<std::uint32_t>(kept - first);
}

// A Full object whose depth range overlaps another object's in the same
// pyray: the visible surface may switch between them inside the pyray (a
// sphere sunk into a plane), though neither has a boundary there.
bool overlapsAnother(const std::vector<Item>& items, std::uint32_t first, std::uint32_t count,
                     std::uint32_t i) {
    const ConeClass& a = items[i].cls;
    for (std::uint32_t j = first; j < first + count; ++j) {
        if (j == i) continue;
        const ConeClass& b = items[j].cls;
        if (b.tNear <= a.tFar && a.tNear <= b.tFar) return true;
    }
    return false;
}

}  // namespace

AsosTracer::AsosTracer(const RayTracer& tracer, const CameraModel& camera,
                       const AsosSettings& sceneSettings, std::uint64_t seed, bool patternEdges)
    : tracer_(tracer), scene_(tracer.scene()), camera_(camera), seed_(seed),
      patternEdges_(patternEdges) {
    const SceneDescription& d = scene_.description();
    objectSettings_.reserve(d.objects.size());
    selfShadowing_.reserve(d.objects.size());
    patterned_.reserve(d.objects.size());
    for (const Object& o : d.objects) {
        objectSettings_.push_back(sceneSettings.refinedBy(o.asos));
        selfShadowing_.push_back(canShadowItself(o.shape) ? 1 : 0);
        patterned_.push_back(hasPattern(textureOf(o).pigment) ? 1 : 0);
    }
    for (const Light& l : d.lights) lightSettings_.push_back(sceneSettings.refinedBy(l.asos));

    // An orthographic pyray is a prism, which a cone can only hold with its
    // apex far behind the camera; over an unbounded depth its rays spread by
    // a fixed angle, and the farther objects lie, the more pyrays near their
    // edges are called marginal. When every object is bounded the prism can
    // end behind the last of them, and the cone stays within 1/16 of the
    // prism (geometry/beam_eye.hpp).
    bool allBounded = !scene_.bvh().empty();
    for (std::uint32_t i = 0; i < scene_.objectCount() && allBounded; ++i)
        allBounded = scene_.primitive(i).bounded();
    if (camera_.orthographic() && allBounded) {
        const Bounds3& b = scene_.bvh().bounds();
        const Vec3 dir = glm::normalize(camera_.direction());
        double farthest = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            farthest = std::max(farthest, glm::dot(b.corner(corner) - camera_.location(), dir));
        }
        // Camera ray origins lie in the plane through the location spanned by
        // right and up, which may lean on the direction: allow for its slope.
        const Vec3 r = camera_.right(), u = camera_.up();
        farthest += 0.5 * (std::abs(glm::dot(r, dir)) + std::abs(glm::dot(u, dir)));
        // Well beyond the last object, so that no object's far side is near
        // the end of the range (where classifications turn cautious); the
        // cone's spread is relative to the depth, so this costs nothing.
        eyeTMax_ = 2.0 * std::max(farthest, 0.0) + 1.0;
    }
}

PixelResult AsosTracer::tracePixel(int x, int y, AsosScratch& scratch, RenderCounters& counters) const {
    return trace(x, y, scratch, counters, nullptr);
}

AsosPixelReport AsosTracer::tracePixelReport(int x, int y, AsosScratch& scratch,
                                             RenderCounters& counters) const {
    AsosPixelReport report;
    report.result = trace(x, y, scratch, counters, &report);
    return report;
}

std::optional<SurfaceHit> AsosTracer::nearestInList(const Ray& ray, const std::vector<Item>& items,
                                                    std::uint32_t first, std::uint32_t count,
                                                    std::uint8_t* marks,
                                                    RenderCounters& counters) const {
    std::optional<SurfaceHit> nearest;
    for (std::uint32_t i = first; i < first + count; ++i) {
        ++counters.rayTests;
        // With marks to keep, every object is asked whether the ray hits it
        // at all; without, only for a hit nearer than the best so far.
        const double tMax = marks || !nearest ? kInfinity : nearest->t;
        std::optional<SurfaceHit> hit =
            scene_.primitive(items[i].object).intersect(ray, kPovMinIsectDepth, tMax);
        if (marks) marks[i] = hit.has_value();
        if (hit && (!nearest || hit->t < nearest->t)) {
            hit->objectIndex = static_cast<int>(items[i].object);
            nearest = hit;
        }
    }
    return nearest;
}

Vec3 AsosTracer::shadeLeaf(const ImageSquare& square, int level, std::uint32_t ix, std::uint32_t iy,
                           const Ray& ray, const std::optional<SurfaceHit>& hit,
                           const PixelRandom& rng, AsosScratch& scratch,
                           RenderCounters& counters) const {
    if (!hit) return backgroundColor(scene_.description());
    std::optional<Footprint> footprint;  // made when a light first needs it
    LightSample storage;
    // Area lights: shadow beams from the shaded point (render/area_light.hpp),
    // with random numbers of this leaf's own.
    LightContext context{&scratch.area, rng, subPosition(level, ix, iy), nullptr};
    auto lightArriving = [&](const ShadingPoint& p) -> std::span<const LightSample> {
        const Light& light = *p.light;
        if (tracer_.sceneLights()[static_cast<std::size_t>(p.lightIndex)].isArea()) {
            if (tracer_.sceneLights().setup().apex == ShadowApex::Behind && !footprint)
                footprint.emplace(camera_, square, hit->position, hit->normal, hit->t);
            context.footprint = footprint ? &*footprint : nullptr;
            return tracer_.areaLightSamples(p, context, counters);
        }
        if (!facesLight(p.position, p.normal, light.position)) return {};
        double lit = 1.0;
        if (!light.shadowless) {
            if (!footprint) footprint.emplace(camera_, square, hit->position, hit->normal, hit->t);
            PointShadowQuery query;
            query.lightPosition = light.position;
            query.lightIndex = static_cast<std::size_t>(p.lightIndex);
            query.settings = lightSettings_[static_cast<std::size_t>(p.lightIndex)];
            query.shadedObject = static_cast<std::uint32_t>(hit->objectIndex);
            // An open tube is the boundary of a convex solid: its outer side,
            // like any convex surface, shadows itself only through N.L <= 0.
            // Only its inner side, seen through an opening (the normal
            // turned toward the viewer points inward), can be in its own
            // shadow.
            query.shadedCanSelfShadow = selfShadowing_[query.shadedObject] != 0 &&
                                        glm::dot(p.normal, hit->normal) < 0.0;
            query.level = level;
            query.ix = ix;
            query.iy = iy;
            query.rng = rng;
            query.jitterKey = mix64(static_cast<std::uint64_t>(p.lightIndex));
            lit = pointLightLitFraction(scene_, *footprint, query, scratch.shadow, counters);
            if (!(lit > 0.0)) return {};
        }
        storage = pointLightSample(light.position, light.color, p.position, lit);
        return {&storage, 1};
    };
    return tracer_.shadeWith(*hit, ray, 1, 1.0, lightArriving, counters, context);
}

PixelResult AsosTracer::trace(int px, int py, AsosScratch& s, RenderCounters& c,
                              AsosPixelReport* report) const {
    const PixelRandom rng(seed_, px, py);
    auto rayAt = [this](double u, double v) { return camera_.ray(u, v); };
    const Vec3 background = backgroundColor(scene_.description());
    Vec3 color(0.0);
    std::uint32_t pyrays = 0;
    int deepest = 0, leaves = 0;

    // The central ray of a pyray resolved by one Full object in front of
    // everything else must hit that object ("additional eye rays through
    // this pixel can only strike this object").
    auto frontHit = [&](const EyePyray& pyray, const Item& front) {
        const Ray& ray = pyray.centralRay();
        ++c.eyeRays;
        ++c.rayTests;
        std::optional<SurfaceHit> hit =
            scene_.primitive(front.object).intersect(ray, kPovMinIsectDepth, kInfinity);
        if (hit) hit->objectIndex = static_cast<int>(front.object);
        else hit = tracer_.nearestHit(ray);  // rounding at the cone's rim: ask the scene
        return hit;
    };
    // Whether the front object's pigment pattern may change inside the
    // pyray's footprint (an edge of the texture rather than of the object).
    auto patternEdge = [&](const EyePyray& pyray, const Item& front,
                           const std::optional<SurfaceHit>& hit) {
        if (!patternEdges_ || !patterned_[front.object] || !hit ||
            hit->objectIndex != static_cast<int>(front.object))
            return PatternChange{};
        const Footprint footprint(camera_, pyray.square(), hit->position, hit->normal, hit->t);
        return pigmentMayChange(textureOf(scene_.object(front.object)).pigment, footprint);
    };
    // How a fresh pyray's objects items[first, first + count) decide it:
    // resolved with no object (background) or one in front, or marginal.
    struct Resolution {
        bool resolved;
        const Item* front;
    };
    auto resolve = [](const std::vector<Item>& items, std::uint32_t first, std::uint32_t count) {
        if (count == 0) return Resolution{true, nullptr};
        if (count == 1 && items[first].cls.coverage == Coverage::Full)
            return Resolution{true, &items[first]};
        return Resolution{false, nullptr};
    };

    // Detection phase: the pixel's list.
    const ImageSquare pixel{double(px), double(py), px + 1.0, py + 1.0};
    const EyePyray root = EyePyray::make(rayAt, pixel, 0, kPovMinIsectDepth, eyeTMax_);
    ++pyrays;
    c.countPyray(0);
    std::vector<Item>& rootItems = s.items[0];
    rootItems.clear();
    const PreparedCone rootCone(root.cone());
    auto detect = [&](std::uint32_t object) {
        ++c.coneTests;
        const ConeClass k = scene_.primitive(object).classify(rootCone);
        if (k.coverage != Coverage::Miss) rootItems.push_back({object, k});
    };
    // Neighbouring pixels' cones share the eye as apex: a remembered wider
    // cone's objects serve them (perspective cameras; orthographic pyrays
    // have an apex each).
    if (camera_.orthographic()) scene_.coneCandidates(root.cone(), detect);
    else s.eyeCandidates.visit(scene_, root.cone(), detect);
    sortByObject(rootItems.data(), rootItems.data() + rootItems.size());
    const std::uint32_t rootCount = pruneHidden(rootItems, 0);
    const auto [resolved, front] = resolve(rootItems, 0, rootCount);

    auto finish = [&]() {
        if (report) report->leaves = leaves;
        return PixelResult{color, pyrays, static_cast<std::uint32_t>(deepest)};
    };
    s.hits[0].assign(rootCount, 0);
    s.nodes[0].clear();
    if (resolved && !front) {
        ++leaves;
        color = background;
        return finish();
    }
    if (resolved) {
        std::optional<SurfaceHit> hit = frontHit(root, *front);
        const PatternChange pattern = patternEdge(root, *front, hit);
        if (!pattern.mayChange) {
            ++leaves;
            color = shadeLeaf(root.square(), 0, 0, 0, root.centralRay(), hit, rng, s, c);
            return finish();
        }
        s.hits[0][0] = 1;
        s.nodes[0].push_back({root, 0, 0, 0, rootCount, std::move(hit), pattern});
    } else {
        s.nodes[0].push_back({root, 0, 0, 0, rootCount, std::nullopt, {}});
        ++c.eyeRays;
        s.nodes[0][0].hit =
            nearestInList(root.centralRay(), rootItems, 0, rootCount, s.hits[0].data(), c);
    }

    // Subdivision phase, all marginal pyrays of a level together.
    int cur = 0;
    for (int level = 0;; ++level) {
        const std::vector<AsosScratch::Node>& nodes = s.nodes[cur];
        const std::vector<Item>& items = s.items[cur];
        const std::vector<std::uint8_t>& hits = s.hits[cur];
        const double weight = std::ldexp(1.0, -2 * level);

        // The tally: each marginal pyray against each object it is marginal
        // on (in: its K-ray hits it), and the Full objects that interpenetrate
        // another (in: its K-ray sees them). The settings are the finest
        // among those objects.
        s.tally.clear();
        AsosSettings settings = AsosSettings::coarsest();
        for (const AsosScratch::Node& n : nodes)
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                const std::uint32_t object = items[i].object;
                const ConeClass& k = items[i].cls;
                if (k.coverage == Coverage::Marginal) {
                    s.tally.add(object, hits[i] != 0, k.singleEdge);
                } else if (overlapsAnother(items, n.first, n.count, i)) {
                    s.tally.add(object, n.hit && n.hit->objectIndex == static_cast<int>(object),
                                false);
                } else if (n.pattern.mayChange) {
                    // in: the K-ray sees the pattern's second colour.
                    s.tally.add(object,
                                n.hit && pigmentIndex(textureOf(scene_.object(object)).pigment,
                                                      n.hit->position) == 1,
                                n.pattern.singleEdge);
                } else {
                    continue;
                }
                settings = settings.finest(objectSettings_[object]);
            }
        const double bound = s.tally.changeBound(level);
        if (report) {
            AsosLevelReport r;
            r.level = level;
            r.marginal = static_cast<int>(nodes.size());
            for (const SubdivisionTally::Entry& e : s.tally.entries()) {
                r.in += e.in;
                r.out += e.out;
            }
            r.bound = bound;
            r.settings = settings;
            report->levels.push_back(r);
        }

        if (level >= settings.maxLevel || bound <= settings.eps) {
            // Stop: each marginal K-pyray is shaded with its K-ray, or at MAX
            // with jitter, a random ray inside it.
            const bool jitter = settings.jitter && level >= settings.maxLevel;
            for (const AsosScratch::Node& n : nodes) {
                ++leaves;
                if (jitter) {
                    const Vec2 p = n.pyray.square().pointAt(
                        rng.uniform2(SampleStream::AsosJitter, subPosition(level, n.ix, n.iy)));
                    const Ray ray = camera_.ray(p.x, p.y);
                    ++c.eyeRays;
                    const std::optional<SurfaceHit> hit =
                        nearestInList(ray, items, n.first, n.count, nullptr, c);
                    color += weight * shadeLeaf(n.pyray.square(), level, n.ix, n.iy, ray, hit, rng,
                                                s, c);
                } else {
                    color += weight * shadeLeaf(n.pyray.square(), level, n.ix, n.iy,
                                                n.pyray.centralRay(), n.hit, rng, s, c);
                }
            }
            break;
        }

        const int childLevel = level + 1;
        const double childWeight = 0.25 * weight;
        deepest = childLevel;
        if (childLevel >= settings.maxLevel) {
            // MAX-pyrays need no detection: each is one point sample, its
            // central ray or, with jitter, a random ray inside it.
            for (const AsosScratch::Node& n : nodes)
                for (int quarter = 0; quarter < 4; ++quarter) {
                    const ImageSquare sq = n.pyray.square().quarter(quarter);
                    const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
                    const Vec2 p = settings.jitter
                                       ? sq.pointAt(rng.uniform2(SampleStream::AsosJitter,
                                                                 subPosition(childLevel, ix, iy)))
                                       : Vec2(sq.uMid(), sq.vMid());
                    const Ray ray = camera_.ray(p.x, p.y);
                    ++pyrays;
                    ++leaves;
                    c.countPyray(childLevel);
                    ++c.eyeRays;
                    const std::optional<SurfaceHit> hit =
                        nearestInList(ray, items, n.first, n.count, nullptr, c);
                    color += childWeight * shadeLeaf(sq, childLevel, ix, iy, ray, hit, rng, s, c);
                }
            break;
        }

        // Subdivide: each marginal pyray into four, tested against its own
        // objects only.
        const int next = 1 - cur;
        std::vector<Item>& childItems = s.items[next];
        std::vector<std::uint8_t>& childHits = s.hits[next];
        std::vector<AsosScratch::Node>& childNodes = s.nodes[next];
        childItems.clear();
        childHits.clear();
        childNodes.clear();
        for (const AsosScratch::Node& n : nodes) {
            const std::array<EyePyray, 4> children = n.pyray.split(rayAt);
            for (int quarter = 0; quarter < 4; ++quarter) {
                const EyePyray& child = children[quarter];
                const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
                ++pyrays;
                c.countPyray(childLevel);
                const auto first = static_cast<std::uint32_t>(childItems.size());
                const PreparedCone cone(child.cone());
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    ++c.coneTests;
                    const ConeClass k = scene_.primitive(items[i].object).classify(cone);
                    if (k.coverage != Coverage::Miss) childItems.push_back({items[i].object, k});
                }
                const std::uint32_t count = pruneHidden(childItems, first);
                const auto [childResolved, childFront] = resolve(childItems, first, count);
                if (childResolved && !childFront) {
                    ++leaves;
                    color += childWeight * background;
                    continue;
                }
                childHits.resize(childItems.size(), 0);
                if (childResolved) {
                    std::optional<SurfaceHit> hit = frontHit(child, *childFront);
                    const PatternChange pattern = patternEdge(child, *childFront, hit);
                    if (!pattern.mayChange) {
                        ++leaves;
                        color += childWeight * shadeLeaf(child.square(), childLevel, ix, iy,
                                                         child.centralRay(), hit, rng, s, c);
                        continue;
                    }
                    childHits[first] = 1;
                    childNodes.push_back({child, ix, iy, first, count, std::move(hit), pattern});
                    continue;
                }
                ++c.eyeRays;
                std::optional<SurfaceHit> hit =
                    nearestInList(child.centralRay(), childItems, first, count, childHits.data(), c);
                childNodes.push_back({child, ix, iy, first, count, std::move(hit), {}});
            }
        }
        if (childNodes.empty()) break;
        cur = next;
    }
    return finish();
}

}  // namespace asos
