#include "asos/render/asos_tracer.hpp"

#include <algorithm>
#include <cmath>

#include "asos/render/highlight_bound.hpp"
#include "asos/render/pattern_filter.hpp"
#include "asos/render/transparent_shadow.hpp"
#include "asos/shapes/depth_order.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos {

namespace {

using Item = AsosScratch::Item;
using Node = AsosScratch::Node;

// Whether a's first hit comes before b's on every ray of the cone that meets
// both: a's depths all before b's, or their order shown (depth_order.hpp).
bool inFront(const Scene& scene, const PreparedCone& cone, const Item& a, const Item& b) {
    return a.cls.tFar < b.cls.tNear ||
           surelyInFront(scene.primitive(a.object), a.cls, scene.primitive(b.object), b.cls, cone);
}

// Sorts out the objects of items[first, end) for a pyray: drops, in place
// and in order, those no ray of the pyray can see, which an opaque Full
// object (met by every ray; a transparent one hides nothing) comes before
// on every ray (two that each come before the
// other, to the tolerances of surelyInFront, are both kept); then marks as
// crossed each Full object left whose order against another one left is
// not known (a sphere sunk into a plane). Returns how many are left; items
// is cut to first + that.
std::uint32_t sortOut(const Scene& scene, const PreparedCone& cone, std::vector<Item>& items,
                      std::uint32_t first, std::vector<std::uint8_t>& hidden) {
    const std::size_t end = items.size();
    // Wholly behind the nearest far depth of a Full object: hidden, as
    // cheaply as that.
    // A transparent object hides nothing: what is behind it shows through.
    const auto hides = [&](const Item& item) {
        return item.cls.coverage == Coverage::Full && !scene.transparent(item.object);
    };
    double front = kInfinity;
    for (std::size_t i = first; i < end; ++i)
        if (hides(items[i])) front = std::min(front, items[i].cls.tFar);
    hidden.assign(end - first, 0);
    for (std::size_t i = first; i < end; ++i) {
        if (items[i].cls.tNear > front) {
            hidden[i - first] = 1;
            continue;
        }
        for (std::size_t j = first; j < end; ++j) {
            if (j == i || !hides(items[j]) || items[j].cls.tNear > front) continue;
            if (inFront(scene, cone, items[j], items[i]) &&
                !(items[i].cls.coverage == Coverage::Full && inFront(scene, cone, items[i], items[j]))) {
                hidden[i - first] = 1;
                break;
            }
        }
    }
    std::size_t kept = first;
    for (std::size_t i = first; i < end; ++i)
        if (!hidden[i - first]) items[kept++] = items[i];
    items.resize(kept);
    // Two Full objects left are crossed: neither hid the other.
    for (std::size_t i = first; i < kept; ++i) {
        Item& a = items[i];
        a.crossed = false;
        if (a.cls.coverage != Coverage::Full) continue;
        for (std::size_t j = first; j < kept && !a.crossed; ++j)
            a.crossed = j != i && items[j].cls.tNear <= a.cls.tFar && a.cls.tNear <= items[j].cls.tFar &&
                        (items[j].cls.coverage == Coverage::Full || !inFront(scene, cone, items[j], a));
    }
    return static_cast<std::uint32_t>(kept - first);
}

}  // namespace

