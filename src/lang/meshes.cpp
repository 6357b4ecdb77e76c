// POV-Ray's triangle, smooth_triangle, mesh and mesh2 as TriangleMesh faces
// (description.hpp): a mesh is one ObjectTree holding its faces, placed as
// one Object per face (flatten, placeCsg).
#include <cmath>
#include <string>

#include "asos/diag/format_number.hpp"
#include "asos/shapes/shape_issue.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

bool isTriangleBlock(const Node& n) {
    return n.kind == NodeKind::Block && (n.word == Word::Triangle || n.word == Word::SmoothTriangle);
}

// A corner's normal made unit, as POV-Ray keeps it (a zero one stays, for
// the shape's validate to refuse).
Vec3 unitNormal(const Vec3& v) {
    const double length = glm::length(v);
    // One already unit to rounding stays as written, so that a dumped scene
    // reads back the same.
    if (std::abs(length - 1.0) <= 4e-16) return v;
    return length > 0.0 && std::isfinite(length) ? v / length : v;
}

}  // namespace

void Interpreter::addTriangle(TriangleMesh& mesh, const Node& block) {
    const auto args = block.children();
    TriangleMesh::Face face;
    face.smooth = block.word == Word::SmoothTriangle;
    const auto vertices = static_cast<std::uint32_t>(mesh.vertices.size());
    const auto normals = static_cast<std::uint32_t>(mesh.normals.size());
    for (std::uint32_t i = 0; i < 3; ++i) {
        face.vertex[i] = vertices + i;
        mesh.vertices.push_back(evalVector(args[face.smooth ? 2 * i : i]));
        if (!face.smooth) continue;
        face.normal[i] = normals + i;
        mesh.normals.push_back(unitNormal(evalVector(args[2 * i + 1])));
    }
    mesh.faces.push_back(face);
}

void Interpreter::evalMesh(const Node& block, ObjectTree& t) {
    auto mesh = std::make_shared<TriangleMesh>();
    std::size_t degenerate = 0;
    const Node* firstDegenerate = nullptr;
    auto entry = [&](const Node& n) {
        if (!isTriangleBlock(n)) {
            t.modified = true;
            applyObjectModifier(t, n, true);
            return;
        }
        if (t.modified) fail(n, "the triangles of a mesh come before its modifiers");
        if (n.count > n.flags)
            fail(n.children()[n.flags], "a mesh's triangles take no modifiers (a texture for each triangle is not "
                                        "supported by asos)");
        addTriangle(*mesh, n);
        // POV-Ray leaves a degenerate triangle of a mesh out.
        if (!shapeIssues(TriangleShape{mesh, static_cast<std::uint32_t>(mesh->faces.size() - 1)}).empty()) {
            mesh->faces.pop_back();
            if (degenerate++ == 0) firstDegenerate = &n;
        }
        checkObjects(n, mesh->faces.size(), "this mesh");
    };
    const std::size_t errorsBefore = errorCount_;
    runEntries(block.children(), EntryHandler(entry));
    if (errorCount_ != errorsBefore) throw Abandon{};  // reported at the entry
    if (degenerate > 0)
        diagnostics_.warning(locOf(*firstDegenerate), std::to_string(degenerate) +
                                                          " degenerate triangle(s) of this mesh left out, as POV-Ray does");
    if (mesh->faces.empty()) fail(block, "a mesh needs at least one triangle that is not degenerate");
    t.mesh = std::move(mesh);
    t.leaves = t.mesh->faces.size();
}

