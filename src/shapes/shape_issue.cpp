#include "asos/shapes/shape_issue.hpp"

#include <cmath>

#include "asos/diag/format_number.hpp"

namespace asos {

std::string formatVector(const Vec3& v) {
    std::string out = "<";
    out += formatNumber(v.x);
    out += ", ";
    out += formatNumber(v.y);
    out += ", ";
    out += formatNumber(v.z);
    out += '>';
    return out;
}

bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool IssueList::finite(int argument, const Vec3& v, const char* what) {
    if (isFinite(v)) return true;
    add(argument, std::string(what) + " must be finite, not " + formatVector(v));
    return false;
}

bool IssueList::positive(int argument, double v, const char* what) {
    if (!(v > 0.0)) add(argument, std::string(what) + " must be positive, not " + formatNumber(v));
    else if (!std::isfinite(v)) add(argument, std::string(what) + " must be finite, not " + formatNumber(v));
    else return true;
    return false;
}

bool IssueList::notNegative(int argument, double v, const char* what) {
    if (v < 0.0) add(argument, std::string(what) + " must not be negative, not " + formatNumber(v));
    else if (!std::isfinite(v)) add(argument, std::string(what) + " must be finite, not " + formatNumber(v));
    else return true;
    return false;
}

}  // namespace asos
