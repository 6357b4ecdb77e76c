#pragma once
// The exact image of a flat scene, the physical limit of anti-aliasing that
// every method and the brute-force reference are checked against
// (docs/performance.md, "Exact coverage"). A flat scene holds only convex
// polygons and discs (no hole) in front of a perspective camera, each of one
// solid colour lit by ambient only (diffuse, phong, specular and reflection
// 0): a pixel's colour is then the sum over the shapes of colour times the
// area of the pixel square it sees, plus the background's share.
//
// In the image, a polygon projects to a convex polygon and a disc to an
// ellipse (its circle through the camera's homography). Per pixel the shapes
// are taken front to back by the depth of their planes along the pixel's
// centre ray; the part of the square not yet covered is kept as convex
// polygons less the ellipses in front: a polygon is subtracted by clipping
// (convex pieces), an ellipse's area in a convex polygon is the unit disc's
// in its image under the affine map that makes the ellipse a circle, in
// closed form (a sum over edges of circle-triangle areas). So that the sum
// stays exact, the scene must have no two discs overlapping in one pixel,
// and shapes overlapping in a pixel must keep one depth order over it
// (flat shapes that do not interpenetrate, their planes not crossing there).
#include <optional>
#include <vector>

#include "asos/geometry/vec.hpp"
#include "asos/image/image.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// An ellipse in the image: the points x with |toUnit (x - centre)| <= 1.
struct ImageEllipse {
    Vec2 centre{0.0};
    glm::dmat2 toUnit{1.0};
};

// A shape in image coordinates: a convex polygon (either orientation), or an
// ellipse, and its colour.
struct ImageShape {
    std::vector<Vec2> polygon;
    std::optional<ImageEllipse> ellipse;
    Vec3 color{0.0};
};

// The area of a convex polygon (either orientation; 0 below 3 points).
double convexArea(const std::vector<Vec2>& polygon);

// The area of the ellipse inside a convex polygon, in closed form.
double ellipseAreaIn(const ImageEllipse& ellipse, const std::vector<Vec2>& polygon);

// The area each shape shows of the convex `region` (a pixel's square), the
// shapes given front to back, and last the area none covers. Throws
// std::invalid_argument when two ellipses both cover part of the region.
std::vector<double> visibleAreas(const std::vector<ImageShape>& frontToBack, const std::vector<Vec2>& region);

// The exact linear image of a flat scene at width x height. Throws
// std::invalid_argument naming the first thing that makes it not flat.
Image exactCoverageImage(const SceneDescription& scene, int width, int height);

}  // namespace asos
