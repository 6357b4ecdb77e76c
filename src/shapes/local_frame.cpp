#include "asos/shapes/local_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"

namespace asos {

namespace {

bool finite(const Mat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Eigenvalues of a symmetric 3x3 matrix by cyclic Jacobi rotations.
Vec3 symmetricEigenvalues(Mat3 a) {
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        // Converged once the off-diagonal is a few ulps of the diagonal (squared).
        if (off <= kFewUlps * kFewUlps * diag) break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0.0 ? 1.0 : -1.0) /
                                 (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                Mat3 j(1.0);
                j[p][p] = c;
                j[q][q] = c;
                j[q][p] = s;   // column q, row p
                j[p][q] = -s;  // column p, row q
                a = glm::transpose(j) * a * j;
            }
        }
    }
    return {a[0][0], a[1][1], a[2][2]};
}

}  // namespace

LocalFrame LocalFrame::make(const Transform& worldFromObject, const Mat3& objectFromLocal,
                            const Vec3& objectOffset) {
    LocalFrame f;
    f.objectFromLocal = objectFromLocal;
    f.objectOffset = objectOffset;
    const Mat4& m = worldFromObject.matrix();
    const Mat4& inv = worldFromObject.inverseMatrix();
    const Mat3 wo(m), ow(inv);
    // The placement is rigid: its inverse is its transpose.
    const Mat3 lo = glm::transpose(objectFromLocal);
    f.worldFromLocal = wo * objectFromLocal;
    f.worldOffset = wo * objectOffset + Vec3(m[3]);
    f.localFromWorld = lo * ow;
    f.localOffset = lo * (ow * Vec3(0.0) + Vec3(inv[3]) - objectOffset);
    const Mat3& w = f.worldFromLocal;
    if (!finite(w) || !std::isfinite(f.worldOffset.x + f.worldOffset.y + f.worldOffset.z))
        throw std::invalid_argument("the object's transform is not finite");
    const double colNorms = glm::length(w[0]) * glm::length(w[1]) * glm::length(w[2]);
    const double volume = glm::determinant(w);
    if (!std::isfinite(colNorms) || !std::isfinite(volume))  // finite entries, but their volume overflows
        throw std::invalid_argument("the object's transform scales it too much: its volume is not a finite number");
    if (!(std::abs(volume) > kThousandsOfUlps * colNorms))  // zero to rounding
        throw std::invalid_argument(
            "the object's transform is singular (a zero scale flattens the object)");
    if (!finite(f.localFromWorld) ||
        !std::isfinite(f.localOffset.x + f.localOffset.y + f.localOffset.z))
        throw std::invalid_argument("the object's inverse transform is not finite");

    if (w == Mat3(1.0)) {
        f.kind = Kind::Translate;
        f.localFromWorld = Mat3(1.0);
        f.worldFromLocal = Mat3(1.0);
        f.localOffset = -f.worldOffset;
        return f;
    }
    const Mat3 gram = glm::transpose(w) * w;
    const double s2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.0;
    // A similarity to rounding: a rotation and a uniform scale, composed.
    bool similar = true;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(gram[c][r] - (c == r ? s2 : 0.0)) > kThousandsOfUlps * s2) similar = false;
    if (similar) {
        f.kind = Kind::Similarity;
        f.worldPerLocal = std::sqrt(s2);
        f.localPerWorld = 1.0 / f.worldPerLocal;
        f.localRotation = f.localFromWorld * f.worldPerLocal;
        f.sigmaMax = f.sigmaMin = f.localPerWorld;
        return f;
    }
    f.kind = Kind::General;
    const Mat3 localGram = glm::transpose(f.localFromWorld) * f.localFromWorld;
    f.gramTrace = localGram[0][0] + localGram[1][1] + localGram[2][2];
    f.gram = localGram;
    const double det = glm::determinant(f.localFromWorld);
    f.gramDeterminant = det * det;
    const Vec3 ev = symmetricEigenvalues(localGram);
    const double hi = std::max({ev.x, ev.y, ev.z}), low = std::min({ev.x, ev.y, ev.z});
    // Singular values, rounded outward.
    f.sigmaMax = padUp(std::sqrt(hi));
    f.sigmaMin = padDown(std::sqrt(std::max(low, 0.0)));
    return f;
}

LocalFrame::Flattened LocalFrame::flattened(double angle) const {
    // The plane's unit normal as normalToWorld gives it, and a rotation
    // taking +z to it, turned by `angle` about it; the plane's origin stays
    // worldOffset.
    Mat3 r = frameAroundAxis(
        glm::normalize(Vec3(localFromWorld[0][2], localFromWorld[1][2], localFromWorld[2][2])));
    if (angle != 0.0) {
        const double c = std::cos(angle), s = std::sin(angle);
        const Vec3 u = r[0], v = r[1];
        r[0] = c * u + s * v;
        r[1] = c * v - s * u;
    }
    // (x, y, 0) is at worldOffset + x W0 + y W1 (W = worldFromLocal), whose
    // new local coordinates are its components along r's first two columns.
    const Mat3& w = worldFromLocal;
    const glm::dmat2 inPlane(glm::dot(r[0], w[0]), glm::dot(r[1], w[0]),   // column 0
                             glm::dot(r[0], w[1]), glm::dot(r[1], w[1]));  // column 1
    Flattened out{make(Transform(), r, worldOffset), inPlane};
    const glm::dmat2 back = glm::inverse(inPlane);
    out.frame.objectFromLocal =
        objectFromLocal * Mat3(Vec3(back[0], 0.0), Vec3(back[1], 0.0), Vec3(0.0, 0.0, 1.0));
    out.frame.objectOffset = objectOffset;
    return out;
}

}  // namespace asos
