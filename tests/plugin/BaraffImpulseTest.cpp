// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BaraffImpulse.h>

#include "ImpulseBodies.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::Sphere;
using crumple::common::StaticGround;

namespace
{

constexpr double cTolerance = 1.0e-12;

double Relative(double inValue, double inReference)
{
    return std::abs(inValue - inReference) / std::abs(inReference);
}

} // namespace

TEST_CASE("Head-on sphere on a static plane: j = (1+e) m v", "[plugin]")
{
    for (double e : {0.0, 0.1, 0.5, 1.0})
        for (double mass : {1.0e-3, 1.0, 1200.0, 1.0e6})
        {
            const double v = 13.7;
            const BodyState sphere = Sphere(mass, 0.3, Vec3(0.0, 0.0, 0.3), Vec3(0.0, 0.0, -v));
            const double j = BaraffImpulse(sphere, StaticGround(), Vec3::Zero(), Vec3::UnitZ(), e);
            CHECK(Relative(j, (1.0 + e) * mass * v) <= cTolerance);
        }
}

TEST_CASE("Head-on two-sphere collision: j = (1+e) m_eff v_rel", "[plugin]")
{
    const double m_a = 3.0, m_b = 7.0, e = 0.4;
    const BodyState a = Sphere(m_a, 0.5, Vec3(0.0, 0.0, 0.5), Vec3(0.0, 0.0, -2.0));
    const BodyState b = Sphere(m_b, 0.5, Vec3(0.0, 0.0, -0.5), Vec3(0.0, 0.0, 4.0));
    const double m_eff = m_a * m_b / (m_a + m_b);
    const double j = BaraffImpulse(a, b, Vec3::Zero(), Vec3::UnitZ(), e);
    CHECK(Relative(j, (1.0 + e) * m_eff * 6.0) <= cTolerance);
    // Conservation: momentum unchanged, relative velocity reversed times e.
    const double va = -2.0 + j / m_a, vb = 4.0 - j / m_b;
    CHECK(std::abs(m_a * va + m_b * vb - (m_a * -2.0 + m_b * 4.0)) <= 1.0e-12);
    CHECK(Relative(va - vb, e * 6.0) <= 1.0e-12);
}

TEST_CASE("Off-centre hit with rotation matches the hand-derived impulse", "[plugin]")
{
    // A body with principal inertia I_y falls with v0 and spins with w_y; it hits static ground at
    // r = (a, 0, -h) from its centre of mass. With n = z:
    //   r x n = (0, -a, 0),  n . ((I^-1 (r x n)) x r) = a^2 / I_y,
    //   v_rel = n . (v + w x r) = -v0 - a w_y,
    //   j = (1 + e)(v0 + a w_y) / (1/m + a^2 / I_y).
    const double m = 50.0, i_x = 2.0, i_y = 5.0, i_z = 4.0, a = 0.4, h = 0.25, v0 = 3.0, w_y = 1.5, e = 0.2;
    BodyState body;
    body.mMass = m;
    body.mInverseInertiaWorld = Vec3(1.0 / i_x, 1.0 / i_y, 1.0 / i_z).asDiagonal();
    body.mCenterOfMass = Vec3(0.0, 0.0, h);
    body.mTransform.mTranslation = body.mCenterOfMass;
    body.mLinearVelocity = Vec3(0.0, 0.0, -v0);
    body.mAngularVelocity = Vec3(0.0, w_y, 0.0);
    const Vec3 contact(a, 0.0, 0.0);
    const double expected = (1.0 + e) * (v0 + a * w_y) / (1.0 / m + a * a / i_y);
    const double j = BaraffImpulse(body, StaticGround(), contact, Vec3::UnitZ(), e);
    CHECK(Relative(j, expected) <= cTolerance);

    // Independent check: applying j makes the contact point leave at -e times its approach speed.
    BodyState after = body;
    after.mLinearVelocity += j * Vec3::UnitZ() / m;
    after.mAngularVelocity += body.mInverseInertiaWorld * (contact - body.mCenterOfMass).cross(j * Vec3::UnitZ());
    const double v_before = RelativeNormalVelocity(body, StaticGround(), contact, Vec3::UnitZ());
    const double v_after = RelativeNormalVelocity(after, StaticGround(), contact, Vec3::UnitZ());
    CHECK(Relative(v_after, -e * v_before) <= 1.0e-12);
}

TEST_CASE("Separating, resting and immovable contacts give no impulse", "[plugin]")
{
    const BodyState rising = Sphere(1.0, 0.1, Vec3(0.0, 0.0, 0.1), Vec3(0.0, 0.0, 1.0));
    CHECK(BaraffImpulse(rising, StaticGround(), Vec3::Zero(), Vec3::UnitZ(), 0.5) == 0.0);
    const BodyState resting = Sphere(1.0, 0.1, Vec3(0.0, 0.0, 0.1), Vec3(3.0, 0.0, 0.0)); // sliding
    CHECK(BaraffImpulse(resting, StaticGround(), Vec3::Zero(), Vec3::UnitZ(), 0.5) == 0.0);
    BodyState kinematic = Sphere(1.0, 0.1, Vec3(0.0, 0.0, 0.1), Vec3(0.0, 0.0, -5.0));
    kinematic.mMotionType = EMotionType::Kinematic;
    CHECK(BaraffImpulse(kinematic, StaticGround(), Vec3::Zero(), Vec3::UnitZ(), 0.5) == 0.0);

    // Slow approach under the resting speed: no impulse from the simultaneous solve.
    const BodyState settling = Sphere(1.0, 0.1, Vec3(0.0, 0.0, 0.1), Vec3(0.0, 0.0, -0.16));
    const ImpulseContact contact{Vec3::Zero(), Vec3::UnitZ()};
    CHECK(SimultaneousImpulses(settling, StaticGround(), std::span(&contact, 1), 0.1, 0.5)[0] == 0.0);
}

