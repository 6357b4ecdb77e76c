#pragma once
// The Pareto front of a benchmark's (cost, error) points: the settings worth
// choosing, those no other setting beats on both (`asos-bench accuracy`).
#include <vector>

namespace asos {

// For each point, whether it is on the front: no other point has cost and
// error both no larger and one of them smaller. Equal points are all kept.
// Throws std::invalid_argument when the lists differ in length.
std::vector<bool> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

}  // namespace asos
