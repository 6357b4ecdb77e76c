#pragma once
// What is wrong with a shape's description record (a radius below zero, a
// cap on its base, a polygon off its plane), with the argument of the scene's
// statement that says it. Each shape checks its own record (its `validate`,
// beside it: sphere.hpp, ...); the interpreter reports every issue at the
// argument it names, and Primitive::make, which also takes records that did
// not come through the interpreter, throws the first.
#include <string>
#include <utility>
#include <vector>

#include "asos/geometry/vec.hpp"
#include "asos/scene/description.hpp"

namespace asos {

struct ShapeIssue {
    // The argument at fault, counted from 0 in the order POV-Ray writes the
    // statement's arguments (sphere { centre, radius }: the radius is 1).
    int argument = 0;
    // For a list argument (a polygon's points, argument 1 after its count),
    // the place of the item at fault in the list; -1 for the whole argument.
    int element = -1;
    std::string message;
};

// Every issue of the record, in the order its shape checks them (its
// validate, found by the record's type as Primitive::make finds it).
std::vector<ShapeIssue> shapeIssues(const Shape& record);

// A record's issues as its shape's validate finds them. Each check adds an
// issue about `argument` when the value fails it (the message names the
// value by `what`: "the radius of a sphere") and says whether it passed.
class IssueList {
public:
    bool finite(int argument, const Vec3& v, const char* what);
    bool positive(int argument, double v, const char* what);     // > 0 and finite
    bool notNegative(int argument, double v, const char* what);  // >= 0 and finite
    void add(int argument, std::string message, int element = -1) {
        issues_.push_back({argument, element, std::move(message)});
    }
    bool empty() const { return issues_.empty(); }
    std::vector<ShapeIssue> take() { return std::move(issues_); }

private:
    std::vector<ShapeIssue> issues_;
};

// A vector as the scene writes it, "<x, y, z>".
std::string formatVector(const Vec3& v);
bool isFinite(const Vec3& v);

}  // namespace asos