AsosTracer::AsosTracer(const RayTracer& tracer, const CameraModel& camera,
                       const AsosSettings& sceneSettings, std::uint64_t seed, bool patternEdges,
                       bool patternFilter)
    : tracer_(tracer), scene_(tracer.scene()), camera_(camera), seed_(seed), sceneSettings_(sceneSettings),
      patternEdges_(patternEdges), patternFilter_(patternFilter) {
    const SceneDescription& d = scene_.description();
    objectSettings_.reserve(d.objects.size());
    selfShadowing_.reserve(d.objects.size());
    patterned_.reserve(d.objects.size());
    for (std::uint32_t i = 0; i < scene_.objectCount(); ++i) {
        const Object& o = d.objects[i];
        objectSettings_.push_back(sceneSettings.refinedBy(o.asos));
        selfShadowing_.push_back(scene_.primitive(i).canShadowItself() ? 1 : 0);
        // A layered texture's patterns are sampled at each leaf's point, as
        // the map patterns are (docs/algorithm.md, "Layered textures").
        patterned_.push_back(textureOf(o).above.empty() && hasPattern(textureOf(o).pigment) ? 1 : 0);
    }
    for (const Light& l : d.lights) {
        lightSettings_.push_back(sceneSettings.refinedBy(l.asos));
        if (lightSettings_.back().highlights && !l.shadowless) highlightLights_.push_back(l);
    }
    highlighted_.reserve(d.objects.size());
    for (std::uint32_t i = 0; i < scene_.objectCount(); ++i)
        highlighted_.push_back(objectSettings_[i].highlights && !highlightLights_.empty() &&
                                       hasHighlights(textureOf(d.objects[i]))
                                   ? 1
                                   : 0);

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

    // A mesh's faces join sheets where only the normal's jumps at creases
    // change the colour: opaque, one plain layer with no normal pattern, no
    // reflection, no highlights, brilliance 1 (docs/algorithm.md, "Meshes").
    if (!camera_.orthographic()) {
        std::vector<std::uint8_t> coverable(d.objects.size(), 0);
        double diffuse = 0.0;
        bool anyFace = false;
        for (std::uint32_t i = 0; i < scene_.objectCount(); ++i) {
            const Object& o = d.objects[i];
            const Texture& t = textureOf(o);
            if (!std::holds_alternative<TriangleShape>(o.shape) || scene_.transparent(i) || highlighted_[i] ||
                !t.above.empty() || t.normal || reflects(t.finish) || t.finish.brilliance != 1.0)
                continue;
            coverable[i] = 1;
            anyFace = true;
            diffuse = std::max(diffuse, t.finish.diffuse);
        }
        if (anyFace) {
            double lights = 0.0;
            for (const Light& l : d.lights) lights += std::max({l.color.x, l.color.y, l.color.z, 0.0});
            meshJumpScale_ = lights * diffuse;
            meshCover_.emplace(d, std::move(coverable));
            if (!meshCover_->any()) meshCover_.reset();
        }
    }
}

// One pixel's trace, in the paper's phases: detect() forms the pixel's list
// and settles its 0-pyray; each level of the subdivision is tallied by
// decide() and either stops (shadeStopped, shadeMaxPyrays) or is split into
// the next by subdivide(); settle() decides each fresh pyray, a leaf or a
// marginal pyray of the next decision. Holds the pixel's running sums.
class AsosTracer::PixelTrace {
public:
    PixelTrace(const AsosTracer& tracer, int px, int py, AsosScratch& scratch,
               RenderCounters& counters, AsosPixelReport* report)
        : asos_(tracer), tracer_(tracer.tracer_), scene_(tracer.scene_), camera_(tracer.camera_),
          px_(px), py_(py), rng_(tracer.seed_, px, py), s_(scratch), c_(counters), report_(report),
          atmosphere_(tracer_.atmosphere()) {}

    PixelResult run();

private:
    // One level's buffers: the lists of its pyrays (items, and per item
    // whether the pyray's K-ray hits the object) and its marginal pyrays.
    struct LevelBuffers {
        std::vector<Item>& items;
        std::vector<std::uint8_t>& hits;
        std::vector<Node>& nodes;
    };
    LevelBuffers buffers(int slot) { return {s_.items[slot], s_.hits[slot], s_.nodes[slot]}; }

    // What a level's tally decided, at the finest settings among the objects
    // it involved.
    struct LevelDecision {
        bool stop;
        AsosSettings settings;
    };

    std::optional<Vec3> detect(const EyePyray& pixel, LevelBuffers to);
    std::optional<Vec3> settle(const EyePyray& pyray, const PreparedCone& cone, int level,
                               std::uint32_t ix, std::uint32_t iy, LevelBuffers to, std::uint32_t first);
    bool settleOnSheet(const EyePyray& pyray, const PreparedCone& cone, int level, std::uint32_t ix,
                       std::uint32_t iy, LevelBuffers to, std::uint32_t first, std::optional<Vec3>& leaf);
    LevelDecision decide(int level, LevelBuffers from);
    void subdivide(int level, double weight, LevelBuffers from, LevelBuffers to);
    void shadeStopped(int level, double weight, const AsosSettings& settings, LevelBuffers from);
    void shadeMaxPyrays(int level, double weight, bool jitter, LevelBuffers from);

