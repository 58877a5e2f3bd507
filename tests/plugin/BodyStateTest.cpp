// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/DamageWorld.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

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

namespace
{

// A car's state as an engine in single precision holds it: rotation and world inverse inertia R D R^T
// computed in float, then widened to double.
BodyState SinglePrecisionCar(const Eigen::Quaternionf& inOrientation)
{
    const Eigen::Matrix3f rotation = inOrientation.normalized().toRotationMatrix();
    const Eigen::Vector3f inverse_moments(1.0f / 450.0f, 1.0f / 1900.0f, 1.0f / 2100.0f);
    BodyState state;
    state.mMass = 1200.0;
    state.mTransform.mRotation = rotation.cast<double>();
    state.mInverseInertiaWorld =
        (rotation * inverse_moments.asDiagonal() * rotation.transpose()).eval().cast<double>();
    return state;
}

double Asymmetry(const Mat3& inMatrix)
{
    return (inMatrix - inMatrix.transpose()).cwiseAbs().maxCoeff() / inMatrix.cwiseAbs().maxCoeff();
}

} // namespace

// Jolt, PhysX and Bullet's default build hand their states over in float: before, ValidateBodyState asked a
// rotation orthonormal to 1e-6 and an inverse inertia symmetric to 1e-9, and refused most of them (the
// glue's SetBodyState then kept the body's last state, and its impulses came from stale velocities).
TEST_CASE(
    "A single-precision engine's body states are accepted and kept as a rotation and a symmetric inertia",
    "[plugin]")
{
    std::mt19937 random(7);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    double worst_rotation = 0.0, worst_asymmetry = 0.0;
    int refused_before = 0;
    for (int draw = 0; draw < 2000; ++draw)
    {
        const BodyState given = SinglePrecisionCar(
            Eigen::Quaternionf(normal(random), normal(random), normal(random), normal(random)));
        worst_rotation =
            std::max(worst_rotation,
                     (given.mTransform.mRotation * given.mTransform.mRotation.transpose() - Mat3::Identity())
                         .cwiseAbs()
                         .maxCoeff());
        worst_asymmetry = std::max(worst_asymmetry, Asymmetry(given.mInverseInertiaWorld));
        refused_before +=
            !IsRotation(given.mTransform.mRotation, 1.0e-6) || Asymmetry(given.mInverseInertiaWorld) > 1.0e-9
                ? 1
                : 0;
        REQUIRE(ValidateBodyState(given));
        const BodyState kept = CanonicalBodyState(given);
        // within the bounds the library held before it took float input
        CHECK(IsRotation(kept.mTransform.mRotation, 1.0e-6));
        CHECK(Asymmetry(kept.mInverseInertiaWorld) <= 1.0e-9);
        // within float round-off of what was given
        CHECK((kept.mTransform.mRotation - given.mTransform.mRotation).cwiseAbs().maxCoeff() <= 2.0e-6);
        CHECK((kept.mInverseInertiaWorld - given.mInverseInertiaWorld).cwiseAbs().maxCoeff() <=
              1.0e-6 * given.mInverseInertiaWorld.cwiseAbs().maxCoeff());
    }
    INFO("float states: rotations orthonormal to " << worst_rotation << ", inverse inertias symmetric to "
                                                   << worst_asymmetry << "; " << refused_before
                                                   << " of 2000 past the old bounds");
    CHECK(refused_before > 1000); // the case is real: most float states failed the old bounds

    // A damage world takes them and keeps their canonical form.
    const std::unique_ptr<DamageWorld> world = std::move(DamageWorld::Create().Get());
    const BodyState given = SinglePrecisionCar(Eigen::Quaternionf(0.3f, -0.2f, 0.9f, 0.1f));
    REQUIRE(Asymmetry(given.mInverseInertiaWorld) > 1.0e-9);
    const Result<BodyId> car = world->CreateBody(given);
    REQUIRE(car);
    CHECK(Asymmetry(world->GetBodyState(car.Get())->mInverseInertiaWorld) <= 1.0e-9);
    CHECK(world->SetBodyState(car.Get(), SinglePrecisionCar(Eigen::Quaternionf(-0.5f, 0.4f, 0.1f, 0.7f))));
    CHECK(Asymmetry(world->GetBodyState(car.Get())->mInverseInertiaWorld) <= 1.0e-9);
}

TEST_CASE("A double-precision body state is kept bit for bit, one past single-precision round-off is refused",
          "[plugin]")
{
    BodyState exact;
    exact.mTransform.mRotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    exact.mInverseInertiaWorld = exact.mTransform.mRotation *
                                 Vec3(1.0 / 450.0, 1.0 / 1900.0, 1.0 / 2100.0).asDiagonal() *
                                 exact.mTransform.mRotation.transpose();
    exact.mInverseInertiaWorld =
        0.5 * (exact.mInverseInertiaWorld + exact.mInverseInertiaWorld.transpose()).eval();
    exact.mLinearVelocity = Vec3(15.0, 0.1, -0.2);
    const BodyState kept = CanonicalBodyState(exact);
    CHECK(std::memcmp(kept.mTransform.mRotation.data(), exact.mTransform.mRotation.data(), sizeof(Mat3)) ==
          0);
    CHECK(std::memcmp(kept.mInverseInertiaWorld.data(), exact.mInverseInertiaWorld.data(), sizeof(Mat3)) ==
          0);
    CHECK(kept.mLinearVelocity == exact.mLinearVelocity);

    BodyState stretched = exact;
    stretched.mTransform.mRotation *= 1.0 + 1.0e-4;
    CHECK(ValidateBodyState(stretched).GetError().mCode == EError::DegenerateGeometry);
    BodyState skewed = exact;
    skewed.mInverseInertiaWorld(0, 1) += 1.0e-4 * exact.mInverseInertiaWorld.cwiseAbs().maxCoeff();
    const Status refused = ValidateBodyState(skewed);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("symmetric") != std::string::npos);
}
