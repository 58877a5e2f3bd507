// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FlipFlatEdges.h>

#include "DirectedEdges.h"
#include "PositionEdges.h"
#include "SeamTwins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

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

// The flip loop both entry points share. inMayFlip(t0, t1, new0, new1) says whether the pair t0 = (a, b, c),
// t1 = (b, a, d) may become new0 = (c, d, b), new1 = (d, c, a); the loop adds the Delaunay condition.
// The edge map names vertex v by its seam twin (inTwins, SeamTwins) when inAcrossSeams, else by v itself; a
// flip across a seam makes each new triangle take its corners from the old triangle whose slot it takes, d
// and c from the other one. inSeedAngle > 0: only edges facing a corner of at least this angle (rad) flip
// (a cap's long edge).
template <class MayFlip>
std::size_t FlipWhere(TriangleMesh& ioMesh, const std::vector<std::uint32_t>& inTwins, bool inAcrossSeams, double inSeedAngle,
                      MayFlip&& inMayFlip)
{
    const std::vector<Vec3>& positions = ioMesh.mPositions;
    std::vector<Triangle>& triangles = ioMesh.mTriangles;
    auto name = [&](std::uint32_t inVertex) { return inAcrossSeams ? inTwins[inVertex] : inVertex; };
    auto edge_key = [&](std::uint32_t inFrom, std::uint32_t inTo) { return DirectedKey(name(inFrom), name(inTo)); };
    // intent: each directed edge's triangle, cNonManifold for an edge used twice the same way (never flipped)
    DirectedEdges owner(positions.size());
    {
        // intent: each vertex's list allocated once at its size (a flip adds an edge now and then)
        std::vector<std::uint32_t> out_degree(positions.size(), 0);
        for (const Triangle& triangle : triangles)
            for (std::uint32_t v : triangle)
                ++out_degree[name(v)];
        for (std::size_t v = 0; v < out_degree.size(); ++v)
            if (out_degree[v] > 0)
                owner.Reserve(static_cast<std::uint32_t>(v), out_degree[v] + 2);
    }
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            owner.Add(name(triangles[t][k]), name(triangles[t][(k + 1) % 3]), static_cast<std::uint32_t>(t));
    // intent: keyed by index, the edges by position beside them; keyed by twins, the owner map is that already
    std::optional<PositionEdges> by_position;
    if (!inAcrossSeams)
    {
        std::vector<std::uint8_t> seam(inTwins.size(), 0);
        bool any = false;
        for (std::size_t v = 0; v < inTwins.size(); ++v)
            if (inTwins[v] != v)
                seam[v] = seam[inTwins[v]] = 1, any = true;
        if (any)
            by_position.emplace(triangles, inTwins, std::move(seam));
    }
    auto joined = [&](std::uint32_t inC, std::uint32_t inD) {
        return owner.Find(name(inC), name(inD)) != DirectedEdges::cNone || owner.Find(name(inD), name(inC)) != DirectedEdges::cNone ||
               (by_position && (by_position->Has(inC, inD) || by_position->Has(inD, inC)));
    };

    // intent: each undirected edge once, in triangle order (deterministic); or only the edges that face a
    // corner of at least inSeedAngle, each from the triangle of that corner
    std::deque<std::uint64_t> queue;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
        {
            const std::uint32_t from = triangles[t][k], to = triangles[t][(k + 1) % 3];
            if (inSeedAngle > 0.0)
            {
                // intent: a corner whose edges do not point apart (u . v >= 0) is at most pi/2, so past an obtuse
                // seed angle it needs no arctangent: the same decisions, at a third of the cost on a car's mesh
                const Vec3& apex = positions[triangles[t][(k + 2) % 3]];
                if (inSeedAngle > 0.5 * std::numbers::pi && (positions[from] - apex).dot(positions[to] - apex) >= 0.0)
                    continue;
                if (AngleAt(apex, positions[from], positions[to]) >= inSeedAngle)
                    queue.push_back(edge_key(from, to));
            }
            else if (name(from) < name(to))
                queue.push_back(edge_key(from, to));
        }
    std::size_t flips = 0;
    // intent: in a plane every flip raises the sum of the smallest angles, so this ends; the cap guards
    // round-off cycles and the slightly bent quads FlipNearlyFlatEdges accepts
    const std::size_t max_flips = 16 * triangles.size();
    while (!queue.empty() && flips < max_flips)
    {
        const std::uint64_t key = queue.front();
        queue.pop_front();
        const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xFFFFFFFFu);
        const std::uint32_t t0 = owner.Find(a, b);
        if (t0 == DirectedEdges::cNone || t0 == DirectedEdges::cNonManifold)
            continue;
        const std::uint32_t t1 = owner.Find(b, a);
        if (t1 == DirectedEdges::cNone || t1 == DirectedEdges::cNonManifold)
            continue;
        if (t0 == t1)
            continue;
        // t0 = (a, b, c) and t1 = (b, a, d), each up to rotation; corner k of the edge's start in each
        auto start = [&](std::uint32_t inT, std::uint32_t inFrom, std::uint32_t inTo) {
            const Triangle& tri = triangles[inT];
            for (int k = 0; k < 3; ++k)
                if (name(tri[k]) == inFrom && name(tri[(k + 1) % 3]) == inTo)
                    return k;
            return 0; // cannot happen: the map says the edge is there
        };
        const int k0 = start(t0, a, b), k1 = start(t1, b, a);
        const std::uint32_t c = triangles[t0][(k0 + 2) % 3], d = triangles[t1][(k1 + 2) % 3];
        if (name(c) == name(d) || name(c) == a || name(c) == b || name(d) == a || name(d) == b)
            continue;
        // the old pair's own indices of a and b (different across a seam)
        const std::uint32_t a0 = triangles[t0][k0], b0 = triangles[t0][(k0 + 1) % 3], a1 = triangles[t1][(k1 + 1) % 3];
        // intent: two corners whose edges do not point apart are at most pi/2 each, never more than pi
        // together: no arctangent needed to leave the edge (most edges of a mesh)
        if ((positions[a0] - positions[c]).dot(positions[b0] - positions[c]) >= 0.0 &&
            (positions[b0] - positions[d]).dot(positions[a0] - positions[d]) >= 0.0)
            continue;
        const double angle_c = AngleAt(positions[c], positions[a0], positions[b0]);
        const double angle_d = AngleAt(positions[d], positions[b0], positions[a0]);
        // a hair above pi: cocircular quads are left alone, so no pair flips back and forth
        if (!(angle_c + angle_d > std::numbers::pi + 1.0e-9))
            continue;
        if (inSeedAngle > 0.0 && !(std::max(angle_c, angle_d) >= inSeedAngle))
            continue;
        if (joined(c, d))
            continue;
        const Triangle new0{c, d, b0}, new1{d, c, a1};
        if (!inMayFlip(t0, t1, new0, new1))
            continue;
        // intent: rewire the directed-edge map, then queue the quad's four outer edges
        owner.Erase(a, b);
        owner.Erase(b, a);
        if (by_position)
        {
            by_position->Remove(a0, b0);
            by_position->Remove(b0, a0);
            by_position->Add(c, d);
            by_position->Add(d, c);
        }
        triangles[t0] = new0;
        triangles[t1] = new1;
        for (int k = 0; k < 3; ++k)
        {
            owner.Set(name(new0[k]), name(new0[(k + 1) % 3]), t0);
            owner.Set(name(new1[k]), name(new1[(k + 1) % 3]), t1);
        }
        for (std::uint64_t outer : {edge_key(b0, c), edge_key(c, a0), edge_key(a1, d), edge_key(d, b0)})
            queue.push_back(outer);
        ++flips;
    }
    return flips;
}