    std::optional<SurfaceHit> frontHit(const EyePyray& pyray, const Item& front) const;
    PatternChange patternEdge(const EyePyray& pyray, const Item& front,
                              const std::optional<SurfaceHit>& hit) const;
    double highlightChange(const EyePyray& pyray, const Item& front,
                           const std::optional<SurfaceHit>& hit) const;
    Ray jitteredRay(const ImageSquare& square, int level, std::uint32_t ix, std::uint32_t iy) const;
    Vec3 pointSample(const ImageSquare& square, int level, std::uint32_t ix, std::uint32_t iy,
                     const Ray& ray, const std::vector<Item>& items, const Node& parent);
    Vec3 shadeLeaf(const ImageSquare& square, int level, std::uint32_t ix, std::uint32_t iy,
                   const Ray& ray, const std::optional<SurfaceHit>& hit);
    Vec3 skyLeaf(const ImageSquare& square, int level) const;
    std::optional<Color> leafPigment(const ImageSquare& square, const SurfaceHit& hit) const;
    std::optional<SurfaceHit> nearestInList(const Ray& ray, const std::vector<Item>& items,
                                            std::uint32_t first, std::uint32_t count,
                                            std::uint8_t* marks);
    PixelResult finish() const {
        if (report_) report_->leaves = leaves_;
        return PixelResult{color_, pyrays_, static_cast<std::uint32_t>(deepest_)};
    }

    const AsosTracer& asos_;
    const RayTracer& tracer_;
    const Scene& scene_;
    const CameraModel& camera_;
    int px_, py_;
    PixelRandom rng_;
    AsosScratch& s_;
    RenderCounters& c_;
    AsosPixelReport* report_;
    const Atmosphere& atmosphere_;
    Vec3 color_{0.0};
    std::uint32_t pyrays_ = 0;
    int deepest_ = 0, leaves_ = 0;
};

PixelResult AsosTracer::tracePixel(int x, int y, AsosScratch& scratch, RenderCounters& counters) const {
    return PixelTrace(*this, x, y, scratch, counters, nullptr).run();
}

AsosPixelReport AsosTracer::tracePixelReport(int x, int y, AsosScratch& scratch,
                                             RenderCounters& counters) const {
    AsosPixelReport report;
    report.result = PixelTrace(*this, x, y, scratch, counters, &report).run();
    return report;
}

PixelResult AsosTracer::PixelTrace::run() {
    const ImageSquare pixel{double(px_), double(py_), px_ + 1.0, py_ + 1.0};
    const EyePyray root = EyePyray::make([this](double u, double v) { return camera_.ray(u, v); },
                                         pixel, 0, kPovMinIsectDepth, asos_.eyeTMax_);
    if (const std::optional<Vec3> leaf = detect(root, buffers(0))) {
        color_ = *leaf;
        return finish();
    }
    // The subdivision phase, all marginal pyrays of a level together; the
    // buffers of a level and of the next alternate.
    int cur = 0;
    for (int level = 0;; ++level) {
        const LevelBuffers from = buffers(cur);
        const double weight = std::ldexp(1.0, -2 * level);
        const LevelDecision decision = decide(level, from);
        if (decision.stop) {
            shadeStopped(level, weight, decision.settings, from);
            break;
        }
        const int childLevel = level + 1;
        deepest_ = childLevel;
        if (childLevel >= decision.settings.maxLevel) {
            shadeMaxPyrays(childLevel, 0.25 * weight, decision.settings.jitter, from);
            break;
        }
        const int next = 1 - cur;
        subdivide(childLevel, 0.25 * weight, from, buffers(next));
        if (s_.nodes[next].empty()) break;
        cur = next;
    }
    return finish();
}

