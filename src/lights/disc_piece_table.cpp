#include "asos/lights/disc_piece_table.hpp"

#include <cmath>

#include "asos/geometry/tangent_cone.hpp"

namespace asos {

DiscPieceTable::Piece DiscPieceTable::piece(const DiscCell& cell, DiscMap map) {
    const PolarBounds b = polarBounds(cell, map);
    const Vec2 centre = discPoint(map, 0.5 * (cell.s0 + cell.s1), 0.5 * (cell.t0 + cell.t1));
    const TangentCone::Radial radial = TangentCone::radial(centre);
    return {cell,
            centre,
            radial.rho2,
            radial.rim,
            b.r0,
            b.r1,
            {std::cos(b.phi0), std::sin(b.phi0)},
            {std::cos(b.phi1), std::sin(b.phi1)}};
}

DiscPieceTable::DiscPieceTable(DiscMap map) {
    pieces_.push_back(piece(DiscCell{}, map));
    for (int level = 0; level < kLevels; ++level) {
        const std::size_t first = ((std::size_t(1) << (2 * level)) - 1) / 3;
        const std::size_t count = std::size_t(1) << (2 * level);
        for (std::size_t i = first; i < first + count; ++i) {
            const DiscCell c = pieces_[i].cell;
            const double s[3] = {c.s0, 0.5 * (c.s0 + c.s1), c.s1}, t[3] = {c.t0, 0.5 * (c.t0 + c.t1), c.t1};
            for (int q = 0; q < 4; ++q) {
                const int u = q & 1, v = q >> 1;
                pieces_.push_back(piece(DiscCell{s[u], s[u + 1], t[v], t[v + 1]}, map));
            }
        }
    }
}

const DiscPieceTable& discPieceTable(DiscMap map) {
    static const DiscPieceTable concentric(DiscMap::Concentric), povray(DiscMap::Povray);
    return map == DiscMap::Povray ? povray : concentric;
}

}  // namespace asos
