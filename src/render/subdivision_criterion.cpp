#include "asos/render/subdivision_criterion.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

SubdivisionTally::Entry& SubdivisionTally::entry(std::uint32_t object) {
    for (Entry& e : entries_)
        if (e.object == object) return e;
    entries_.push_back({object, 0, 0, true});
    return entries_.back();
}

double SubdivisionTally::changeBound(int level) const {
    // Area of one K-pyray: 1 / 2^(2K) of the pixel.
    return changeBoundForShare(std::ldexp(1.0, -2 * level));
}

double SubdivisionTally::changeBoundForShare(double area) const {
    double bound = 0.0;
    for (const Entry& e : entries_) {
        const double l = std::max(e.in, e.out);
        bound += e.allSingleEdge ? 0.5 * l * area : l * area;
    }
    return bound;
}

double SubdivisionTally::leastChangeBoundForShare(double area) const {
    double bound = 0.0;
    for (const Entry& e : entries_) {
        const double l = double((e.in + e.out + 1) / 2);
        bound += e.allSingleEdge ? 0.5 * l * area : l * area;
    }
    return bound;
}

}  // namespace asos
