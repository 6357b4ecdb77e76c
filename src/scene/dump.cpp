#include "asos/scene/dump.hpp"

#include "asos/scene/function_text.hpp"

#include <charconv>
#include <ostream>
#include <sstream>

namespace asos {

namespace {

// Shortest text that reads back to the same double; -0 is written 0 (the
// language has no negative zero literal, and the sign means nothing here).
class Writer {
public:
    Writer(std::ostream& out, const DumpOptions& options) : out_(out), options_(options) {}

    Writer& operator<<(std::string_view s) {
        out_ << s;
        return *this;
    }
    Writer& operator<<(char c) {
        out_ << c;
        return *this;
    }
    Writer& operator<<(int v) {
        out_ << v;
        return *this;
    }
    Writer& num(double v) {
        if (v == 0.0) {
            out_ << '0';
            return *this;
        }
        char buffer[32];
        const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
        out_.write(buffer, r.ptr - buffer);
        return *this;
    }
    Writer& vec(const Vec3& v) {
        out_ << '<';
        num(v.x) << ", ";
        num(v.y) << ", ";
        num(v.z) << '>';
        return *this;
    }
    Writer& colour(const Color& c) {
        out_ << "color rgbft <";
        num(c.rgb.x) << ", ";
        num(c.rgb.y) << ", ";
        num(c.rgb.z) << ", ";
        num(c.filter) << ", ";
        num(c.transmit) << '>';
        return *this;
    }
    Writer& rgb(const Vec3& v) {
        out_ << "rgb ";
        return vec(v);
    }
    Writer& matrix(const Transform& t) {
        double m[12];
        t.toPovMatrix(m);
        out_ << "matrix <";
        for (int i = 0; i < 12; ++i) {
            if (i) out_ << (i % 3 == 0 ? ",  " : ", ");
            num(m[i]);
        }
        out_ << '>';
        return *this;
    }
    void location(const SourceLoc& loc) {
        if (!options_.locations) return;
        if (loc.file && loc.line > 0)
            out_ << "// " << *loc.file << ':' << loc.line << ':' << loc.column << '\n';
        else
            out_ << "// (default)\n";
    }
    void asos(const AsosOptions& a, std::string_view indent) {
        if (!a.eps && !a.maxLevel && !a.jitter && !a.highlights && !a.emitter) return;
        out_ << indent << "asos {";
        if (a.eps) {
            out_ << " eps ";
            num(*a.eps);
        }
        if (a.maxLevel) out_ << " max " << *a.maxLevel;
        if (a.jitter) out_ << " jitter " << (*a.jitter ? "on" : "off");
        if (a.highlights) out_ << " highlights " << (*a.highlights ? "on" : "off");
        if (a.emitter) out_ << " emitter " << (*a.emitter == LightEmitter::Panel ? "panel" : "povray");
        out_ << " }\n";
    }

private:
    std::ostream& out_;
    const DumpOptions& options_;
};

void writeShape(Writer& w, const Shape& shape) {
    struct Visitor {
        Writer& w;
        void operator()(const SphereShape& s) const {
            w << "sphere {\n  ";
            w.vec(s.center) << ", ";
            w.num(s.radius) << '\n';
        }
        void operator()(const BoxShape& b) const {
            w << "box {\n  ";
            w.vec(b.corner1) << ", ";
            w.vec(b.corner2) << '\n';
        }
        void operator()(const ConeShape& c) const {
            w << "cone {\n  ";
            w.vec(c.base) << ", ";
            w.num(c.baseRadius) << ", ";
            w.vec(c.cap) << ", ";
            w.num(c.capRadius) << (c.open ? "\n  open\n" : "\n");
        }
        void operator()(const CylinderShape& c) const {
            w << "cylinder {\n  ";
            w.vec(c.base) << ", ";
            w.vec(c.cap) << ", ";
            w.num(c.radius) << (c.open ? "\n  open\n" : "\n");
        }
        void operator()(const DiscShape& d) const {
            w << "disc {\n  ";
            w.vec(d.center) << ", ";
            w.vec(d.normal) << ", ";
            w.num(d.radius) << ", ";
            w.num(d.holeRadius) << '\n';
        }
        void operator()(const PolygonShape& p) const {
            w << "polygon {\n  " << static_cast<int>(p.points.size());
            for (const Vec3& q : p.points) {
                w << ",\n  ";
                w.vec(q);
            }
            w << '\n';
        }
        void operator()(const PlaneShape& p) const {
            w << "plane {\n  ";
            w.vec(p.normal) << ", ";
            w.num(p.distance) << '\n';
        }
        // A CSG's leaves are written with their tree (writeCsg), never alone.
        void operator()(const CsgShape&) const {}
        void operator()(const QuadricShape& q) const {
            w << "quadric {\n  ";
            w.vec(q.squares) << ", ";
            w.vec(q.mixed) << ", ";
            w.vec(q.linear) << ", ";
            w.num(q.constant) << '\n';
        }
        void operator()(const TorusShape& t) const {
            w << "torus {\n  ";
            w.num(t.major) << ", ";
            w.num(t.minor) << '\n';
            if (t.sturm) w << "  sturm\n";
        }
        // As written: quartic and cubic without their order; the coefficients
        // eight to a line.
        void operator()(const PolyShape& p) const {
            const std::string keyword = p.keyword ? p.keyword : "poly";
            w << keyword << " {\n  ";
            if (keyword == "poly") w << p.order << ", ";
            w << '<';
            for (std::size_t n = 0; n < p.coefficients.size(); ++n) {
                if (n > 0) w << (n % 8 == 0 ? ",\n   " : ", ");
                w.num(p.coefficients[n]);
            }
            w << ">\n";
            if (p.sturm) w << "  sturm\n";
        }
        // As a prism of cubic pieces (a line's or a quadratic's raised to
        // degree 3 exactly); a text's glyph is such a prism under its
        // transform.
        void operator()(const ExtrusionShape& e) const {
            std::size_t count = 0;
            for (const OutlineContour& c : *e.outline) count += 4 * c.pieces.size();
            w << "prism {\n  bezier_spline ";
            w.num(e.y0) << ", ";
            w.num(e.y1) << ", " << static_cast<int>(count) << '\n';
            for (const OutlineContour& c : *e.outline) {
                for (const OutlinePiece& p : c.pieces) {
                    double x[4], z[4];
                    const auto at = [&](int i, int k) { return p.p[static_cast<std::size_t>(2 * i + k)]; };
                    for (int k = 0; k < 2; ++k) {
                        double* out = k == 0 ? x : z;
                        if (p.degree == 1) {
                            out[0] = at(0, k);
                            out[1] = at(0, k) + (at(1, k) - at(0, k)) / 3.0;
                            out[2] = at(1, k) + (at(0, k) - at(1, k)) / 3.0;
                            out[3] = at(1, k);
                        } else if (p.degree == 2) {
                            out[0] = at(0, k);
                            out[1] = at(0, k) + 2.0 * (at(1, k) - at(0, k)) / 3.0;
                            out[2] = at(2, k) + 2.0 * (at(1, k) - at(2, k)) / 3.0;
                            out[3] = at(2, k);
                        } else {
                            for (int i = 0; i < 4; ++i) out[i] = at(i, k);
                        }
                    }
                    w << " ";
                    for (int i = 0; i < 4; ++i) {
                        w << " <";
                        w.num(x[i]) << ", ";
                        w.num(z[i]) << ">";
                    }
                    w << '\n';
                }
            }
            if (e.open) w << "  open\n";
            if (e.sturm) w << "  sturm\n";
        }
        // A mesh's face as the triangle it is (a mesh is written face by face).
        void operator()(const TriangleShape& t) const {
            const TriangleMesh& mesh = *t.mesh;
            const TriangleMesh::Face& f = mesh.faces[t.face];
            w << (f.smooth ? "smooth_triangle {\n  " : "triangle {\n  ");
            for (int i = 0; i < 3; ++i) {
                if (i > 0) w << ", ";
                w.vec(mesh.vertices[f.vertex[i]]);
                if (f.smooth) {
                    w << ", ";
                    w.vec(mesh.normals[f.normal[i]]);
                }
            }
            w << '\n';
        }
    };
    std::visit(Visitor{w}, shape);
}

void writeTexture(Writer& w, const Texture& t);

// An object's statement: its shape, transform, texture and modifiers
// (`inverse` for a CSG's member).
// A clip's shape: it has no texture or modifiers of its own.
void writeClipShape(Writer& w, const Shape& shape, const Transform& worldFromObject, bool inverse) {
    writeShape(w, shape);
    if (!worldFromObject.isIdentity()) {
        w << "  ";
        w.matrix(worldFromObject) << '\n';
    }
    if (inverse) w << "  inverse\n";
    w << "}\n";
}

void writeObject(Writer& w, const Shape& shape, const Transform& worldFromObject, const Object& o, bool inverse) {
    w.location(o.loc);
    writeShape(w, shape);
    if (!worldFromObject.isIdentity()) {
        w << "  ";
        w.matrix(worldFromObject) << '\n';
    }
    writeTexture(w, o.texture ? *o.texture : Texture{});
    if (o.interior && !(*o.interior == Interior{})) {
        const Interior& in = *o.interior;
        w << "  interior {\n    ior ";
        w.num(in.ior) << '\n';
        if (in.caustics != 0.0) (w << "    caustics ").num(in.caustics) << '\n';
        if (in.dispersion != 1.0) (w << "    dispersion ").num(in.dispersion) << '\n';
        if (in.dispersionSamples != 7) (w << "    dispersion_samples ").num(in.dispersionSamples) << '\n';
        if (in.fadeDistance != 0.0) (w << "    fade_distance ").num(in.fadeDistance) << '\n';
        if (in.fadePower != 0.0) (w << "    fade_power ").num(in.fadePower) << '\n';
        if (in.fadeColor != Vec3(0.0)) (w << "    fade_color ").rgb(in.fadeColor) << '\n';
        w << "  }\n";
    }
    if (o.noShadow) w << "  no_shadow\n";
    w.asos(o.asos, "  ");
    if (inverse) w << "  inverse\n";
    w << "}\n";
}

// A CSG's node and its members; `leaves` are the Objects of the tree's
// leaves but its clips', in leaf order (their textures and modifiers), the
// next one at `next`. A node's clip members are written as its clipped_by
// (a clip is always a member of an intersection, which means the same).
void writeCsg(Writer& w, const CsgTree& tree, std::uint32_t index, const Object* leaves, std::size_t& next) {
    const CsgTree::Node& node = tree.nodes[index];
    if (node.op == CsgTree::Op::Leaf) {
        const CsgTree::Leaf& leaf = tree.leaves[node.leaf];
        if (node.clip)
            writeClipShape(w, leaf.shape, leaf.worldFromObject, node.inverse);
        else
            writeObject(w, leaf.shape, leaf.worldFromObject, leaves[next++], node.inverse);
        return;
    }
    static constexpr const char* kOps[] = {"union", "merge", "intersection", "difference"};
    w << kOps[static_cast<int>(node.op)] << " {\n";
    bool clips = false;
    for (std::uint32_t child : node.children) {
        if (tree.nodes[child].clip && !node.clip) {
            clips = true;
            continue;
        }
        writeCsg(w, tree, child, leaves, next);
    }
    if (clips) {
        w << "clipped_by {\n";
        for (std::uint32_t child : node.children)
            if (tree.nodes[child].clip) writeCsg(w, tree, child, leaves, next);
        w << "}\n";
    }
    if (node.inverse) w << "  inverse\n";
    w << "}\n";
}

// A map pattern's name (and gradient's vector, agate's agate_turb,
// crackle's form, metric, offset and solid).
void writeMapPatternName(Writer& w, const Pigment& p) {
    switch (p.kind) {
        case Pigment::Kind::Solid: case Pigment::Kind::Checker: case Pigment::Kind::Brick: break;
        case Pigment::Kind::Gradient:
            w << "gradient ";
            w.vec(p.gradient);
            break;
        case Pigment::Kind::Radial: w << "radial"; break;
        case Pigment::Kind::Onion: w << "onion"; break;
        case Pigment::Kind::Marble: w << "marble"; break;
        case Pigment::Kind::Wood: w << "wood"; break;
        case Pigment::Kind::Leopard: w << "leopard"; break;
        case Pigment::Kind::Bozo: w << "bozo"; break;
        case Pigment::Kind::Spotted: w << "spotted"; break;
        case Pigment::Kind::Granite: w << "granite"; break;
        case Pigment::Kind::Bumps: w << "bumps"; break;
        case Pigment::Kind::Dents: w << "dents"; break;
        case Pigment::Kind::Wrinkles: w << "wrinkles"; break;
        case Pigment::Kind::Ripples: w << "ripples"; break;
        case Pigment::Kind::Waves: w << "waves"; break;
        case Pigment::Kind::Agate:
            w << "agate agate_turb ";
            w.num(p.agateTurb);
            break;
        case Pigment::Kind::Crackle:
            w << "crackle form ";
            w.vec(p.crackleForm) << " metric ";
            w.num(p.crackleMetric) << " offset ";
            w.num(p.crackleOffset);
            if (p.crackleSolid) w << " solid";
            break;
        case Pigment::Kind::Function: {
            const std::string xyz[] = {"x", "y", "z"};
            w << "function { " << functionText(*p.function, xyz) << " }";
            break;
        }
        case Pigment::Kind::Average: w << "average"; break;
    }
}

// The map patterns' modifiers, all of them (a normal's pattern too).
void writeMapModifiers(Writer& w, const Pigment& p) {
    if (p.turbulence != Vec3(0.0)) {
        w << " turbulence ";
        w.vec(p.turbulence);
    }
    w << " octaves " << p.octaves << " omega ";
    w.num(p.omega) << " lambda ";
    w.num(p.lambda) << " frequency ";
    w.num(p.frequency) << " phase ";
    w.num(p.phase);
    w << (p.wave == Pigment::Wave::Ramp ? " ramp_wave" : p.wave == Pigment::Wave::Sine ? " sine_wave" : " triangle_wave");
    if (p.noiseGenerator != 0) w << " noise_generator " << p.noiseGenerator;
}

void writeNormal(Writer& w, const Normal& n) {
    w << "    normal { ";
    switch (n.kind) {
        case Normal::Kind::Bumps: w << "bumps"; break;
        case Normal::Kind::Dents: w << "dents"; break;
        case Normal::Kind::Wrinkles: w << "wrinkles"; break;
        case Normal::Kind::Ripples: w << "ripples"; break;
        case Normal::Kind::Waves: w << "waves"; break;
        case Normal::Kind::Pattern: writeMapPatternName(w, n.pattern); break;
    }
    w << " bump_size ";
    w.num(n.amount) << " accuracy ";
    w.num(n.accuracy);
    writeMapModifiers(w, n.pattern);
    if (!n.pattern.worldFromPattern.isIdentity()) {
        w << ' ';
        w.matrix(n.pattern.worldFromPattern);
    }
    w << " }\n";
}

void writePigmentBody(Writer& w, const Pigment& p);

// checker's and brick's two colours, or their two pigments.
void writePatternItems(Writer& w, const Pigment& p) {
    if (!p.pigmentMap) {
        w.colour(p.color1) << ", ";
        w.colour(p.color2);
        return;
    }
    for (std::size_t i = 0; i < p.pigmentMap->size(); ++i) {
        w << (i > 0 ? " pigment { " : "pigment { ");
        writePigmentBody(w, *(*p.pigmentMap)[i].pigment);
        w << " }";
    }
}

// What a pigment { … } holds (a pigment_map's entry holds it too).
void writePigmentBody(Writer& w, const Pigment& p) {
    switch (p.kind) {
        case Pigment::Kind::Solid:
            w.colour(p.color1);
            break;
        case Pigment::Kind::Checker:
            w << "checker ";
            writePatternItems(w, p);
            break;
        case Pigment::Kind::Brick:
            w << "brick ";
            writePatternItems(w, p);
            w << " brick_size ";
            w.vec(p.brickSize) << " mortar ";
            w.num(p.mortar);
            break;
        default: writeMapPatternName(w, p); break;
    }
    if (p.kind != Pigment::Kind::Solid && p.kind != Pigment::Kind::Checker && p.kind != Pigment::Kind::Brick) {
        if (p.pigmentMap) {
            w << " pigment_map {";
            for (const PigmentMapEntry& e : *p.pigmentMap) {
                w << " [";
                w.num(e.value) << ' ';
                writePigmentBody(w, *e.pigment);
                w << ']';
            }
            w << " }";
        } else if (!p.colourMap.empty()) {
            w << " color_map {";
            for (const ColourMapEntry& e : p.colourMap) {
                w << " [";
                w.num(e.value) << ' ';
                w.colour(e.color) << ']';
            }
            w << " }";
        }
        writeMapModifiers(w, p);
    }
    if (!p.worldFromPattern.isIdentity()) {
        w << ' ';
        w.matrix(p.worldFromPattern);
    }
}

// pigment { … }, without a line end.
void writePigment(Writer& w, const Pigment& p) {
    w << "pigment { ";
    writePigmentBody(w, p);
    w << " }";
}

void writeLayer(Writer& w, const TextureLayer& t) {
    w << "  texture {\n    ";
    writePigment(w, t.pigment);
    w << '\n';
    if (t.normal) writeNormal(w, *t.normal);
    const Finish& f = t.finish;
    w << "    finish { ambient ";
    w.rgb(f.ambient) << " diffuse ";
    w.num(f.diffuse) << " brilliance ";
    w.num(f.brilliance) << " phong ";
    w.num(f.phong) << " phong_size ";
    w.num(f.phongSize) << " specular ";
    w.num(f.specular) << " roughness ";
    w.num(f.roughness);
    const Finish plain;
    const Vec3 head = f.reflectionMin.value_or(f.reflection);
    if (head == f.reflection && !f.fresnel && f.reflectionFalloff == plain.reflectionFalloff &&
        f.reflectionExponent == plain.reflectionExponent && f.reflectionMetallic == plain.reflectionMetallic) {
        w << " reflection ";
        w.rgb(f.reflection);
    } else {
        w << " reflection { ";
        w.rgb(head) << ", ";
        w.rgb(f.reflection);
        if (f.fresnel) w << " fresnel";
        if (f.reflectionFalloff != plain.reflectionFalloff) {
            w << " falloff ";
            w.num(f.reflectionFalloff);
        }
        if (f.reflectionExponent != plain.reflectionExponent) {
            w << " exponent ";
            w.num(1.0 / f.reflectionExponent);
        }
        if (f.reflectionMetallic != plain.reflectionMetallic) {
            w << " metallic ";
            w.num(f.reflectionMetallic);
        }
        w << " }";
    }
    if (f.metallic != 0.0) {
        w << " metallic ";
        w.num(f.metallic);
    }
    if (f.conserveEnergy) w << " conserve_energy";
    if (f.crand != 0.0) {
        w << " crand ";
        w.num(f.crand);
    }
    w << " }\n  }\n";
}

// A layered texture as POV-Ray layers textures on an object: each one
// written goes over those before it.
void writeTexture(Writer& w, const Texture& t) {
    writeLayer(w, t);
    for (const TextureLayer& layer : t.above) writeLayer(w, layer);
}

}  // namespace

void writeDump(std::ostream& out, const SceneDescription& scene, const DumpOptions& options) {
    Writer w(out, options);
    w << "// asos scene description: the canonical dump (a scene itself)\n#version ";
    w.num(scene.version) << ";\n\n";

    const GlobalSettings& g = scene.globals;
    w << "global_settings {\n";
    // No assumed_gamma and a version before 3.7 (written above) turn gamma
    // correction off, as they did in the scene.
    if (g.assumedGamma) {
        w << "  assumed_gamma ";
        w.num(*g.assumedGamma) << '\n';
    }
    w << "  max_trace_level " << g.maxTraceLevel << "\n  ambient_light ";
    w.rgb(g.ambientLight) << '\n';
    if (g.noiseGenerator != GlobalSettings{}.noiseGenerator) w << "  noise_generator " << g.noiseGenerator << '\n';
    w.asos(g.asos, "  ");
    w << "}\n\nbackground { ";
    w.colour(scene.background) << " }\n\n";
    if (const std::optional<SkySphere>& sky = scene.skySphere) {
        w.location(sky->loc);
        w << "sky_sphere {\n";
        for (const Pigment& p : sky->pigments) {
            w << "  ";
            writePigment(w, p);
            w << '\n';
        }
        if (sky->emission != Vec3(1.0)) {
            w << "  emission ";
            w.rgb(sky->emission) << '\n';
        }
        if (!sky->worldFromSky.isIdentity()) {
            w << "  ";
            w.matrix(sky->worldFromSky) << '\n';
        }
        w << "}\n\n";
    }
    for (const Fog& f : scene.fogs) {
        w.location(f.loc);
        w << "fog {\n  fog_type " << f.type << "\n  distance ";
        w.num(f.distance) << "\n  ";
        w.colour(f.color) << "\n  up ";
        w.vec(f.up) << '\n';
        if (f.type == 2) {
            w << "  fog_offset ";
            w.num(f.offset) << "\n  fog_alt ";
            w.num(f.alt) << '\n';
        }
        if (f.turbulent) {
            w << "  turbulence ";
            w.vec(f.turbulence) << " octaves " << f.octaves << " omega ";
            w.num(f.omega) << " lambda ";
            w.num(f.lambda) << " turb_depth ";
            w.num(f.turbDepth) << '\n';
        }
        w << "}\n\n";
    }

    const Camera& c = scene.camera;
    w.location(c.loc);
    w << "camera {\n  " << (c.projection == Camera::Projection::Orthographic ? "orthographic" : "perspective")
      << "\n  location ";
    w.vec(c.location) << "\n  direction ";
    w.vec(c.direction) << "\n  right ";
    w.vec(c.right) << "\n  up ";
    w.vec(c.up) << "\n}\n";

    for (const Light& l : scene.lights) {
        w << '\n';
        w.location(l.loc);
        w << "light_source {\n  ";
        w.vec(l.position) << ", ";
        w.rgb(l.color) << '\n';
        if (l.area) {
            const AreaLight& a = *l.area;
            w << "  area_light ";
            w.vec(a.axis1) << ", ";
            w.vec(a.axis2) << ", " << a.size1 << ", " << a.size2 << '\n';
            if (a.adaptive) w << "  adaptive " << *a.adaptive << '\n';
            if (a.jitter) w << "  jitter\n";
            if (a.circular) w << "  circular\n";
            if (a.orient) w << "  orient\n";
        }
        if (l.type != LightType::Point) {
            w << (l.type == LightType::Spot ? "  spotlight\n" : "  cylinder\n");
            (w << "  radius ").num(l.radius) << '\n';
            (w << "  falloff ").num(l.falloff) << '\n';
            (w << "  tightness ").num(l.tightness) << '\n';
        }
        if (l.parallel && l.type != LightType::Cylinder) w << "  parallel\n";
        if (l.type != LightType::Point || l.parallel) {
            w << "  point_at ";
            w.vec(l.pointAt) << '\n';
        }
        if (l.fadeDistance > 0) {
            w << "  fade_distance ";
            w.num(l.fadeDistance) << '\n';
        }
        if (l.fadePower != 0) {
            w << "  fade_power ";
            w.num(l.fadePower) << '\n';
        }
        if (l.shadowless) w << "  shadowless\n";
        if (l.areaIllumination) w << "  area_illumination on\n";
        w.asos(l.asos, "  ");
        w << "}\n";
    }

    const CsgTree* lastTree = nullptr;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const auto* csg = std::get_if<CsgShape>(&o.shape);
        // A CSG's tree once, at its first leaf; the leaves' Objects follow
        // it in leaf order.
        if (csg && csg->tree.get() == lastTree) continue;
        lastTree = csg ? csg->tree.get() : nullptr;
        w << '\n';
        std::size_t next = 0;
        if (csg)
            writeCsg(w, *csg->tree, 0, &o, next);
        else
            writeObject(w, o.shape, o.worldFromObject, o, false);
    }
}

std::string dumpScene(const SceneDescription& scene, const DumpOptions& options) {
    std::ostringstream out;
    writeDump(out, scene, options);
    return std::move(out).str();
}

}  // namespace asos
