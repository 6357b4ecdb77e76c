#include "asos/render/mesh_cover.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace asos {

bool segmentMissesCone(const PreparedCone& cone, const Vec3& p, const Vec3& q) {
    const Vec3 a = p - cone.apex, b = q - cone.apex;
    const double da = glm::dot(a, cone.axis), db = glm::dot(b, cone.axis);
    // An end at or behind the apex: not worth the clipping, say it may meet.
    if (!(da > 0.0) || !(db > 0.0) || !cone.valid) return false;
    const Vec3 pa = a / da - cone.axis, pb = b / db - cone.axis;  // images at unit depth
    const Vec3 d = pb - pa;
    const double dd = glm::dot(d, d);
    const double s = dd > 0.0 ? std::clamp(-glm::dot(pa, d) / dd, 0.0, 1.0) : 0.0;
    const double distance = glm::length(pa + s * d);
    const double radius = cone.sinHalf / cone.cosHalf;
    return distance > radius * (1.0 + 1e-9) + 1e-12;
}

MeshCover::MeshCover(const SceneDescription& scene, std::vector<std::uint8_t> coverable)
    : coverable_(std::move(coverable)), meshOf_(scene.objects.size(), kNone) {
    std::unordered_map<const TriangleMesh*, std::uint32_t> index;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const auto* face = std::get_if<TriangleShape>(&scene.objects[i].shape);
        if (!face || !coverable_[i] || face->mesh->faces.size() < 2) continue;
        const auto [it, fresh] = index.try_emplace(face->mesh.get(), std::uint32_t(meshes_.size()));
        if (fresh) meshes_.push_back({face->mesh.get(), {}});
        meshOf_[i] = it->second;
    }
    // Each edge as (lower vertex, higher vertex, face, edge), sorted: the
    // faces of an edge are neighbours in the list.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint8_t>> edges;
    for (Mesh& m : meshes_) {
        const auto& faces = m.mesh->faces;
        m.across.assign(faces.size(), {kNone, kNone, kNone});
        edges.clear();
        for (std::uint32_t f = 0; f < faces.size(); ++f)
            for (std::uint8_t k = 0; k < 3; ++k) {
                const std::uint32_t u = faces[f].vertex[k], v = faces[f].vertex[(k + 1) % 3];
                if (u != v) edges.emplace_back(std::min(u, v), std::max(u, v), f, k);
            }
        std::sort(edges.begin(), edges.end());
        for (std::size_t i = 0; i < edges.size();) {
            std::size_t j = i + 1;
            while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
                   std::get<1>(edges[j]) == std::get<1>(edges[i]))
                ++j;
            if (j == i + 2) {  // a manifold edge: exactly two faces
                const auto& [u0, v0, f0, k0] = edges[i];
                const auto& [u1, v1, f1, k1] = edges[i + 1];
                if (f0 != f1) {
                    m.across[f0][k0] = f1;
                    m.across[f1][k1] = f0;
                }
            }
            i = j;
        }
    }
}

namespace {

// A face of the sheet's mesh, in world space.
struct WorldFace {
    std::array<Vec3, 3> v;
    Vec3 normal;  // unit, of the plane, turned toward the apex
    bool seen = false;  // the apex is clearly off its plane
};

WorldFace worldFace(const Object& object, const TriangleMesh& mesh, const TriangleMesh::Face& face,
                    const Vec3& apex, int& side) {
    WorldFace w;
    for (int k = 0; k < 3; ++k) w.v[k] = object.worldFromObject.point(mesh.vertices[face.vertex[k]]);
    const Vec3 n = glm::cross(w.v[1] - w.v[0], w.v[2] - w.v[0]);
    const double len = glm::length(n);
    const Vec3 toApex = apex - w.v[0];
    const double d = len > 0.0 ? glm::dot(n / len, toApex) : 0.0;
    w.seen = std::abs(d) > 1e-9 * glm::length(toApex) && len > 0.0;
    side = d > 0.0 ? 1 : -1;
    w.normal = w.seen ? (d > 0.0 ? n / len : -n / len) : Vec3(0.0);
    return w;
}

// The shading normal of a face at its corner k, turned as the face's plane
// normal is toward the apex.
Vec3 shadingNormal(const Object& object, const TriangleMesh& mesh, const TriangleMesh::Face& face,
                   const WorldFace& w, int k) {
    if (!face.smooth) return w.normal;
    Vec3 n = object.worldFromObject.normal(mesh.normals[face.normal[k]]);
    const double len = glm::length(n);
    if (!(len > 0.0)) return w.normal;
    n /= len;
    return glm::dot(n, w.normal) < 0.0 ? -n : n;
}

}  // namespace

