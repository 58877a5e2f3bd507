// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BodyState.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

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

    // A subnormal mass is > 0 but has an infinite inverse (found by a bad-input audit: its contacts made no
    // collision); the least dynamic mass is the engines' bodies' (ConvexBodySettings), 1e-12 kg.
    BodyState subnormal = state;
    subnormal.mMass = std::numeric_limits<double>::denorm_min();
    CHECK(ValidateBodyState(subnormal).GetError().mCode == EError::OutOfRange);
    subnormal.mMass = 0.9e-12;
    CHECK(ValidateBodyState(subnormal).GetError().mCode == EError::OutOfRange);
    subnormal.mMass = cMinBodyMass;
    CHECK(ValidateBodyState(subnormal).IsValid());

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

TEST_CASE("ValidateBodyState judges an inverse inertia by its smallest eigenvalue, semi-definite ones too", "[plugin]")
{
    // In a tilted frame, so that no entry alone tells: R diag(d) R^T.
    const Mat3 tilt = (Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized())).toRotationMatrix();
    const auto with_eigenvalues = [&](const Vec3& inEigenvalues) {
        BodyState state;
        state.mInverseInertiaWorld = tilt * inEigenvalues.asDiagonal() * tilt.transpose();
        state.mInverseInertiaWorld = 0.5 * (state.mInverseInertiaWorld + state.mInverseInertiaWorld.transpose()).eval();
        return ValidateBodyState(state);
    };
    CHECK(with_eigenvalues(Vec3(0.5, 0.25, 2.0)).IsValid());  // positive definite (the fast path)
    CHECK(with_eigenvalues(Vec3(0.5, 0.0, 2.0)).IsValid());   // infinite inertia about one axis
    CHECK(with_eigenvalues(Vec3(0.5, -1.0e-15, 2.0)).IsValid()); // within the tolerance of 1e-12 x the largest entry
    CHECK(with_eigenvalues(Vec3(0.5, -1.0e-6, 2.0)).HasError());
    CHECK(with_eigenvalues(Vec3(-0.5, 0.25, 2.0)).HasError());
}

TEST_CASE("A motion type outside the enum is refused", "[plugin]")
{
    BodyState state;
    state.mMotionType = static_cast<EMotionType>(7);
    const Status status = ValidateBodyState(state);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("mMotionType") != std::string::npos);
}

TEST_CASE("Body states past the documented ranges are refused", "[plugin]")
{
    auto refused = [](const BodyState& inState, const char* inField) {
        const Status status = ValidateBodyState(inState);
        INFO(inField);
        REQUIRE(status.HasError());
        CHECK(status.GetError().mMessage.find(inField) != std::string::npos);
    };
    BodyState state;
    state.mLinearVelocity = Vec3(1.0e160, 0.0, 0.0); // its impulses overflowed and dented nothing
    refused(state, "mLinearVelocity");
    state = BodyState{};
    state.mAngularVelocity = Vec3(0.0, 2.0e6, 0.0);
    refused(state, "mAngularVelocity");
    state = BodyState{};
    state.mMass = 1.0e13;
    refused(state, "mMass");
    state = BodyState{};
    state.mCenterOfMass = Vec3(0.0, 0.0, 1.0e10);
    refused(state, "farther");
    state = BodyState{};
    state.mInverseInertiaWorld = 1.0e13 * Mat3::Identity();
    refused(state, "mInverseInertiaWorld");
    CHECK(ValidateBodyState(BodyState{}));
}
