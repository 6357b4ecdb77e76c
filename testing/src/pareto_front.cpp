#include "asos/testing/pareto_front.hpp"

#include <stdexcept>

namespace asos {

std::vector<bool> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
    if (cost.size() != error.size()) throw std::invalid_argument("paretoFront: as many costs as errors");
    // Quadratic, on purpose: ladders hold tens of points, and this reads as the definition.
    std::vector<bool> front(cost.size(), true);
    for (std::size_t i = 0; i < cost.size(); ++i)
        for (std::size_t k = 0; k < cost.size() && front[i]; ++k)
            if (cost[k] <= cost[i] && error[k] <= error[i] && (cost[k] < cost[i] || error[k] < error[i]))
                front[i] = false;
    return front;
}

}  // namespace asos
