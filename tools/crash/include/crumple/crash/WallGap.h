// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/ffd/TriangleMesh.h>

#include <span>

namespace crumple::crash
{

/// How far the surface a flat rigid wall struck ended behind the wall's final plane: a flat wall leaves a
/// flat front, so this is the crushed front's departure from it (a dome where a rounded nose's sides were
/// pushed past the plane, a wavy face).
struct WallGap
{
    double mMean = 0.0;    ///< Mean over the squares below of their gap (m, >= 0)
    double mLargest = 0.0; ///< The largest gap of a square (m, >= 0)
    int mSquares = 0;      ///< Squares the wall met the body in (0: no vertex moved)
};

/// The part of a body a wall that does not span it covers (an offset wall): the rest points p (body frame)
/// with mAcross . p >= mFrom.
struct WallReach
{
    Vec3 mAcross =
        Vec3::UnitY();  ///< Unit direction across the wall's edge, into the wall's span (body frame)
    double mFrom = 0.0; ///< m
};

/// The wall's gap for a car body (its rest mesh and deformed positions, #V, body frame, m). inIntoWall: the
/// wall's normal into the wall, a unit direction in the body frame; inRestNormals: the vertex normals at rest
/// (#V, either winding).
/// The moved vertices are those that moved more than 1 cm; the wall's final plane is the foremost of their
/// positions along inIntoWall. The wall met the foremost surface of each column across it that reached ahead
/// of that plane at rest, so that surface should end on the plane: across the wall in squares of 10 cm, each
/// square's gap is the plane's distance ahead of the foremost final position among the moved vertices in it
/// that lay ahead of the plane at rest on a surface facing the wall (the rest normal within 75 degrees of the
/// wall's normal, either way). Only the foremost counts, and surfaces seen edge-on (a body's sides, its
/// underside) do not: the crush packs what lies behind the struck face behind the wall, as real structure
/// folds. A lattice of control spacing h cannot bend the field within h, so where the crush changes across
/// the front (a nose's flanks, the edge of a bumper) the gap is of the order of h times the surface's slope.
/// inReach: for a wall that covers part of the body only, the vertices it covers (the others, however they
/// moved, are not the wall's to flatten); null: the wall spans the body. Rest positions, rest normals and
/// positions of different lengths give NaN mean and largest over 0 squares.
WallGap MeasureWallGap(const ffd::TriangleMesh& inRest, std::span<const Vec3> inRestNormals,
                       std::span<const Vec3> inPositions, const Vec3& inIntoWall,
                       const WallReach* inReach = nullptr);

} // namespace crumple::crash
