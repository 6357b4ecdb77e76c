// Scene items: objects (with POV-Ray's texture and transform rules), lights,
// the camera, pigments, finishes, textures, global settings.
//
// Transform rule: a transform applies to what the object has so far: its
// shape and the texture it already carries. A pigment written after a
// transform is not moved by it. So an object's pattern transform is "the
// transforms written after its texture, then the texture's own".
//
// Union rule: the union's transforms apply to every member; its texture goes,
// when the union is placed in the scene, to the members that have none. The
// same holds for difference, intersection and merge (CSG), whose members are
// kept as a tree (CsgTree) shared by one Object per leaf.
#include <cmath>

#include "asos/geometry/margins.hpp"
#include "asos/scene/asos_settings.hpp"
#include "asos/scene/pov_tolerances.hpp"
#include "asos/shapes/shape_issue.hpp"
#include "src/lang/interpreter_impl.hpp"
#include "src/lang/object_bounds.hpp"

namespace asos::lang {

namespace {

bool isObjectBlock(const Node& n) {
    if (n.kind != NodeKind::Block) return false;
    switch (n.word) {
    case Word::Sphere: case Word::Box: case Word::Cone: case Word::Cylinder: case Word::Disc:
    case Word::Polygon: case Word::Plane: case Word::Union: case Word::Object:
    case Word::Difference: case Word::Intersection: case Word::Merge: case Word::LightSource:
    case Word::Quadric: case Word::Torus: case Word::Poly: case Word::Quartic: case Word::Cubic: case Word::Text: case Word::Prism: case Word::Triangle: case Word::SmoothTriangle: case Word::Mesh:
    case Word::Mesh2:
        return true;
    default:
        return false;
    }
}

// A declared value named where a block's entry may stand: Name or Name[i]….
bool isReference(const Node& n) { return n.kind == NodeKind::Name || n.kind == NodeKind::Index; }

// A light's position and area axes are finite numbers (a transform can
// overflow them).
bool finitePlacement(const Light& l) {
    return isFinite(l.position) && (!l.area || (isFinite(l.area->axis1) && isFinite(l.area->axis2)));
}

bool isTransform(const Node& n) {
    return n.kind == NodeKind::Item && (n.word == Word::Translate || n.word == Word::Rotate ||
                                        n.word == Word::Scale || n.word == Word::Matrix);
}

AsosOptions inherit(const AsosOptions& own, const AsosOptions& outer) {
    AsosOptions r = own;
    if (!r.eps) r.eps = outer.eps;
    if (!r.maxLevel) r.maxLevel = outer.maxLevel;
    if (!r.jitter) r.jitter = outer.jitter;
    if (!r.highlights) r.highlights = outer.highlights;
    return r;
}

constexpr Color kCheckerBlue{Vec3(0.0, 0.0, 1.0), 0.0, 0.0};  // POV-Ray's checker defaults
constexpr Color kCheckerGreen{Vec3(0.0, 1.0, 0.0), 0.0, 0.0};
constexpr Color kBrickMortar{Vec3(0.5, 0.5, 0.5), 0.0, 0.0};  // POV-Ray's brick defaults
constexpr Color kBrickRed{Vec3(0.6, 0.15, 0.15), 0.0, 0.0};

bool isMapPattern(Word w) {
    switch (w) {
    case Word::Gradient: case Word::Radial: case Word::Onion: case Word::Marble: case Word::Wood:
    case Word::Leopard: case Word::Bozo: case Word::Spotted: case Word::Granite: case Word::Agate:
    case Word::Crackle: case Word::Function:
    case Word::Bumps: case Word::Dents: case Word::Wrinkles: case Word::Ripples: case Word::Waves:
        return true;
    default: return false;
    }
}

Pigment::Kind mapKind(Word w) {
    switch (w) {
    case Word::Gradient: return Pigment::Kind::Gradient;
    case Word::Radial: return Pigment::Kind::Radial;
    case Word::Onion: return Pigment::Kind::Onion;
    case Word::Marble: return Pigment::Kind::Marble;
    case Word::Wood: return Pigment::Kind::Wood;
    case Word::Leopard: return Pigment::Kind::Leopard;
    case Word::Bozo: return Pigment::Kind::Bozo;
    case Word::Spotted: return Pigment::Kind::Spotted;
    case Word::Granite: return Pigment::Kind::Granite;
    case Word::Crackle: return Pigment::Kind::Crackle;
    case Word::Function: return Pigment::Kind::Function;
    case Word::Bumps: return Pigment::Kind::Bumps;
    case Word::Dents: return Pigment::Kind::Dents;
    case Word::Wrinkles: return Pigment::Kind::Wrinkles;
    case Word::Ripples: return Pigment::Kind::Ripples;
    case Word::Waves: return Pigment::Kind::Waves;
    default: return Pigment::Kind::Agate;
    }
}

bool isMapModifier(Word w) {
    switch (w) {
    case Word::Turbulence: case Word::Octaves: case Word::Omega: case Word::Lambda: case Word::Frequency:
    case Word::Phase: case Word::RampWave: case Word::TriangleWave: case Word::SineWave: case Word::AgateTurb:
    case Word::NoiseGenerator: case Word::Form: case Word::Metric: case Word::Offset: case Word::Solid:
        return true;
    default: return false;
    }
}

// crackle's own modifiers, which POV-Ray refuses on any other pattern.
bool isCrackleModifier(Word w) {
    return w == Word::Form || w == Word::Metric || w == Word::Offset || w == Word::Solid;
}

bool isMapPigment(Pigment::Kind k) {
    return k != Pigment::Kind::Solid && k != Pigment::Kind::Checker && k != Pigment::Kind::Brick;
}

}  // namespace

// --- the top level ------------------------------------------------------------------------

void Interpreter::runTopEntry(const Node& n) {
    switch (n.word) {
    case Word::Camera:
        scene_.camera = evalCamera(n).camera;
        return;
    case Word::GlobalSettings:
        applyGlobalSettings(n);
        return;
    case Word::Background:
        scene_.background = evalColour(n[0]);
        return;
    case Word::SkySphere:
        // POV-Ray keeps the last sky_sphere.
        scene_.skySphere = evalSkySphere(n);
        return;
    case Word::Fog:
        scene_.fogs.push_back(evalFog(n));
        return;
    default:
        if (!isObjectBlock(n)) fail(n, "this is not a scene item");
        placeObject(evalObject(n), n);
    }
}

Value Interpreter::evalDeclarable(const Node& n) {
    if (n.kind != NodeKind::Block) return eval(n);
    switch (n.word) {
    case Word::Camera: return std::make_shared<const CameraValue>(evalCamera(n));
    case Word::Pigment: return evalPigment(n, defaultTexture_->pigment);
    case Word::Finish: return evalFinish(n, defaultTexture_->finish);
    case Word::Normal: return evalNormal(n, defaultTexture_->normal);
    case Word::Texture: return evalTexture(n);
    case Word::Interior: return evalInterior(n, Interior{});
    case Word::Material: return evalMaterial(n);
    case Word::ColorMap: return evalColourMap(n);
    // A declared pigment_map's entries start with their values: POV-Ray reads
    // it outside any pattern, so not as average's optional weights.
    case Word::PigmentMap: return std::make_shared<const PigmentMapValue>(PigmentMapValue{evalPigmentMap(n, false)});
    case Word::SkySphere: return std::make_shared<const SkySphere>(evalSkySphere(n));
    case Word::Fog: return std::make_shared<const Fog>(evalFog(n));
    default: return std::make_shared<const ObjectTree>(evalObject(n));
    }
}

void Interpreter::moveLayers(const Node& at, Texture& t, const Transform& m) {
    auto move = [&](TextureLayer& layer) {
        layer.pigment.worldFromPattern = composeAt(at, m, layer.pigment.worldFromPattern);
        if (layer.normal) layer.normal->pattern.worldFromPattern = composeAt(at, m, layer.normal->pattern.worldFromPattern);
    };
    move(t);
    for (TextureLayer& layer : t.above) move(layer);
}

// A copy of `base` whose top layer takes the pigment {}, normal {} or
// finish {} item `n` (an object's modifier, a #default entry).
std::shared_ptr<const Texture> Interpreter::withTopLayerItem(const Texture& base, const Node& n) {
    auto texture = std::make_shared<Texture>(base);
    TextureLayer& top = topLayer(*texture);
    if (n.word == Word::Pigment)
        top.pigment = *evalPigment(n, top.pigment);
    else if (n.word == Word::Normal)
        top.normal = *evalNormal(n, top.normal);
    else
        top.finish = *evalFinish(n, top.finish);
    return texture;
}

void Interpreter::placeObject(ObjectTree&& tree, const Node& at) {
    checkObjects(at, objects_.size() + scene_.lights.size() + tree.leaves, "the scene");
    checkMemory(at, tree.leaves * sizeof(Object), "the scene's objects");
    flatten(tree, nullptr, false, AsosOptions{}, nullptr, true);
}

// Past a limit the run stops: going on would repeat the work that passed it
// (a doubling union's next line copies the same large tree again).
void Interpreter::checkObjects(const Node& at, std::size_t count, const char* what) {
    if (count <= options_.maxObjects) return;
    error(at, std::string(what) + " would hold " + std::to_string(count) + " objects, over the limit of " +
                  std::to_string(options_.maxObjects) + " (raise it with --max-objects)");
    throw Stop{};
}

void Interpreter::checkMemory(const Node& at, std::size_t bytes, const char* what) {
    constexpr double kMiB = 1024.0 * 1024.0;
    const double total = static_cast<double>(objects_.size() * sizeof(Object)) +
                         static_cast<double>(unionNodes_ * sizeof(ObjectTree)) + static_cast<double>(bytes);
    if (total <= static_cast<double>(options_.maxMemoryMiB) * kMiB) return;
    const auto mib = static_cast<std::uint64_t>(std::ceil(total / kMiB));
    error(at, std::string(what) + " would take about " + std::to_string(mib) +
                  " MiB, over the limit of " + std::to_string(options_.maxMemoryMiB) +
                  " MiB a scene may ask for (raise it with --max-memory)");
    throw Stop{};
}

// Consumes `node` (moves its parts into the scene).
void Interpreter::flatten(ObjectTree& node, const std::shared_ptr<const Texture>& inherited,
                          bool inheritedNoShadow, const AsosOptions& inheritedAsos,
                          const std::shared_ptr<const Interior>& inheritedInterior, bool placed) {
    const std::shared_ptr<const Texture>& texture = node.texture ? node.texture : inherited;
    const std::shared_ptr<const Interior>& interior = node.interior ? node.interior : inheritedInterior;
    const bool noShadow = inheritedNoShadow || node.noShadow;
    const AsosOptions asos = inherit(node.asos, inheritedAsos);
    settleBounds(node, placed);
    if (!clipsOf(node).empty()) {
        placeCsg(node, texture, noShadow, asos, interior);
        return;
    }
    switch (node.kind) {
    case ObjectTree::Kind::Shape: {
        const std::shared_ptr<const Texture> interned = texture ? textures_.intern(texture) : defaultTexture_;
        const auto add = [&](Shape shape) {
            Object& o = objects_.add();
            o.shape = std::move(shape);
            o.worldFromObject = node.worldFromObject;
            o.texture = interned;
            o.interior = interior;
            o.noShadow = noShadow;
            o.asos = asos;
            o.loc = node.loc;
        };
        if (!node.mesh) {
            add(std::move(node.shape));
            return;
        }
        // A mesh: an object per face, all sharing its lists.
        const auto faces = static_cast<std::uint32_t>(node.mesh->faces.size());
        for (std::uint32_t face = 0; face < faces; ++face) add(TriangleShape{node.mesh, face});
        return;
    }
    case ObjectTree::Kind::Light: {
        Light& l = scene_.lights.emplace_back(*node.light);
        l.asos = inherit(node.light->asos, asos);
        return;
    }
    case ObjectTree::Kind::Union:
        // An inverted union is POV-Ray's intersection of its inverted
        // members: a CSG, as the others.
        if (node.op != CsgTree::Op::Union || node.inverse) {
            placeCsg(node, texture, noShadow, asos, interior);
            return;
        }
        for (ObjectTree& child : node.children) flatten(child, texture, noShadow, asos, interior, false);
        return;
    }
}

void Interpreter::placeCsg(ObjectTree& root, const std::shared_ptr<const Texture>& inherited,
                           bool inheritedNoShadow, const AsosOptions& inheritedAsos,
                           const std::shared_ptr<const Interior>& inheritedInterior) {
    // Filled in below, through this pointer, while the leaves' Objects
    // already share it.
    auto tree = std::make_shared<CsgTree>();
    // Adds node's clip objects to the tree as clip members of `index`.
    const auto addClips = [&](auto& add, std::uint32_t index, ObjectTree& node) {
        for (ObjectTree& member : ownClipping(node).clips) {
            const std::uint32_t c = add(add, member, nullptr, false, AsosOptions{}, nullptr, true, false);
            tree->nodes[index].children.push_back(c);
        }
    };
    // Adds `node` (and its members) to the tree; its leaves become Objects
    // in leaf order (but those of a clip: `clip`), its lights go to the
    // scene. A node clipped_by others is added as the intersection of it
    // (`clipped`: its clips taken) and them.
    auto add = [&](auto& self, ObjectTree& node, const std::shared_ptr<const Texture>& outer, bool outerNoShadow,
                   const AsosOptions& outerAsos, const std::shared_ptr<const Interior>& outerInterior, bool clip,
                   bool clipped) -> std::uint32_t {
        // An intersection takes its clips as members of its own.
        const bool absorbsClips =
            node.kind == ObjectTree::Kind::Union && node.op == CsgTree::Op::Intersection && !node.inverse;
        if (!clipped) {
            settleBounds(node, false);
            if (!clipsOf(node).empty() && !absorbsClips) {
                const auto index = static_cast<std::uint32_t>(tree->nodes.size());
                tree->nodes.emplace_back();
                tree->nodes[index].op = CsgTree::Op::Intersection;
                tree->nodes[index].clip = clip;
                const std::uint32_t own = self(self, node, outer, outerNoShadow, outerAsos, outerInterior, clip, true);
                tree->nodes[index].children.push_back(own);
                addClips(self, index, node);
                return index;
            }
        }
        const std::shared_ptr<const Texture>& texture = node.texture ? node.texture : outer;
        const std::shared_ptr<const Interior>& interior = node.interior ? node.interior : outerInterior;
        const bool noShadow = outerNoShadow || node.noShadow;
        const AsosOptions asos = inherit(node.asos, outerAsos);
        const auto index = static_cast<std::uint32_t>(tree->nodes.size());
        tree->nodes.emplace_back();
        tree->nodes[index].inverse = node.inverse;
        tree->nodes[index].clip = clip;
        const auto leafObject = [&](Shape shape, std::uint32_t at) {
            const auto leaf = static_cast<std::uint32_t>(tree->leaves.size());
            tree->nodes[at].leaf = leaf;
            tree->nodes[at].clip = clip;
            tree->leaves.push_back({std::move(shape), node.worldFromObject, at});
            if (clip) return;
            Object& o = objects_.add();
            o.shape = CsgShape{tree, leaf};
            o.texture = texture ? textures_.intern(texture) : defaultTexture_;
            o.interior = interior;
            o.noShadow = noShadow;
            o.asos = asos;
            o.loc = node.loc;
        };
        if (node.kind == ObjectTree::Kind::Shape && node.mesh) {
            // A union of its faces: surfaces without an inside, as POV-Ray's
            // mesh without inside_vector.
            tree->nodes[index].op = CsgTree::Op::Union;
            for (std::uint32_t face = 0; face < node.mesh->faces.size(); ++face) {
                const auto at = static_cast<std::uint32_t>(tree->nodes.size());
                tree->nodes.emplace_back();
                leafObject(TriangleShape{node.mesh, face}, at);
                tree->nodes[index].children.push_back(at);
            }
            return index;
        }
        if (node.kind == ObjectTree::Kind::Shape) {
            leafObject(std::move(node.shape), index);
            return index;
        }
        tree->nodes[index].op = node.op;
        for (ObjectTree& child : node.children) {
            if (child.kind == ObjectTree::Kind::Light) {
                // A light in a clip or bound is refused where it is read.
                flatten(child, texture, noShadow, asos, interior, false);
                continue;
            }
            const std::uint32_t c = self(self, child, texture, noShadow, asos, interior, clip, false);
            tree->nodes[index].children.push_back(c);
        }
        if (absorbsClips && !clipped && node.clipping) addClips(self, index, node);
        return index;
    };
    add(add, root, inherited, inheritedNoShadow, inheritedAsos, inheritedInterior, false, false);
}

void Interpreter::settleBounds(ObjectTree& node, bool placed) {
    if (boundsOf(node).empty()) return;
    const BoundsFate fate = boundsFate(node, placed);
    ClipLists& own = ownClipping(node);
    const SourceLoc at = own.boundsLoc;
    if (!fate.contained && warnedBounds_.insert({at.file.get(), at.line, at.column}).second) {
        if (fate.kind == BoundsFate::Kind::Box)
            diagnostics_.warning(at, "asos clips this object to the box of its bounded_by: POV-Ray drops the bound "
                                     "but takes its box, the smaller, as the object's, so it shows the object on the "
                                     "rays that meet the box only, also where the object reaches outside it");
        else
            diagnostics_.warning(at, "asos clips this object to its bounded_by: POV-Ray keeps this bound and tests "
                                     "the object on the rays that meet it, so it shows also what lies outside the "
                                     "bound on those rays; asos could not show that the object lies within it");
    }
    switch (fate.kind) {
    case BoundsFate::Kind::Dropped:
        break;
    case BoundsFate::Kind::Bound:
        for (ObjectTree& bound : own.bounds) own.clips.push_back(std::move(bound));
        break;
    case BoundsFate::Kind::Box: {
        ObjectTree box;
        box.shape = BoxShape{fate.box.lo, fate.box.hi};
        box.loc = at;
        own.clips.push_back(std::move(box));
        break;
    }
    }
    own.bounds.clear();
}

// --- objects ----------------------------------------------------------------------------------

ObjectTree Interpreter::evalObject(const Node& block) {
    ObjectTree t;
    t.loc = locOf(block);
    bool bad = false;
    auto invalid = [&](const Node& at, std::string message) {
        error(at, std::move(message));
        bad = true;
    };
    const auto args = block.children();
    // The shape's own checks (its validate, shape_issue.hpp), each issue
    // reported at the argument it names.
    auto checkShape = [&] {
        for (const ShapeIssue& issue : shapeIssues(t.shape)) {
            const Node& argument = args[issue.argument];
            invalid(issue.element < 0 ? argument : argument.children()[issue.element], issue.message);
        }
    };

    switch (block.word) {
    case Word::Sphere:
        t.shape = SphereShape{evalVector(args[0]), evalFloat(args[1])};
        checkShape();
        break;
    case Word::Box:
        t.shape = BoxShape{evalVector(args[0]), evalVector(args[1])};
        checkShape();
        break;
    case Word::Cone:
        t.shape = ConeShape{evalVector(args[0]), evalFloat(args[1]), evalVector(args[2]), evalFloat(args[3]), false};
        checkShape();
        break;
    case Word::Cylinder:
        t.shape = CylinderShape{evalVector(args[0]), evalVector(args[1]), evalFloat(args[2]), false};
        checkShape();
        break;
    case Word::Disc:
        t.shape = DiscShape{evalVector(args[0]), evalVector(args[1]), evalFloat(args[2]),
                            block.flags == 4 ? evalFloat(args[3]) : 0.0};
        checkShape();
        break;
    case Word::Polygon: {
        // The count is the statement's own: it must match the list before
        // the points are checked.
        const double count = evalFloat(args[0]);
        PolygonShape p;
        const auto points = args[1].children();
        p.points.reserve(points.size());
        for (const Node& point : points) p.points.push_back(evalVector(point));
        t.shape = std::move(p);
        if (count != std::floor(count) || count < 3)
            invalid(args[0], "a polygon needs a whole number of at least 3 points, not " + formatNumber(count));
        else if (static_cast<double>(points.size()) != count)
            invalid(args[0], "the polygon announces " + formatNumber(count) + " points but lists " +
                                 std::to_string(points.size()));
        else
            checkShape();
        break;
    }
    case Word::Plane:
        t.shape = PlaneShape{evalVector(args[0]), evalFloat(args[1])};
        checkShape();
        break;
    case Word::Quadric:
        t.shape = QuadricShape{evalVector(args[0]), evalVector(args[1]), evalVector(args[2]), evalFloat(args[3])};
        checkShape();
        break;
    case Word::Torus:
        t.shape = TorusShape{evalFloat(args[0]), evalFloat(args[1]), false};
        checkShape();
        break;
    case Word::Poly: case Word::Quartic: case Word::Cubic: {
        // poly { N, <...> }; quartic and cubic have no order argument, so
        // the record's argument 1 (the coefficients) is their argument 0.
        const bool hasOrder = block.word == Word::Poly;
        PolyShape p;
        p.keyword = hasOrder ? "poly" : block.word == Word::Quartic ? "quartic" : "cubic";
        p.order = block.word == Word::Quartic ? 4 : 3;
        if (hasOrder) {
            // POV-Ray's (int) of the value.
            const double order = evalFloat(args[0]);
            if (!(order >= 2.0 && order < PolyShape::kMaxOrder + 1.0)) {
                invalid(args[0], "the order of a poly must be 2 to " + std::to_string(PolyShape::kMaxOrder) +
                                     ", not " + formatNumber(order));
                break;
            }
            p.order = static_cast<int>(order);
        }
        const Node& list = args[hasOrder ? 1 : 0];
        p.coefficients.reserve(list.children().size());
        for (const Node& c : list.children()) p.coefficients.push_back(evalFloat(c));
        t.shape = std::move(p);
        for (const ShapeIssue& issue : shapeIssues(t.shape)) {
            const Node& argument = args[hasOrder ? issue.argument : 0];
            invalid(issue.element < 0 ? argument : argument.children()[issue.element], issue.message);
        }
        break;
    }
    case Word::Text:
        evalText(block, t);
        break;
    case Word::Prism:
        evalPrism(block, t);
        break;
    case Word::Triangle: case Word::SmoothTriangle: {
        auto mesh = std::make_shared<TriangleMesh>();
        addTriangle(*mesh, block);
        t.shape = TriangleShape{std::move(mesh), 0};
        checkShape();
        break;
    }
    case Word::Mesh:
        evalMesh(block, t);
        if (bad) throw Abandon{};
        return t;
    case Word::Mesh2:
        evalMesh2(block, t);
        break;
    case Word::LightSource:
        t.kind = ObjectTree::Kind::Light;
        t.light = std::make_shared<const Light>(evalLight(block));
        return t;
    case Word::Union: case Word::Difference: case Word::Intersection: case Word::Merge: {
        t.kind = ObjectTree::Kind::Union;
        t.op = block.word == Word::Union          ? CsgTree::Op::Union
               : block.word == Word::Difference   ? CsgTree::Op::Difference
               : block.word == Word::Intersection ? CsgTree::Op::Intersection
                                                  : CsgTree::Op::Merge;
        t.leaves = 0;
        const HeldNodes held(*this, t);
        bool hasObject = false;
        const std::string named = (block.word == Word::Intersection ? "an " : "a ") + std::string(wordText(block.word));
        auto entry = [&](const Node& n) {
            if (isObjectBlock(n)) {
                if (t.modified)
                    fail(n, "the objects of " + named + " come before its modifiers");
                ObjectTree child = evalObject(n);
                // A union of a declared union doubles it: 30 lines make 2^30
                // objects. The tree is counted before it grows.
                checkObjects(n, t.leaves + child.leaves, ("this " + std::string(wordText(block.word))).c_str());
                t.leaves += child.leaves;
                t.nodes += child.nodes;
                unionNodes_ += child.nodes;
                hasObject |= child.kind != ObjectTree::Kind::Light;
                t.children.push_back(std::move(child));
            } else {
                t.modified = true;
                applyObjectModifier(t, n, false);
            }
        };
        runEntries(args, EntryHandler(entry));
        if (t.op != CsgTree::Op::Union && !hasObject)
            fail(block, named + " needs at least one object");
        return t;
    }
    case Word::Object: {
        const Node& base = args[0];
        if (base.kind != NodeKind::Block) {  // a declared object, an array's element, a macro's value
            const Value v = eval(base);
            const auto* o = std::get_if<std::shared_ptr<const ObjectTree>>(&v);
            if (!o) fail(base, referenceText(base) + " is " + describe(v) + ", not an object");
            // Before the copy is made; counted twice, for the declared
            // original stays alive beside it (a doubling union's peak).
            checkMemory(base, 2 * (*o)->nodes * sizeof(ObjectTree), "a copy of this object");
            t = **o;
        } else {
            t = evalObject(base);
        }
        break;
    }
    default:
        fail(block, "this is not an object");
    }

    const bool isShape = t.kind == ObjectTree::Kind::Shape;
    auto modifier = [&](const Node& n) { applyObjectModifier(t, n, isShape); };
    runEntries(args.subspan(block.flags), EntryHandler(modifier));
    if (bad) throw Abandon{};
    return t;
}

void Interpreter::applyTransform(ObjectTree& tree, const Transform& m, const Node& at) {
    switch (tree.kind) {
    case ObjectTree::Kind::Shape:
        tree.worldFromObject = composeAt(at, m, tree.worldFromObject);
        break;
    case ObjectTree::Kind::Light: {
        auto light = std::make_shared<Light>(*tree.light);
        light->position = m.point(light->position);
        light->pointAt = m.point(light->pointAt);
        if (light->area) {
            light->area->axis1 = m.vector(light->area->axis1);
            light->area->axis2 = m.vector(light->area->axis2);
        }
        if (!finitePlacement(*light))
            fail(at, "this transform moves a light_source out of range: its position is no longer finite");
        tree.light = std::move(light);
        break;
    }
    case ObjectTree::Kind::Union:
        for (ObjectTree& child : tree.children) applyTransform(child, m, at);
        break;
    }
    // POV-Ray's: an object's clip and bound move with it.
    if (tree.clipping) {
        ClipLists& own = ownClipping(tree);
        for (ObjectTree& clip : own.clips) applyTransform(clip, m, at);
        for (ObjectTree& bound : own.bounds) applyTransform(bound, m, at);
    }
    if (tree.texture) {
        auto moved = std::make_shared<Texture>(*tree.texture);
        moveLayers(at, *moved, m);
        tree.texture = std::move(moved);
    }
}

Transform Interpreter::evalTransformItem(const Node& item) {
    switch (item.word) {
    case Word::Translate:
        return Transform::translate(evalVector(item[0]));
    case Word::Rotate:
        return Transform::rotateDegrees(evalVector(item[0]));
    case Word::Scale: {
        const Vec3 s = evalVector(item[0]);
        if (s.x == 0 || s.y == 0 || s.z == 0)
            fail(item[0], "scale by zero (" + formatVector(s) + ") flattens everything");
        const Transform t = Transform::scale(s);
        if (!isFinite(t))
            fail(item[0], "scale by " + formatVector(s) + " is too small: its inverse is not a finite number");
        return t;
    }
    default: {
        double m[12];
        for (int i = 0; i < 12; ++i) m[i] = evalFloat(item[i]);
        const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                           m[2] * (m[3] * m[7] - m[4] * m[6]);
        if (det == 0 || !std::isfinite(det)) fail(item, "this matrix cannot be inverted");
        const Transform t = Transform::fromPovMatrix(m);
        if (!isFinite(t)) fail(item, "this matrix cannot be inverted: its inverse is not a finite number");
        return t;
    }
    }
}

void Interpreter::applyObjectModifier(ObjectTree& tree, const Node& n, bool isShape) {
    if (isTransform(n)) {
        applyTransform(tree, evalTransformItem(n), n);
        return;
    }
    const bool isLight = tree.kind == ObjectTree::Kind::Light;
    switch (n.word) {
    case Word::Pigment: case Word::Normal: case Word::Finish: case Word::Texture: {
        if (isLight) fail(n, std::string("a light_source has no ") += wordText(n.word));
        if (n.word == Word::Texture) {
            std::shared_ptr<const Texture> texture = evalTexture(n);
            if (tree.texture) {
                // POV-Ray's Link_Textures: a texture on an object that has
                // one goes over it.
                auto layered = std::make_shared<Texture>(*tree.texture);
                layerOver(*layered, *texture);
                texture = std::move(layered);
            }
            tree.texture = std::move(texture);
            return;
        }
        // pigment {}, normal {} and finish {} change the texture the object
        // has (as POV-Ray's Parse_Object_Mods), or a copy of the default one.
        tree.texture = withTopLayerItem(tree.texture ? *tree.texture : *defaultTexture_, n);
        return;
    }
    case Word::Interior:
        if (isLight) fail(n, "a light_source has no interior");
        tree.interior = evalInterior(n, tree.interior ? *tree.interior : Interior{});
        return;
    case Word::Material: {
        // POV-Ray's: the material's texture and interior, each replacing the
        // object's (a texture given on an object that has one goes over it,
        // as a texture {} there does).
        if (isLight) fail(n, "a light_source has no material");
        const std::shared_ptr<const MaterialValue> material = evalMaterial(n);
        if (material->texture) {
            if (tree.texture) {
                auto layered = std::make_shared<Texture>(*tree.texture);
                layerOver(*layered, *material->texture);
                tree.texture = std::move(layered);
            } else {
                tree.texture = material->texture;
            }
        }
        if (material->interior) tree.interior = material->interior;
        return;
    }
    case Word::NoShadow:
        tree.noShadow = true;
        return;
    case Word::Inverse:
        // POV-Ray's: the object's inside and outside swap (each `inverse`
        // toggles), which only a CSG around it shows.
        if (isLight) fail(n, "a light_source has no inside to invert");
        tree.inverse = !tree.inverse;
        return;
    case Word::ClippedBy: case Word::BoundedBy:
        if (isLight) fail(n, "a light_source has no " + std::string(wordText(n.word)));
        applyClipOrBound(tree, n);
        return;
    case Word::Hollow:
        // POV-Ray's hollow lets media and fog inside the object; asos has
        // neither, so it changes nothing here. Its value is still checked.
        if (n.count > 0) evalBool(n[0]);
        return;
    case Word::Open:
        if (isShape) {
            if (auto* cone = std::get_if<ConeShape>(&tree.shape)) {
                cone->open = true;
                return;
            }
            if (auto* cylinder = std::get_if<CylinderShape>(&tree.shape)) {
                cylinder->open = true;
                return;
            }
            if (auto* prism = std::get_if<ExtrusionShape>(&tree.shape); prism && prism->keyword == std::string_view("prism")) {
                prism->open = true;
                return;
            }
        }
        fail(n, "'open' applies only to a cone, a cylinder or a prism");
    case Word::Sturm:
        // The torus' roots are found robustly without it (docs/geometry.md);
        // it is kept for the dump.
        if (isShape) {
            if (auto* torus = std::get_if<TorusShape>(&tree.shape)) {
                torus->sturm = true;
                return;
            }
            if (auto* poly = std::get_if<PolyShape>(&tree.shape)) {
                poly->sturm = true;
                return;
            }
            if (auto* prism = std::get_if<ExtrusionShape>(&tree.shape); prism && prism->keyword == std::string_view("prism")) {
                prism->sturm = true;
                return;
            }
        }
        fail(n, "'sturm' applies only to a torus, a poly, a quartic, a cubic or a prism here");
    case Word::Asos:
        if (isLight) {
            auto light = std::make_shared<Light>(*tree.light);
            light->asos = evalAsos(n, light->asos, true);
            tree.light = std::move(light);
        } else {
            tree.asos = evalAsos(n, tree.asos);
        }
        return;
    default:
        fail(n, "this is not an object modifier");
    }
}

// POV-Ray's Parse_Object_Mods: clipped_by and bounded_by add objects to
// their lists; clipped_by { bounded_by } and bounded_by { clipped_by } make
// one list serve as both, and nothing may be added to either after that.
void Interpreter::applyClipOrBound(ObjectTree& tree, const Node& n) {
    const bool clip = n.word == Word::ClippedBy;
    const std::string name(wordText(n.word));
    const auto entries = n.children();
    const char* other = clip ? "bounded_by" : "clipped_by";
    ClipLists& own = ownClipping(tree);
    if (own.linked)
        fail(n, std::string("this object's clipped_by and bounded_by are one list (linked by ") + other +
                    " { " + name + " }): nothing can be added to it");
    if (entries.size() == 1 && entries[0].kind == NodeKind::Item &&
        entries[0].word == (clip ? Word::BoundedBy : Word::ClippedBy)) {
        std::vector<ObjectTree>& from = clip ? own.bounds : own.clips;
        if (from.empty())
            fail(n, name + " { " + other + " } needs a " + other + " before it");
        if (!(clip ? own.clips : own.bounds).empty())
            fail(n, name + " { " + other + " } cannot follow a " + name +
                        " of objects");
        if (clip) own.clips = std::move(own.bounds);
        own.bounds.clear();
        own.linked = true;
        return;
    }
    std::vector<ObjectTree>& list = clip ? own.clips : own.bounds;
    // POV-Ray's Parse_Bound_Clip: the objects, then transforms of them
    // all; an object with a texture, a triangle or a mesh is refused.
    const std::size_t first = list.size();
    bool transformed = false;
    auto entry = [&](const Node& e) {
        if (isTransform(e)) {
            if (list.size() == first) fail(e, "a transform in " + name + " comes after its objects");
            const Transform m = evalTransformItem(e);
            for (std::size_t i = first; i < list.size(); ++i) applyTransform(list[i], m, e);
            transformed = true;
            return;
        }
        if (!isObjectBlock(e)) fail(e, "expected an object in " + name);
        if (transformed) fail(e, "the objects of " + name + " come before its transforms");
        ObjectTree member = evalObject(e);
        if (member.kind == ObjectTree::Kind::Light) fail(e, "a light_source cannot be in " + name);
        if (member.texture)
            fail(e, "an object in " + name + " cannot have a texture (POV-Ray: illegal texture in clip or bound)");
        if (member.mesh || std::holds_alternative<TriangleShape>(member.shape))
            fail(e, "a triangle or a mesh cannot be in " + name + " (POV-Ray: illegal patch in clip or bound)");
        list.push_back(std::move(member));
    };
    const std::size_t errorsBefore = errorCount_;
    runEntries(entries, EntryHandler(entry));
    if (errorCount_ != errorsBefore) throw Abandon{};  // reported at the entry
    if (list.size() == first) fail(n, name + " needs at least one object");
    if (!clip) own.boundsLoc = locOf(n);
}

// --- pigments, finishes, textures ---------------------------------------------------------

std::shared_ptr<const Pigment> Interpreter::evalPigment(const Node& block, const Pigment& start) {
    return evalPigmentEntries(block.children(), start, block);
}

// A pigment's items: a pigment { … }'s, or a pigment map entry's. `where`:
// the block or entry, where what the pigment lacks as a whole is reported.
std::shared_ptr<const Pigment> Interpreter::evalPigmentEntries(std::span<const Node> entries, const Pigment& start,
                                                               const Node& where) {
    auto p = std::make_shared<Pigment>(start);
    // POV-Ray's order inside a pigment: an optional declared pigment, then at
    // most one colour or pattern, then transforms. POV-Ray rejects anything else
    // ("No matching } in 'pigment'"); so do we, naming the reason.
    enum class Stage { Empty, Declared, Pattern, Modifiers } stage = Stage::Empty;
    bool mapGiven = false;  // a pigment map written, read or refused
    auto pattern = [&](const Node& n) {
        if (stage == Stage::Pattern) fail(n, "a pigment has one colour or pattern; this is a second one");
        if (stage == Stage::Modifiers) fail(n, "a pigment's colour or pattern must come before its transforms");
        stage = Stage::Pattern;
    };
    auto entry = [&](const Node& n) {
        if (isTransform(n)) {
            p->worldFromPattern = composeAt(n, evalTransformItem(n), p->worldFromPattern);
            stage = Stage::Modifiers;
        } else if (n.kind == NodeKind::Item && n.word == Word::Checker) {
            pattern(n);
            p->kind = Pigment::Kind::Checker;
            p->pigmentMap = nullptr;
            if (patternOfPigments(n, *p, kCheckerBlue, kCheckerGreen)) return;
            p->color1 = n.count > 0 ? evalColour(n[0]) : kCheckerBlue;
            p->color2 = n.count > 1 ? evalColour(n[1]) : kCheckerGreen;
        } else if (n.kind == NodeKind::Item && n.word == Word::Brick) {
            pattern(n);
            // As POV-Ray: a brick pigment given brick again keeps its size and
            // mortar; any other starts from the defaults.
            if (p->kind != Pigment::Kind::Brick) {
                const Pigment fresh;
                p->brickSize = fresh.brickSize;
                p->mortar = fresh.mortar;
            }
            p->kind = Pigment::Kind::Brick;
            p->pigmentMap = nullptr;
            if (patternOfPigments(n, *p, kBrickMortar, kBrickRed)) return;
            p->color1 = n.count > 0 ? evalColour(n[0]) : kBrickMortar;
            p->color2 = n.count > 1 ? evalColour(n[1]) : kBrickRed;
        } else if (n.kind == NodeKind::Item && isMapPattern(n.word)) {
            pattern(n);
            startMapPattern(n, *p);
            p->color1 = p->color2 = Color{};
        } else if (n.kind == NodeKind::Item && n.word == Word::Average) {
            // POV-Ray's average pattern: no value of its own, the weighted
            // mean of its pigment map's entries.
            pattern(n);
            p->kind = Pigment::Kind::Average;
            p->function = nullptr;
            p->wave = Pigment::Wave::Ramp;
            p->color1 = p->color2 = Color{};
            if (!p->colourMap.empty()) fail(n, "Cannot use color_map with this pattern type (average takes a pigment_map)");
        } else if (n.kind == NodeKind::Item && isMapModifier(n.word)) {
            applyMapModifier(n, *p);
            if (stage == Stage::Empty) stage = Stage::Modifiers;
        } else if (n.kind == NodeKind::Block && n.word == Word::ColorMap) {
            if (p->kind == Pigment::Kind::Checker || p->kind == Pigment::Kind::Brick)
                fail(n, std::string("a colour map on ") + (p->kind == Pigment::Kind::Checker ? "checker" : "brick") +
                            " is not supported by asos; give it two colours");
            if (p->kind == Pigment::Kind::Average) {
                mapGiven = true;
                fail(n, "Cannot use color_map with this pattern type (average)");
            }
            // On a plain colour POV-Ray reads the map and ignores it.
            const auto map = evalColourMap(n);
            if (isMapPigment(p->kind)) {
                // One map per pattern: a colour map replaces a pigment map.
                p->colourMap = map->entries;
                p->pigmentMap = nullptr;
            }
        } else if (n.kind == NodeKind::Block && n.word == Word::PigmentMap) {
            // POV-Ray's Not_With: no pigment map on a plain colour or on a
            // pattern of two colours.
            if (!isMapPigment(p->kind))
                fail(n, std::string("Cannot use pigment_map with this pigment type (") +
                            (p->kind == Pigment::Kind::Solid     ? "a plain colour"
                             : p->kind == Pigment::Kind::Checker ? "checker"
                                                                 : "brick") +
                            "); give it a pattern first");
            mapGiven = true;
            p->pigmentMap = evalPigmentMap(n, p->kind == Pigment::Kind::Average);
            p->colourMap.clear();
        } else if (n.kind == NodeKind::Item && (n.word == Word::BrickSize || n.word == Word::Mortar)) {
            // Pattern modifiers, like the transforms (POV-Ray reads them in the
            // same loop), of a brick pigment only.
            if (p->kind != Pigment::Kind::Brick)
                fail(n, "'" + std::string(wordText(n.word)) + "' applies only to the brick pattern");
            if (n.word == Word::Mortar) {
                p->mortar = evalFloat(n[0]);
            } else {
                const Vec3 size = evalVector(n[0]);
                if (size.x == 0.0 || size.y == 0.0 || size.z == 0.0)
                    fail(n[0], "brick_size <" + formatNumber(size.x) + ", " + formatNumber(size.y) + ", " +
                                   formatNumber(size.z) + "> has a zero component (the pattern divides by it)");
                p->brickSize = size;
            }
            stage = Stage::Modifiers;
        } else {
            const Value v = eval(n);
            if (const auto* declared = std::get_if<std::shared_ptr<const Pigment>>(&v)) {
                if (stage != Stage::Empty) fail(n, "a declared pigment must come first in the pigment");
                *p = **declared;
                stage = Stage::Declared;
            } else if (const auto* num = std::get_if<Num>(&v)) {
                pattern(n);
                p->kind = Pigment::Kind::Solid;
                p->pigmentMap = nullptr;
                p->color1 = toColour(*num, n);
                p->color2 = Color{};
            } else {
                fail(n, "expected a colour or a pigment, found " + describe(v));
            }
        }
    };
    runEntries(entries, EntryHandler(entry));
    if (p->kind == Pigment::Kind::Average && !p->pigmentMap && !mapGiven)
        fail(where, "Missing pigment_map in average pigment");
    return p;
}

// checker or brick of pigments (POV-Ray's pigment list): a pigment map of
// the pattern's two values, 0 and 1, each a pigment from the default
// pigment; the second, when left out, the pattern's default colour (as
// POV-Ray fills a short list from the pattern's default map). False when
// the item holds colours.
bool Interpreter::patternOfPigments(const Node& item, Pigment& p, const Color& first, const Color& second) {
    if (item.count == 0 || !(item[0].kind == NodeKind::Block && item[0].word == Word::Pigment)) return false;
    auto map = std::make_shared<PigmentMap>();
    for (std::uint32_t i = 0; i < item.count; ++i)
        map->push_back({double(i), evalPigment(item[i], defaultTexture_->pigment)});
    if (map->size() == 1) {
        auto fill = std::make_shared<Pigment>();
        fill->color1 = second;
        map->push_back({1.0, std::move(fill)});
    }
    p.color1 = first;
    p.color2 = second;
    p.pigmentMap = std::move(map);
    return true;
}

// pigment_map { [value pigment-body] … }: each entry's pigment made from
// POV-Ray's default pigment (the #default texture's) by the entry's items.
// Under `average` the value is an optional weight, 1 when left out (POV-Ray's
// Allow_Float): what the grammar read as the value is then the entry's first
// pigment item unless it is a float. At most 256 entries, as POV-Ray.
std::shared_ptr<const PigmentMap> Interpreter::evalPigmentMap(const Node& block, bool average) {
    auto map = std::make_shared<PigmentMap>();
    std::shared_ptr<const PigmentMap> declared;
    for (const Node& n : block.children()) {
        if (!(n.kind == NodeKind::Item && n.word == Word::PigmentMap)) {
            const Value v = eval(n);
            const auto* named = std::get_if<std::shared_ptr<const PigmentMapValue>>(&v);
            if (!named) fail(n, referenceText(n) + " is " + describe(v) + ", not a pigment map");
            declared = (*named)->entries;
            continue;
        }
        if (map->size() == 256) fail(n, "Too many entries in map. The maximum is 256 entries per map.");
        std::span<const Node> items = n.children();
        double value = 1.0;
        if (n.flags == 1) {
            const Node& written = n[0];
            if (!average) {
                const Value v = eval(written);
                const auto* num = std::get_if<Num>(&v);
                if (!num || !num->isFloat())
                    fail(written, "expected the value of the pigment map entry, found " + describe(v) +
                                      (std::holds_alternative<std::shared_ptr<const Pigment>>(v)
                                           ? " (only an average entry may leave its value out)"
                                           : ""));
                value = num->v[0];
                items = items.subspan(1);
            } else {
                // POV-Ray takes a number there as the weight, and refuses a
                // colour or a vector ("Expected 'numeric expression'").
                const Value v = eval(written);
                if (const auto* num = std::get_if<Num>(&v)) {
                    if (!num->isFloat())
                        fail(written, "expected the weight of the average entry, found " + describe(v) +
                                          " (POV-Ray reads a colour there as the weight; write [1 colour])");
                    value = num->v[0];
                    items = items.subspan(1);
                }
            }
        } else if (!average) {
            fail(n, "expected the value of the pigment map entry");
        }
        map->push_back({value, evalPigmentEntries(items, defaultTexture_->pigment, n)});
    }
    // A declared map is shared as it is (POV-Ray takes nothing after its
    // name, nor does the grammar: `M [` reads as an index).
    if (map->empty() && declared) return declared;
    if (map->empty()) fail(block, "a pigment map needs at least one entry");
    return map;
}

// The modifiers of the map patterns, in any order after the pattern, as
// POV-Ray reads them with the transforms.
void Interpreter::applyMapModifier(const Node& n, Pigment& p) {
    if (isCrackleModifier(n.word)) {
        setMapModifier(n, p);
        return;
    }
    if (p.kind == Pigment::Kind::Checker || p.kind == Pigment::Kind::Brick)
        fail(n, "'" + std::string(wordText(n.word)) + "' on " +
                    (p.kind == Pigment::Kind::Checker ? "checker" : "brick") + " is not supported by asos");
    // POV-Ray reads them on a plain colour too, where they change nothing.
    if (p.kind == Pigment::Kind::Solid) {
        for (std::uint32_t i = 0; i < n.count; ++i) evalNum(n[i]);
        return;
    }
    setMapModifier(n, p);
}

// A map pattern's item in a pigment or a normal: as POV-Ray, a new pattern
// starts from its own defaults (its kind, its wave, gradient's direction),
// but the modifiers read before it (turbulence, a colour map) stay.
void Interpreter::startMapPattern(const Node& n, Pigment& p) {
    p.kind = mapKind(n.word);
    if (n.word == Word::Crackle) {
        const Pigment fresh;
        p.crackleForm = fresh.crackleForm;
        p.crackleMetric = fresh.crackleMetric;
        p.crackleOffset = fresh.crackleOffset;
        p.crackleSolid = fresh.crackleSolid;
    }
    p.function = n.word == Word::Function ? compileFunctionOfPoint(n[0]) : nullptr;
    p.wave = (n.word == Word::Marble || n.word == Word::Wood) ? Pigment::Wave::Triangle : Pigment::Wave::Ramp;
    if (n.word == Word::Gradient) {
        const Vec3 g = evalVector(n[0]);
        const double length = glm::length(g);
        if (length == 0.0) fail(n[0], "gradient <0, 0, 0> has no direction");
        // A vector already of unit length to rounding (the dump's) is kept:
        // dividing again moves it by an ulp, and the dump would not read
        // back to itself.
        p.gradient = std::abs(length - 1.0) <= kFewUlps ? g : g / length;
    }
}

// One modifier's value (a normal's pattern takes them all, its
// normal-only patterns included).
void Interpreter::setMapModifier(const Node& n, Pigment& p) {
    switch (n.word) {
    case Word::Turbulence: {
        const Num t = evalNum(n[0]);
        if (t.dim > 3) fail(n[0], "expected a float or a vector after turbulence, found " + describe(t));
        p.turbulence = t.dim == 1 ? Vec3(t.v[0]) : Vec3(t.v[0], t.v[1], t.v[2]);
        break;
    }
    case Word::Octaves: {
        // POV-Ray clips octaves to 1..10.
        const double v = evalFloat(n[0]);
        p.octaves = static_cast<int>(std::clamp(v, 1.0, 10.0));
        break;
    }
    case Word::Omega: p.omega = evalFloat(n[0]); break;
    case Word::Lambda: p.lambda = evalFloat(n[0]); break;
    case Word::Frequency: p.frequency = evalFloat(n[0]); break;
    case Word::Phase: p.phase = evalFloat(n[0]); break;
    case Word::RampWave: p.wave = Pigment::Wave::Ramp; break;
    case Word::TriangleWave: p.wave = Pigment::Wave::Triangle; break;
    case Word::SineWave: p.wave = Pigment::Wave::Sine; break;
    case Word::AgateTurb:
        if (p.kind != Pigment::Kind::Agate) fail(n, "'agate_turb' applies only to the agate pattern");
        p.agateTurb = evalFloat(n[0]);
        break;
    case Word::NoiseGenerator: p.noiseGenerator = evalNoiseGenerator(n[0]); break;
    case Word::Form: case Word::Metric: case Word::Offset: case Word::Solid:
        if (p.kind != Pigment::Kind::Crackle)
            fail(n, "'" + std::string(wordText(n.word)) + "' applies only to the crackle pattern");
        if (n.word == Word::Form) p.crackleForm = evalVector(n[0]);
        if (n.word == Word::Metric) p.crackleMetric = evalVector(n[0]).x;  // POV-Ray reads a vector, uses x
        if (n.word == Word::Offset) p.crackleOffset = evalFloat(n[0]);
        if (n.word == Word::Solid) p.crackleSolid = true;
        break;
    default: fail(n, "this is not a pattern modifier");
    }
}

// normal { … }: an optional declared normal, then at most one pattern with
// its bump size, then bump_size, accuracy, the pattern's modifiers and
// transforms in any order (POV-Ray's Parse_Tnormal). `start`: the normal the
// layer has, or none (POV-Ray's defaults).
std::shared_ptr<const Normal> Interpreter::evalNormal(const Node& block, const std::optional<Normal>& start) {
    auto normal = std::make_shared<Normal>(start.value_or(Normal{}));
    bool declaredOk = true, patternSeen = false;
    auto entry = [&](const Node& n) {
        const bool first = declaredOk;
        declaredOk = false;
        if (isTransform(n)) {
            normal->pattern.worldFromPattern = composeAt(n, evalTransformItem(n), normal->pattern.worldFromPattern);
            return;
        }
        if (n.kind == NodeKind::Block && n.word == Word::ColorMap)
            fail(n, "a normal has no colour map (normal_map and slope_map are not supported by asos)");
        if (n.kind == NodeKind::Item) {
            const bool own = n.word == Word::Bumps || n.word == Word::Dents || n.word == Word::Wrinkles ||
                             n.word == Word::Ripples || n.word == Word::Waves;
            if (own || isMapPattern(n.word)) {
                if (patternSeen) fail(n, "a normal has one pattern; this is a second one");
                patternSeen = true;
                Pigment& p = normal->pattern;
                if (own) {
                    p.kind = Pigment::Kind::Solid;  // the value is not read
                    p.wave = Pigment::Wave::Ramp;
                } else {
                    startMapPattern(n, p);
                }
                p.colourMap.clear();
                switch (n.word) {
                case Word::Bumps: normal->kind = Normal::Kind::Bumps; break;
                case Word::Dents: normal->kind = Normal::Kind::Dents; break;
                case Word::Wrinkles: normal->kind = Normal::Kind::Wrinkles; break;
                case Word::Ripples: normal->kind = Normal::Kind::Ripples; break;
                case Word::Waves: normal->kind = Normal::Kind::Waves; break;
                default: normal->kind = Normal::Kind::Pattern; break;
                }
                return;
            }
            if (n.word == Word::BumpSize) {
                normal->amount = evalFloat(n[0]);
                return;
            }
            if (n.word == Word::Accuracy) {
                const double delta = evalFloat(n[0]);
                if (delta == 0.0) fail(n[0], "accuracy 0 leaves no distance to measure the pattern's slope over");
                normal->accuracy = delta;
                return;
            }
            if (isMapModifier(n.word)) {
                setMapModifier(n, normal->pattern);
                return;
            }
        }
        const Value v = eval(n);
        const auto* declared = std::get_if<std::shared_ptr<const Normal>>(&v);
        if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a normal");
        if (!first) fail(n, "a declared normal must come first in the normal");
        *normal = **declared;
    };
    runEntries(block.children(), EntryHandler(entry));
    return normal;
}

int Interpreter::evalNoiseGenerator(const Node& n) {
    const double v = evalFloat(n);
    // Truncated as POV-Ray does, once it is known to fit (NaN does not).
    if (!(v >= 1.0 && v < 4.0)) fail(n, "noise_generator must be 1, 2 or 3, not " + formatNumber(v));
    return static_cast<int>(v);
}

// color_map { [v colour] … }: a declared map by name first, if any, whose
// entries the block's own replace; POV-Ray's older [v1, v2 colour1 colour2]
// gives two entries. As POV-Ray: at most 256 entries, the values neither
// sorted nor clipped (the lookup takes them as they are: colourMapAt).
std::shared_ptr<const ColourMapValue> Interpreter::evalColourMap(const Node& block) {
    auto map = std::make_shared<ColourMapValue>();
    bool own = false;
    for (const Node& n : block.children()) {
        if (!(n.kind == NodeKind::Item && n.word == Word::ColorMap)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const ColourMapValue>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a colour map");
            map->entries = (*declared)->entries;
            continue;
        }
        if (!own) map->entries.clear();
        own = true;
        auto add = [&](const Node& valueNode, const Node& colourNode) {
            const double value = evalFloat(valueNode);
            if (map->entries.size() == 256) fail(n, "a colour map has at most 256 entries");
            map->entries.push_back({value, evalColour(colourNode)});
        };
        if (n.count == 2) {
            add(n[0], n[1]);
        } else if (n.count == 4) {
            add(n[0], n[2]);
            add(n[1], n[3]);
        } else {
            fail(n, "a colour map entry is [value colour] or [value1, value2 colour1 colour2]");
        }
    }
    if (map->entries.empty()) fail(block, "a colour map needs at least one entry");
    return map;
}

std::shared_ptr<const Finish> Interpreter::evalFinish(const Node& block, const Finish& start) {
    auto f = std::make_shared<Finish>(start);
    auto entry = [&](const Node& n) {
        if (isReference(n)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const Finish>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a finish");
            *f = **declared;
            return;
        }
        switch (n.word) {
        case Word::Ambient: f->ambient = evalRgb(n[0], "ambient"); break;
        case Word::Diffuse: f->diffuse = evalFloat(n[0]); break;
        case Word::Brilliance: f->brilliance = evalFloat(n[0]); break;
        case Word::Phong: f->phong = evalFloat(n[0]); break;
        case Word::PhongSize: f->phongSize = evalFloat(n[0]); break;
        case Word::Specular: f->specular = evalFloat(n[0]); break;
        case Word::Roughness: {
            const double r = evalFloat(n[0]);
            if (!(r > 0)) fail(n[0], "roughness must be positive, not " + formatNumber(r));
            f->roughness = r;
            break;
        }
        case Word::Reflection:
            if (n.kind == NodeKind::Block) {
                evalReflection(n, *f);
            } else {
                // POV-Ray's older form: one reflectivity at every angle.
                f->reflection = evalRgb(n[0], "reflection");
                f->reflectionMin.reset();
                f->reflectionFalloff = 1.0;
                f->fresnel = false;
            }
            break;
        case Word::ReflectionExponent: f->reflectionExponent = 1.0 / positiveExponent(n[0]); break;
        case Word::Metallic: f->metallic = n.count > 0 ? evalFloat(n[0]) : 1.0; break;
        case Word::ConserveEnergy: f->conserveEnergy = true; break;
        case Word::Crand: f->crand = evalFloat(n[0]); break;
        case Word::Ior:
        case Word::Caustics:
        case Word::Refraction:
            fail(n, "'" + std::string(wordText(n.word)) +
                        "' in a finish is POV-Ray 3.0's syntax, which asos does not read; write it in interior { … }");
        default: fail(n, "this is not a finish item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    return f;
}

// reflection { [C_min,] C_max  fresnel [B]  falloff F  exponent F  metallic [F] }
// as POV-Ray's Parse_Finish reads it: one colour is both; fresnel without a
// second colour starts from black.
void Interpreter::evalReflection(const Node& block, Finish& f) {
    const std::size_t colours = block.flags;
    const Vec3 first = evalRgb(block[0], "reflection");
    f.reflection = colours > 1 ? evalRgb(block[1], "reflection") : first;
    f.reflectionMin = first;
    for (std::size_t i = colours; i < block.count; ++i) {
        const Node& n = block[i];
        switch (n.word) {
        case Word::Fresnel: {
            f.fresnel = n.count > 0 ? evalBool(n[0]) : true;
            if (f.fresnel && colours < 2) f.reflectionMin = Vec3(0.0);
            break;
        }
        case Word::Falloff: f.reflectionFalloff = evalFloat(n[0]); break;
        case Word::Exponent: f.reflectionExponent = 1.0 / positiveExponent(n[0]); break;
        case Word::Metallic: f.reflectionMetallic = n.count > 0 ? evalFloat(n[0]) : 1.0; break;
        default: fail(n, "this is not an item of reflection { … }");
        }
    }
}

// A reflection exponent (POV-Ray stores its reciprocal).
double Interpreter::positiveExponent(const Node& n) {
    const double e = evalFloat(n);
    if (!(e > 0.0) || !std::isfinite(e)) fail(n, "a reflection exponent must be positive, not " + formatNumber(e));
    return e;
}

std::shared_ptr<const Interior> Interpreter::evalInterior(const Node& block, const Interior& start) {
    auto in = std::make_shared<Interior>(start);
    const auto finite = [&](const Node& n, const char* what) {
        const double v = evalFloat(n);
        if (!std::isfinite(v)) fail(n, std::string(what) + " must be a finite number, not " + formatNumber(v));
        return v;
    };
    auto entry = [&](const Node& n) {
        if (isReference(n)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const Interior>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not an interior");
            *in = **declared;
            return;
        }
        switch (n.word) {
        case Word::Ior: {
            const double ior = evalFloat(n[0]);
            if (!(ior > 0.0) || !std::isfinite(ior)) fail(n[0], "ior must be positive, not " + formatNumber(ior));
            in->ior = ior;
            break;
        }
        case Word::Caustics: in->caustics = finite(n[0], "caustics"); break;
        case Word::Dispersion: {
            const double d = evalFloat(n[0]);
            if (!(d > 0.0) || !std::isfinite(d)) fail(n[0], "dispersion must be positive, not " + formatNumber(d));
            in->dispersion = d;
            break;
        }
        case Word::DispersionSamples: {
            // POV-Ray truncates it and wants at least 2.
            const double s = evalFloat(n[0]);
            if (!(s >= 2.0) || !(s <= 1000.0))
                fail(n[0], "dispersion_samples must be from 2 to 1000, not " + formatNumber(s));
            in->dispersionSamples = static_cast<int>(s);
            break;
        }
        case Word::FadeDistance: in->fadeDistance = finite(n[0], "fade_distance"); break;
        case Word::FadePower: in->fadePower = finite(n[0], "fade_power"); break;
        case Word::FadeColor: in->fadeColor = evalRgb(n[0], "fade_color"); break;
        default: fail(n, "this is not an interior item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    return in;
}

std::shared_ptr<const MaterialValue> Interpreter::evalMaterial(const Node& block) {
    auto m = std::make_shared<MaterialValue>();
    auto entry = [&](const Node& n) {
        if (isReference(n)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const MaterialValue>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a material");
            *m = **declared;
        } else if (isTransform(n)) {
            // POV-Ray's Parse_Material: the transform moves the texture (an
            // interior has nothing to move).
            if (m->texture) {
                auto moved = std::make_shared<Texture>(*m->texture);
                moveLayers(n, *moved, evalTransformItem(n));
                m->texture = std::move(moved);
            }
        } else if (n.word == Word::Texture) {
            std::shared_ptr<const Texture> texture = evalTexture(n);
            if (m->texture) {
                auto layered = std::make_shared<Texture>(*m->texture);
                layerOver(*layered, *texture);
                texture = std::move(layered);
            }
            m->texture = std::move(texture);
        } else if (n.word == Word::Interior) {
            m->interior = evalInterior(n, m->interior ? *m->interior : Interior{});
        } else {
            fail(n, "this is not a material item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    return m;
}

std::shared_ptr<const Texture> Interpreter::evalTexture(const Node& block) {
    // A layered texture's block holds its layers, lowest first, as positional
    // children (the grammar's layered_texture); the first may be another kind
    // of block.
    if (block.flags > 0 && block[0].word != Word::Texture)
        fail(block[0], "only textures are layered: this " + std::string(wordText(block[0].word)) +
                           " is followed by a texture");
    auto t = std::make_shared<Texture>(*defaultTexture_);
    bool layered = false;  // the block's layers so far
    auto entry = [&](const Node& n) {
        if (block.flags > 0) {
            const std::shared_ptr<const Texture> layer = evalTexture(n);
            if (layered) layerOver(*t, *layer);
            else *t = *layer;
            layered = true;
        } else if (isReference(n)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const Texture>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a texture");
            *t = **declared;
        } else if (isTransform(n)) {
            moveLayers(n, *t, evalTransformItem(n));
        } else if ((n.word == Word::Pigment || n.word == Word::Normal || n.word == Word::Finish) &&
                   !t->above.empty()) {
            fail(n, std::string("a ") + std::string(wordText(n.word)) +
                        " in a layered texture's block is not supported by asos; give it to one of its layers");
        } else if (n.word == Word::Pigment) {
            t->pigment = *evalPigment(n, t->pigment);
        } else if (n.word == Word::Finish) {
            t->finish = *evalFinish(n, t->finish);
        } else if (n.word == Word::Normal) {
            t->normal = *evalNormal(n, t->normal);
        } else {
            fail(n, "this is not a texture item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    return t;
}

// --- lights -----------------------------------------------------------------------------------

Light Interpreter::evalLight(const Node& block) {
    Light l;
    l.loc = locOf(block);
    const auto args = block.children();
    const Value first = eval(args[0]);
    bool fromIdentifier = false;
    if (const auto* o = std::get_if<std::shared_ptr<const ObjectTree>>(&first)) {
        if ((*o)->kind != ObjectTree::Kind::Light)
            fail(args[0], "expected the position of the light or a declared light_source, found an object");
        l = *(*o)->light;
        l.loc = locOf(block);
        fromIdentifier = true;
    } else if (std::holds_alternative<Num>(first)) {
        l.position = evalVector(args[0]);
    } else {
        fail(args[0], "expected the position of the light, found " + describe(first));
    }
    if (block.flags >= 2)
        l.color = evalRgb(args[1], "a light's colour");
    else if (!fromIdentifier)
        fail(block, "a light_source needs a colour after its position");

    // adaptive, jitter, circular and orient belong to the area light; POV-Ray
    // accepts them before or after area_light.
    AreaLight pending = l.area.value_or(AreaLight{});
    bool areaFlags = false;
    auto entry = [&](const Node& n) {
        if (isTransform(n)) {
            const Transform m = evalTransformItem(n);
            l.position = m.point(l.position);
            l.pointAt = m.point(l.pointAt);
            if (l.area) {
                l.area->axis1 = m.vector(l.area->axis1);
                l.area->axis2 = m.vector(l.area->axis2);
            }
            if (!finitePlacement(l))
                fail(n, "this transform moves the light_source out of range: its position is no longer finite");
            return;
        }
        switch (n.word) {
        case Word::AreaLight: {
            AreaLight a = pending;
            a.axis1 = evalVector(n[0]);
            a.axis2 = evalVector(n[1]);
            a.size1 = evalInt(n[2], 1);
            a.size2 = evalInt(n[3], 1);
            l.area = a;
            break;
        }
        case Word::Adaptive: pending.adaptive = evalInt(n[0], 0); areaFlags = true; break;
        case Word::Jitter: pending.jitter = true; areaFlags = true; break;
        case Word::Circular: pending.circular = true; areaFlags = true; break;
        case Word::Orient: pending.orient = true; areaFlags = true; break;
        case Word::FadeDistance: {
            const double d = evalFloat(n[0]);
            if (!(d > 0)) fail(n[0], "fade_distance must be positive, not " + formatNumber(d));
            l.fadeDistance = d;
            break;
        }
        case Word::FadePower: {
            const double p = evalFloat(n[0]);
            if (p < 0) fail(n[0], "fade_power must not be negative, not " + formatNumber(p));
            l.fadePower = p;
            break;
        }
        case Word::Shadowless: l.shadowless = true; break;
        // POV-Ray sets a type's defaults at its keyword, and takes point_at,
        // radius, falloff and tightness only after it (point_at after
        // parallel too).
        case Word::Spotlight:
            l.type = LightType::Spot;
            l.radius = 30.0;
            l.falloff = 45.0;
            l.tightness = 0.0;
            break;
        case Word::Cylinder:
            l.type = LightType::Cylinder;
            l.radius = 0.75;
            l.falloff = 1.0;
            l.tightness = 0.0;
            l.parallel = true;
            break;
        case Word::Parallel: l.parallel = true; break;
        case Word::PointAt:
            if (l.type == LightType::Point && !l.parallel)
                fail(n, "point_at needs spotlight, cylinder or parallel before it in the light_source (as in POV-Ray)");
            l.pointAt = evalVector(n[0]);
            break;
        case Word::Radius: case Word::Falloff: case Word::Tightness: {
            const std::string name(wordText(n.word));
            if (l.type == LightType::Point)
                fail(n, name + " needs spotlight or cylinder before it in the light_source (as in POV-Ray)");
            const double v = evalFloat(n[0]);
            (n.word == Word::Radius ? l.radius : n.word == Word::Falloff ? l.falloff : l.tightness) = v;
            break;
        }
        case Word::AreaIllumination: l.areaIllumination = n.count == 0 || evalBool(n[0]); break;
        case Word::Asos: l.asos = evalAsos(n, l.asos, true); break;
        default: fail(n, "this is not a light_source item");
        }
        if (l.area) {
            l.area->adaptive = pending.adaptive;
            l.area->jitter = pending.jitter;
            l.area->circular = pending.circular;
            l.area->orient = pending.orient;
        }
    };
    runEntries(args.subspan(block.flags), EntryHandler(entry));
    if (areaFlags && !l.area)
        report(Severity::Warning, block, "adaptive, jitter, circular and orient have no effect without area_light");
    return l;
}

// --- camera -------------------------------------------------------------------------------------

CameraValue Interpreter::evalCamera(const Node& block) {
    // POV-Ray 3.7: items are gathered in any order, then angle sets the length
    // of direction, look_at turns the camera (keeping the lengths of direction,
    // right and up, and the handedness), and last the transforms apply.
    CameraValue cv;
    cv.camera.loc = locOf(block);
    std::optional<Vec3> lookAt;
    std::optional<double> angle;
    const Node* angleNode = nullptr;
    const Node* lookAtNode = nullptr;
    bool hadUp = false, hadRight = false, hadItems = false;
    Transform transform;
    auto entry = [&](const Node& n) {
        if (!isReference(n)) hadItems = true;
        if (isReference(n)) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const CameraValue>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a camera");
            cv = **declared;
            cv.camera.loc = locOf(block);
            return;
        }
        if (isTransform(n)) {
            transform = composeAt(n, evalTransformItem(n), transform);
            return;
        }
        Camera& c = cv.camera;
        switch (n.word) {
        case Word::Perspective: c.projection = Camera::Projection::Perspective; break;
        case Word::Orthographic: c.projection = Camera::Projection::Orthographic; break;
        case Word::Location: c.location = evalVector(n[0]); break;
        case Word::Direction: c.direction = evalVector(n[0]); break;
        case Word::Right: c.right = evalVector(n[0]); hadRight = true; break;
        case Word::Up: c.up = evalVector(n[0]); hadUp = true; break;
        case Word::Sky: cv.sky = evalVector(n[0]); break;
        case Word::LookAt: lookAt = evalVector(n[0]); lookAtNode = &n; break;
        case Word::Angle: angle = evalFloat(n[0]); angleNode = &n; break;
        default: fail(n, "this is not a camera item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));

    Camera& c = cv.camera;
    if (glm::length(c.direction) == 0) fail(block, "the camera's direction must not be zero");
    if (glm::length(c.right) == 0) fail(block, "the camera's right vector must not be zero");
    if (glm::length(c.up) == 0) fail(block, "the camera's up vector must not be zero");
    if (angle) {
        if (!(*angle > 0 && *angle < 180))
            fail((*angleNode)[0], "the camera angle must be between 0 and 180 degrees, not " + formatNumber(*angle));
        c.direction = glm::normalize(c.direction) *
                      (0.5 * glm::length(c.right) / std::tan(*angle * kPi / 360.0));
    }
    if (lookAt) {
        const double directionLength = glm::length(c.direction);
        const double rightLength = glm::length(c.right);
        const double upLength = glm::length(c.up);
        const double handedness = glm::dot(glm::cross(c.up, c.direction), c.right);
        const Vec3 toTarget = *lookAt - c.location;
        if (glm::length(toTarget) == 0)
            fail((*lookAtNode)[0], "the camera looks at its own location");
        const Vec3 direction = glm::normalize(toTarget);
        const double sign = handedness > 0 ? 1.0 : -1.0;
        const Vec3 side = glm::cross(cv.sky, direction);
        Vec3 right;
        if (glm::length(side) > 0) {
            right = glm::normalize(side) * sign;
        } else {
            // POV-Ray warns and keeps the right vector as given.
            report(Severity::Warning, (*lookAtNode)[0],
                   "the camera looks along its sky vector; the right vector is kept as given");
            right = glm::normalize(c.right);
            if (glm::length(glm::cross(direction, right)) == 0)
                fail((*lookAtNode)[0], "the camera looks along both its sky and its right vectors");
        }
        c.direction = direction * directionLength;
        c.right = right * rightLength;
        c.up = glm::normalize(glm::cross(direction, right)) * (sign * upLength);
        cv.lookAt = *lookAt;
    }
    // POV-Ray 3.7 sizes an orthographic view as the perspective camera's at
    // the look_at point (its default <0, 0, 1> included) unless right or up
    // is given without an angle: right and up grow by that distance over
    // direction's length.
    if (c.projection == Camera::Projection::Orthographic && hadItems && ((!hadUp && !hadRight) || angle)) {
        const double distance = glm::length(cv.lookAt - c.location);
        const double directionLength = glm::length(c.direction);
        if (distance > kPovEpsilon && directionLength > kPovEpsilon) {
            c.right *= distance / directionLength;
            c.up *= distance / directionLength;
        }
    }
    if (!transform.isIdentity()) {
        c.location = transform.point(c.location);
        c.direction = transform.vector(c.direction);
        c.right = transform.vector(c.right);
        c.up = transform.vector(c.up);
        cv.sky = transform.vector(cv.sky);
        cv.lookAt = transform.point(cv.lookAt);
    }
    return cv;
}

// --- global settings --------------------------------------------------------------------------

void Interpreter::applyGlobalSettings(const Node& block) {
    GlobalSettings& g = scene_.globals;
    auto entry = [&](const Node& n) {
        switch (n.word) {
        case Word::AssumedGamma: {
            const double v = evalFloat(n[0]);
            if (!(v > 0)) fail(n[0], "assumed_gamma must be positive, not " + formatNumber(v));
            g.assumedGamma = v;
            assumedGammaSet_ = true;
            break;
        }
        case Word::MaxTraceLevel: {
            const double v = evalFloat(n[0]);
            if (!(v >= 1))
                fail(n[0], "max_trace_level must be a whole number of at least 1, not " + formatNumber(v));
            if (v > kMaxTraceLevelLimit) {
                report(Severity::Warning, n[0],
                       "max_trace_level is at most " + std::to_string(kMaxTraceLevelLimit) + " (as in POV-Ray 3.7): " +
                           formatNumber(v) + " becomes " + std::to_string(kMaxTraceLevelLimit));
                g.maxTraceLevel = kMaxTraceLevelLimit;
            } else {
                g.maxTraceLevel = static_cast<int>(v);  // POV-Ray truncates
            }
            break;
        }
        case Word::NoiseGenerator: g.noiseGenerator = evalNoiseGenerator(n[0]); break;
        case Word::AmbientLight: g.ambientLight = evalRgb(n[0], "ambient_light"); break;
        case Word::Asos: g.asos = evalAsos(n, g.asos); break;
        default: fail(n, "this is not a global setting");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
}

// --- sky_sphere and fog ----------------------------------------------------------------------

// POV-Ray's Parse_Skysphere: a declared sky_sphere first (its pigments,
// emission and transform the start), then pigments (each in POV-Ray's
// default pigment, added after the declared one's), emission and transforms
// in any order; the transforms move the sphere, not the pigments written
// after them.
SkySphere Interpreter::evalSkySphere(const Node& block) {
    SkySphere sky;
    bool first = true;
    auto entry = [&](const Node& n) {
        const bool declaredOk = first;
        first = false;
        if (n.kind != NodeKind::Block && n.kind != NodeKind::Item) {
            const Value v = eval(n);
            const auto* declared = std::get_if<std::shared_ptr<const SkySphere>>(&v);
            if (!declared) fail(n, referenceText(n) + " is " + describe(v) + ", not a sky_sphere");
            if (!declaredOk) fail(n, "a declared sky_sphere must come first in the sky_sphere");
            sky = **declared;
        } else if (isTransform(n)) {
            sky.worldFromSky = composeAt(n, evalTransformItem(n), sky.worldFromSky);
        } else if (n.kind == NodeKind::Block && n.word == Word::Pigment) {
            sky.pigments.push_back(*evalPigment(n, defaultTexture_->pigment));
        } else if (n.kind == NodeKind::Item && n.word == Word::Emission) {
            sky.emission = evalRgb(n[0], "emission");
        } else {
            fail(n, "this is not a sky_sphere item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    sky.loc = locOf(block);
    if (sky.pigments.empty()) fail(block, "a sky_sphere needs at least one pigment (POV-Ray: empty sky_sphere statement)");
    return sky;
}

// POV-Ray's Parse_Fog: a declared fog first (the start), then its items in
// any order; rotate, scale and matrix turn its up vector, translate is
// ignored with POV-Ray's warning; up is made unit at the end.
Fog Interpreter::evalFog(const Node& block) {
    Fog fog;
    bool first = true;
    auto entry = [&](const Node& n) {
        const bool declaredOk = first;
        first = false;
        if (isTransform(n)) {
            if (n.word == Word::Translate) {
                evalVector(n[0]);
                report(Severity::Warning, n, "a fog's up vector can't be translated (as in POV-Ray, ignored)");
            } else {
                fog.up = evalTransformItem(n).vector(fog.up);
            }
            return;
        }
        if (n.kind != NodeKind::Item) {
            // A declared fog, or a bare colour (the fog's colour) or float
            // (its distance).
            const Value value = eval(n);
            if (const auto* declared = std::get_if<std::shared_ptr<const Fog>>(&value)) {
                if (!declaredOk) fail(n, "a declared fog must come first in the fog");
                fog = **declared;
                return;
            }
            const auto* num = std::get_if<Num>(&value);
            if (!num) fail(n, "expected a colour, a float or a declared fog, found " + describe(value));
            const Num& v = *num;
            if (v.dim == 1) {
                report(Severity::Warning, n, "should use the distance keyword (as POV-Ray warns)");
                fog.distance = v.v[0];
            } else {
                fog.color = toColour(v, n);
            }
            return;
        }
        switch (n.word) {
        case Word::FogType: {
            // POV-Ray truncates, warns of a type it does not know and
            // renders it as constant fog.
            const double t = evalFloat(n[0]);
            fog.type = std::isfinite(t) ? static_cast<int>(std::clamp(t, -1e9, 1e9)) : 0;
            if (fog.type != 1 && fog.type != 2)
                report(Severity::Warning, n[0], "unknown fog type " + formatNumber(t) + ": rendered as constant fog (as POV-Ray)");
            break;
        }
        case Word::Distance: fog.distance = evalFloat(n[0]); break;
        case Word::FogOffset: fog.offset = evalFloat(n[0]); break;
        case Word::FogAlt: fog.alt = evalFloat(n[0]); break;
        case Word::TurbDepth: fog.turbDepth = evalFloat(n[0]); break;
        case Word::Up: fog.up = evalVector(n[0]); break;
        case Word::Turbulence: {
            const Num t = evalNum(n[0]);
            if (t.dim > 3) fail(n[0], "expected a float or a vector after turbulence, found " + describe(t));
            fog.turbulence = t.dim == 1 ? Vec3(t.v[0]) : Vec3(t.v[0], t.v[1], t.v[2]);
            fog.turbulent = true;
            break;
        }
        case Word::Octaves:
            fog.octaves = static_cast<int>(std::clamp(evalFloat(n[0]), 1.0, 10.0));
            fog.turbulent = true;
            break;
        case Word::Omega: fog.omega = evalFloat(n[0]); fog.turbulent = true; break;
        case Word::Lambda: fog.lambda = evalFloat(n[0]); fog.turbulent = true; break;
        default: fail(n, "this is not a fog item");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    fog.loc = locOf(block);
    const double length = glm::length(fog.up);
    if (!(length > 0.0)) fail(block, "the fog's up vector is <0, 0, 0>");
    fog.up /= length;
    if (fog.type == 2 && fog.alt == 0.0 && std::fabs(fog.distance) > kPovEpsilon)
        fail(block, "a ground fog (fog_type 2) needs a fog_alt other than 0 (its density divides by it)");
    return fog;
}

AsosOptions Interpreter::evalAsos(const Node& block, AsosOptions start, bool forLight) {
    auto entry = [&](const Node& n) {
        switch (n.word) {
        case Word::Eps: {
            const double e = evalFloat(n[0]);
            if (std::string problem = epsProblem(e); !problem.empty()) fail(n[0], problem);
            start.eps = e;
            break;
        }
        case Word::Max: {
            const double m = evalFloat(n[0]);
            if (!(m >= 0) || m != std::floor(m) || m > 2147483647.0)
                fail(n[0], "max must be a whole number, at least 0, not " + formatNumber(m));
            start.maxLevel = static_cast<int>(m);
            break;
        }
        case Word::Jitter: start.jitter = evalBool(n[0]); break;
        case Word::Emitter:
            if (!forLight) fail(n, "emitter is an option of a light_source's asos block");
            start.emitter = n[0].word == Word::Panel ? LightEmitter::Panel : LightEmitter::Povray;
            break;
        case Word::Highlights: start.highlights = evalBool(n[0]); break;
        default: fail(n, "this is not an asos option");
        }
    };
    runEntries(block.children(), EntryHandler(entry));
    return start;
}

}  // namespace asos::lang
