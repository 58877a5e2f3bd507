// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FlipFlatEdges.h>

#include <cmath>
#include <numbers>
#include <deque>
#include <string>
#include <unordered_map>

namespace crumple::ffd
{

namespace
{

using Triangle = std::array<std::uint32_t, 3>;

std::uint64_t DirectedKey(std::uint32_t inFrom, std::uint32_t inTo)
{
    return (static_cast<std::uint64_t>(inFrom) << 32) | inTo;
}

// The angle at inApex of the triangle (inApex, inA, inB).
double AngleAt(const Vec3& inApex, const Vec3& inA, const Vec3& inB)
{
    const Vec3 u = inA - inApex, v = inB - inApex;
    return std::atan2(u.cross(v).norm(), u.dot(v));
}

Vec3 UnitNormal(const std::vector<Vec3>& inPositions, const Triangle& inTriangle)
{
    const Vec3 n = (inPositions[inTriangle[1]] - inPositions[inTriangle[0]]).cross(inPositions[inTriangle[2]] - inPositions[inTriangle[0]]);
    const double length = n.norm();
    return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

} // namespace

Result<std::size_t> FlipFlatEdges(TriangleMesh& ioMesh, double inFlatCosine)
{
    if (Status valid = ValidateTriangleMesh(ioMesh); !valid)
        return valid.GetError();
    if (!(inFlatCosine > 0.0 && inFlatCosine <= 1.0))
        return MakeError(EError::InvalidArgument, "FlipFlatEdges: the flatness cosine must be in (0, 1], not " + std::to_string(inFlatCosine));
    const std::vector<Vec3>& positions = ioMesh.mPositions;
    std::vector<Triangle>& triangles = ioMesh.mTriangles;
    // intent: each directed edge's triangle, cNonManifold for an edge used twice the same way (never flipped)
    constexpr std::uint32_t cNonManifold = 0xFFFFFFFFu;
    std::unordered_map<std::uint64_t, std::uint32_t> owner;
    owner.reserve(triangles.size() * 3);
    std::vector<Vec3> normals(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
        normals[t] = UnitNormal(positions, triangles[t]);
        for (int k = 0; k < 3; ++k)
        {
            const auto [it, added] = owner.try_emplace(DirectedKey(triangles[t][k], triangles[t][(k + 1) % 3]), static_cast<std::uint32_t>(t));
            if (!added)
                it->second = cNonManifold;
        }
    }

    // intent: each undirected edge once, in triangle order (deterministic)
    std::deque<std::uint64_t> queue;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (triangles[t][k] < triangles[t][(k + 1) % 3])
                queue.push_back(DirectedKey(triangles[t][k], triangles[t][(k + 1) % 3]));
    std::size_t flips = 0;
    // intent: every flip raises the sum of the smallest angles, so this ends; the cap only guards round-off cycles
    const std::size_t max_flips = 16 * triangles.size();
    while (!queue.empty() && flips < max_flips)
    {
        const std::uint64_t key = queue.front();
        queue.pop_front();
        const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xFFFFFFFFu);
        const auto mine = owner.find(key);
        if (mine == owner.end() || mine->second == cNonManifold)
            continue;
        const auto theirs = owner.find(DirectedKey(b, a));
        if (theirs == owner.end() || theirs->second == cNonManifold)
            continue;
        const std::uint32_t t0 = mine->second, t1 = theirs->second;
        // intent: only two triangles of one plane, facing the same way
        if (t0 == t1 || normals[t0].isZero(0.0) || normals[t1].isZero(0.0) || normals[t0].dot(normals[t1]) < inFlatCosine)
            continue;
        // t0 = (a, b, c) and t1 = (b, a, d), each up to rotation
        auto third = [&](std::uint32_t inT, std::uint32_t inFrom, std::uint32_t inTo) {
            const Triangle& tri = triangles[inT];
            for (int k = 0; k < 3; ++k)
                if (tri[k] == inFrom && tri[(k + 1) % 3] == inTo)
                    return tri[(k + 2) % 3];
            return inFrom; // cannot happen: the map says the edge is there
        };
        const std::uint32_t c = third(t0, a, b), d = third(t1, b, a);
        if (c == d || c == a || c == b || d == a || d == b)
            continue;
        const double opposite = AngleAt(positions[c], positions[a], positions[b]) + AngleAt(positions[d], positions[b], positions[a]);
        // a hair above pi: cocircular quads are left alone, so no pair flips back and forth
        if (!(opposite > std::numbers::pi + 1.0e-9))
            continue;
        if (owner.contains(DirectedKey(c, d)) || owner.contains(DirectedKey(d, c)))
            continue;
        // the new pair (c, d, b) and (d, c, a) must keep the plane's orientation: a non-convex quad would turn one over
        const Triangle new0{c, d, b}, new1{d, c, a};
        const Vec3 n0 = UnitNormal(positions, new0), n1 = UnitNormal(positions, new1);
        if (n0.dot(normals[t0]) < inFlatCosine || n1.dot(normals[t0]) < inFlatCosine)
            continue;
        // intent: rewire the directed-edge map, then queue the quad's four outer edges
        for (std::uint64_t old : {DirectedKey(a, b), DirectedKey(b, a)})
            owner.erase(old);
        triangles[t0] = new0;
        triangles[t1] = new1;
        normals[t0] = n0;
        normals[t1] = n1;
        for (int k = 0; k < 3; ++k)
        {
            owner[DirectedKey(new0[k], new0[(k + 1) % 3])] = t0;
            owner[DirectedKey(new1[k], new1[(k + 1) % 3])] = t1;
        }
        for (std::uint64_t outer : {DirectedKey(b, c), DirectedKey(c, a), DirectedKey(a, d), DirectedKey(d, b)})
            queue.push_back(outer);
        ++flips;
    }
    return flips;
}

} // namespace crumple::ffd
