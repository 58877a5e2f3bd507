// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/InterpolateWideImpact.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace crumple::ffd
{

namespace
{

using Vec2 = Eigen::Vector2d;
using Triangle = std::array<int, 3>;

// Twice the signed area of (a, b, c): > 0 when counter-clockwise.
double Orient(const Vec2& inA, const Vec2& inB, const Vec2& inC)
{
    return (inB.x() - inA.x()) * (inC.y() - inA.y()) - (inB.y() - inA.y()) * (inC.x() - inA.x());
}

// True when p lies inside the circumcircle of the counter-clockwise triangle (a, b, c) by more than the
// determinant's round-off: p on the circle, or within round-off of it, is outside. Points on one circle (a
// round impactor's rim) otherwise fall in or out by the sign of round-off, half of them in: every insertion's
// cavity then held most triangles, and 1,024 such contacts took seconds.
bool InCircumcircle(const Vec2& inA, const Vec2& inB, const Vec2& inC, const Vec2& inP)
{
    const Vec2 a = inA - inP, b = inB - inP, c = inC - inP;
    const double bx_cy = b.x() * c.y(), cx_by = c.x() * b.y(), ax_cy = a.x() * c.y(), cx_ay = c.x() * a.y();
    const double ax_by = a.x() * b.y(), bx_ay = b.x() * a.y();
    const double a2 = a.squaredNorm(), b2 = b.squaredNorm(), c2 = c.squaredNorm();
    const double det = a2 * (bx_cy - cx_by) - b2 * (ax_cy - cx_ay) + c2 * (ax_by - bx_ay);
    // intent: the size of the terms whose differences make det (the permanent); the evaluation's error is a
    // few rounding units of it
    const double size = a2 * (std::abs(bx_cy) + std::abs(cx_by)) + b2 * (std::abs(ax_cy) + std::abs(cx_ay)) +
                        c2 * (std::abs(ax_by) + std::abs(bx_ay));
    return det > 1.0e-12 * size;
}

// Bowyer-Watson Delaunay triangulation of distinct 2D points; triangles are counter-clockwise.
std::vector<Triangle> Delaunay(const std::vector<Vec2>& inPoints)
{
    const int n = static_cast<int>(inPoints.size());
    Vec2 lo = inPoints[0], hi = inPoints[0];
    for (const Vec2& p : inPoints)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double extent = std::max((hi - lo).maxCoeff(), 1.0e-12);
    const Vec2 centre = 0.5 * (lo + hi);
    // A super-triangle far larger than the set, so its corners do not bend the hull.
    std::vector<Vec2> vertices = inPoints;
    vertices.push_back(centre + Vec2(-1.0e4 * extent, -1.0e4 * extent));
    vertices.push_back(centre + Vec2(1.0e4 * extent, -1.0e4 * extent));
    vertices.push_back(centre + Vec2(0.0, 1.0e4 * extent));
    std::vector<Triangle> triangles{{n, n + 1, n + 2}};
    std::vector<Triangle> kept;
    std::vector<std::pair<int, int>> edges;
    std::vector<std::pair<std::uint64_t, std::size_t>> sorted_edges; // (undirected edge, its index in edges)
    std::vector<std::uint8_t> shared;                                // per cavity edge: a second triangle has it
    for (int p = 0; p < n; ++p)
    {
        // Remove the triangles whose circumcircle holds p; keep their boundary edges.
        kept.clear();
        edges.clear();
        for (const Triangle& t : triangles)
        {
            if (InCircumcircle(vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[p]))
            {
                for (int e = 0; e < 3; ++e)
                    edges.emplace_back(t[e], t[(e + 1) % 3]);
            }
            else
                kept.push_back(t);
        }
        // Re-triangulate the cavity from p: an edge two cavity triangles share is inside it. Shared edges found
        // by sorting (a cavity is a few edges, but points on a circle, a round impactor's rim, make it hundreds:
        // counting each edge's copies made that quadratic), new triangles made in the cavity edges' order.
        sorted_edges.clear();
        for (std::size_t e = 0; e < edges.size(); ++e)
        {
            const auto low = static_cast<std::uint32_t>(std::min(edges[e].first, edges[e].second));
            const auto high = static_cast<std::uint32_t>(std::max(edges[e].first, edges[e].second));
            sorted_edges.emplace_back((static_cast<std::uint64_t>(high) << 32) | low, e);
        }
        std::sort(sorted_edges.begin(), sorted_edges.end());
        shared.assign(edges.size(), 0);
        for (std::size_t k = 1; k < sorted_edges.size(); ++k)
            if (sorted_edges[k].first == sorted_edges[k - 1].first)
                shared[sorted_edges[k].second] = shared[sorted_edges[k - 1].second] = 1;
        for (std::size_t e = 0; e < edges.size(); ++e)
            if (shared[e] == 0)
                kept.push_back({edges[e].first, edges[e].second, p});
        triangles.swap(kept);
    }
    // Drop everything attached to the super-triangle.
    std::vector<Triangle> result;
    for (const Triangle& t : triangles)
        if (t[0] < n && t[1] < n && t[2] < n && std::abs(Orient(vertices[t[0]], vertices[t[1]], vertices[t[2]])) > 0.0)
            result.push_back(t);
    return result;
}

PointDisplacement Lerp(const PointDisplacement& inA, const PointDisplacement& inB, double inT)
{
    return {inA.mPoint + inT * (inB.mPoint - inA.mPoint),
            inA.mDisplacement + inT * (inB.mDisplacement - inA.mDisplacement)};
}

// Samples along segment a-b, strictly between its ends, every inSpacing at most.
void SampleSegment(const PointDisplacement& inA, const PointDisplacement& inB, double inLength, double inSpacing,
                   std::vector<PointDisplacement>& ioOut)
{
    // The caller keeps inLength / inSpacing small (see InterpolateWideImpact); clamp anyway so a count can
    // never overflow.
    const double count = std::ceil(inLength / inSpacing - 1.0e-9);
    const int pieces = count >= 1.0e6 ? 1000000 : (count >= 1.0 ? static_cast<int>(count) : 1); // NaN: none
    for (int k = 1; k < pieces; ++k)
        ioOut.push_back(Lerp(inA, inB, static_cast<double>(k) / pieces));
}

constexpr double cThinningRadius = 0.5;
// The samples less than half a pitch from a point kept before them are dropped (the given points are all
// kept): edge samples of neighbouring triangles and grid samples beside them repeat one constraint the
// lattice cannot tell apart, and each repeat costs the direct-manipulation solve a row (64 random contacts
// on a car front gave 325 rows of rank 156). Order-preserving, so deterministic.
std::vector<PointDisplacement> Thinned(std::vector<PointDisplacement> inPoints, std::size_t inGiven, const Vec3& inCentroid,
                                       const Vec3& inE1, const Vec3& inE2, double inSpacing)
{
    const double radius = cThinningRadius * inSpacing;
    // Kept points bucketed by a grid over the points' extent: a closer point is in the same or a
    // neighbouring bucket. Each bucket is a list threaded through the kept points (no allocation per
    // bucket); whether a close point exists does not depend on the order a bucket is searched in.
    std::vector<Vec2> plane(inPoints.size());
    Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (std::size_t i = 0; i < inPoints.size(); ++i)
    {
        const Vec3 d = inPoints[i].mPoint - inCentroid;
        plane[i] = Vec2(d.dot(inE1), d.dot(inE2));
        lo = lo.cwiseMin(plane[i]);
        hi = hi.cwiseMax(plane[i]);
    }
    // Buckets no smaller than the radius (so the neighbours hold every closer point) and at most 128 a side.
    const double bucket_size = std::max(radius, (hi - lo).maxCoeff() / 128.0);
    const auto bucket_of = [&](const Vec2& inQ, std::size_t inAxis) {
        return static_cast<long>(std::floor(inQ[static_cast<Eigen::Index>(inAxis)] / bucket_size)) -
               static_cast<long>(std::floor(lo[static_cast<Eigen::Index>(inAxis)] / bucket_size));
    };
    const long columns = bucket_of(hi, 0) + 1, rows = bucket_of(hi, 1) + 1;
    std::vector<int> first(static_cast<std::size_t>(columns * rows), -1), next;
    std::vector<Vec2> kept_plane;
    std::vector<PointDisplacement> kept;
    kept.reserve(inPoints.size());
    for (std::size_t i = 0; i < inPoints.size(); ++i)
    {
        const Vec2& q = plane[i];
        const long bx = bucket_of(q, 0), by = bucket_of(q, 1);
        bool near = false;
        for (long y = std::max(by - 1, 0L); y <= std::min(by + 1, rows - 1) && !near && i >= inGiven; ++y)
            for (long x = std::max(bx - 1, 0L); x <= std::min(bx + 1, columns - 1) && !near; ++x)
                for (int k = first[static_cast<std::size_t>(y * columns + x)]; k >= 0 && !near; k = next[static_cast<std::size_t>(k)])
                    near = (kept_plane[static_cast<std::size_t>(k)] - q).norm() < radius;
        if (near)
            continue;
        const std::size_t bucket = static_cast<std::size_t>(by * columns + bx);
        next.push_back(first[bucket]);
        first[bucket] = static_cast<int>(kept_plane.size());
        kept_plane.push_back(q);
        kept.push_back(inPoints[i]);
    }
    return kept;
}

std::vector<PointDisplacement> Interpolate(std::span<const PointDisplacement> inPoints, double inSpacing)
{
    std::vector<PointDisplacement> out(inPoints.begin(), inPoints.end());

    // Project on the plane normal to the mean dent direction (PCA normal when displacements cancel).
    Vec3 centroid = Vec3::Zero();
    Vec3 direction = Vec3::Zero();
    for (const PointDisplacement& p : inPoints)
    {
        centroid += p.mPoint;
        direction += p.mDisplacement;
    }
    centroid /= static_cast<double>(inPoints.size());
    Mat3 covariance = Mat3::Zero();
    for (const PointDisplacement& p : inPoints)
        covariance += (p.mPoint - centroid) * (p.mPoint - centroid).transpose();
    Eigen::SelfAdjointEigenSolver<Mat3> pca(covariance);
    Vec3 normal = direction.norm() > 0.0 ? Vec3(direction.normalized()) : Vec3(pca.eigenvectors().col(0));
    Vec3 e1 = normal.unitOrthogonal();
    // Align the in-plane frame with the main spread, so a collinear set is detected on e1.
    const Vec3 spread = pca.eigenvectors().col(2) - pca.eigenvectors().col(2).dot(normal) * normal;
    if (spread.norm() > 1.0e-6)
        e1 = spread.normalized();
    const Vec3 e2 = normal.cross(e1);

    // Distinct 2D points (coincident projections keep the first).
    std::vector<Vec2> plane;
    std::vector<int> source;
    const double coincident = 1.0e-9 * inSpacing;
    for (std::size_t i = 0; i < inPoints.size(); ++i)
    {
        const Vec3 d = inPoints[i].mPoint - centroid;
        const Vec2 q(d.dot(e1), d.dot(e2));
        if (std::none_of(plane.begin(), plane.end(), [&](const Vec2& o) { return (o - q).norm() <= coincident; }))
        {
            plane.push_back(q);
            source.push_back(static_cast<int>(i));
        }
    }

    double width = 0.0;
    for (const Vec2& p : plane)
        width = std::max(width, std::abs(p.y()));
    if (plane.size() < 3 || width < 1.0e-6 * inSpacing)
    {
        // Collinear: sample consecutive points along the line.
        std::vector<int> order(plane.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = static_cast<int>(i);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return plane[a].x() < plane[b].x(); });
        for (std::size_t i = 1; i < order.size(); ++i)
        {
            const double length = (plane[order[i]] - plane[order[i - 1]]).norm();
            SampleSegment(inPoints[source[order[i - 1]]], inPoints[source[order[i]]], length, inSpacing, out);
        }
        return out;
    }

    const std::vector<Triangle> triangles = Delaunay(plane);

    // Grid samples strictly inside triangles, away from the given points.
    Vec2 lo = plane[0], hi = plane[0];
    for (const Vec2& p : plane)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    // The grid nodes already sampled, one byte each over the set's box (a node satisfies
    // lo + g inSpacing <= hi, so g <= (hi - lo) / inSpacing + 1 in floating point).
    const auto grid_nodes = [&](Eigen::Index inAxis) { return static_cast<long>(std::floor((hi[inAxis] - lo[inAxis]) / inSpacing)) + 2; };
    const long grid_columns = grid_nodes(0);
    std::vector<char> taken(static_cast<std::size_t>(grid_columns * grid_nodes(1)), 0);
    for (const Triangle& t : triangles)
    {
        const Vec2 &a = plane[t[0]], &b = plane[t[1]], &c = plane[t[2]];
        const double area = Orient(a, b, c);
        const Vec2 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
        for (long gy = static_cast<long>(std::ceil((tlo.y() - lo.y()) / inSpacing));
             lo.y() + static_cast<double>(gy) * inSpacing <= thi.y(); ++gy)
            for (long gx = static_cast<long>(std::ceil((tlo.x() - lo.x()) / inSpacing));
                 lo.x() + static_cast<double>(gx) * inSpacing <= thi.x(); ++gx)
            {
                const Vec2 q = lo + inSpacing * Vec2(static_cast<double>(gx), static_cast<double>(gy));
                const double wa = Orient(b, c, q) / area, wb = Orient(c, a, q) / area, wc = Orient(a, b, q) / area;
                if (wa <= 1.0e-9 || wb <= 1.0e-9 || wc <= 1.0e-9)
                    continue;
                char& node = taken[static_cast<std::size_t>(gy * grid_columns + gx)];
                if (node != 0)
                    continue;
                node = 1;
                if (std::any_of(plane.begin(), plane.end(), [&](const Vec2& o) { return (o - q).norm() < 0.5 * inSpacing; }))
                    continue;
                const PointDisplacement &pa = inPoints[source[t[0]]], &pb = inPoints[source[t[1]]],
                                        &pc = inPoints[source[t[2]]];
                out.push_back({wa * pa.mPoint + wb * pb.mPoint + wc * pc.mPoint,
                               wa * pa.mDisplacement + wb * pb.mDisplacement + wc * pc.mDisplacement});
            }
    }

    // Edges longer than the spacing, each once (after the grid, so that thinning keeps the regular grid
    // and drops the edge samples beside it).
    std::vector<std::pair<int, int>> edges;
    edges.reserve(3 * triangles.size());
    for (const Triangle& t : triangles)
        for (int e = 0; e < 3; ++e)
            edges.emplace_back(std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [a, b] : edges)
    {
        const double length = (plane[a] - plane[b]).norm();
        if (length > inSpacing)
            SampleSegment(inPoints[source[a]], inPoints[source[b]], length, inSpacing, out);
    }
    return Thinned(std::move(out), inPoints.size(), centroid, e1, e2, inSpacing);
}

} // namespace

