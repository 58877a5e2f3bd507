// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A contact's impulse spread over its footprint (ContactSpread, FemProp::SetContactSpread): the impulse is
// kept, only free nodes within the radius take a share, their velocity change follows the kernel, a radius of
// 0 (or one no node lies within) is the containing element's four nodes bit for bit, and bad radii are
// refused, changing nothing.
#include "WallPanelMesh.h"

#include <crumple/fem/TetSolver.h>
#include <crumple/props/CollisionImpulses.h>
#include <crumple/props/FemProp.h>
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif

#include "GpuFallback.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// The wall panel in 0.2 m cells (the prop's body frame).
TetMesh PanelMesh()
{
    return test::WallPanelMesh({1, 10, 10});
}

TetSolver Panel()
{
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    return TetSolver::Create(PanelMesh(), FemMaterialSettings{}, settings).Get();
}

// One contact on the face x = 0, off every node, pushing the prop (body A) along +x and a little sideways.
Collision OneContact(const Vec3& inPoint)
{
    Collision collision;
    collision.mBodyA = BodyId{3};
    collision.mBodyB = BodyId{7};
    CollisionContact contact;
    contact.mLocalPointOnA = inPoint;
    contact.mLocalPointOnB = inPoint;
    contact.mLocalNormalOnA = Vec3(1.0, 0.3, 0.0).normalized();
    contact.mLocalNormalOnB = -contact.mLocalNormalOnA;
    contact.mImpulse = 400.0;
    collision.mContacts.push_back(contact);
    return collision;
}

ContactSpread SpreadOf(const TetSolver& inSolver, double inRadius)
{
    return ContactSpread{.mRadius = inRadius, .mMasses = inSolver.GetMasses(), .mInverseMasses = inSolver.GetInverseMasses()};
}

} // namespace

TEST_CASE("A contact spread keeps the impulse and gives the free nodes within its radius a smooth velocity change",
          "[props]")
{
    TetSolver panel = Panel();
    const Vec3 point(0.0, 0.13, -0.07);
    const double radius = 0.45;
    // Two nodes inside the footprint are anchored: they take no share, and the rest still take it all.
    int anchored = 0;
    for (std::size_t node = 0; node < panel.GetPositions().size() && anchored < 2; ++node)
        if ((panel.GetPositions()[node] - point).norm() < 0.3)
        {
            REQUIRE(panel.SetNodeFixed(static_cast<int>(node), true));
            ++anchored;
        }
    REQUIRE(anchored == 2);
    const Collision collision = OneContact(point);
    const Result<std::vector<NodalImpulse>> spread =
        CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(), SpreadOf(panel, radius));
    REQUIRE(spread.IsValid());

    const Vec3 impulse = 400.0 * collision.mContacts[0].mLocalNormalOnA;
    Vec3 total = Vec3::Zero();
    std::map<int, Vec3> per_node;
    for (const NodalImpulse& share : spread.Get())
    {
        total += share.mImpulse;
        per_node.try_emplace(share.mNode, Vec3::Zero()).first->second += share.mImpulse; // Eigen leaves a default Vec3 unset
    }
    CHECK((total - impulse).norm() <= 1e-12 * impulse.norm());

    // Exactly the free nodes within the radius, each moved along the impulse by c (1 - d^2/r^2)^2 with one c.
    int inside = 0;
    double scale = 0.0;
    for (std::size_t node = 0; node < panel.GetPositions().size(); ++node)
    {
        const double reach = (panel.GetPositions()[node] - point).squaredNorm() / (radius * radius);
        const bool free = panel.GetInverseMasses()[node] > 0.0;
        const auto found = per_node.find(static_cast<int>(node));
        INFO("node " << node << " at reach " << reach);
        CHECK((found != per_node.end()) == (reach < 1.0 && free));
        if (found == per_node.end())
            continue;
        ++inside;
        const Vec3 velocity_change = panel.GetInverseMasses()[node] * found->second;
        CHECK(velocity_change.cross(impulse).norm() <= 1e-12 * velocity_change.norm() * impulse.norm());
        const double kernel = (1.0 - reach) * (1.0 - reach);
        if (scale == 0.0)
            scale = velocity_change.norm() / kernel;
        CHECK(velocity_change.norm() == Approx(scale * kernel).epsilon(1e-12));
    }
    CHECK(inside > 8); // a footprint, not an element

    // The material the contact struck moves slower than the element's four nodes alone would.
    const Result<std::vector<NodalImpulse>> element =
        CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions());
    double fastest_element = 0.0;
    for (const NodalImpulse& share : element.Get())
        fastest_element = std::max(fastest_element, panel.GetInverseMasses()[share.mNode] * share.mImpulse.norm());
    CHECK(scale < 0.25 * fastest_element);
}

