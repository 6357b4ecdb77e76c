#include "asos/render/subdivision_criterion.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

SubdivisionTally::Entry& SubdivisionTally::entry(std::uint32_t object, std::uint8_t part, double weight) {
    for (Entry& e : entries_)
        if (e.object == object && e.part == part) return e;
    entries_.push_back({object, part, 0, 0, true, weight});
    return entries_.back();
}

double SubdivisionTally::changeBound(int level) const {
    // Area of one K-pyray: 1 / 2^(2K) of the pixel.
    return changeBoundForShare(std::ldexp(1.0, -2 * level));
}

double SubdivisionTally::changeBoundForShare(double area) const {
    double bound = 0.0;
    for (const Entry& e : entries_) {
        const double l = e.weight * std::max(e.in, e.out);
        bound += e.allSingleEdge ? 0.5 * l * area : l * area;
    }
    return bound;
}

double SubdivisionTally::leastChangeBoundForShare(double area) const {
    double bound = 0.0;
    for (const Entry& e : entries_) {
        const double l = e.weight * double((e.in + e.out + 1) / 2);
        bound += e.allSingleEdge ? 0.5 * l * area : l * area;
    }
    return bound;
}

}  // namespace asos
