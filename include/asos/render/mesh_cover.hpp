#pragma once
// A pyray covered by the faces of one mesh (docs/algorithm.md, "Meshes"):
// each face of a mesh is its own object, and a cone over the edge between
// two faces is Marginal on both, so without this every pyray over a mesh's
// inner edge would be subdivided down to MAX. MeshCover sees that the faces
// a cone meets join into one sheet with no boundary and no silhouette edge
// inside the cone, in front of everything else the cone meets: the mesh is
// then Full for the cone, and the only edges left inside it are creases,
// where the shading normal jumps.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "asos/shapes/local_cone.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// One object the cone may meet, with the depths its classification gives.
struct MeshCandidate {
    std::uint32_t object = 0;
    double tNear = 0.0, tFar = 0.0;
};

// The sheet found: which candidates are its faces, its depths, and the
// largest jump of the shading normal across an edge of it that may meet the
// cone (0 where the faces meet smoothly or are coplanar).
struct MeshSheet {
    std::vector<std::uint8_t> member;  // per candidate
    double tNear = 0.0, tFar = 0.0;
    double normalJump = 0.0;
};

// Whether the segment pq surely misses the (widened) cone: both ends in
// front of its apex and the segment's image on the plane at unit depth
// farther than the cone's radius there from the axis.
bool segmentMissesCone(const PreparedCone& cone, const Vec3& p, const Vec3& q);

class MeshCover {
public:
    // The edges of every mesh of the scene; `coverable` says which objects
    // may join a sheet (the tracer's choice: opaque, unreflecting faces).
    MeshCover(const SceneDescription& scene, std::vector<std::uint8_t> coverable);

    // Whether any object may join a sheet.
    bool any() const { return !meshes_.empty(); }

    // The sheet of mesh faces among the candidates that covers the cone, seen
    // from its apex (a perspective eye), with every other candidate wholly
    // behind it; nothing where there is none. Conservative: a boundary or
    // silhouette edge of the mesh that may meet the cone, a face seen edge
    // on, or another object or part of the mesh whose depths overlap the
    // sheet's gives nothing. The sheet may still miss the cone altogether
    // (its faces' classes are conservative): the caller checks that the
    // cone's axis hits one of its faces.
    std::optional<MeshSheet> cover(const SceneDescription& scene, const PreparedCone& cone,
                                   const std::vector<MeshCandidate>& candidates) const;

private:
    struct Mesh {
        const TriangleMesh* mesh = nullptr;
        // Per face and edge (vertex k to k+1): the face across it, or kNone
        // for a boundary edge or one shared by more than two faces.
        std::vector<std::array<std::uint32_t, 3>> across;
    };
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<Mesh> meshes_;
    std::vector<std::uint8_t> coverable_;
    std::vector<std::uint32_t> meshOf_;  // per object: index in meshes_, or kNone
};

}  // namespace asos
