// A description record to its Primitive, through the record's shape: its
// validate and its place (beside each shape), found by the record's type.
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "asos/geometry/frame.hpp"
#include "asos/shapes/csg_clip.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

static_assert(kEveryAlternativeShapeRecord<Shape>,
              "every description record answers ShapeRecord (primitive_shape.hpp)");

std::vector<ShapeIssue> shapeIssues(const Shape& record) {
    return std::visit([](const auto& r) { return validate(r); }, record);
}

template <class S>
Primitive Primitive::fromPlaced(Placed<S>&& placed) {
    return Primitive(std::move(placed.shape), placed.frame, placed.keyword);
}

template <class... S>
Primitive Primitive::fromPlaced(std::variant<Placed<S>...>&& placed) {
    return std::visit([](auto&& one) { return fromPlaced(std::move(one)); }, std::move(placed));
}

Primitive Primitive::make(const Shape& shape, const Transform& worldFromObject) {
    CsgSolidCache solids;
    return make(shape, worldFromObject, solids);
}

Primitive Primitive::make(const Shape& shape, const Transform& worldFromObject, CsgSolidCache& solids) {
    return std::visit(
        [&]<class R>(const R& record) {
            if constexpr (std::is_same_v<R, CsgShape>) {
                return makeCsgLeaf(record, worldFromObject, solids);
            } else {
                std::vector<ShapeIssue> issues = validate(record);
                if (!issues.empty()) throw std::invalid_argument(std::move(issues.front().message));
                return fromPlaced(place(record, worldFromObject));
            }
        },
        shape);
}

}  // namespace asos
