// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SameBytes.h"
#include "WorldFixture.h"

#include <crumple/base/ByteWriter.h>
#include <crumple/base/Crc32.h>

#include <catch2/catch.hpp>

#include <cstring>

using namespace crumple;
using crumple::common::SameBytes;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

namespace
{

void Crash(WorldFixture& ioFixture, double inSpeed, double inY)
{
    REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(inSpeed)));
    REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{ioFixture.FrontContact(inY, 0.2, 0.0)}));
    ioFixture.mWorld.Flush();
}

const std::vector<Vec3>& CarPositions(const WorldFixture& inFixture)
{
    return inFixture.mWorld.GetObject(inFixture.mCarObject)->GetDeformer().GetPositions();
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

TEST_CASE("Damage saved and loaded into a fresh world rebuilds the same mesh bit for bit", "[plugin]")
{
    WorldFixture live;
    Crash(live, 12.0, 0.3);
    Crash(live, 6.0, -0.5);
    const std::vector<std::byte> saved = live.mWorld.SaveDamage();

    WorldFixture restored;
    REQUIRE(restored.mWorld.LoadDamage(saved));
    CHECK(SameBytes(CarPositions(restored), CarPositions(live)));
    CHECK(restored.mWorld.SaveDamage() == saved);
}

TEST_CASE("A corrupt, truncated, foreign or mismatched damage file is refused and changes nothing", "[plugin]")
{
    WorldFixture live;
    Crash(live, 12.0, 0.3);
    std::vector<std::byte> saved = live.mWorld.SaveDamage();

    WorldFixture target;
    Crash(target, 5.0, -0.2);
    const std::vector<Vec3> before = CarPositions(target);

    SECTION("a flipped bit")
    {
        saved[saved.size() / 2] ^= std::byte{0x01};
        const Status status = target.mWorld.LoadDamage(saved);
        REQUIRE(status.HasError());
        CHECK(status.GetError().mCode == EError::CorruptData);
    }
    SECTION("truncated at every length")
    {
        for (std::size_t length = 0; length < saved.size(); length += 97)
            REQUIRE(target.mWorld.LoadDamage(std::span(saved).first(length)).HasError());
    }
    SECTION("another version")
    {
        saved[8] = std::byte{static_cast<unsigned char>(cDamageStateVersion + 1)};
        FixChecksum(saved);
        CHECK(target.mWorld.LoadDamage(saved).GetError().mCode == EError::VersionMismatch);
    }
    SECTION("not a damage file")
    {
        saved[0] = std::byte{'X'};
        CHECK(target.mWorld.LoadDamage(saved).GetError().mCode == EError::CorruptData);
    }
    SECTION("a NaN displacement behind a valid checksum")
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::memcpy(saved.data() + 28, &nan, sizeof(double)); // the first control displacement
        FixChecksum(saved);
        CHECK(target.mWorld.LoadDamage(saved).GetError().mCode == EError::CorruptData);
    }
    SECTION("a world with other objects")
    {
        WorldFixture other(4000, {6, 6, 6});
        Crash(other, 12.0, 0.3);
        CHECK(target.mWorld.LoadDamage(other.mWorld.SaveDamage()).GetError().mCode == EError::StateMismatch);
    }
    CHECK(SameBytes(CarPositions(target), before));
}

TEST_CASE("A damage state with a value on a control that reaches no vertex is refused and changes nothing", "[plugin]")
{
    // On the default 0.15 m lattice the controls in the middle of the box car reach no surface vertex. A
    // dent never stores a value there, so a state that does was not written by Crumple: 1e3 m there made a
    // later 10 m/s crash dent 0.3 m instead of 0.013 m.
    WorldFixture fixture(4000, {0, 0, 0});
    DamageState state = fixture.mWorld.GetDamageState();
    REQUIRE(state.mObjects.size() == 1);
    const ffd::FfdLattice& zone = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer().GetZones()[0];
    const std::array<int, 3>& n = zone.GetSettings().mControlCount;
    const int middle = zone.ControlIndex(n[0] / 2, n[1] / 2, n[2] / 2);
    const std::vector<Vec3> before = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer().GetPositions();
    for (double value : {1.0e-6, 1.0e3, 1.0e300})
    {
        INFO("value " << value);
        DamageState bad = state;
        bad.mObjects[0].mZones[0][static_cast<std::size_t>(middle)] = Vec3(value, 0.0, 0.0);
        const Status status = fixture.mWorld.SetDamageState(bad);
        REQUIRE(status.HasError());
        CHECK(status.GetError().mMessage.find("reaches no vertex") != std::string::npos);
        CHECK(fixture.mWorld.GetDamageState().mObjects[0].mZones[0] == state.mObjects[0].mZones[0]);
    }
    CHECK(fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer().GetPositions() == before);
    // And a crash leaves every such control at zero, so its saved state loads back.
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0)));
    const std::vector<ContactEvent> hit{fixture.FrontContact(-0.8, -0.6, 0.0), fixture.FrontContact(0.8, 0.6, 0.0)};
    REQUIRE(fixture.mWorld.SubmitContacts(hit));
    fixture.mWorld.Flush();
    CHECK(fixture.mWorld.GetDamageState().mObjects[0].mZones[0][static_cast<std::size_t>(middle)] == Vec3::Zero());
    CHECK(fixture.mWorld.LoadDamage(fixture.mWorld.SaveDamage()));
}
