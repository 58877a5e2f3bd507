// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/InterpolateWideImpact.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

// An affine displacement field: linear interpolation must reproduce it exactly.
Vec3 Affine(const Vec3& inPoint)
{
    Mat3 gradient;
    gradient << 0.01, 0.02, 0.0, -0.03, 0.0, 0.01, 0.05, 0.04, 0.0;
    return Vec3(-0.1, 0.0, 0.02) + gradient * inPoint;
}

} // namespace

TEST_CASE("A box face's four corners become one coherent dent", "[ffd]")
{
    // The corners of a 1.2 m x 0.8 m face in the plane x = 2, pushed along -x.
    std::vector<PointDisplacement> corners;
    for (double y : {-0.6, 0.6})
        for (double z : {-0.4, 0.4})
            corners.push_back({Vec3(2.0, y, z), Affine(Vec3(2.0, y, z))});
    const double spacing = 0.2;
    const std::vector<PointDisplacement> filled = InterpolateWideImpact(corners, spacing);

    REQUIRE(filled.size() > 20);
    for (std::size_t i = 0; i < corners.size(); ++i)
        CHECK(filled[i].mPoint == corners[i].mPoint);
    for (const PointDisplacement& p : filled)
    {
        // On the face, inside it, with the linearly interpolated displacement.
        CHECK(p.mPoint.x() == Approx(2.0).margin(1.0e-12));
        CHECK(std::abs(p.mPoint.y()) <= 0.6 + 1.0e-12);
        CHECK(std::abs(p.mPoint.z()) <= 0.4 + 1.0e-12);
        CHECK((p.mDisplacement - Affine(p.mPoint)).norm() <= 1.0e-12);
    }
    // Coverage: every point of the face is within one spacing of a sample.
    for (double y = -0.6; y <= 0.6; y += 0.05)
        for (double z = -0.4; z <= 0.4; z += 0.05)
        {
            double nearest = 1.0e9;
            for (const PointDisplacement& p : filled)
                nearest = std::min(nearest, (p.mPoint - Vec3(2.0, y, z)).norm());
            REQUIRE(nearest <= spacing);
        }
}

TEST_CASE("A ring of contacts (a round impactor's rim) fills its disc with the linear field", "[ffd]")
{
    // 150 points on one circle, every one on every other's circumcircle: the Delaunay step's degenerate case,
    // with cavities of hundreds of edges.
    constexpr int cRing = 150;
    constexpr double cRadius = 0.6;
    std::vector<PointDisplacement> ring;
    for (int i = 0; i < cRing; ++i)
    {
        const double angle = 2.0 * 3.14159265358979323846 * i / cRing;
        const Vec3 point(2.0, cRadius * std::cos(angle), cRadius * std::sin(angle));
        ring.push_back({point, Affine(point)});
    }
    const double spacing = 0.15;
    const std::vector<PointDisplacement> filled = InterpolateWideImpact(ring, spacing);
    REQUIRE(filled.size() > ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i)
        CHECK(filled[i].mPoint == ring[i].mPoint);
    for (const PointDisplacement& p : filled)
    {
        // In the disc's plane, inside the ring, with the linearly interpolated displacement.
        CHECK(p.mPoint.x() == Approx(2.0).margin(1.0e-12));
        CHECK(p.mPoint.tail<2>().norm() <= cRadius + 1.0e-12);
        CHECK((p.mDisplacement - Affine(p.mPoint)).norm() <= 1.0e-12);
    }
    // Coverage: every point of the disc (inside the inscribed polygon) is within one spacing of a sample.
    for (double y = -0.55; y <= 0.55; y += 0.05)
        for (double z = -0.55; z <= 0.55; z += 0.05)
        {
            if (std::hypot(y, z) > cRadius * std::cos(3.14159265358979323846 / cRing))
                continue;
            double nearest = 1.0e9;
            for (const PointDisplacement& p : filled)
                nearest = std::min(nearest, (p.mPoint - Vec3(2.0, y, z)).norm());
            REQUIRE(nearest <= spacing);
        }
}

TEST_CASE("Contacts within one spacing are left alone", "[ffd]")
{
    const std::vector<PointDisplacement> points{{Vec3(0.0, 0.0, 0.0), Vec3(-0.1, 0.0, 0.0)},
                                                {Vec3(0.0, 0.1, 0.05), Vec3(-0.1, 0.0, 0.0)}};
    const std::vector<PointDisplacement> kept = InterpolateWideImpact(points, 0.2);
    REQUIRE(kept.size() == 2);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        // intent: the same points with the same displacements, bit for bit, in order
        CHECK(kept[i].mPoint == points[i].mPoint);
        CHECK(kept[i].mDisplacement == points[i].mDisplacement);
    }
}