// "Detection Phase": the pixel's 0-pyray against the objects the BVH offers
// gives the pixel's list, which every subpyray is tested against.
std::optional<Vec3> AsosTracer::PixelTrace::detect(const EyePyray& pixel, LevelBuffers to) {
    ++pyrays_;
    c_.countPyray(0);
    to.items.clear();
    to.hits.clear();
    to.nodes.clear();
    const PreparedCone cone(pixel.cone(), true);
    auto test = [&](std::uint32_t object) {
        ++c_.coneTests;
        const ConeClass k = scene_.primitive(object).classify(cone);
        if (k.coverage != Coverage::Miss) to.items.push_back({object, k});
    };
    // Neighbouring pixels' cones share the eye as apex: a remembered wider
    // cone's objects serve them (perspective cameras; orthographic pyrays
    // have an apex each).
    if (camera_.orthographic()) scene_.coneCandidates(pixel.cone(), test);
    else s_.eyeCandidates.visit(scene_, pixel.cone(), test);
    sortByObject(to.items.data(), to.items.data() + to.items.size());
    return settle(pixel, cone, 0, 0, 0, to, 0);
}

// A pyray whose objects are to.items[first, end): with those hidden
// dropped, none left is background and one Full object in front of all
// covers the pyray ("this object covers the entire pixel and shading can be
// performed"): a leaf, whose colour is returned. Otherwise the pyray is
// marginal (or a crease of that object crosses it, or its pattern may change
// in it) and joins the level's nodes, with its K-ray traced against its list
// for the tally.
std::optional<Vec3> AsosTracer::PixelTrace::settle(const EyePyray& pyray, const PreparedCone& cone,
                                                   int level, std::uint32_t ix, std::uint32_t iy,
                                                   LevelBuffers to, std::uint32_t first) {
    if (std::optional<Vec3> leaf; asos_.meshCover_ && to.items.size() - first >= 2 &&
                                  settleOnSheet(pyray, cone, level, ix, iy, to, first, leaf))
        return leaf;
    const std::uint32_t count = sortOut(scene_, cone, to.items, first, s_.hidden);
    to.hits.resize(to.items.size(), 0);
    if (count == 0) {
        ++leaves_;
        return skyLeaf(pyray.square(), level);
    }
    if (count == 1 && to.items[first].cls.coverage == Coverage::Full) {
        const Item& front = to.items[first];
        std::optional<SurfaceHit> hit = frontHit(pyray, front);
        const PatternChange pattern = patternEdge(pyray, front, hit);
        // A crease inside it is an edge between the parts of its surface; a
        // highlight that may change by more than EPS inside it is subdivided
        // as an edge is.
        double shading = 0.0;
        if (!pattern.mayChange && front.cls.creaseParts == 0) {
            shading = highlightChange(pyray, front, hit);
            if (!(shading > asos_.objectSettings_[front.object].eps)) {
                ++leaves_;
                return shadeLeaf(pyray.square(), level, ix, iy, pyray.centralRay(), hit);
            }
        }
        to.hits[first] = 1;
        to.nodes.push_back({pyray, ix, iy, first, count, std::move(hit), pattern, shading});
        return std::nullopt;
    }
    ++c_.eyeRays;
    std::optional<SurfaceHit> hit =
        nearestInList(pyray.centralRay(), to.items, first, count, to.hits.data());
    to.nodes.push_back({pyray, ix, iy, first, count, std::move(hit), {}});
    return std::nullopt;
}