std::optional<MeshSheet> MeshCover::cover(const SceneDescription& scene, const PreparedCone& cone,
                                          const std::vector<MeshCandidate>& candidates) const {
    if (meshes_.empty() || !cone.valid) return std::nullopt;
    // The seed: the nearest candidate that is a coverable mesh face.
    std::size_t seed = candidates.size();
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (meshOf_[candidates[i].object] != kNone &&
            (seed == candidates.size() || candidates[i].tNear < candidates[seed].tNear))
            seed = i;
    if (seed == candidates.size()) return std::nullopt;
    const Object& seedObject = scene.objects[candidates[seed].object];
    const std::uint32_t meshIndex = meshOf_[candidates[seed].object];
    const Mesh& m = meshes_[meshIndex];
    const TriangleMesh& mesh = *m.mesh;
    // The candidates that are faces of the same mesh, placed and textured
    // alike, by face.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> faces;  // (face, candidate)
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const std::uint32_t object = candidates[i].object;
        if (meshOf_[object] != meshIndex) continue;
        const Object& o = scene.objects[object];
        if (o.texture != seedObject.texture ||
            o.worldFromObject.matrix() != seedObject.worldFromObject.matrix())
            continue;
        faces.emplace_back(std::get<TriangleShape>(o.shape).face, std::uint32_t(i));
    }
    std::sort(faces.begin(), faces.end());
    const auto candidateOf = [&](std::uint32_t face) -> std::uint32_t {
        const auto it = std::lower_bound(faces.begin(), faces.end(), std::make_pair(face, 0u));
        return it != faces.end() && it->first == face ? it->second : kNone;
    };

    MeshSheet sheet;
    sheet.member.assign(candidates.size(), 0);
    std::vector<std::uint32_t> queue{std::get<TriangleShape>(seedObject.shape).face};
    sheet.member[seed] = 1;
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const std::uint32_t f = queue[next];
        const TriangleMesh::Face& face = mesh.faces[f];
        int side = 0;
        const WorldFace w = worldFace(seedObject, mesh, face, cone.apex, side);
        if (!w.seen) return std::nullopt;  // seen edge on: its own silhouette
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t g = m.across[f][k];
            const std::uint32_t c = g == kNone ? kNone : candidateOf(g);
            bool inner = false;
            WorldFace wg;
            if (c != kNone) {
                // A manifold edge between two faces the cone may meet: inner
                // (no fold) when the apex sees both from the same side of the
                // surface, as the faces' windings orient it.
                int sideG = 0;
                wg = worldFace(seedObject, mesh, mesh.faces[g], cone.apex, sideG);
                const std::uint32_t u = face.vertex[k];
                int kg = 0;
                while (kg < 3 && mesh.faces[g].vertex[kg] != u) ++kg;
                const bool sameWay = kg < 3 && mesh.faces[g].vertex[(kg + 1) % 3] == face.vertex[(k + 1) % 3];
                inner = wg.seen && (sameWay ? sideG != side : sideG == side);
            }
            const Vec3& p = w.v[k];
            const Vec3& q = w.v[(k + 1) % 3];
            if (!inner) {
                // A boundary or silhouette edge, or one to a face the cone
                // misses: it must miss the cone.
                if (!segmentMissesCone(cone, p, q)) return std::nullopt;
                continue;
            }
            // A crease: how far the shading normal jumps across it.
            const TriangleMesh::Face& fg = mesh.faces[g];
            for (int e = 0; e < 2; ++e) {
                const int kf = (k + e) % 3;
                int kg = 0;
                while (kg < 3 && fg.vertex[kg] != face.vertex[kf]) ++kg;
                if (kg == 3) continue;
                const double jump = glm::length(shadingNormal(seedObject, mesh, face, w, kf) -
                                                shadingNormal(seedObject, mesh, fg, wg, kg));
                if (jump > sheet.normalJump && !segmentMissesCone(cone, p, q))
                    sheet.normalJump = std::max(sheet.normalJump, jump);
            }
            if (!sheet.member[c]) {
                sheet.member[c] = 1;
                queue.push_back(g);
            }
        }
    }
    sheet.tNear = kInfinity;
    sheet.tFar = -kInfinity;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (sheet.member[i]) {
            sheet.tNear = std::min(sheet.tNear, candidates[i].tNear);
            sheet.tFar = std::max(sheet.tFar, candidates[i].tFar);
        }
    // Everything else, the rest of the mesh included, wholly behind.
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (!sheet.member[i] && !(candidates[i].tNear > sheet.tFar)) return std::nullopt;
    return sheet;
}

}  // namespace asos
