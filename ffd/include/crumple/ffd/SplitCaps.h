// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/RefineLongEdges.h>
#include <crumple/ffd/TriangleMesh.h>

namespace crumple::ffd
{

/// Splits every cap, a triangle with a corner of at least inCapAngle, at the foot of that corner's altitude
/// on its long edge, and every other triangle on that edge at the same point, so the surface keeps its shape
/// exactly and stays closed. A cap becomes two triangles with a right angle at the foot.
///
/// Why: a dent's field bends a cap's long edge by its sagitta, kappa L^2 / 8 for a bend of curvature kappa
/// over the edge's length L, and a cap whose far corner is closer to that edge than the sagitta turns over
/// although the field folds nothing (the Toy Car's front lip: caps 4 mm high and 15 cm long, in a pole's
/// pocket). FlipNearlyFlatEdges removes the caps that lie in a nearly flat pair; a cap whose long edge is a
/// crease (a lip, a trim's edge) cannot flip without changing the shape, and is split here, as Botsch and
/// Kobbelt split what they cannot flip ("A Robust Procedure to Eliminate Degenerate Faces from Triangle
/// Meshes", VMV 2001). The two halves have their short edge across the bend, so the field is nearly affine
/// over it and they turn only where it folds.
///
/// Exporters split vertices along texture seams and hard edges: an edge's other side by position (==) is
/// split too, at the same point, with a vertex of its own, so a seam stays closed and each side keeps its
/// own vertices (textured meshes stay right). A cap whose long edge another cap has already claimed uses
/// that cap's point (triangle order decides); an edge is split once. The result depends only on the input.
///
/// A triangle whose far corner lies on its long edge to within 1e-9 of the edge's length is degenerate, not a
/// cap, and is left as it is: it shows nothing, and its pieces would be as degenerate.
///
/// One pass: a neighbour split at a cap's point can leave a cap among its pieces. In a nearly flat pair
/// FlipNearlyFlatEdges removes it without adding vertices; crumple-crash alternates the two until no cap is
/// left (crash::RecutCarMesh). Splitting again instead adds a vertex per cap and converges slowly (on the
/// Toy Car 4,193 split edges, then 3,094, 2,250, ... 955 after eight passes; with a flip between passes
/// 4,193, 1,430, 591, 238, 81, 31).
///
/// @param[in] inMesh      the mesh; ValidateTriangleMesh must accept it
/// @param[in] inCapAngle  smallest corner that makes a cap (rad), in [pi/2, pi] (crumple-crash: 150 degrees)
/// @return the mesh with the caps split (RefinedMesh: where each added vertex lies), or an error for bad
///         input (nothing is half-made)
CRUMPLE_API Result<RefinedMesh> SplitCaps(const TriangleMesh& inMesh, double inCapAngle);

} // namespace crumple::ffd
