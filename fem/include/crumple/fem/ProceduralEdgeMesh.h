// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/EmbeddedMesh.h>
#include <crumple/fem/ProceduralEdgeSettings.h>
#include <crumple/fem/TetGrid.h>

#include <array>
#include <vector>

namespace crumple::fem
{

/// One display section of a ProceduralEdgeMesh: a closed, outward-oriented triangle mesh (a prism over its
/// outline) that follows one TetGrid cell. Its vertices are its own (not shared with other sections), so a
/// piece that breaks off carries all its faces.
struct CRUMPLE_API EdgeSection
{
    int mGroup = 0; ///< Group id of its cell, i + n_x (j + n_y k): every vertex follows it
    std::array<int, 3> mCell{{0, 0, 0}}; ///< Cell (i, j, k) along x, y, z
    /// Vertices [mFirstVertex, + mOutlineCount) are the back outline (smaller thickness coordinate),
    /// [+ mOutlineCount, + 2 mOutlineCount) the front outline in the same order
    int mFirstVertex = 0;
    int mOutlineCount = 0; ///< Outline vertices, counter-clockwise in (u, v) (width, height; see WallAxes)
    /// Outline positions (0 .. mOutlineCount - 1) of the four jittered cell corners: lower-left, lower-right,
    /// upper-right, upper-left in (u, v). The outline starts at the lower-left one; between two corners lie
    /// that side's inserted edge vertices
    std::array<int, 4> mCorners{{0, 0, 0, 0}};
    int mFirstTriangle = 0; ///< Triangles [mFirstTriangle, + mTriangleCount): front cap, back cap, sides
    int mTriangleCount = 0; ///< 2 (mOutlineCount - 2) cap + 2 mOutlineCount side triangles
};

/// The procedural broken-edge display mesh of a box prop built by TetGrid (Morris & Anderson, "GPU
/// destruction", section IV.C, after Scheepers & Whittock): one section per grid cell, their boundaries
/// jittered and their interior edges given random extra vertices, so that the intact prop looks uncut (the
/// sections tile the box exactly) and broken-off pieces show material-like edges.
///
/// Construction, in wall coordinates (u, v) = (width, height), see WallAxes and ProceduralEdgeSettings:
///  - lattice corner (i, j) sits at (i w, j h) moved by uniform random amounts within +- r_u w along u
///    (only when 0 < i < n_u) and +- r_v h along v (only when 0 < j < n_v): the perimeter stays on the box
///    faces; the same through the whole thickness.
///  - each interior horizontal edge (0 < j < n_v) gets m = round(f_h w) vertices, evenly spaced in u over
///    the free span (i w + g_u, (i + 1) w - g_u) with g_u = r_u w + A_v, on the jittered segment and then
///    offset along v by uniform random amounts within +- A_h; vertical edges likewise (m = round(f_v h), span
///    (j h + g_v, (j + 1) h - g_v), g_v = r_v h + A_h, offset along u within +- A_v). Perimeter edges stay
///    straight. Each edge is generated once and used by both sections beside it.
///  - each cell's outline is triangulated by ear clipping (the outlines are simple polygons but, with
///    splinters, not star-shaped) and extruded over each cell layer of the thickness.
/// Random numbers come from one SplitMix64 stream seeded with mSeed, drawn in a fixed order (lattice corners
/// row by row, then horizontal edges, then vertical edges): bitwise reproducible.
class CRUMPLE_API ProceduralEdgeMesh
{
  public:
    /// Builds the sections and binds each vertex to an element of its own cell's group (EmbeddedMesh).
    /// Refused with a message naming the field: invalid settings (ValidateProceduralEdgeSettings, then the
    /// amplitudes against the actual cell sizes, ValidateEdgeAmplitudes), an invalid grid, a mesh that is not
    /// the grid's (node or element count), or more than TetMesh::cMaxCount display vertices.
    /// @param[in] inGrid      the box, as given to TetGrid()
    /// @param[in] inMesh      TetGrid(inGrid), in its rest state
    /// @param[in] inSettings  the edge parameters
    static Result<ProceduralEdgeMesh> Create(const TetGridSettings& inGrid, const TetMesh& inMesh,
                                             const ProceduralEdgeSettings& inSettings);

    /// The display mesh and its binding; EmbeddedMesh::Update() moves it with the simulation
    const EmbeddedMesh& GetEmbeddedMesh() const { return mEmbeddedMesh; }
    /// The sections in group order (group id = index), n_x n_y n_z of them
    const std::vector<EdgeSection>& GetSections() const { return mSections; }
    /// {width axis u, height axis v, thickness axis t} (WallAxes of the grid size)
    const std::array<int, 3>& GetAxes() const { return mAxes; }

  private:
    ProceduralEdgeMesh(EmbeddedMesh inEmbeddedMesh, std::vector<EdgeSection> inSections,
                       std::array<int, 3> inAxes);

    EmbeddedMesh mEmbeddedMesh;
    std::vector<EdgeSection> mSections;
    std::array<int, 3> mAxes;
};

} // namespace crumple::fem