// A pyray covered by a sheet of one mesh's faces, everything else behind it
// (render/mesh_cover.hpp): its items cut to the sheet's faces, then a leaf
// where no crease of the sheet can change the colour by more than EPS and
// no pattern edge crosses it, otherwise a node marginal on those alone.
// False (nothing changed) where no sheet covers it.
bool AsosTracer::PixelTrace::settleOnSheet(const EyePyray& pyray, const PreparedCone& cone, int level,
                                           std::uint32_t ix, std::uint32_t iy, LevelBuffers to,
                                           std::uint32_t first, std::optional<Vec3>& leaf) {
    std::vector<MeshCandidate>& candidates = s_.meshCandidates;
    candidates.clear();
    for (std::size_t i = first; i < to.items.size(); ++i)
        candidates.push_back({to.items[i].object, to.items[i].cls.tNear, to.items[i].cls.tFar});
    std::optional<MeshSheet> sheet = asos_.meshCover_->cover(scene_.description(), cone, candidates);
    if (!sheet) return false;
    // The sheet's faces are met conservatively: it covers the cone only if
    // the central ray hits one of them.
    ++c_.eyeRays;
    std::optional<SurfaceHit> hit = tracer_.nearestHit(pyray.centralRay());
    if (!hit) return false;
    std::size_t hitItem = candidates.size();
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (sheet->member[i] && candidates[i].object == static_cast<std::uint32_t>(hit->objectIndex)) hitItem = i;
    if (hitItem == candidates.size()) return false;
    std::size_t kept = first;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (sheet->member[i]) to.items[kept++] = to.items[first + i];
    to.items.resize(kept);
    to.hits.resize(kept, 0);
    const auto count = static_cast<std::uint32_t>(kept - first);
    Item front{static_cast<std::uint32_t>(hit->objectIndex), {}, false};
    const PatternChange pattern = patternEdge(pyray, front, hit);
    const double shading = asos_.meshJumpScale_ * sheet->normalJump;
    if (!pattern.mayChange && !(shading > asos_.objectSettings_[front.object].eps)) {
        ++leaves_;
        leaf = shadeLeaf(pyray.square(), level, ix, iy, pyray.centralRay(), hit);
        return true;
    }
    to.nodes.push_back({pyray, ix, iy, first, count, std::move(hit), pattern, shading, true});
    return true;
}

// "Subdivision Phase", the decision: the tally of each marginal K-pyray
// against each object it is marginal on (in: its K-ray hits it), of the Full
// objects crossed by another (in: its K-ray sees them) and of the parts
// beside a crease inside a Full object (in: its K-ray sees that part) gives
// the paper's bound on the change another level could make, L / 2^2K, or
// half that where every pyray of an object is near one edge of it
// ("Proximity to One Edge"); the level stops when the bound is within EPS or
// the level is MAX.
AsosTracer::PixelTrace::LevelDecision AsosTracer::PixelTrace::decide(int level, LevelBuffers from) {
    s_.tally.clear();
    AsosSettings settings = AsosSettings::coarsest();
    for (const Node& n : from.nodes) {
        if (n.meshSheet) {
            // Marginal on its pattern or its creases only.
            const auto object = static_cast<std::uint32_t>(n.hit->objectIndex);
            if (n.pattern.mayChange)
                s_.tally.add(object, pigmentIndex(textureOf(scene_.object(object)).pigment, n.hit->position) == 1,
                             n.pattern.singleEdge);
            else
                s_.tally.addShading(object, n.shading);
            settings = settings.finest(asos_.objectSettings_[object]);
            continue;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
            const std::uint32_t object = from.items[i].object;
            const ConeClass& k = from.items[i].cls;
            const bool sees = n.hit && n.hit->objectIndex == static_cast<int>(object);
            if (k.coverage == Coverage::Marginal) {
                s_.tally.add(object, from.hits[i] != 0, k.singleEdge);
            } else {
                // Each part the rays may see beside a crease, and a tip.
                for (std::uint8_t part = 0; part < 7; ++part)
                    if (k.creaseParts & (1u << part))
                        s_.tally.addPart(object, part, sees && n.hit->part == part, k.singleEdge);
                if (k.creaseParts & ConeClass::kTipCrease) s_.tally.addTip(object);
                if (from.items[i].crossed) {
                    s_.tally.add(object, sees, false);
                } else if (n.pattern.mayChange) {
                    // in: the K-ray sees the pattern's second colour.
                    s_.tally.add(object,
                                 n.hit && pigmentIndex(textureOf(scene_.object(object)).pigment,
                                                       n.hit->position) == 1,
                                 n.pattern.singleEdge);
                } else if (n.shading > 0.0) {
                    s_.tally.addShading(object, n.shading);
                } else if (k.creaseParts == 0) {
                    continue;
                }
            }
            settings = settings.finest(asos_.objectSettings_[object]);
        }
    }
    const double bound = s_.tally.changeBound(level);
    if (report_) {
        AsosLevelReport r;
        r.level = level;
        r.marginal = static_cast<int>(from.nodes.size());
        for (const SubdivisionTally::Entry& e : s_.tally.entries()) {
            r.in += e.in;
            r.out += e.out;
        }
        r.bound = bound;
        r.settings = settings;
        report_->levels.push_back(r);
    }
    return {level >= settings.maxLevel || bound <= settings.eps, settings};
}