Vec3 AreaVector(const std::vector<Vec3>& inPositions, const Triangle& inTriangle)
{
    return (inPositions[inTriangle[1]] - inPositions[inTriangle[0]]).cross(inPositions[inTriangle[2]] - inPositions[inTriangle[0]]);
}

} // namespace

Result<std::size_t> FlipFlatEdges(TriangleMesh& ioMesh, double inFlatCosine)
{
    if (Status valid = ValidateTriangleMesh(ioMesh); !valid)
        return valid.GetError();
    if (!(inFlatCosine > 0.0 && inFlatCosine <= 1.0))
        return MakeError(EError::InvalidArgument, "FlipFlatEdges: the flatness cosine must be in (0, 1], not " + std::to_string(inFlatCosine));
    const std::vector<Vec3>& positions = ioMesh.mPositions;
    std::vector<Vec3> normals(ioMesh.mTriangles.size());
    for (std::size_t t = 0; t < normals.size(); ++t)
        normals[t] = UnitNormal(positions, ioMesh.mTriangles[t]);
    const std::vector<std::uint32_t> twins = SeamTwins(positions);
    return FlipWhere(ioMesh, twins, false, 0.0, [&](std::uint32_t inT0, std::uint32_t inT1, const Triangle& inNew0, const Triangle& inNew1) {
        // intent: only two triangles of one plane, facing the same way
        if (normals[inT0].isZero(0.0) || normals[inT1].isZero(0.0) || normals[inT0].dot(normals[inT1]) < inFlatCosine)
            return false;
        // the new pair must keep the plane's orientation: a non-convex quad would turn one over
        const Vec3 n0 = UnitNormal(positions, inNew0), n1 = UnitNormal(positions, inNew1);
        if (n0.dot(normals[inT0]) < inFlatCosine || n1.dot(normals[inT0]) < inFlatCosine)
            return false;
        normals[inT0] = n0;
        normals[inT1] = n1;
        return true;
    });
}

