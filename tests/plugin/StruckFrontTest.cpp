// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box: the struck front (plugin/src/StruckFront.h) reads the body cell by cell and skips the cells that
// cannot change it; a scan of every vertex is the answer it must give, bit for bit.
#include "StruckFront.h"
#include "BoxMesh.h"
#include "DrawVec3.h"

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/Collision.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

// The struck front as the plain definition gives it (MeasureStruckFront's documentation), with no large
// triangles: every vertex in the grid marks its bin met and lowers it to its depth behind the front (at most
// the slab's); unmet bins take the least depth of their met neighbours, ring by ring over the whole grid;
// then two chamfer sweeps, one bin and one neighbour at a time.
StruckFront EveryVertexFront(const CrushPlan& inPlan, const CrossRect& inRegion, const std::vector<Vec3>& inPositions,
                             double inSlope)
{
    StruckFront grid;
    const double depth = inPlan.mDepth;
    const double margin = inPlan.mFlatLayer + inPlan.mRamp + inPlan.mSpacing;
    const double side0 = inRegion.mSideMin - margin, side1 = inRegion.mSideMax + margin;
    const double third0 = inRegion.mThirdMin - margin, third1 = inRegion.mThirdMax + margin;
    const double bin = std::max({inPlan.mSpacing, (side1 - side0) / 255.0, (third1 - third0) / 255.0});
    const int ns = static_cast<int>(std::ceil((side1 - side0) / bin)) + 1;
    const int nt = static_cast<int>(std::ceil((third1 - third0) / bin)) + 1;
    std::vector<double> front(static_cast<std::size_t>(ns) * static_cast<std::size_t>(nt), depth);
    std::vector<std::uint8_t> met(front.size(), 0);
    auto index = [&](int inI, int inJ) { return static_cast<std::size_t>(inJ) * static_cast<std::size_t>(ns) + static_cast<std::size_t>(inI); };
    for (const Vec3& p : inPositions)
    {
        const double u = (inPlan.mSide.dot(p) - side0) * (1.0 / bin) + 0.5;
        const double w = (inPlan.mThird.dot(p) - third0) * (1.0 / bin) + 0.5;
        if (!(u >= 0.0 && u < ns && w >= 0.0 && w < nt))
            continue;
        const std::size_t b = index(static_cast<int>(u), static_cast<int>(w));
        met[b] = 1;
        front[b] = std::min(front[b], std::max(inPlan.mDirection.dot(p) - inPlan.mFront, 0.0));
    }
    if (std::find(met.begin(), met.end(), std::uint8_t{1}) == met.end())
        return grid;
    for (bool open = true; open;)
    {
        open = false;
        std::vector<std::uint8_t> next = met;
        for (int j = 0; j < nt; ++j)
            for (int i = 0; i < ns; ++i)
            {
                if (met[index(i, j)] != 0)
                    continue;
                double least = std::numeric_limits<double>::infinity();
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                        if (i + di >= 0 && i + di < ns && j + dj >= 0 && j + dj < nt && met[index(i + di, j + dj)] != 0)
                            least = std::min(least, front[index(i + di, j + dj)]);
                if (std::isfinite(least))
                {
                    front[index(i, j)] = least;
                    next[index(i, j)] = 1;
                }
                else
                    open = true;
            }
        met.swap(next);
    }
    const double straight = inSlope * bin, diagonal = inSlope * bin * std::numbers::sqrt2;
    auto relax = [&](int inI, int inJ, int inDi, int inDj, double inStep) {
        if (inI + inDi >= 0 && inI + inDi < ns && inJ + inDj >= 0 && inJ + inDj < nt)
            front[index(inI, inJ)] = std::min(front[index(inI, inJ)], front[index(inI + inDi, inJ + inDj)] + inStep);
    };
    for (int j = 0; j < nt; ++j)
        for (int i = 0; i < ns; ++i)
        {
            relax(i, j, -1, 0, straight);
            relax(i, j, 0, -1, straight);
            relax(i, j, -1, -1, diagonal);
            relax(i, j, 1, -1, diagonal);
        }
    for (int j = nt - 1; j >= 0; --j)
        for (int i = ns - 1; i >= 0; --i)
        {
            relax(i, j, 1, 0, straight);
            relax(i, j, 0, 1, straight);
            relax(i, j, 1, 1, diagonal);
            relax(i, j, -1, 1, diagonal);
        }
    if (std::all_of(front.begin(), front.end(), [](double inDepth) { return inDepth == 0.0; }))
        return grid;
    grid.mSideOrigin = side0;
    grid.mThirdOrigin = third0;
    grid.mBin = bin;
    grid.mSlope = inSlope;
    grid.mSideCount = ns;
    grid.mThirdCount = nt;
    grid.mDepth = std::move(front);
    return grid;
}