// "Subdivision Phase", the split: each marginal pyray into four subpyrays,
// each tested against its parent's objects only ("that list has already been
// formed"), then settled.
void AsosTracer::PixelTrace::subdivide(int level, double weight, LevelBuffers from,
                                       LevelBuffers to) {
    to.items.clear();
    to.hits.clear();
    to.nodes.clear();
    for (const Node& n : from.nodes) {
        const std::array<EyePyray, 4> children =
            n.pyray.split([this](double u, double v) { return camera_.ray(u, v); });
        for (int quarter = 0; quarter < 4; ++quarter) {
            const EyePyray& child = children[quarter];
            const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
            ++pyrays_;
            c_.countPyray(level);
            const auto first = static_cast<std::uint32_t>(to.items.size());
            const PreparedCone cone(child.cone(), true);
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                ++c_.coneTests;
                const ConeClass k = scene_.primitive(from.items[i].object).classify(cone);
                if (k.coverage != Coverage::Miss) to.items.push_back({from.items[i].object, k});
            }
            if (const std::optional<Vec3> leaf = settle(child, cone, level, ix, iy, to, first))
                color_ += weight * *leaf;
        }
    }
}

// The stop: each marginal K-pyray is a leaf shaded with its K-ray, or, at
// MAX with jitter, with a random ray inside it ("Jittering of MAX-rays").
void AsosTracer::PixelTrace::shadeStopped(int level, double weight, const AsosSettings& settings,
                                          LevelBuffers from) {
    const bool jitter = settings.jitter && level >= settings.maxLevel;
    for (const Node& n : from.nodes) {
        ++leaves_;
        const ImageSquare& square = n.pyray.square();
        color_ += weight *
                  (jitter ? pointSample(square, level, n.ix, n.iy,
                                        jitteredRay(square, level, n.ix, n.iy), from.items, n)
                          : shadeLeaf(square, level, n.ix, n.iy, n.pyray.centralRay(), n.hit));
    }
}

// "Jittering of MAX-rays": a MAX-pyray needs no detection, it is one point
// sample, its central ray or, with jitter, a random ray inside it.
void AsosTracer::PixelTrace::shadeMaxPyrays(int level, double weight, bool jitter,
                                            LevelBuffers from) {
    for (const Node& n : from.nodes)
        for (int quarter = 0; quarter < 4; ++quarter) {
            const ImageSquare square = n.pyray.square().quarter(quarter);
            const std::uint32_t ix = 2 * n.ix + (quarter & 1), iy = 2 * n.iy + (quarter >> 1);
            const Ray ray = jitter ? jitteredRay(square, level, ix, iy)
                                   : camera_.ray(square.uMid(), square.vMid());
            ++pyrays_;
            ++leaves_;
            c_.countPyray(level);
            color_ += weight * pointSample(square, level, ix, iy, ray, from.items, n);
        }
}

// The central ray of a pyray resolved by one Full object in front of
// everything else must hit that object ("additional eye rays through this
// pixel can only strike this object").
std::optional<SurfaceHit> AsosTracer::PixelTrace::frontHit(const EyePyray& pyray,
                                                           const Item& front) const {
    const Ray& ray = pyray.centralRay();
    ++c_.eyeRays;
    ++c_.rayTests;
    std::optional<SurfaceHit> hit =
        scene_.primitive(front.object).intersect(ray, kPovMinIsectDepth, kInfinity);
    if (hit) hit->objectIndex = static_cast<int>(front.object);
    else hit = tracer_.nearestHit(ray);  // rounding at the cone's rim: ask the scene
    return hit;
}

