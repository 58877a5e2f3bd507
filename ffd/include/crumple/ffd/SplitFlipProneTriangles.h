// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/RefineLongEdges.h>
#include <crumple/ffd/TriangleMesh.h>

namespace crumple::ffd
{

/// Splits every triangle that a dent bending the surface with curvature up to inBendCurvature could turn
/// over, at the foot of its largest angle on its longest edge (and every other triangle on that edge at the
/// same point), so the surface keeps its shape exactly and stays closed.
///
/// Why: a triangle shows a dent's smooth displacement field as the plane through its three samples. Along its
/// longest edge (length L) a field bending with curvature kappa departs from the straight line between the
/// edge's ends by kappa L^2 s (1 - s) / 2 at the fraction s where the far corner's foot lies; when that
/// exceeds the corner's distance h from the edge, the corner passes the edge and the triangle turns over,
/// although the field folds nothing. So a triangle is flip-prone when h < kappa L^2 s (1 - s) / 2, that is
/// when its own bend limit 2 h / (L^2 s (1 - s)) is below inBendCurvature. SplitCaps' cap angle is the
/// scale-free form of the same test (the sagitta against the height) and misses long triangles under the
/// angle: on the racing car's floor a 0.56 m triangle with a 149.5 degree corner (bend limit 2.0 /m) turned
/// over when the car hit the parked car's corner. The two halves have their short edges across the edge's
/// line and bend limits of order 2 / h: larger triangles need a few rounds (see the return value).
///
/// An edge two flip-prone triangles share is split at the foot of the one with the lower bend limit (the other
/// is looked at again in the next pass; the first in triangle order among equals). Seams and degenerate
/// triangles are treated as SplitCaps treats them.
///
/// @param[in] inMesh           the mesh; ValidateTriangleMesh must accept it
/// @param[in] inBendCurvature  the largest curvature of a dent's displacement field the mesh must show
///                             without turning over (1/m), finite and > 0
/// @return the mesh with the flip-prone triangles split (RefinedMesh: where each added vertex lies; none
///         added when no triangle is flip-prone), or an error for bad input (nothing is half-made). One pass:
///         a piece can still be flip-prone; call again until nothing is added.
CRUMPLE_API Result<RefinedMesh> SplitFlipProneTriangles(const TriangleMesh& inMesh, double inBendCurvature);

} // namespace crumple::ffd
