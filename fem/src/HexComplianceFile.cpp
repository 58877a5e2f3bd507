// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/FileBytes.h>
#include <crumple/base/Math.h>
#include <crumple/fem/HexComplianceFile.h>
#include <crumple/fem/HexMesh.h>

#include <string>

namespace crumple::fem
{

namespace
{

// Reads one node list, refusing out-of-range and repeated indices.
Status ReadNodeList(ByteReader& ioReader, std::uint32_t inCount, std::uint32_t inNodeCount, const char* inName,
                    std::vector<int>& outNodes)
{
    std::vector<char> seen(inNodeCount, 0);
    outNodes.resize(inCount);
    for (int& node : outNodes)
    {
        const std::uint32_t value = ioReader.ReadU32();
        if (ioReader.Failed() || value >= inNodeCount || seen[value])
            return MakeError(EError::CorruptData, std::string("compliance file: ") + inName +
                                                      " node list is corrupt (index out of range or repeated)");
        seen[value] = 1;
        node = static_cast<int>(value);
    }
    return Status::Ok();
}

// A node list DecodeHexCompliance would take: indices in [0, inNodeCount), none twice.
bool IsNodeList(const std::vector<int>& inNodes, int inNodeCount)
{
    std::vector<char> seen(static_cast<std::size_t>(inNodeCount), 0);
    for (int node : inNodes)
    {
        if (node < 0 || node >= inNodeCount || seen[static_cast<std::size_t>(node)] != 0)
            return false;
        seen[static_cast<std::size_t>(node)] = 1;
    }
    return true;
}

} // namespace

Result<std::vector<std::byte>> EncodeHexCompliance(const HexCompliance& inCompliance)
{
    // Only what DecodeHexCompliance takes is written: a file Save writes over a good one must load again.
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(inCompliance.mOutputNodes.size());
    const Eigen::Index cols = 3 * static_cast<Eigen::Index>(inCompliance.mLoadNodes.size());
    if (cols == 0 || rows == 0 || inCompliance.mMatrix.rows() != rows || inCompliance.mMatrix.cols() != cols ||
        inCompliance.mNodeCount <= 0 || inCompliance.mNodeCount > HexMesh::cMaxNodeCount)
        return MakeError(EError::InvalidArgument,
                         "EncodeHexCompliance: the compliance is empty, has too many nodes, or its matrix does not match "
                         "its node lists");
    if (!IsNodeList(inCompliance.mLoadNodes, inCompliance.mNodeCount) ||
        !IsNodeList(inCompliance.mOutputNodes, inCompliance.mNodeCount))
        return MakeError(EError::InvalidArgument,
                         "EncodeHexCompliance: a load or output node is out of range or repeated");
    if (!IsFinite(inCompliance.mMatrix))
        return MakeError(EError::NonFinite, "EncodeHexCompliance: the matrix holds a non-finite entry");

    ByteWriter writer;
    writer.WriteTag(cHexComplianceMagic);
    writer.WriteU32(cHexComplianceVersion);
    writer.WriteU32(static_cast<std::uint32_t>(inCompliance.mNodeCount));
    writer.WriteU32(inCompliance.mSourceCrc);
    writer.WriteU32(static_cast<std::uint32_t>(inCompliance.mLoadNodes.size()));
    writer.WriteU32(static_cast<std::uint32_t>(inCompliance.mOutputNodes.size()));
    for (int node : inCompliance.mLoadNodes)
        writer.WriteU32(static_cast<std::uint32_t>(node));
    for (int node : inCompliance.mOutputNodes)
        writer.WriteU32(static_cast<std::uint32_t>(node));
    for (Eigen::Index col = 0; col < cols; ++col)
        for (Eigen::Index row = 0; row < rows; ++row)
            writer.WriteDouble(inCompliance.mMatrix(row, col));
    writer.WriteChecksum();
    return writer.TakeBytes();
}

Result<HexCompliance> DecodeHexCompliance(std::span<const std::byte> inBytes)
{
    // Magic and version first, so a foreign or newer file gets the right message.
    ByteReader header(inBytes);
    if (!header.ReadTag(cHexComplianceMagic))
        return MakeError(EError::CorruptData, "not a Crumple hex compliance file (bad magic)");
    const std::uint32_t version = header.ReadU32();
    if (header.Failed())
        return MakeError(EError::CorruptData, "compliance file is truncated in its header");
    if (version != cHexComplianceVersion)
        return MakeError(EError::VersionMismatch, "compliance file version " + std::to_string(version) +
                                                      ", this library reads version " +
                                                      std::to_string(cHexComplianceVersion));
    ByteReader body(inBytes);
    if (Status checksum = body.VerifyAndStripChecksum(); !checksum)
        return MakeError(EError::CorruptData, "compliance file: " + checksum.GetError().mMessage);
    body.Skip(cHexComplianceMagic.size() + 4);

    // Counts, checked against the bytes left so that a corrupt count cannot allocate gigabytes.
    HexCompliance compliance;
    const std::uint32_t node_count = body.ReadU32();
    compliance.mSourceCrc = body.ReadU32();
    const std::uint32_t load_count = body.ReadU32();
    const std::uint32_t output_count = body.ReadU32();
    if (body.Failed() || node_count == 0 || node_count > static_cast<std::uint32_t>(HexMesh::cMaxNodeCount) ||
        load_count == 0 || output_count == 0 || load_count > node_count || output_count > node_count)
        return MakeError(EError::CorruptData, "compliance file: node counts are corrupt");
    const unsigned long long expected = 4ULL * load_count + 4ULL * output_count + 72ULL * load_count * output_count;
    if (expected != body.Remaining())
        return MakeError(EError::CorruptData, "compliance file: counts do not match the length (truncated or corrupt)");
    compliance.mNodeCount = static_cast<int>(node_count);

    if (Status status = ReadNodeList(body, load_count, node_count, "load", compliance.mLoadNodes); !status)
        return status.GetError();
    if (Status status = ReadNodeList(body, output_count, node_count, "output", compliance.mOutputNodes); !status)
        return status.GetError();

    // The matrix, column-major.
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(output_count);
    const Eigen::Index cols = 3 * static_cast<Eigen::Index>(load_count);
    compliance.mMatrix.resize(rows, cols);
    for (Eigen::Index col = 0; col < cols; ++col)
        for (Eigen::Index row = 0; row < rows; ++row)
            compliance.mMatrix(row, col) = body.ReadDouble();
    if (body.Failed() || body.Remaining() != 0)
        return MakeError(EError::CorruptData, "compliance file length does not match its contents");
    if (!IsFinite(compliance.mMatrix))
        return MakeError(EError::CorruptData, "compliance file holds a non-finite entry");
    return compliance;
}

Status SaveHexCompliance(const std::filesystem::path& inPath, const HexCompliance& inCompliance)
{
    Result<std::vector<std::byte>> bytes = EncodeHexCompliance(inCompliance);
    if (bytes.HasError())
        return bytes.GetError();
    if (inPath.empty())
        return MakeError(EError::InvalidArgument, "SaveHexCompliance: empty path");

    return WriteFileAtomically(inPath, bytes.Get(), "SaveHexCompliance");
}

Result<HexCompliance> LoadHexCompliance(const std::filesystem::path& inPath)
{
    Result<std::vector<std::byte>> bytes = ReadFileBytes(inPath);
    if (bytes.HasError())
        return bytes.GetError();
    Result<HexCompliance> compliance = DecodeHexCompliance(bytes.Get());
    if (compliance.HasError())
        return MakeError(compliance.GetError().mCode, inPath.string() + ": " + compliance.GetError().mMessage);
    return compliance;
}

} // namespace crumple::fem