// Whether the front object's pigment pattern may change inside the pyray's
// footprint (an edge of the texture rather than of the object).
PatternChange AsosTracer::PixelTrace::patternEdge(const EyePyray& pyray, const Item& front,
                                                  const std::optional<SurfaceHit>& hit) const {
    if (!asos_.patternEdges_ || !asos_.patterned_[front.object] || !hit ||
        hit->objectIndex != static_cast<int>(front.object))
        return PatternChange{};
    const Footprint footprint(camera_, pyray.square(), hit->position, hit->normal, hit->t);
    return pigmentMayChange(textureOf(scene_.object(front.object)).pigment, footprint);
}

// How far the front object's highlights may stray from the central ray's
// inside the pyray (render/highlight_bound.hpp); 0 where it has none.
double AsosTracer::PixelTrace::highlightChange(const EyePyray& pyray, const Item& front,
                                               const std::optional<SurfaceHit>& hit) const {
    if (!asos_.highlighted_[front.object] || !hit || hit->objectIndex != static_cast<int>(front.object))
        return 0.0;
    c_.rayTests += 4;  // the corner rays against the object
    const SurfaceSpread spread = SurfaceSpread::over(pyray, *hit, scene_.primitive(front.object));
    return highlightVariation(textureOf(scene_.object(front.object)), asos_.highlightLights_, spread);
}

Ray AsosTracer::PixelTrace::jitteredRay(const ImageSquare& square, int level, std::uint32_t ix,
                                        std::uint32_t iy) const {
    const Vec2 p =
        square.pointAt(rng_.uniform2(SampleStream::AsosJitter, subPosition(level, ix, iy)));
    return camera_.ray(p.x, p.y);
}

// A leaf's point sample by `ray` against its parent's objects.
Vec3 AsosTracer::PixelTrace::pointSample(const ImageSquare& square, int level, std::uint32_t ix,
                                         std::uint32_t iy, const Ray& ray,
                                         const std::vector<Item>& items, const Node& parent) {
    ++c_.eyeRays;
    const std::optional<SurfaceHit> hit =
        nearestInList(ray, items, parent.first, parent.count, nullptr);
    return shadeLeaf(square, level, ix, iy, ray, hit);
}

