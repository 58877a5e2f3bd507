// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"

#include <crumple/base/ByteWriter.h>
#include <crumple/base/Crc32.h>
#include <crumple/base/FileBytes.h>
#include <crumple/fem/HexComplianceFile.h>
#include <crumple/fem/HexCompliancePrecompute.h>
#include <crumple/fem/HexNodesInBox.h>
#include <crumple/fem/HexStaticPrecompute.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A small clamped steel bar and the compliance of its tip face onto every node.
HexCompliance TipCompliance()
{
    HexMeshSettings settings;
    settings.mSize = Vec3(0.5, 0.1, 0.1);
    settings.mCellCount = {5, 2, 2};
    const HexMesh mesh = HexMesh::Create(settings).Get();
    const HexMaterial steel = HexMaterial::Create({}).Get();
    const std::vector<int> clamp = HexNodesInBox(mesh, Vec3(0.0, -1.0, -1.0), Vec3(0.0, 1.0, 1.0));
    const HexStaticData data = HexStaticPrecompute(mesh, steel, clamp).Get();
    const std::vector<int> tip = HexNodesInBox(mesh, Vec3(0.5, -1.0, -1.0), Vec3(0.5, 1.0, 1.0));
    return HexCompliancePrecompute(data, tip, {}).Get();
}

bool SameBits(const HexCompliance& inA, const HexCompliance& inB)
{
    return inA.mNodeCount == inB.mNodeCount && inA.mSourceCrc == inB.mSourceCrc &&
           inA.mLoadNodes == inB.mLoadNodes && inA.mOutputNodes == inB.mOutputNodes &&
           inA.mMatrix.rows() == inB.mMatrix.rows() && inA.mMatrix.cols() == inB.mMatrix.cols() &&
           std::memcmp(inA.mMatrix.data(), inB.mMatrix.data(), sizeof(double) * inA.mMatrix.size()) == 0;
}

// Rewrites the trailing checksum so that a deliberate edit is not caught by the CRC.
void FixChecksum(std::vector<std::byte>& ioBytes)
{
    ioBytes.resize(ioBytes.size() - 4);
    ByteWriter tail;
    tail.WriteU32(Crc32(ioBytes));
    ioBytes.insert(ioBytes.end(), tail.GetBytes().begin(), tail.GetBytes().end());
}

} // namespace

TEST_CASE("Hex compliance save and load round-trip bit for bit", "[fem][hex]")
{
    const HexCompliance compliance = TipCompliance();
    const std::vector<std::byte> bytes = EncodeHexCompliance(compliance).Get();
    // 28-byte header, 9 + 54 node indices, 27 x 162 doubles, 4-byte checksum.
    CHECK(bytes.size() == 28 + 4 * (9 + 54) + 8 * 27 * 162 + 4);
    CHECK(std::memcmp(bytes.data(), "CRUMPHEX", 8) == 0);

    const Result<HexCompliance> decoded = DecodeHexCompliance(bytes);
    REQUIRE(decoded.IsValid());
    CHECK(SameBits(decoded.Get(), compliance));
    CHECK(EncodeHexCompliance(decoded.Get()).Get() == bytes);

    // Through a file.
    const std::filesystem::path path = common::ScratchDirectory() / "hex_round_trip.crumphex";
    REQUIRE(SaveHexCompliance(path, compliance));
    CHECK(ReadFileBytes(path).Get() == bytes);
    const Result<HexCompliance> loaded = LoadHexCompliance(path);
    REQUIRE(loaded.IsValid());
    CHECK(SameBits(loaded.Get(), compliance));
    CHECK_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

TEST_CASE("A corrupt, truncated or other-version compliance file is refused", "[fem][hex]")
{
    const HexCompliance compliance = TipCompliance();
    std::vector<std::byte> bytes = EncodeHexCompliance(compliance).Get();
    SECTION("a flipped bit in the matrix")
    {
        bytes[bytes.size() / 2] ^= std::byte{0x10};
        const Result<HexCompliance> decoded = DecodeHexCompliance(bytes);
        REQUIRE(decoded.HasError());
        CHECK(decoded.GetError().mCode == EError::CorruptData);
        CHECK(decoded.GetError().mMessage.find("checksum") != std::string::npos);
    }
    SECTION("truncated at many lengths")
    {
        for (std::size_t length = 0; length < bytes.size(); length += 71)
        {
            const Result<HexCompliance> decoded = DecodeHexCompliance(std::span(bytes).first(length));
            REQUIRE(decoded.HasError());
            CHECK(decoded.GetError().mCode == EError::CorruptData);
        }
        CHECK(DecodeHexCompliance(std::span(bytes).first(bytes.size() - 1)).HasError());
    }
    SECTION("another version")
    {
        bytes[8] = std::byte{2};
        FixChecksum(bytes);
        const Result<HexCompliance> decoded = DecodeHexCompliance(bytes);
        CHECK(decoded.GetError().mCode == EError::VersionMismatch);
        CHECK(decoded.GetError().mMessage.find("version 2, this library reads version 1") != std::string::npos);
    }
    SECTION("not a compliance file")
    {
        bytes[0] = std::byte{'X'};
        CHECK(DecodeHexCompliance(bytes).GetError().mMessage.find("bad magic") != std::string::npos);
    }
    SECTION("a NaN entry or an out-of-range node behind a valid checksum")
    {
        std::vector<std::byte> nan_bytes = bytes;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::memcpy(nan_bytes.data() + 28 + 4 * 63 + 8 * 100, &nan, sizeof(double));
        FixChecksum(nan_bytes);
        CHECK(DecodeHexCompliance(nan_bytes).GetError().mMessage.find("non-finite") != std::string::npos);
        bytes[28] = std::byte{0xFF}; // first load node becomes >= 255
        FixChecksum(bytes);
        CHECK(DecodeHexCompliance(bytes).GetError().mCode == EError::CorruptData);
    }
}

TEST_CASE("A refused compliance load or save changes nothing on disk", "[fem][hex]")
{
    const HexCompliance compliance = TipCompliance();
    const std::filesystem::path path = common::ScratchDirectory() / "hex_refused.crumphex";
    REQUIRE(SaveHexCompliance(path, compliance));
    std::vector<std::byte> bytes = ReadFileBytes(path).Get();

    // An inconsistent compliance is not written over the good file.
    HexCompliance broken = compliance;
    broken.mLoadNodes.pop_back();
    CHECK(SaveHexCompliance(path, broken).GetError().mCode == EError::InvalidArgument);
    CHECK(ReadFileBytes(path).Get() == bytes);

    // A truncated file on disk is refused with its path in the message.
    const std::filesystem::path cut = common::ScratchDirectory() / "hex_truncated.crumphex";
    {
        std::ofstream out(cut, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size() / 3));
    }
    const Result<HexCompliance> loaded = LoadHexCompliance(cut);
    REQUIRE(loaded.HasError());
    CHECK(loaded.GetError().mCode == EError::CorruptData);
    CHECK(loaded.GetError().mMessage.find("hex_truncated.crumphex") != std::string::npos);
    CHECK(LoadHexCompliance(common::ScratchDirectory() / "missing.crumphex").GetError().mCode == EError::IoError);
}
