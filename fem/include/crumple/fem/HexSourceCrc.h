// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/HexMaterial.h>
#include <crumple/fem/HexMesh.h>

#include <cstdint>
#include <span>

namespace crumple::fem
{

/// Fingerprint of what a precomputation depends on: CRC-32 of the node positions, the connectivity, E, nu,
/// the formulation and the fixed nodes, in the little-endian encoding of ByteWriter. HexStaticData and
/// HexCompliance carry it, so that a game can check that a loaded compliance belongs to its mesh.
/// @param[in] inMesh        the mesh
/// @param[in] inMaterial    the material
/// @param[in] inFixedNodes  fixed node indices, ascending and without repeats (as in HexStaticData)
CRUMPLE_API std::uint32_t HexSourceCrc(const HexMesh& inMesh, const HexMaterial& inMaterial, std::span<const int> inFixedNodes);

} // namespace crumple::fem
