#pragma once
// The pieces of a disc light's disc (a sphere light's apparent disc, POV-Ray's
// oriented disc): the images of the quadtree's cells of the unit square
// under the light's map (geometry/concentric_disc.hpp). Their layout does not
// depend on the point, so the first levels are made once per map
// (discPieceTable()), with their central points and the cosines and sines of
// their polar bounds' angles; deeper pieces are made as they are needed.
#include <cstdint>
#include <vector>

#include "asos/geometry/concentric_disc.hpp"

namespace asos {

class DiscPieceTable {
public:
    struct Trig {
        double c, s;
    };
    struct Piece {
        DiscCell cell;
        Vec2 centre;       // the image of the cell's centre on the unit disc,
        double rho2, rim;  // its |centre|^2 and sqrt(1 - |centre|^2)
        double r0, r1;     // the polar rectangle holding the image: radii,
        Trig at0, at1;     // and its angles' cosines and sines
    };
    static Piece piece(const DiscCell& cell, DiscMap map);

    static constexpr int kLevels = 5;  // 1365 pieces
    explicit DiscPieceTable(DiscMap map);
    // The four children of piece `path` at `level`, or null past the table.
    const Piece* children(int level, std::uint64_t path) const {
        if (level + 1 > kLevels) return nullptr;
        return &pieces_[(((std::size_t(1) << (2 * (level + 1))) - 1) / 3) + 4 * path];
    }

private:
    std::vector<Piece> pieces_;  // level by level, each level in path order
};

// The one table of each map, made on first use and constant after.
const DiscPieceTable& discPieceTable(DiscMap map);

}  // namespace asos
