// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>

namespace crumple::test
{

/// A floor panel as the racing car's (the triangle that turned over at the parked car): in the plane z = 0
/// (normal +z), a long edge from 0 (0, 0) to 1 (0, 0.56) along y, the thin triangle's far corner 2 at
/// (-0.05, 0.448) behind it (s = 0.8, h = 0.05: a 149.5 degree corner, under the 150-degree cap angle) and a
/// well-shaped triangle on the edge's other side to 3 (0.4, 0.28).
inline ffd::TriangleMesh ThinFloorPair()
{
    ffd::TriangleMesh mesh;
    mesh.mPositions = {Vec3(0.0, 0.0, 0.0), Vec3(0.0, 0.56, 0.0), Vec3(-0.05, 0.448, 0.0),
                       Vec3(0.4, 0.28, 0.0)};
    mesh.mTriangles = {{0, 1, 2}, {1, 0, 3}};
    return mesh;
}

/// The thin triangle's bend limit 2 h / (L^2 s (1 - s)) = 0.1 / (0.3136 * 0.16) = 1.993 /m.
constexpr double cThinFloorBendLimit = 0.1 / (0.56 * 0.56 * 0.8 * 0.2);

} // namespace crumple::test
