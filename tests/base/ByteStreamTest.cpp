// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;

TEST_CASE("ByteWriter and ByteReader round-trip every type bit-exactly", "[base]")
{
    ByteWriter writer;
    writer.WriteTag("MAGIC");
    writer.WriteU8(0xAB);
    writer.WriteU32(0xDEADBEEFu);
    writer.WriteU64(0x0123456789ABCDEFull);
    writer.WriteDouble(-0.1);
    writer.WriteDouble(std::numeric_limits<double>::denorm_min());
    writer.WriteVec3(Vec3(1.0 / 3.0, -2.5e300, 0.0));
    writer.WriteChecksum();

    ByteReader reader(writer.GetBytes());
    REQUIRE(reader.VerifyAndStripChecksum());
    CHECK(reader.ReadTag("MAGIC"));
    CHECK(reader.ReadU8() == 0xAB);
    CHECK(reader.ReadU32() == 0xDEADBEEFu);
    CHECK(reader.ReadU64() == 0x0123456789ABCDEFull);
    CHECK(reader.ReadDouble() == -0.1);
    CHECK(reader.ReadDouble() == std::numeric_limits<double>::denorm_min());
    CHECK(reader.ReadVec3() == Vec3(1.0 / 3.0, -2.5e300, 0.0));
    CHECK_FALSE(reader.Failed());
    CHECK(reader.Remaining() == 0);
}

TEST_CASE("ByteWriter writes little-endian", "[base]")
{
    ByteWriter writer;
    writer.WriteU32(0x04030201u);
    const std::vector<std::byte>& bytes = writer.GetBytes();
    REQUIRE(bytes.size() == 4);
    for (int i = 0; i < 4; ++i)
        CHECK(static_cast<int>(bytes[static_cast<std::size_t>(i)]) == i + 1);
}

TEST_CASE("ByteReader refuses truncated and corrupt data", "[base]")
{
    ByteWriter writer;
    writer.WriteU64(42);
    writer.WriteChecksum();
    std::vector<std::byte> bytes = writer.GetBytes();

    SECTION("a flipped bit fails the checksum")
    {
        bytes[3] ^= std::byte{0x10};
        ByteReader reader(bytes);
        const Status status = reader.VerifyAndStripChecksum();
        REQUIRE(status.HasError());
        CHECK(status.GetError().mCode == EError::CorruptData);
    }
    SECTION("a truncated buffer fails the checksum")
    {
        bytes.pop_back();
        ByteReader reader(bytes);
        CHECK(reader.VerifyAndStripChecksum().HasError());
    }
    SECTION("reading past the end fails and stays failed")
    {
        ByteReader reader(std::span<const std::byte>(bytes).first(6));
        CHECK(reader.ReadU64() == 0);
        CHECK(reader.Failed());
        CHECK(reader.ReadU8() == 0);
        CHECK(reader.Failed());
    }
}