std::vector<PointDisplacement> InterpolateWideImpact(std::span<const PointDisplacement> inPoints, double inSpacing,
                                                     std::size_t inMaxPoints)
{
    if (inPoints.size() < 2 || !(inSpacing > 0.0) || !std::isfinite(inSpacing))
        return {inPoints.begin(), inPoints.end()};

    // Nothing to fill when every pair is within the spacing. A set whose extent or displacements are past
    // the double range (their differences or sums overflow) is not filled: interpolating it would make NaN.
    double diameter = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < inPoints.size(); ++i)
    {
        largest = std::max(largest, inPoints[i].mDisplacement.cwiseAbs().maxCoeff());
        for (std::size_t j = i + 1; j < inPoints.size(); ++j)
            diameter = std::max(diameter, (inPoints[i].mPoint - inPoints[j].mPoint).norm());
    }
    if (!(diameter <= inSpacing * 1.0e9) || !(largest <= 1.0e100) || diameter <= inSpacing)
        return {inPoints.begin(), inPoints.end()};

    // Start at a pitch whose grid over the set's extent fits the cap (the extent bounds the hull's area and
    // every edge), then coarsen until the samples really fit: the cost never depends on how fine the
    // lattice or how wide the contact set is.
    const double cap = static_cast<double>(std::max<std::size_t>(inMaxPoints, 4));
    double spacing = std::max(inSpacing, diameter / std::sqrt(cap));
    for (int attempt = 0; attempt < 16; ++attempt, spacing *= 1.5)
    {
        std::vector<PointDisplacement> out = Interpolate(inPoints, spacing);
        if (out.size() <= std::max(inMaxPoints, inPoints.size()))
            return out;
    }
    return {inPoints.begin(), inPoints.end()};
}

} // namespace crumple::ffd