TEST_CASE("A collinear contact pair is sampled along its segment", "[ffd]")
{
    const std::vector<PointDisplacement> points{{Vec3(0.0, -0.5, 0.0), Vec3(-0.1, 0.0, 0.0)},
                                                {Vec3(0.0, 0.5, 0.0), Vec3(-0.2, 0.0, 0.0)}};
    const std::vector<PointDisplacement> filled = InterpolateWideImpact(points, 0.25);
    REQUIRE(filled.size() == 5);
    for (const PointDisplacement& p : filled)
    {
        CHECK(p.mPoint.x() == Approx(0.0).margin(1.0e-15));
        const double t = p.mPoint.y() + 0.5;
        CHECK(p.mDisplacement.x() == Approx(-0.1 - 0.1 * t));
    }
}

TEST_CASE("Interpolation respects its output cap", "[ffd]")
{
    std::vector<PointDisplacement> corners;
    for (double y : {-5.0, 5.0})
        for (double z : {-5.0, 5.0})
            corners.push_back({Vec3(0.0, y, z), Vec3(-0.1, 0.0, 0.0)});
    const std::size_t filled = InterpolateWideImpact(corners, 0.01, 300).size();
    CHECK(filled <= 300);
    CHECK(filled > 4); // it did interpolate, at a coarser pitch
}

TEST_CASE("Interpolation cost does not depend on the spacing or the spread", "[ffd]")
{
    // A 1 km contact spread at a 0.4 mm lattice spacing (a thin zone) must return at once, within the cap.
    std::vector<PointDisplacement> corners;
    for (double y : {-500.0, 500.0})
        for (double z : {-0.7, 0.7})
            corners.push_back({Vec3(2.0, y, z), Vec3(-0.1, 0.0, 0.0)});
    const std::size_t filled = InterpolateWideImpact(corners, 4.0e-4, 512).size();
    CHECK(filled <= 512);
    CHECK(filled > 4);
}

TEST_CASE("Contacts past the double range are left as they are, never NaN", "[ffd]")
{
    // Displacements whose sums overflow, and a set so wide its extent does: no sample is made and nothing
    // becomes NaN (a NaN was cast to int here).
    const std::vector<PointDisplacement> huge{{Vec3(0.0, 0.0, 0.0), Vec3(-1.7e308, 0.0, 0.0)},
                                              {Vec3(0.0, 1.0, 0.0), Vec3(-1.7e308, 0.0, 0.0)},
                                              {Vec3(0.0, 1.0, 1.0), Vec3(-1.7e308, 0.0, 0.0)}};
    const std::vector<PointDisplacement> wide{{Vec3(0.0, -1.0e308, 0.0), Vec3(-0.1, 0.0, 0.0)},
                                              {Vec3(0.0, 1.0e308, 0.0), Vec3(-0.1, 0.0, 0.0)},
                                              {Vec3(0.0, 0.0, 1.0e308), Vec3(-0.1, 0.0, 0.0)}};
    for (const auto* set : {&huge, &wide})
    {
        const std::vector<PointDisplacement> out = InterpolateWideImpact(*set, 0.2);
        CHECK(out.size() == set->size());
        for (const PointDisplacement& p : out)
            CHECK(!std::isnan(p.mDisplacement.x()));
    }
}

TEST_CASE("Samples closer than half the pitch are dropped, and the face stays covered", "[ffd]")
{
    // 64 random contacts on a 1.8 m x 1.4 m face in the plane x = 2 (a car's front), an affine push.
    std::mt19937_64 random(64);
    std::uniform_real_distribution<double> y(-0.9, 0.9), z(-0.7, 0.7);
    std::vector<PointDisplacement> contacts;
    for (int i = 0; i < 64; ++i)
    {
        const double pz = z(random), py = y(random); // sequenced, last argument first (common::DrawVec3)
        const Vec3 point(2.0, py, pz);
        contacts.push_back({point, Affine(point)});
    }
    const double spacing = 0.15;
    const std::vector<PointDisplacement> filled = InterpolateWideImpact(contacts, spacing);
    REQUIRE(filled.size() > contacts.size());
    for (std::size_t i = 0; i < contacts.size(); ++i)
        CHECK(filled[i].mPoint == contacts[i].mPoint); // every contact kept, first
    // No sample within half a pitch of any point before it (contacts included).
    for (std::size_t i = contacts.size(); i < filled.size(); ++i)
    {
        CHECK((filled[i].mDisplacement - Affine(filled[i].mPoint)).norm() <= 1.0e-12);
        for (std::size_t j = 0; j < i; ++j)
            REQUIRE((filled[i].mPoint - filled[j].mPoint).norm() >= 0.5 * spacing - 1.0e-12);
    }
    // Inside the contacts' hull every point is within one pitch of a constrained point: take the hull's
    // inner part (the contacts' box shrunk by a pitch), where the hull surely reaches.
    for (double py = -0.6; py <= 0.6; py += 0.05)
        for (double pz = -0.45; pz <= 0.45; pz += 0.05)
        {
            double nearest = 1.0e9;
            for (const PointDisplacement& p : filled)
                nearest = std::min(nearest, (p.mPoint - Vec3(2.0, py, pz)).norm());
            REQUIRE(nearest <= spacing);
        }
}
