#include "geometry/MassProperties.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rl {

namespace {

// Jacobi converges quadratically; a symmetric 3x3 tensor needs well under ten sweeps in double precision.
constexpr int kMaxJacobiSweeps = 64;

Mat3 outer(const Vec3& a, const Vec3& b) {
    Mat3 m(0.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            m[c][r] = a[r] * b[c];
    return m;
}

// Inertia per unit density from the second-moment (covariance) matrix C = integral of x x^T dV: I = tr(C) E - C.
Mat3 inertiaFromCovariance(const Mat3& c) {
    const Real trace = c[0][0] + c[1][1] + c[2][2];
    return Mat3(trace) - c;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool allFinite(const Mat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r]))
                return false;
    return true;
}

// Shapes beyond about 1e100 m overflow the integrals (volume ~ size^3, inertia ~ size^5). Such a result is not
// representable; it is reported as empty at a finite point instead of letting infinities and NaN reach a body.
MassProperties representable(const MassProperties& mp, const Vec3& fallbackCentroid) {
    if (std::isfinite(mp.volume) && std::isfinite(mp.area) && finite(mp.centroid) && allFinite(mp.inertia))
        return mp;
    MassProperties empty;
    empty.centroid = finite(fallbackCentroid) ? fallbackCentroid : Vec3(0.0);
    return empty;
}

} // namespace

MassProperties polyhedronMassProperties(std::span<const Vec3> vertices,
                                        std::span<const std::array<uint32_t, 3>> triangles) {
    MassProperties out;
    // Integrate relative to a vertex of the mesh: a box far from the origin would otherwise lose its inertia
    // to cancellation between huge first and second moments.
    Vec3 ref(0.0);
    bool haveRef = false;
    Real area = 0.0;
    Vec3 areaMoment(0.0);
    Real sixVolume = 0.0; // sum of determinants: 6 V
    Vec3 moment(0.0);     // 24 * integral of x dV
    Mat3 covariance(0.0); // 120 * integral of x x^T dV
    for (const auto& tri : triangles) {
        if (tri[0] >= vertices.size() || tri[1] >= vertices.size() || tri[2] >= vertices.size())
            continue; // bad indices are skipped, never read
        if (!finite(vertices[tri[0]]) || !finite(vertices[tri[1]]) || !finite(vertices[tri[2]]))
            continue; // a non-finite corner would turn every sum into NaN
        if (!haveRef) {
            ref = vertices[tri[0]];
            haveRef = true;
        }
        const Vec3 a = vertices[tri[0]] - ref;
        const Vec3 b = vertices[tri[1]] - ref;
        const Vec3 c = vertices[tri[2]] - ref;
        const Real triArea = 0.5 * glm::length(glm::cross(b - a, c - a));
        area += triArea;
        areaMoment += triArea * (a + b + c) / 3.0;
        // The signed tetrahedron (ref, a, b, c). With one vertex at the origin its moments are, with D = det[a b c]:
        // volume D/6, first moment D/24 (a+b+c), second moment D/120 (a a^T + b b^T + c c^T + s s^T), s = a+b+c.
        // Summed over a closed surface the parts outside the solid cancel (divergence theorem).
        const Real det = glm::dot(a, glm::cross(b, c));
        const Vec3 s = a + b + c;
        sixVolume += det;
        moment += det * s;
        covariance += det * (outer(a, a) + outer(b, b) + outer(c, c) + outer(s, s));
    }
    out.area = area;
    if (!haveRef)
        return out;

    Real volume = sixVolume / 6.0;
    Vec3 firstMoment = moment / 24.0;
    Mat3 secondMoment = covariance * (1.0 / 120.0);
    // An inward-wound mesh gives the same magnitudes with the opposite sign; accept it rather than report negatives.
    if (volume < 0.0) {
        volume = -volume;
        firstMoment = -firstMoment;
        secondMoment = -secondMoment;
    }
    // A volume that is rounding noise relative to the mesh size means the surface is flat or open: no solid.
    Real scale2 = 0.0;
    for (const auto& tri : triangles) {
        for (uint32_t i : tri) {
            if (i < vertices.size() && finite(vertices[i]))
                scale2 = std::max(scale2, glm::dot(vertices[i] - ref, vertices[i] - ref));
        }
    }
    const Real scale3 = scale2 * std::sqrt(scale2);
    if (!(volume > 1e-12 * scale3) || !std::isfinite(volume)) {
        out.volume = 0.0;
        out.centroid = area > 0.0 ? ref + areaMoment / area : ref;
        return representable(out, ref);
    }
    const Vec3 c = firstMoment / volume;
    // Parallel-axis step for the covariance: about the centroid it is the moment minus V c c^T.
    const Mat3 centred = secondMoment - volume * outer(c, c);
    out.volume = volume;
    out.centroid = ref + c;
    out.inertia = inertiaFromCovariance(centred);
    return representable(out, ref);
}

