// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/ProceduralEdgeMesh.h>
#include <crumple/fem/SplitMix64.h>
#include <crumple/fem/WallAxes.h>

#include <cmath>
#include <sstream>
#include <utility>

namespace crumple::fem
{

// Why the outlines never cross or fold. Write g_u = r_u w + A_v < w / 2 and g_v = r_v h + A_h < h / 2
// (ProceduralEdgeSettings::cMaxAmplitudeFraction = 0.4 < 1/2 guarantees both). Every vertical polyline of
// lattice column i lies in the strip S_i = |u - i w| <= g_u (its corners move by at most r_u w, its vertices
// by A_v more), every horizontal polyline of row j in T_j = |v - j h| <= g_v; the strips of neighbouring
// columns (rows) are disjoint. Horizontal edge vertices keep their u (they move along v only) and lie
// strictly outside the column strips, so a horizontal polyline is u-monotone and meets S_i only in its first
// (or last) segment, from the corner P to its first vertex q; likewise a vertical polyline meets T_j only in
// its segment from P to its first vertex p. Around a corner P the four first vertices q+ (right), p+ (up),
// q-, p- satisfy q+.u > p+.u and q+.v < p+.v (q+ is right of S_i, p+ above T_j), with q+.u > P.u and p+.v >
// P.v; in each sign case cross(q+ - P, p+ - P) > 0, and the same for each consecutive pair, so the four
// segments leave P in counter-clockwise order and the four turns add up to exactly one revolution. Hence the
// polylines form a planar subdivision of the rectangle whose faces are the sections: each outline is a
// simple polygon and the sections tile the box. They need not be star-shaped (a long splintered edge seen
// from the centre folds), so they are triangulated by ear clipping, which any simple polygon admits.

namespace
{

using Vec2 = Eigen::Vector2d;

// Twice the signed area of (inA, inB, inC): > 0 when counter-clockwise.
double Cross(const Vec2& inA, const Vec2& inB, const Vec2& inC)
{
    return (inB - inA).x() * (inC - inA).y() - (inB - inA).y() * (inC - inA).x();
}

// True when inP lies inside or on the counter-clockwise triangle (inA, inB, inC).
bool InTriangle(const Vec2& inP, const Vec2& inA, const Vec2& inB, const Vec2& inC)
{
    return Cross(inA, inB, inP) >= 0.0 && Cross(inB, inC, inP) >= 0.0 && Cross(inC, inA, inP) >= 0.0;
}

// Ear clipping of a simple counter-clockwise polygon: repeatedly cut off a strictly convex corner whose
// triangle holds no other remaining vertex. Appends n - 2 counter-clockwise triangles (outline indices);
// false if no ear is found (the outline was not simple).
bool EarClip(const std::vector<Vec2>& inOutline, std::vector<TriangleIndices>& outTriangles)
{
    std::vector<int> remaining(inOutline.size());
    for (std::size_t index = 0; index < remaining.size(); ++index)
        remaining[index] = static_cast<int>(index);
    std::size_t cursor = 0;
    while (remaining.size() > 3)
    {
        // Scan once around from the cursor for an ear.
        const std::size_t count = remaining.size();
        bool clipped = false;
        for (std::size_t step = 0; step < count && !clipped; ++step)
        {
            const std::size_t at = (cursor + step) % count;
            const int a = remaining[(at + count - 1) % count];
            const int b = remaining[at];
            const int c = remaining[(at + 1) % count];
            if (!(Cross(inOutline[a], inOutline[b], inOutline[c]) > 0.0))
                continue;
            bool empty = true;
            for (const int other : remaining)
                if (other != a && other != b && other != c &&
                    InTriangle(inOutline[other], inOutline[a], inOutline[b], inOutline[c]))
                {
                    empty = false;
                    break;
                }
            if (!empty)
                continue;
            outTriangles.push_back({{a, b, c}});
            remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(at));
            cursor = at % remaining.size();
            clipped = true;
        }
        if (!clipped)
            return false;
    }
    if (!(Cross(inOutline[remaining[0]], inOutline[remaining[1]], inOutline[remaining[2]]) > 0.0))
        return false;
    outTriangles.push_back({{remaining[0], remaining[1], remaining[2]}});
    return true;
}

// The inserted vertices of one section edge, from its lower (u or v) corner to its upper one.
using EdgeVertices = std::vector<Vec2>;

// Vertices of one edge from inStart to inEnd along axis inAlong (0: u, horizontal edge; 1: v, vertical):
// inCount of them evenly spaced over (inSpanBegin, inSpanEnd) on the segment, offset across by up to
// inAmplitude.
EdgeVertices MakeEdge(const Vec2& inStart, const Vec2& inEnd, int inAlong, int inCount, double inSpanBegin,
                      double inSpanEnd, double inAmplitude, SplitMix64& ioRandom)
{
    const int across = 1 - inAlong;
    EdgeVertices vertices(static_cast<std::size_t>(inCount));
    for (int index = 0; index < inCount; ++index)
    {
        // Even spacing strictly inside the free span, the point on the jittered segment, then the offset.
        const double along = inSpanBegin + (inSpanEnd - inSpanBegin) * (index + 1) / (inCount + 1);
        const double t = (along - inStart[inAlong]) / (inEnd[inAlong] - inStart[inAlong]);
        Vec2 vertex;
        vertex[inAlong] = along;
        vertex[across] =
            inStart[across] + t * (inEnd[across] - inStart[across]) + inAmplitude * ioRandom.NextSigned();
        vertices[index] = vertex;
    }
    return vertices;
}

} // namespace