TEST_CASE("A contact spread of 0, or with no free node in reach, is the containing element's four nodes bit for bit",
          "[props]")
{
    const TetSolver panel = Panel();
    for (const Vec3& point : {Vec3(0.0, 0.13, -0.07), Vec3(0.05, -0.51, 0.33)})
    {
        const Collision collision = OneContact(point);
        const std::vector<NodalImpulse> element =
            CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions()).Get();
        for (double radius : {0.0, 1.0e-3})
        {
            const std::vector<NodalImpulse> spread =
                CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(), SpreadOf(panel, radius))
                    .Get();
            REQUIRE(spread.size() == element.size());
            for (std::size_t index = 0; index < spread.size(); ++index)
            {
                CHECK(spread[index].mNode == element[index].mNode);
                CHECK(spread[index].mImpulse == element[index].mImpulse);
            }
        }
    }
}

TEST_CASE("A contact whose footprint holds only fixed nodes falls back to its element", "[props]")
{
    TetSolver panel = Panel();
    const Vec3 point(0.0, 0.13, -0.07);
    const double radius = 0.25;
    for (std::size_t node = 0; node < panel.GetPositions().size(); ++node)
        if ((panel.GetPositions()[node] - point).norm() < radius)
            REQUIRE(panel.SetNodeFixed(static_cast<int>(node), true));
    const Collision collision = OneContact(point);
    const std::vector<NodalImpulse> element =
        CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions()).Get();
    const std::vector<NodalImpulse> spread =
        CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(), SpreadOf(panel, radius)).Get();
    REQUIRE(spread.size() == element.size());
    for (std::size_t index = 0; index < spread.size(); ++index)
    {
        CHECK(spread[index].mNode == element[index].mNode);
        CHECK(spread[index].mImpulse == element[index].mImpulse);
    }
}

TEST_CASE("A bad contact spread is refused and changes nothing", "[props]")
{
    const TetSolver panel = Panel();
    const Collision collision = OneContact(Vec3(0.0, 0.13, -0.07));
    for (double radius : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const Result<std::vector<NodalImpulse>> refused =
            CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(), SpreadOf(panel, radius));
        REQUIRE(refused.HasError());
        CHECK(refused.GetError().mMessage.find("spread radius") != std::string::npos);
    }
    // A spread needs one mass and one inverse mass per node.
    const std::vector<double> short_masses(3, 1.0);
    const Result<std::vector<NodalImpulse>> no_masses = CollisionNodalImpulses(
        collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(),
        ContactSpread{.mRadius = 0.2, .mMasses = short_masses, .mInverseMasses = panel.GetInverseMasses()});
    CHECK(no_masses.HasError());
    const std::vector<double> short_inverse(3, 1.0);
    CHECK(CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(),
                                 ContactSpread{.mRadius = 0.2, .mMasses = panel.GetMasses(), .mInverseMasses = short_inverse})
              .HasError());
    // A mass a spread cannot weigh by, even far from the contact: refused, not a silent fallback or a negative share.
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), -1.0, 0.0})
    {
        std::vector<double> masses = panel.GetMasses();
        masses.back() = bad;
        const Result<std::vector<NodalImpulse>> refused =
            CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(),
                                   ContactSpread{.mRadius = 0.2, .mMasses = masses, .mInverseMasses = panel.GetInverseMasses()});
        REQUIRE(refused.HasError());
        CHECK(refused.GetError().mMessage.find("node " + std::to_string(masses.size() - 1)) != std::string::npos);
    }
    std::vector<double> inverse = panel.GetInverseMasses();
    inverse.front() = -1.0;
    CHECK(CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions(),
                                 ContactSpread{.mRadius = 0.2, .mMasses = panel.GetMasses(), .mInverseMasses = inverse})
              .HasError());

    Result<FemProp> prop = FemProp::Create(nullptr, PanelMesh(), FemMaterialSettings{}, TetSolverSettings{}, FemPropSettings{});
    REQUIRE(prop.IsValid());
    CHECK(prop.Get().GetContactSpread() == 0.0);
    REQUIRE(prop.Get().SetContactSpread(0.3).IsValid());
    for (double radius : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const Status refused = prop.Get().SetContactSpread(radius);
        REQUIRE(refused.HasError());
        CHECK(refused.GetError().mCode ==
              (std::isfinite(radius) ? EError::InvalidArgument : EError::NonFinite));
        CHECK(prop.Get().GetContactSpread() == 0.3);
    }
}

