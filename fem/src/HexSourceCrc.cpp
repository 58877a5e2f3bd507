// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteWriter.h>
#include <crumple/base/Crc32.h>
#include <crumple/fem/HexSourceCrc.h>

namespace crumple::fem
{

std::uint32_t HexSourceCrc(const HexMesh& inMesh, const HexMaterial& inMaterial, std::span<const int> inFixedNodes)
{
    // Serialize every input in a fixed order and byte layout, then checksum it.
    ByteWriter writer;
    writer.WriteU32(static_cast<std::uint32_t>(inMesh.GetNodeCount()));
    for (int n = 0; n < inMesh.GetNodeCount(); ++n)
        for (int axis = 0; axis < 3; ++axis)
            writer.WriteDouble(inMesh.GetNodes()(n, axis));
    writer.WriteU32(static_cast<std::uint32_t>(inMesh.GetElementCount()));
    for (int e = 0; e < inMesh.GetElementCount(); ++e)
        for (int c = 0; c < 8; ++c)
            writer.WriteU32(static_cast<std::uint32_t>(inMesh.GetElements()(e, c)));
    writer.WriteDouble(inMaterial.GetSettings().mYoungsModulus);
    writer.WriteDouble(inMaterial.GetSettings().mPoissonRatio);
    writer.WriteU32(static_cast<std::uint32_t>(inMaterial.GetSettings().mFormulation));
    writer.WriteU32(static_cast<std::uint32_t>(inFixedNodes.size()));
    for (int node : inFixedNodes)
        writer.WriteU32(static_cast<std::uint32_t>(node));
    return Crc32(writer.GetBytes());
}

} // namespace crumple::fem
