// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BodyState.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::plugin;

TEST_CASE("ValidateBodyState accepts a normal body and names bad fields", "[plugin]")
{
    BodyState state;
    CHECK(ValidateBodyState(state).IsValid());

    BodyState negative = state;
    negative.mMass = -1.0;
    const Status refused = ValidateBodyState(negative);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::InvalidArgument);
    CHECK(refused.GetError().mMessage.find("mMass") != std::string::npos);

    BodyState nan = state;
    nan.mAngularVelocity.y() = std::numeric_limits<double>::quiet_NaN();
    CHECK(ValidateBodyState(nan).GetError().mCode == EError::NonFinite);

    BodyState skew = state;
    skew.mInverseInertiaWorld(0, 1) = 0.5;
    CHECK(ValidateBodyState(skew).HasError());

    BodyState indefinite = state;
    indefinite.mInverseInertiaWorld(2, 2) = -1.0;
    CHECK(ValidateBodyState(indefinite).HasError());

    BodyState reflected = state;
    reflected.mTransform.mRotation(0, 0) = -1.0;
    CHECK(ValidateBodyState(reflected).GetError().mCode == EError::DegenerateGeometry);

    // Static bodies need no mass.
    BodyState wall;
    wall.mMotionType = EMotionType::Static;
    wall.mMass = 0.0;
    CHECK(ValidateBodyState(wall).IsValid());
    CHECK(wall.InverseMass() == 0.0);
    CHECK(wall.InverseInertia() == Mat3::Zero());
}

TEST_CASE("A motion type outside the enum is refused", "[plugin]")
{
    BodyState state;
    state.mMotionType = static_cast<EMotionType>(7);
    const Status status = ValidateBodyState(state);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("mMotionType") != std::string::npos);
}
