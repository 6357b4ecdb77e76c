#include "asos/shapes/truncated_cone.hpp"

namespace asos {

std::vector<ShapeIssue> validate(const ConeShape& record) {
    IssueList issues;
    const bool baseFinite = issues.finite(0, record.base, "the base point of a cone");
    issues.notNegative(1, record.baseRadius, "the base radius of a cone");
    const bool capFinite = issues.finite(2, record.cap, "the cap point of a cone");
    issues.notNegative(3, record.capRadius, "the cap radius of a cone");
    if (record.baseRadius == 0.0 && record.capRadius == 0.0) issues.add(3, "a cone needs a radius that is not zero");
    if (baseFinite && capFinite && !frustumAxis(record.base, record.cap))
        issues.add(2, "the base and cap points of a cone are the same point");
    return issues.take();
}

std::variant<Placed<TruncatedCone>, Placed<Cylinder>> place(const ConeShape& record,
                                                            const Transform& worldFromObject) {
    const FrustumAxis axis = *frustumAxis(record.base, record.cap);
    const LocalFrame frame = LocalFrame::make(worldFromObject, axis.objectFromLocal, record.base);
    if (record.baseRadius == record.capRadius)  // as POV-Ray: really a cylinder
        return Placed<Cylinder>{Cylinder(record.baseRadius, axis.length, record.open), frame, TruncatedCone::kName};
    return Placed<TruncatedCone>{TruncatedCone(record.baseRadius, record.capRadius, axis.length, record.open), frame,
                                 TruncatedCone::kName};
}

}  // namespace asos