TEST_CASE("A prop with a contact spread applies a collision over its footprint", "[props]")
{
    Result<FemProp> prop = FemProp::Create(nullptr, PanelMesh(), FemMaterialSettings{}, TetSolverSettings{}, FemPropSettings{});
    REQUIRE(prop.IsValid());
    REQUIRE(prop.Get().SetContactSpread(0.45).IsValid());
    const Collision collision = OneContact(Vec3(0.0, 0.13, -0.07));
    std::vector<NodalImpulse> applied;
    REQUIRE(prop.Get().ApplyCollision(collision, BodyId{3}, &applied).IsValid());
    const std::vector<NodalImpulse> expected =
        CollisionNodalImpulses(collision, BodyId{3}, prop.Get().GetElementNodes(), prop.Get().GetCpuSolver()->GetPositions(),
                               SpreadOf(*prop.Get().GetCpuSolver(), 0.45))
            .Get();
    REQUIRE(applied.size() == expected.size());
    Vec3 momentum = Vec3::Zero();
    std::vector<Vec3> velocities;
    prop.Get().ReadVelocities(velocities);
    for (std::size_t node = 0; node < velocities.size(); ++node)
        momentum += prop.Get().GetMasses()[node] * velocities[node];
    const Vec3 impulse = 400.0 * collision.mContacts[0].mLocalNormalOnA;
    CHECK((momentum - impulse).norm() <= 1e-12 * impulse.norm());
    for (std::size_t index = 0; index < applied.size(); ++index)
    {
        CHECK(applied[index].mNode == expected[index].mNode);
        CHECK(applied[index].mImpulse == expected[index].mImpulse);
    }
}

TEST_CASE("A contact spread lands alike on either backend", "[props][gpu]")
{
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
    gpu::ComputeDeviceProvider provider;
    gpu::ComputeDeviceProvider* devices = &provider;
#else
    gpu::ComputeDeviceProvider* devices = nullptr;
#endif
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mIntegrator = EIntegrator::SymplecticEuler; // what the GPU solver runs
    const Collision collision = OneContact(Vec3(0.0, 0.13, -0.07));
    std::vector<std::vector<NodalImpulse>> applied;
    for (EFemBackend backend : {EFemBackend::Cpu, EFemBackend::Gpu})
    {
        FemPropSettings prop_settings;
        prop_settings.mBackend = backend;
        Result<FemProp> prop = FemProp::Create(devices, PanelMesh(), FemMaterialSettings{}, settings, prop_settings);
        REQUIRE(prop.IsValid());
        if (prop.Get().GetBackend() != backend)
        {
            test::RequireNoComputeDevice(devices, prop.Get().GetFallbackReason());
            WARN("GPU case skipped: " << prop.Get().GetFallbackReason());
            break;
        }
        REQUIRE(prop.Get().SetContactSpread(0.45).IsValid());
        applied.emplace_back();
        REQUIRE(prop.Get().ApplyCollision(collision, BodyId{3}, &applied.back()).IsValid());
        CHECK(applied.back().size() > 8u); // a footprint, not an element
    }
    if (applied.size() < 2)
        return;
    // The GPU prop's positions are floats: the same nodes, shares equal to float precision.
    REQUIRE(applied[1].size() == applied[0].size());
    for (std::size_t index = 0; index < applied[0].size(); ++index)
    {
        CHECK(applied[1][index].mNode == applied[0][index].mNode);
        CHECK((applied[1][index].mImpulse - applied[0][index].mImpulse).norm() <= 1e-5 * 400.0);
    }
}