std::optional<SurfaceHit> AsosTracer::PixelTrace::nearestInList(const Ray& ray,
                                                                const std::vector<Item>& items,
                                                                std::uint32_t first,
                                                                std::uint32_t count,
                                                                std::uint8_t* marks) {
    std::optional<SurfaceHit> nearest;
    for (std::uint32_t i = first; i < first + count; ++i) {
        ++c_.rayTests;
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

// A leaf's colour: its ray shaded, point lights shadowed by shadow pyrays
// through the leaf's footprint ("Antialiased Point Light Sources"), area
// lights by shadow beams from the shaded point.
Vec3 AsosTracer::PixelTrace::shadeLeaf(const ImageSquare& square, int level, std::uint32_t ix,
                                       std::uint32_t iy, const Ray& ray,
                                       const std::optional<SurfaceHit>& hit) {
    if (!hit) return atmosphere_.miss(ray);
    std::optional<Footprint> footprint;  // made when a light first needs it
    LightSample storage;
    // Area lights: shadow beams from the shaded point (render/area_light.hpp),
    // with random numbers of this leaf's own.
    LightContext context{&s_.area, rng_, subPosition(level, ix, iy), nullptr, {}, {}};
    auto lightArriving = [&](const ShadingPoint& p) -> std::span<const LightSample> {
        const Light& light = *p.light;
        if (tracer_.sceneLights()[static_cast<std::size_t>(p.lightIndex)].isArea()) {
            if (tracer_.sceneLights().setup().apex == ShadowApex::Behind && !footprint)
                footprint.emplace(camera_, square, hit->position, hit->normal, hit->t);
            context.footprint = footprint ? &*footprint : nullptr;
            return tracer_.areaLightSamples(p, context, c_);
        }
        // A parallel light stands where its beam enters for this point.
        const std::optional<LightBeam::Source> source = lightSourceFor(light, p.position);
        if (!source || !facesLight(p.position, p.normal, source->position)) return {};
        const bool shadowless = light.shadowless || source->unshadowed;
        double lit = 1.0;
        if (!shadowless) {
            if (!footprint) footprint.emplace(camera_, square, hit->position, hit->normal, hit->t);
            PointShadowQuery query;
            query.lightPosition = source->position;
            query.lightIndex = static_cast<std::size_t>(p.lightIndex);
            query.settings = asos_.lightSettings_[static_cast<std::size_t>(p.lightIndex)];
            query.shadedObject = static_cast<std::uint32_t>(hit->objectIndex);
            // An open tube is the boundary of a convex solid: its outer side,
            // like any convex surface, shadows itself only through N.L <= 0.
            // Only its inner side, seen through an opening (the normal
            // turned toward the viewer points inward), can be in its own
            // shadow.
            query.shadedCanSelfShadow = asos_.selfShadowing_[query.shadedObject] != 0 &&
                                        glm::dot(p.normal, hit->normal) < 0.0;
            query.level = level;
            query.ix = ix;
            query.iy = iy;
            query.rng = rng_;
            query.jitterKey = mix64(static_cast<std::uint64_t>(p.lightIndex));
            lit = pointLightLitFraction(scene_, *footprint, query, s_.shadow, c_);
            if (!(lit > 0.0)) return {};
        }
        // Transparent objects are not among the shadow pyrays' occluders:
        // they filter the light along the central shadow ray.
        const Vec3 filter =
            shadowless ? Vec3(1.0) : transparentShadowFilter(scene_, p.position, source->position, c_);
        if (filter == Vec3(0.0)) return {};
        storage = pointLightSample(source->position, light.color * filter, p.position, lit);
        return {&storage, 1};
    };
    const Vec3 shaded = tracer_.shadeWith(*hit, ray, 1, 1.0, lightArriving, c_, context, leafPigment(square, *hit));
    return atmosphere_.fogged(shaded, ray, hit->t);
}

// A pyray that meets no object sees the sky (and the fogs) over its whole
// square: its central ray's colour where the sky cannot vary; otherwise,
// where the sky's colour at the square's corners strays from the centre's
// by more than the scene's EPS, the average of its four quarters, each
// decided again, down to the scene's MAX level (docs/algorithm.md, "The
// sky and fog"). The corner test is an estimate, not a bound: a sky pattern finer
// than the square may slip between the five points.
Vec3 AsosTracer::PixelTrace::skyLeaf(const ImageSquare& square, int level) const {
    const Vec3 centre = atmosphere_.miss(camera_.ray(square.uMid(), square.vMid()));
    const AsosSettings& settings = asos_.sceneSettings_;
    if (!atmosphere_.skyVaries() || level >= settings.maxLevel) return centre;
    double change = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
        const Vec3 c = atmosphere_.miss(camera_.ray((corner & 1) ? square.u1 : square.u0,
                                                    (corner & 2) ? square.v1 : square.v0));
        const Vec3 d = glm::abs(c - centre);
        change = std::max({change, d.x, d.y, d.z});
    }
    if (!(change > settings.eps)) return centre;
    Vec3 sum(0.0);
    for (int quarter = 0; quarter < 4; ++quarter) sum += skyLeaf(square.quarter(quarter), level + 1);
    return 0.25 * sum;
}

// With the pattern filter, a patterned leaf's pigment averaged over the
// leaf's footprint on the tangent plane at its hit ("Pattern filter");
// otherwise (or where the plane does not hold the whole footprint) nothing:
// the pigment at the hit.
std::optional<Color> AsosTracer::PixelTrace::leafPigment(const ImageSquare& square,
                                                         const SurfaceHit& hit) const {
    const auto object = static_cast<std::uint32_t>(hit.objectIndex);
    if (!asos_.patternFilter_ || !asos_.patterned_[object]) return std::nullopt;
    const Pigment& pigment = textureOf(scene_.object(object)).pigment;
    const std::optional<PatternFootprint> footprint = PatternFootprint::make(
        camera_, square, hit.position, hit.normal, pigment.worldFromPattern.inverseMatrix());
    if (!footprint) return std::nullopt;
    return filteredPigment(pigment, *footprint);
}

}  // namespace asos
