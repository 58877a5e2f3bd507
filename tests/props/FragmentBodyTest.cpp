// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A prop's loose fragment as a rigid body: exact mass and inertia, the nodes' momentum, their rigid spin, and
// never more kinetic energy than the nodes had.
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/props/FragmentBody.h>

#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <span>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::props;

namespace
{

// A free 0.6 m x 0.1 m x 0.2 m block (a piece of a fence rail), 3 x 2 x 2 cells.
TetSolver Block()
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(0.1, -0.05, 0.3);
    grid.mSize = Vec3(0.6, 0.1, 0.2);
    grid.mCellCount = {3, 2, 2};
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    return TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings{}, settings).Get();
}

plugin::BodyState StaticProp(const Mat3& inRotation, const Vec3& inTranslation)
{
    plugin::BodyState state;
    state.mMotionType = plugin::EMotionType::Static;
    state.mTransform.mRotation = inRotation;
    state.mTransform.mTranslation = inTranslation;
    return state;
}

} // namespace

TEST_CASE("A loose fragment's rigid body: exact mass, inertia and momentum, its rigid spin, no energy gained", "[props]")
{
    TetSolver block = Block();
    const std::vector<TetFragment> fragments = block.ComputeFragments();
    REQUIRE(fragments.size() == 1);
    const TetFragment& fragment = fragments[0];
    const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
    const Vec3 translation(3.0, -1.0, 0.5);
    const plugin::BodyState prop = StaticProp(rotation, translation);
    const std::vector<Vec3>& x = block.GetPositions();
    const std::vector<double>& m = block.GetMasses();

    SECTION("a rigid motion keeps its spin exactly and its momentum")
    {
        const Vec3 v0(1.0, -2.0, 0.5), w(0.3, 4.0, -1.5);
        std::vector<Vec3> v(x.size());
        for (std::size_t n = 0; n < x.size(); ++n)
            v[n] = v0 + w.cross(x[n] - fragment.mCenterOfMass);
        const FragmentRigidBody body = FragmentBody(fragment, x, v, m, prop).Get();
        CHECK((body.mBody.mAngularVelocity - rotation * w).norm() <= 1.0e-12 * w.norm());
        Vec3 momentum = Vec3::Zero();
        for (std::size_t n = 0; n < x.size(); ++n)
            momentum += m[n] * v[n];
        CHECK((body.mBody.mMass * body.mBody.mLinearVelocity - rotation * momentum).norm() <= 1.0e-12 * momentum.norm());
        CHECK(body.mRigidKineticEnergy <= body.mNodalKineticEnergy);
    }
    SECTION("any motion: mass, inertia, centre and momentum exact, energy never grows")
    {
        std::mt19937_64 random(4);
        std::normal_distribution<double> normal;
        for (int trial = 0; trial < 20; ++trial)
        {
            std::vector<Vec3> v(x.size());
            for (Vec3& velocity : v)
                velocity = common::DrawVec3([&] { return normal(random); });
            const FragmentRigidBody body = FragmentBody(fragment, x, v, m, prop).Get();
            CHECK(body.mBody.mMass == fragment.mMass);
            const Mat3 world_inertia = rotation * fragment.mInertia * rotation.transpose();
            CHECK((body.mBody.WorldInertia() - world_inertia).norm() <= 1.0e-12 * world_inertia.norm());
            CHECK((body.mBody.mPosition - (rotation * fragment.mCenterOfMass + translation)).norm() <= 1.0e-12);
            Vec3 momentum = Vec3::Zero();
            for (std::size_t n = 0; n < x.size(); ++n)
                momentum += m[n] * v[n];
            CHECK((body.mBody.mMass * body.mBody.mLinearVelocity - rotation * momentum).norm() <= 1.0e-12 * momentum.norm());
            CHECK(body.mRigidKineticEnergy <= body.mNodalKineticEnergy);
            CHECK(body.mRigidKineticEnergy > 0.0);
            // The hull points are the nodes, in the body frame.
            REQUIRE(body.mBody.mHullPoints.size() == fragment.mNodes.size());
            const Vec3 node = x[static_cast<std::size_t>(fragment.mNodes[3])];
            CHECK((body.mBody.mOrientation * body.mBody.mHullPoints[3] + body.mBody.mPosition - (rotation * node + translation)).norm() <=
                  1.0e-12);
        }
    }
    SECTION("bad input is refused")
    {
        std::vector<Vec3> v(x.size(), Vec3::Zero());
        TetFragment anchored = fragment;
        anchored.mAnchored = true;
        CHECK_FALSE(FragmentBody(anchored, x, v, m, prop));
        CHECK_FALSE(FragmentBody(fragment, x, std::span<const Vec3>(v).first(3), m, prop));
        TetFragment wrong = fragment;
        wrong.mNodes.push_back(static_cast<int>(x.size()));
        CHECK_FALSE(FragmentBody(wrong, x, v, m, prop));
        v[0].x() = std::nan("");
        CHECK_FALSE(FragmentBody(fragment, x, v, m, prop));
        // Masses that are not the fragment's shared out: a negative one, or all a million times lighter than
        // the fragment (its elements lump at least its mass onto its nodes)
        v[0].x() = 0.0;
        REQUIRE(FragmentBody(fragment, x, v, m, prop));
        std::vector<double> bad_masses = m;
        bad_masses[static_cast<std::size_t>(fragment.mNodes[0])] = -1.0;
        CHECK_FALSE(FragmentBody(fragment, x, v, bad_masses, prop));
        for (double& mass : bad_masses = m)
            mass *= 1.0e-6;
        CHECK_FALSE(FragmentBody(fragment, x, v, bad_masses, prop));
    }
}

TEST_CASE("ConvexBodySettings refuses what no rigid body can be", "[props]")
{
    plugin::ConvexBodySettings settings;
    settings.mHullPoints = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    CHECK(plugin::ValidateConvexBodySettings(settings));
    plugin::ConvexBodySettings bad = settings;
    bad.mMass = -1.0;
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mPrincipalInertia = Vec3(1.0, 1.0, 3.0); // above the sum of the others
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mOrientation(0, 0) = 2.0;
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mHullPoints = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}; // flat
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mAngularVelocity.y() = std::numeric_limits<double>::infinity();
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    // Masses and inertias a single-precision engine would turn into a static body or an infinite inertia
    bad = settings;
    bad.mMass = 1.0e-50;
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mPrincipalInertia = Vec3(1.0e-50, 1.0e-50, 1.0e-50);
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mPrincipalInertia = Vec3(1.0e35, 1.0e35, 1.0e35);
    CHECK_FALSE(plugin::ValidateConvexBodySettings(bad));
    bad = settings;
    bad.mMass = 1.0e-12; // the least accepted
    bad.mPrincipalInertia = Vec3(1.0e-12, 1.0e-12, 1.0e-12);
    CHECK(plugin::ValidateConvexBodySettings(bad));
}