bool SameGrid(const StruckFront& inA, const StruckFront& inB)
{
    return inA.mSideOrigin == inB.mSideOrigin && inA.mThirdOrigin == inB.mThirdOrigin && inA.mBin == inB.mBin &&
           inA.mSlope == inB.mSlope && inA.mSideCount == inB.mSideCount && inA.mThirdCount == inB.mThirdCount &&
           inA.mDepth.size() == inB.mDepth.size() &&
           (inA.mDepth.empty() || std::memcmp(inA.mDepth.data(), inB.mDepth.data(), inA.mDepth.size() * sizeof(double)) == 0);
}

} // namespace

TEST_CASE("The struck front read cell by cell equals a scan of every vertex, bit for bit", "[plugin]")
{
    // 12 seeded bodies: car-sized boxes with a slanted, rounded front (every other one with a cabin), a lattice over all of them or only over
    // their front 60 % (the rest in no zone), some with their rear quarter one rigid part, dented 0-3 times by
    // Campbell crushes first (so cells have moved); each measured from 8 random plans: a direction within 50
    // degrees of the length, a region of the front, a slab 2 cm to 1.5 m deep, bins of 4 to 30 cm.
    std::mt19937_64 random(20261205);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int measured = 0, shaped = 0;
    for (int seed = 0; seed < 12; ++seed)
    {
        const Vec3 half = Vec3(1.5, 0.7, 0.5) +
                          Vec3(1.0, 0.3, 0.3).cwiseProduct(common::DrawVec3([&] { return unit(random); }));
        const double slant = 0.4 * unit(random), round = 0.4 * unit(random);
        ffd::TriangleMesh mesh = common::MakeBoxMesh(half, common::BoxSegmentsForTriangles(half, 8000));
        // Every other body has a cabin: its upper half set back by 0.3-0.9 m over the front 0.6-1.8 m, so
        // columns above the bonnet are met only deeper, by cells behind the bonnet's.
        const double cabin = seed % 2 == 0 ? 0.3 + 0.6 * unit(random) : 0.0;
        for (Vec3& p : mesh.mPositions)
        {
            const double fade = (p.x() + half.x()) / (2.0 * half.x()), across = p.y() / half.y();
            const double upper = std::clamp(p.z() / (0.2 * half.z()), 0.0, 1.0);
            const double set_back = std::clamp((p.x() - (half.x() - 2.0 * cabin)) / (2.0 * cabin + 1.0e-12), 0.0, 1.0);
            p.x() -= fade * (slant * 0.5 * (across + 1.0) + round * across * across) + cabin * upper * set_back;
        }
        ffd::FfdDeformerSettings settings;
        ffd::FfdZoneSettings zone;
        const bool partial = seed % 3 == 1;
        const double rear = partial ? 0.2 * half.x() : -half.x() - 0.01; // the zone starts here along x
        zone.mLattice.mOrigin = Vec3(rear, -half.y() - 0.01, -half.z() - 0.01);
        zone.mLattice.mSize = Vec3(half.x() + 0.01 - rear, 2.0 * half.y() + 0.02, 2.0 * half.z() + 0.02);
        zone.mLattice.mControlCount = {8 + seed % 5 * 4, 8 + seed % 3 * 2, 7 + seed % 2 * 3};
        zone.mMaxTotalDeformation = 1.5;
        settings.mZones.push_back(zone);
        if (seed % 4 == 2)
        {
            std::vector<std::uint32_t>& part = settings.mRigidParts.emplace_back();
            for (std::uint32_t v = 0; v < mesh.mPositions.size(); ++v)
                if (mesh.mPositions[v].x() < -0.5 * half.x())
                    part.push_back(v);
        }
        Result<ffd::FfdDeformer> created = ffd::FfdDeformer::Create(mesh, settings);
        REQUIRE(created);
        ffd::FfdDeformer deformer = std::move(created).Get();

        DamageMaterial material;
        material.mModel = ECrushModel::Campbell;
        for (int dent = 0; dent < seed % 4; ++dent)
        {
            Collision collision;
            CollisionContact contact;
            const double y = half.y() * (1.6 * unit(random) - 0.8), z = half.z() * (1.6 * unit(random) - 0.8);
            contact.mLocalPointOnA = Vec3(half.x(), y, z);
            contact.mLocalNormalOnA = Vec3(-1.0, 0.4 * unit(random) - 0.2, 0.0).normalized();
            contact.mImpulse = 1.0e4;
            collision.mContacts.push_back(contact);
            const std::optional<CrushPlan> plan =
                PlanCampbellCrush(collision, ECollisionSide::A, 2.0e4 + 1.0e5 * unit(random), material, Vec3::UnitZ(), deformer);
            if (plan)
                ApplyCrushPlan(*plan, 1.5, deformer);
        }

        for (int trial = 0; trial < 8; ++trial)
        {
            CrushPlan plan;
            const double yaw = (unit(random) - 0.5) * 100.0 * std::numbers::pi / 180.0;
            const double pitch = (unit(random) - 0.5) * 40.0 * std::numbers::pi / 180.0;
            plan.mDirection = Vec3(-std::cos(yaw) * std::cos(pitch), -std::sin(yaw) * std::cos(pitch), std::sin(pitch));
            plan.mSide = Vec3::UnitZ().cross(plan.mDirection).normalized();
            plan.mThird = plan.mDirection.cross(plan.mSide);
            plan.mFront = std::numeric_limits<double>::infinity();
            for (const Vec3& p : deformer.GetCurrentPositions())
                plan.mFront = std::min(plan.mFront, plan.mDirection.dot(p));
            plan.mFront += 0.05 * (unit(random) - 0.5);
            plan.mSpacing = 0.04 + 0.26 * unit(random);
            plan.mFlatLayer = plan.mSpacing;
            plan.mDepth = 0.02 + 1.48 * unit(random);
            plan.mRamp = std::max(2.0 * plan.mSpacing, plan.mDepth);
            const double side = plan.mSide.dot(Vec3(half.x(), 0.0, 0.0)), third = plan.mThird.dot(Vec3(half.x(), 0.0, 0.0));
            const double width = 0.1 + 1.8 * unit(random), height = 0.1 + 1.2 * unit(random);
            const double middle_side = side + half.y() * (unit(random) - 0.5), middle_third = third + half.z() * (unit(random) - 0.5);
            const CrossRect region{middle_side - 0.5 * width, middle_side + 0.5 * width, middle_third - 0.5 * height,
                                   middle_third + 0.5 * height};
            const double slope = 0.25 + unit(random);

            const StruckFront fast = MeasureStruckFront(plan, region, deformer, {}, slope);
            const StruckFront every = EveryVertexFront(plan, region, deformer.GetCurrentPositions(), slope);
            INFO("seed " << seed << ", trial " << trial);
            CHECK(SameGrid(fast, every));
            ++measured;
            shaped += every.mDepth.empty() ? 0 : 1;
        }
    }
    CHECK(measured == 96);
    CHECK(shaped >= 80); // most fronts are not flat: the grids compared hold depths
}