ProceduralEdgeMesh::ProceduralEdgeMesh(EmbeddedMesh inEmbeddedMesh, std::vector<EdgeSection> inSections,
                                       std::array<int, 3> inAxes)
    : mEmbeddedMesh(std::move(inEmbeddedMesh)), mSections(std::move(inSections)), mAxes(inAxes)
{
}

Result<ProceduralEdgeMesh> ProceduralEdgeMesh::Create(const TetGridSettings& inGrid, const TetMesh& inMesh,
                                                      const ProceduralEdgeSettings& inSettings)
{
    // Settings, grid, and the mesh being the grid's.
    if (Status valid = ValidateProceduralEdgeSettings(inSettings); !valid)
        return valid.GetError();
    if (!IsFinite(inGrid.mOrigin) || !IsFinite(inGrid.mSize) || !(inGrid.mSize.minCoeff() > 0.0))
        return MakeError(EError::InvalidArgument,
                         "ProceduralEdgeMesh: TetGridSettings.mOrigin and mSize must be "
                         "finite, mSize > 0");
    long long cells = 1;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (inGrid.mCellCount[axis] < 1 || inGrid.mCellCount[axis] > TetGridSettings::cMaxCells)
            return MakeError(EError::InvalidArgument,
                             "ProceduralEdgeMesh: TetGridSettings.mCellCount[" + std::to_string(axis) +
                                 "] = " + std::to_string(inGrid.mCellCount[axis]) + " must be >= 1");
        cells *= inGrid.mCellCount[axis];
    }
    if (cells > TetGridSettings::cMaxCells)
        return MakeError(EError::InvalidArgument,
                         "ProceduralEdgeMesh: TetGridSettings.mCellCount: more than 2^22 cells");
    const std::array<int, 3>& n = inGrid.mCellCount;
    const long long grid_nodes = static_cast<long long>(n[0] + 1) * (n[1] + 1) * (n[2] + 1);
    const long long per_cell = inGrid.mSplit == ECubeSplit::Six ? 6 : 5;
    if (inMesh.GetNodeCount() != grid_nodes || inMesh.GetTetCount() != per_cell * cells)
        return MakeError(EError::StateMismatch,
                         "ProceduralEdgeMesh: the mesh has " + std::to_string(inMesh.GetNodeCount()) +
                             " nodes and " + std::to_string(inMesh.GetTetCount()) + " elements, TetGrid(" +
                             "inGrid) has " + std::to_string(grid_nodes) + " and " +
                             std::to_string(per_cell * cells));

    // Wall frame and cell sizes, computed as TetGrid does so unjittered corners land on its nodes bitwise.
    const std::array<int, 3> axes = WallAxes(inGrid.mSize);
    const Vec3 spacing = inGrid.mSize.cwiseQuotient(Vec3(n[0], n[1], n[2]));
    const int nu = n[axes[0]];
    const int nv = n[axes[1]];
    const double w = spacing[axes[0]];
    const double h = spacing[axes[1]];
    if (Status amplitudes = ValidateEdgeAmplitudes(inSettings, w, h); !amplitudes)
        return amplitudes.GetError();
    const double gap_u = inSettings.mRandomSectionWidth * w + inSettings.mVerticalEdgeAmplitude;
    const double gap_v = inSettings.mRandomSectionHeight * h + inSettings.mHorizontalEdgeAmplitude;
    const int count_h =
        static_cast<int>(std::min(1.0e7, std::round(inSettings.mHorizontalEdgeFrequency * w)));
    const int count_v = static_cast<int>(std::min(1.0e7, std::round(inSettings.mVerticalEdgeFrequency * h)));

    // Display size guard: per cell 2 (4 + inserted) vertices.
    const double vertices_per_cell = 2.0 * (4.0 + 2.0 * count_h + 2.0 * count_v);
    if (vertices_per_cell * static_cast<double>(cells) > TetMesh::cMaxCount)
        return MakeError(
            EError::InvalidArgument,
            "ProceduralEdgeMesh: more than 2^26 display vertices; lower mHorizontalEdgeFrequency or "
            "mVerticalEdgeFrequency");

    // Jittered lattice corners, row by row; only interior coordinates move.
    SplitMix64 random(inSettings.mSeed);
    std::vector<Vec2> corners(static_cast<std::size_t>(nu + 1) * (nv + 1));
    const auto corner = [&corners, nu](int inI, int inJ) -> Vec2& { return corners[inI + (nu + 1) * inJ]; };
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i)
        {
            const double du = inSettings.mRandomSectionWidth * w * random.NextSigned();
            const double dv = inSettings.mRandomSectionHeight * h * random.NextSigned();
            corner(i, j) = Vec2(i * w + (i > 0 && i < nu ? du : 0.0), j * h + (j > 0 && j < nv ? dv : 0.0));
        }

    // Horizontal edges (i, j) -> (i + 1, j), then vertical edges (i, j) -> (i, j + 1); perimeter edges
    // straight.
    std::vector<EdgeVertices> horizontal(static_cast<std::size_t>(nu) * (nv + 1));
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i < nu; ++i)
            if (j > 0 && j < nv)
                horizontal[i + nu * j] =
                    MakeEdge(corner(i, j), corner(i + 1, j), 0, count_h, i * w + gap_u, (i + 1) * w - gap_u,
                             inSettings.mHorizontalEdgeAmplitude, random);
    std::vector<EdgeVertices> vertical(static_cast<std::size_t>(nu + 1) * nv);
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j < nv; ++j)
            if (i > 0 && i < nu)
                vertical[i + (nu + 1) * j] =
                    MakeEdge(corner(i, j), corner(i, j + 1), 1, count_v, j * h + gap_v, (j + 1) * h - gap_v,
                             inSettings.mVerticalEdgeAmplitude, random);

    // Outline and cap triangulation of each (u, v) cell, counter-clockwise from the lower-left corner.
    std::vector<std::vector<Vec2>> outlines(static_cast<std::size_t>(nu) * nv);
    std::vector<std::array<int, 4>> outline_corners(outlines.size());
    std::vector<std::vector<TriangleIndices>> caps(outlines.size());
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            std::vector<Vec2>& outline = outlines[i + nu * j];
            std::array<int, 4>& at = outline_corners[i + nu * j];
            const EdgeVertices& bottom = horizontal[i + nu * j];
            const EdgeVertices& right = vertical[(i + 1) + (nu + 1) * j];
            const EdgeVertices& top = horizontal[i + nu * (j + 1)];
            const EdgeVertices& left = vertical[i + (nu + 1) * j];
            at[0] = static_cast<int>(outline.size());
            outline.push_back(corner(i, j));
            outline.insert(outline.end(), bottom.begin(), bottom.end());
            at[1] = static_cast<int>(outline.size());
            outline.push_back(corner(i + 1, j));
            outline.insert(outline.end(), right.begin(), right.end());
            at[2] = static_cast<int>(outline.size());
            outline.push_back(corner(i + 1, j + 1));
            outline.insert(outline.end(), top.rbegin(), top.rend());
            at[3] = static_cast<int>(outline.size());
            outline.push_back(corner(i, j + 1));
            outline.insert(outline.end(), left.rbegin(), left.rend());
            if (!EarClip(outline, caps[i + nu * j]))
                return MakeError(EError::DegenerateGeometry,
                                 "ProceduralEdgeMesh: the outline of section (" + std::to_string(i) + ", " +
                                     std::to_string(j) +
                                     ") could not be triangulated; lower the edge amplitudes");
        }

    // Orientation: triangles are written for a right-handed (u, v, t) frame and reversed otherwise.
    Vec3 unit[3];
    for (int index = 0; index < 3; ++index)
        unit[index] = Vec3::Unit(axes[index]);
    const bool flip = unit[0].cross(unit[1]).dot(unit[2]) < 0.0;
    const auto add_triangle = [flip](std::vector<TriangleIndices>& ioTriangles, int inA, int inB, int inC) {
        ioTriangles.push_back(flip ? TriangleIndices{{inA, inC, inB}} : TriangleIndices{{inA, inB, inC}});
    };

    // Sections in group order: one prism per cell, back outline then front outline, own vertices.
    std::vector<Vec3> positions;
    std::vector<int> vertex_groups;
    std::vector<TriangleIndices> triangles;
    std::vector<EdgeSection> sections;
    sections.reserve(static_cast<std::size_t>(cells));
    for (int z = 0; z < n[2]; ++z)
        for (int y = 0; y < n[1]; ++y)
            for (int x = 0; x < n[0]; ++x)
            {
                const std::array<int, 3> cell{{x, y, z}};
                const int i = cell[axes[0]];
                const int j = cell[axes[1]];
                const int k = cell[axes[2]];
                const std::vector<Vec2>& outline = outlines[i + nu * j];
                const int count = static_cast<int>(outline.size());

                EdgeSection section;
                section.mGroup = x + n[0] * (y + n[1] * z);
                section.mCell = cell;
                section.mFirstVertex = static_cast<int>(positions.size());
                section.mOutlineCount = count;
                section.mCorners = outline_corners[i + nu * j];
                section.mFirstTriangle = static_cast<int>(triangles.size());

                // Vertices: back outline at k t_c, front outline at (k + 1) t_c.
                for (int layer = 0; layer < 2; ++layer)
                    for (const Vec2& point : outline)
                    {
                        Vec3 position = inGrid.mOrigin;
                        position[axes[0]] += point.x();
                        position[axes[1]] += point.y();
                        position[axes[2]] += (k + layer) * spacing[axes[2]];
                        positions.push_back(position);
                        vertex_groups.push_back(section.mGroup);
                    }

                // Front cap facing +t, back cap facing -t, then two side triangles per outline edge (a, b).
                const int back = section.mFirstVertex;
                const int front = back + count;
                for (const TriangleIndices& cap : caps[i + nu * j])
                    add_triangle(triangles, front + cap[0], front + cap[1], front + cap[2]);
                for (const TriangleIndices& cap : caps[i + nu * j])
                    add_triangle(triangles, back + cap[0], back + cap[2], back + cap[1]);
                for (int a = 0; a < count; ++a)
                {
                    const int b = (a + 1) % count;
                    add_triangle(triangles, back + a, back + b, front + b);
                    add_triangle(triangles, back + a, front + b, front + a);
                }
                section.mTriangleCount = static_cast<int>(triangles.size()) - section.mFirstTriangle;
                sections.push_back(section);
            }

    // Bind every vertex to its own cell's group.
    Result<EmbeddedMesh> embedded =
        EmbeddedMesh::Create(inMesh, positions, vertex_groups, std::move(triangles));
    if (!embedded)
        return embedded.GetError();
    return ProceduralEdgeMesh(std::move(embedded).Get(), std::move(sections), axes);
}

} // namespace crumple::fem