// Why the slab bounds the change: the quad's four corners span a tetrahedron whose two diagonals are the old
// edge ab and the new edge cd. When ab and cd cross seen along n = ab x cd (the closest points of their lines
// lie inside both segments), both pairs of triangles cover the same region seen along n, so every point of one
// pair has a point of the other straight along n; both lie between the parallel planes through ab and cd,
// which are |(c - a) . n| / |n| apart.
Result<std::size_t> FlipNearlyFlatEdges(TriangleMesh& ioMesh, double inMaxDeviation, bool inAcrossSeams, double inCapAngle)
{
    if (Status valid = ValidateTriangleMesh(ioMesh); !valid)
        return valid.GetError();
    if (!(inMaxDeviation >= 0.0 && std::isfinite(inMaxDeviation)))
        return MakeError(EError::InvalidArgument,
                         "FlipNearlyFlatEdges: the largest deviation must be finite and >= 0 (m), not " + std::to_string(inMaxDeviation));
    if (!(inCapAngle >= 0.0 && inCapAngle <= std::numbers::pi))
        return MakeError(EError::InvalidArgument,
                         "FlipNearlyFlatEdges: the cap angle must be in [0, pi] (rad), not " + std::to_string(inCapAngle));
    const std::vector<Vec3>& positions = ioMesh.mPositions;
    const std::vector<Triangle>& triangles = ioMesh.mTriangles;
    const std::vector<std::uint32_t> twins = SeamTwins(positions);
    return FlipWhere(ioMesh, twins, inAcrossSeams, inCapAngle, [&](std::uint32_t inT0, std::uint32_t inT1, const Triangle& inNew0, const Triangle& inNew1) {
        const Vec3& a = positions[inNew1[2]];
        const Vec3& b = positions[inNew0[2]];
        const Vec3& c = positions[inNew0[0]];
        const Vec3& d = positions[inNew0[1]];
        // intent: the closest points of lines ab and cd lie strictly inside both segments
        const Vec3 ab = b - a, cd = d - c, ca = a - c;
        const double aa = ab.dot(ab), cc = cd.dot(cd), ac = ab.dot(cd);
        const double denominator = aa * cc - ac * ac;
        if (!(denominator > 0.0))
            return false;
        const double s = (ac * cd.dot(ca) - cc * ab.dot(ca)) / denominator;
        const double t = (aa * cd.dot(ca) - ac * ab.dot(ca)) / denominator;
        if (!(s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0))
            return false;
        // intent: the slab between the two diagonals is at most inMaxDeviation thick
        const Vec3 n = ab.cross(cd);
        if (std::abs(ca.dot(n)) > inMaxDeviation * n.norm())
            return false;
        // intent: both new triangles face the way the old pair faces together (a cap's own normal says little)
        const Vec3 facing = AreaVector(positions, triangles[inT0]) + AreaVector(positions, triangles[inT1]);
        return AreaVector(positions, inNew0).dot(facing) > 0.0 && AreaVector(positions, inNew1).dot(facing) > 0.0;
    });
}

} // namespace crumple::ffd
