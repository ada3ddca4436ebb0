// Shapes and poses shared by the narrowphase tests: random convex hulls, a 2,000-vertex hull, random rotations.
// Hulls are built here by brute force so the tests do not depend on computeConvexHull.
#pragma once

#include "collision/Shape.h"
#include "math/Types.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <vector>

namespace rl::test {

inline Shape mustShape(Result<Shape> r) {
    if (!r) { // a test shape that cannot be built is a bug in the test itself
        std::fprintf(stderr, "test shape: %s\n", r.error().toString().c_str());
        std::abort();
    }
    return std::move(r.value());
}

inline Quat randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<Real> n(0.0, 1.0);
    return glm::normalize(Quat(n(rng), n(rng), n(rng), n(rng)));
}

inline Quat axisAngle(const Vec3& axis, Real angle) {
    return glm::angleAxis(angle, glm::normalize(axis));
}

// Convex hull of points in general position, by testing every triangle: O(n^4), fine for a dozen points. Faces
// are triangles; random points have no coplanar quadruples, so this is the exact hull.
inline ConvexHull bruteForceHull(const std::vector<Vec3>& pts) {
    const size_t n = pts.size();
    Vec3 interior(0.0);
    for (const Vec3& p : pts)
        interior += p;
    interior /= Real(n);
    std::vector<std::array<uint32_t, 3>> tris;
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            for (uint32_t k = j + 1; k < n; ++k) {
                Vec3 nrm = glm::cross(pts[j] - pts[i], pts[k] - pts[i]);
                bool pos = false, neg = false;
                for (uint32_t m = 0; m < n; ++m) {
                    if (m == i || m == j || m == k)
                        continue; // their own distances are rounding noise
                    const Real s = glm::dot(nrm, pts[m] - pts[i]);
                    pos = pos || s > 0.0;
                    neg = neg || s < 0.0;
                }
                if (pos && neg)
                    continue;
                if (glm::dot(nrm, interior - pts[i]) > 0.0)
                    tris.push_back({i, k, j});
                else
                    tris.push_back({i, j, k});
            }
    std::vector<int> remap(n, -1);
    ConvexHull hull;
    hull.dimension = HullDimension::Solid;
    for (const auto& t : tris) {
        HullFace f;
        for (uint32_t v : t) {
            if (remap[v] < 0) {
                remap[v] = int(hull.vertices.size());
                hull.vertices.push_back(pts[v]);
                hull.inputIndex.push_back(v);
            }
            f.vertices.push_back(uint32_t(remap[v]));
        }
        f.normal = glm::normalize(glm::cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]));
        f.offset = glm::dot(f.normal, pts[t[0]]);
        hull.faces.push_back(f);
    }
    return hull;
}

// A random hull: a dozen points in an ellipsoid-ish cloud, a random box or a random prism, so that the tests see
// triangle faces, quads and n-gons.
inline Shape randomPolyhedron(std::mt19937_64& rng) {
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    std::uniform_real_distribution<Real> size(0.2, 1.0);
    std::uniform_int_distribution<int> kind(0, 2);
    switch (kind(rng)) {
    case 0: {
        const Vec3 s(size(rng), size(rng), size(rng));
        std::vector<Vec3> pts(4 + rng() % 9);
        for (Vec3& p : pts)
            p = Vec3(u(rng), u(rng), u(rng)) * s;
        return mustShape(makeHull(bruteForceHull(pts)));
    }
    case 1:
        return mustShape(makeBox(Vec3(size(rng), size(rng), size(rng)) * 0.6));
    default: {
        const int sides = 3 + int(rng() % 6);
        const Real r = size(rng);
        std::vector<Vec3> poly;
        for (int i = 0; i < sides; ++i) {
            const Real a = 2.0 * kPi * i / sides + 0.3 * u(rng) / sides;
            poly.push_back({r * std::cos(a), 0.0, r * std::sin(a)});
        }
        return mustShape(makeHull(prismHull(poly, 0.5 * size(rng))));
    }
    }
}

// A UV sphere: rings of quads (isosceles trapezoids, so exactly planar) and a triangle fan at each pole.
inline ConvexHull uvSphereHull(Real radius, int rings, int segments) {
    ConvexHull hull;
    hull.dimension = HullDimension::Solid;
    for (int r = 1; r <= rings; ++r) {
        const Real theta = kPi * r / (rings + 1);
        for (int s = 0; s < segments; ++s) {
            const Real phi = 2.0 * kPi * s / segments;
            hull.vertices.push_back(
                radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    }
    const uint32_t top = uint32_t(hull.vertices.size());
    hull.vertices.push_back({0.0, radius, 0.0});
    const uint32_t bottom = top + 1;
    hull.vertices.push_back({0.0, -radius, 0.0});
    auto idx = [&](int r, int s) { return uint32_t((r - 1) * segments + (s % segments)); };
    auto addFace = [&](std::vector<uint32_t> loop) {
        HullFace f;
        f.vertices = loop;
        Vec3 c(0.0);
        for (uint32_t i : loop)
            c += hull.vertices[i];
        f.normal = glm::normalize(glm::cross(hull.vertices[loop[1]] - hull.vertices[loop[0]],
                                             hull.vertices[loop[2]] - hull.vertices[loop[0]]));
        if (glm::dot(f.normal, c) < 0.0) {
            std::reverse(f.vertices.begin(), f.vertices.end());
            f.normal = -f.normal;
        }
        f.offset = glm::dot(f.normal, hull.vertices[loop[0]]);
        hull.faces.push_back(f);
    };
    for (int s = 0; s < segments; ++s) {
        addFace({top, idx(1, s + 1), idx(1, s)});
        addFace({bottom, idx(rings, s), idx(rings, s + 1)});
        for (int r = 1; r < rings; ++r)
            addFace({idx(r, s), idx(r, s + 1), idx(r + 1, s + 1), idx(r + 1, s)});
    }
    hull.inputIndex.resize(hull.vertices.size());
    std::iota(hull.inputIndex.begin(), hull.inputIndex.end(), 0u);
    return hull;
}

inline Real angleDegrees(const Vec3& a, const Vec3& b) {
    const Real c = std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0);
    return std::acos(c) * 180.0 / kPi;
}

// Separation of two shapes measured along a given axis (A to B) with the support functions: any axis gives a
// lower bound, and the best axis gives the exact signed distance of polyhedra.
inline Real separationAlong(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb, const Vec3& n) {
    const Vec3 pa = xa.apply(a.support(xa.rotateInverse(n)));
    const Vec3 pb = xb.apply(b.support(xb.rotateInverse(-n)));
    return glm::dot(n, pb - pa);
}

} // namespace rl::test