void Interpreter::evalMesh2(const Node& block, ObjectTree& t) {
    auto mesh = std::make_shared<TriangleMesh>();
    // Each list: its count, then its entries (as many), each handed to `each`.
    auto list = [&](const Node& l, auto&& each) {
        const double count = evalFloat(l[0]);
        std::size_t seen = 0;
        auto entry = [&](const Node& n) {
            ++seen;
            each(n);
        };
        runEntries(l.children().subspan(l.flags), EntryHandler(entry));
        if (count != std::floor(count) || count < 0 || static_cast<double>(seen) != count)
            fail(l[0], std::string(wordText(l.word)) + " announces " + formatNumber(count) + " entries but lists " +
                           std::to_string(seen));
        return seen;
    };
    // An index triple <a, b, c> into a list of `size`.
    auto indices = [&](const Node& n, std::size_t size, const char* of) {
        const Vec3 v = evalVector(n);
        std::array<std::uint32_t, 3> out{};
        for (int i = 0; i < 3; ++i) {
            if (!(v[i] >= 0.0 && v[i] < static_cast<double>(size)) || v[i] != std::floor(v[i]))
                fail(n, "the index " + formatNumber(v[i]) + " is not one of the " + std::to_string(size) + " " + of);
            out[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(v[i]);
        }
        return out;
    };
    const Node* normalList = nullptr;
    std::size_t normalFaces = 0;
    const std::size_t errorsBefore = errorCount_;
    for (const Node& l : block.children().first(block.flags)) {
        switch (l.word) {
        case Word::VertexVectors:
            list(l, [&](const Node& n) { mesh->vertices.push_back(evalVector(n)); });
            break;
        case Word::NormalVectors:
            normalList = &l;
            list(l, [&](const Node& n) { mesh->normals.push_back(unitNormal(evalVector(n))); });
            break;
        case Word::FaceIndices:
            list(l, [&](const Node& n) {
                TriangleMesh::Face face;
                face.vertex = indices(n, mesh->vertices.size(), "vertex_vectors");
                mesh->faces.push_back(face);
                checkObjects(n, mesh->faces.size(), "this mesh2");
            });
            break;
        default:  // normal_indices, after the faces
            list(l, [&](const Node& n) {
                if (normalFaces == mesh->faces.size())
                    fail(n, "normal_indices lists more entries than the " + std::to_string(mesh->faces.size()) +
                                " faces");
                TriangleMesh::Face& face = mesh->faces[normalFaces++];
                face.normal = indices(n, mesh->normals.size(), "normal_vectors");
                face.smooth = true;
            });
            if (normalFaces != mesh->faces.size())
                fail(l[0], "normal_indices lists " + std::to_string(normalFaces) + " entries for the " +
                               std::to_string(mesh->faces.size()) + " faces");
            break;
        }
    }
    if (errorCount_ != errorsBefore) throw Abandon{};  // reported at the entry
    if (normalList && normalFaces == 0) {
        // POV-Ray: without normal_indices, the normals go with the vertices.
        if (mesh->normals.size() != mesh->vertices.size())
            fail((*normalList)[0], "without normal_indices, normal_vectors needs one normal per vertex (" +
                                       std::to_string(mesh->vertices.size()) + ")");
        for (TriangleMesh::Face& face : mesh->faces) {
            face.normal = face.vertex;
            face.smooth = true;
        }
    }
    // POV-Ray leaves a degenerate face out.
    std::size_t degenerate = 0;
    std::vector<TriangleMesh::Face> kept;
    kept.reserve(mesh->faces.size());
    for (std::uint32_t i = 0; i < mesh->faces.size(); ++i) {
        if (shapeIssues(TriangleShape{mesh, i}).empty()) kept.push_back(mesh->faces[i]);
        else ++degenerate;
    }
    mesh->faces = std::move(kept);
    if (degenerate > 0)
        diagnostics_.warning(locOf(block), std::to_string(degenerate) +
                                               " degenerate triangle(s) of this mesh2 left out, as POV-Ray does");
    if (mesh->faces.empty()) fail(block, "a mesh2 needs at least one triangle that is not degenerate");
    t.mesh = std::move(mesh);
    t.leaves = t.mesh->faces.size();
}

}  // namespace asos::lang