TEST_CASE("A kinematic body hitting a dynamic one counts its velocity", "[plugin]")
{
    BodyState pusher;
    pusher.mMotionType = EMotionType::Kinematic;
    pusher.mLinearVelocity = Vec3(0.0, 0.0, -2.0);
    const BodyState ball = Sphere(4.0, 0.2, Vec3(0.0, 0.0, -0.2), Vec3::Zero());
    // A is the kinematic pusher above, B the ball below: only the ball's mass resists.
    CHECK(Relative(BaraffImpulse(pusher, ball, Vec3::Zero(), Vec3::UnitZ(), 0.0), 4.0 * 2.0) <= cTolerance);
}

TEST_CASE("The total impulse does not grow with the number of reported contacts", "[plugin]")
{
    // A 1,200 kg box (4 m x 2 m x 1.4 m) falls flat on static ground at 5 m/s.
    const double m = 1200.0, v = 5.0, e = 0.1;
    BodyState box;
    box.mMass = m;
    box.mInverseInertiaWorld = Vec3(12.0 / (m * (4.0 + 1.96)), 12.0 / (m * (16.0 + 1.96)), 12.0 / (m * 20.0)).asDiagonal();
    box.mCenterOfMass = Vec3(0.0, 0.0, 0.7);
    box.mLinearVelocity = Vec3(0.0, 0.0, -v);
    const double expected = (1.0 + e) * m * v;

    for (int grid : {1, 2, 3, 5, 8})
    {
        std::vector<ImpulseContact> contacts;
        for (int i = 0; i < grid; ++i)
            for (int k = 0; k < grid; ++k)
            {
                const double x = grid == 1 ? 0.0 : -2.0 + 4.0 * i / (grid - 1);
                const double y = grid == 1 ? 0.0 : -1.0 + 2.0 * k / (grid - 1);
                contacts.push_back({Vec3(x, y, 0.0), Vec3::UnitZ()});
            }
        const std::vector<double> j = SimultaneousImpulses(box, StaticGround(), contacts, e, 0.0);
        double total = 0.0;
        for (double ji : j)
        {
            CHECK(ji >= 0.0);
            total += ji;
        }
        INFO(contacts.size() << " contacts");
        CHECK(Relative(total, expected) <= 1.0e-9);
        // Symmetric sets share symmetrically: the four corners carry equal impulses.
        if (grid >= 2)
        {
            const std::size_t last = contacts.size() - 1;
            CHECK(Relative(j[0], j[last]) <= 1.0e-9);
            CHECK(Relative(j[static_cast<std::size_t>(grid - 1)], j[last - static_cast<std::size_t>(grid - 1)]) <= 1.0e-9);
        }
    }

    // The same point reported twice shares one impulse.
    const ImpulseContact twice[2] = {{Vec3(0.0, 0.0, 0.0), Vec3::UnitZ()}, {Vec3(0.0, 0.0, 0.0), Vec3::UnitZ()}};
    const std::vector<double> duplicated = SimultaneousImpulses(box, StaticGround(), twice, e, 0.0);
    CHECK(Relative(duplicated[0] + duplicated[1], expected) <= 1.0e-9);
}

TEST_CASE("A tilted landing gives pushing impulses only", "[plugin]")
{
    // The box lands on one edge while rotating away from the other: the far contacts must not pull.
    const double m = 100.0;
    BodyState box;
    box.mMass = m;
    box.mInverseInertiaWorld = Mat3::Identity() * (12.0 / (m * 2.0));
    box.mCenterOfMass = Vec3(0.0, 0.0, 0.5);
    box.mLinearVelocity = Vec3(0.0, 0.0, -2.0);
    box.mAngularVelocity = Vec3(0.0, 3.0, 0.0); // x = +0.5 side moves down faster
    const std::vector<ImpulseContact> contacts{{Vec3(0.5, -0.5, 0.0), Vec3::UnitZ()}, {Vec3(0.5, 0.5, 0.0), Vec3::UnitZ()},
                                               {Vec3(-0.5, -0.5, 0.0), Vec3::UnitZ()}, {Vec3(-0.5, 0.5, 0.0), Vec3::UnitZ()}};
    const std::vector<double> j = SimultaneousImpulses(box, StaticGround(), contacts, 0.0, 0.0);
    for (double ji : j)
        CHECK(ji >= 0.0);
    // After the impulses no contact still approaches.
    BodyState after = box;
    for (std::size_t i = 0; i < contacts.size(); ++i)
    {
        after.mLinearVelocity += j[i] * Vec3::UnitZ() / m;
        after.mAngularVelocity += box.mInverseInertiaWorld * (contacts[i].mPoint - box.mCenterOfMass).cross(j[i] * Vec3::UnitZ());
    }
    for (const ImpulseContact& c : contacts)
        CHECK(RelativeNormalVelocity(after, StaticGround(), c.mPoint, c.mNormal) >= -1.0e-9);
}