MassProperties hullMassProperties(const ConvexHull& hull) {
    const size_t vertexCount = hull.vertices.size();
    if (hull.dimension == HullDimension::Solid && !hull.triangleCorners.empty()) {
        std::vector<std::array<uint32_t, 3>> triangles(hull.triangleCorners.size() / 3);
        for (uint32_t t = 0; t < triangles.size(); ++t)
            triangles[t] = {3 * t, 3 * t + 1, 3 * t + 2};
        return polyhedronMassProperties(hull.triangleCorners, triangles);
    }
    if (hull.dimension == HullDimension::Solid) {
        std::vector<std::array<uint32_t, 3>> triangles;
        for (const HullFace& face : hull.faces) {
            for (size_t i = 1; i + 1 < face.vertices.size(); ++i)
                triangles.push_back({face.vertices[0], face.vertices[i], face.vertices[i + 1]});
        }
        return polyhedronMassProperties(hull.vertices, triangles);
    }
    MassProperties out;
    if (vertexCount == 0)
        return out;
    if (hull.dimension == HullDimension::Flat && !hull.faces.empty()) {
        // A two-sided sheet: report one side's area and its area centroid; it has no volume and so no inertia.
        const HullFace& face = hull.faces[0];
        Real area = 0.0;
        Vec3 moment(0.0);
        const Vec3 ref = hull.vertices[face.vertices[0]];
        for (size_t i = 1; i + 1 < face.vertices.size(); ++i) {
            const Vec3 a(0.0);
            const Vec3 b = hull.vertices[face.vertices[i]] - ref;
            const Vec3 c = hull.vertices[face.vertices[i + 1]] - ref;
            const Real triArea = 0.5 * glm::length(glm::cross(b, c));
            area += triArea;
            moment += triArea * (a + b + c) / 3.0;
        }
        out.area = area;
        out.centroid = area > 0.0 ? ref + moment / area : ref;
        return representable(out, ref);
    }
    // Points and segments: no area, no volume; the centroid is the mean of the vertices.
    Vec3 sum(0.0);
    for (const Vec3& v : hull.vertices)
        sum += v;
    out.centroid = sum / static_cast<Real>(vertexCount);
    return out;
}

Mat3 shiftInertia(const Mat3& inertiaAboutCentroid, Real mass, const Vec3& offsetFromCentroid) {
    const Vec3& d = offsetFromCentroid;
    return inertiaAboutCentroid + mass * (Mat3(glm::dot(d, d)) - outer(d, d));
}

Mat3 rotateInertia(const Mat3& inertia, const Mat3& rotation) {
    return rotation * inertia * glm::transpose(rotation);
}

void principalAxes(const Mat3& inertia, Vec3& moments, Mat3& axes) {
    if (!allFinite(inertia)) {
        // Nothing meaningful to diagonalise; a neutral answer keeps NaN out of the caller's state.
        moments = Vec3(0.0);
        axes = Mat3(1.0);
        return;
    }
    // Symmetrise first: callers may pass a tensor with rounding asymmetry.
    Real a[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            a[r][c] = 0.5 * (inertia[c][r] + inertia[r][c]);
    Real v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
        const Real off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const Real diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-34 * diag || off == 0.0)
            break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0)
                    continue;
                // Rotation angle that zeroes a[p][q] (Golub & Van Loan, symmetric Schur decomposition).
                const Real theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const Real t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const Real cs = 1.0 / std::sqrt(t * t + 1.0);
                const Real sn = t * cs;
                for (int k = 0; k < 3; ++k) {
                    const Real akp = a[k][p];
                    const Real akq = a[k][q];
                    a[k][p] = cs * akp - sn * akq;
                    a[k][q] = sn * akp + cs * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const Real apk = a[p][k];
                    const Real aqk = a[q][k];
                    a[p][k] = cs * apk - sn * aqk;
                    a[q][k] = sn * apk + cs * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const Real vkp = v[k][p];
                    const Real vkq = v[k][q];
                    v[k][p] = cs * vkp - sn * vkq;
                    v[k][q] = sn * vkp + cs * vkq;
                }
            }
        }
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int x, int y) { return a[x][x] < a[y][y]; });
    for (int i = 0; i < 3; ++i) {
        moments[i] = a[order[i]][order[i]];
        for (int k = 0; k < 3; ++k)
            axes[i][k] = v[k][order[i]];
    }
    // Keep the frame right-handed so that it can be used as a rotation.
    if (glm::determinant(axes) < 0.0)
        axes[2] = -axes[2];
}

} // namespace rl
