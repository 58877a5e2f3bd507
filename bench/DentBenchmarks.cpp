// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"
#include "BoxMesh.h"
#include "BruteForceProbe.h"
#include "ThreadJobSystem.h"

#include <crumple/plugin/BaraffImpulse.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DeformableObject.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

namespace crumple::bench
{

using namespace crumple::plugin;

namespace
{

const Vec3 cHalfExtents(2.1, 0.9, 0.7); // a 4.2 m x 1.8 m x 1.4 m car body

// The car body split along its length into inZones zones of inControls each.
// inControls 0: the default lattice, controls from DeformableObjectSettings::mFittedControlSpacing.
// inRounded (m): the front (+x) set back by inRounded (y / half width)^2, fading to nothing at the rear: a
// nose rounded across the width.
DeformableObject MakeCar(int inTriangles, int inZones, int inControls, ECrushModel inModel = ECrushModel::ImpulseFactor,
                         double inRounded = 0.0)
{
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(cHalfExtents, common::BoxSegmentsForTriangles(cHalfExtents, inTriangles));
    for (Vec3& p : settings.mMesh.mPositions)
        p.x() -= inRounded * (p.x() + cHalfExtents.x()) / (2.0 * cHalfExtents.x()) * std::pow(p.y() / cHalfExtents.y(), 2);
    // ImpulseFactor: the D4MD dent (direct manipulation of the contact points); Campbell: the default
    // material's crush (footprint scan, then the control field written directly).
    settings.mMaterial.mModel = inModel;
    settings.mMaterial.mDeformationFactor = 5.0e-6; // about 0.1 m for a 15 m/s wall hit: below the clamps
    const ffd::FfdZoneSettings whole = FitZoneToMesh(settings.mMesh, {inControls, inControls, inControls}, 0.5,
                                                     settings.mFittedControlSpacing);
    for (int z = 0; z < inZones; ++z)
    {
        ffd::FfdZoneSettings zone = whole;
        zone.mLattice.mSize.x() = whole.mLattice.mSize.x() / inZones;
        zone.mLattice.mOrigin.x() = whole.mLattice.mOrigin.x() + z * zone.mLattice.mSize.x();
        settings.mDeformer.mZones.push_back(zone);
    }
    return DeformableObject::Create(settings).Get();
}

// inContacts contacts on the front face of the 1,200 kg car hitting a wall at 15 m/s, with the impulses
// the core computes for them. The car is the collision's body B.
Collision MakeFrontCollision(int inContacts)
{
    BodyState car;
    car.mMass = 1200.0;
    const Vec3 size = 2.0 * cHalfExtents;
    car.mInverseInertiaWorld = Vec3(12.0 / (1200.0 * (size.y() * size.y() + size.z() * size.z())),
                                    12.0 / (1200.0 * (size.x() * size.x() + size.z() * size.z())),
                                    12.0 / (1200.0 * (size.x() * size.x() + size.y() * size.y())))
                                   .asDiagonal();
    car.mLinearVelocity = Vec3(15.0, 0.0, 0.0);
    BodyState wall;
    wall.mMotionType = EMotionType::Static;

    std::mt19937_64 random(static_cast<std::uint64_t>(inContacts));
    std::uniform_real_distribution<double> y(-0.85, 0.85), z(-0.65, 0.65);
    std::vector<ImpulseContact> contacts;
    for (int i = 0; i < inContacts; ++i)
    {
        const double pz = z(random),
                     py = y(random); // sequenced, last argument first (the tests' common::DrawVec3)
        contacts.push_back({Vec3(cHalfExtents.x(), py, pz), -Vec3::UnitX()});
    }
    const std::vector<double> impulses = SimultaneousImpulses(car, wall, contacts, 0.1, 0.5);

    Collision collision;
    for (std::size_t i = 0; i < contacts.size(); ++i)
    {
        CollisionContact contact;
        contact.mLocalPointOnB = contacts[i].mPoint;
        contact.mLocalNormalOnB = Vec3::UnitX(); // from the car (B) to the wall (A)
        contact.mImpulse = impulses[i];
        collision.mContacts.push_back(contact);
    }
    // What a Campbell material absorbs of it: the car's kinetic energy less a rebound of e = 0.1.
    collision.mCrushEnergyB = 0.5 * car.mMass * car.mLinearVelocity.squaredNorm() * (1.0 - 0.1 * 0.1);
    return collision;
}

// One contact column at the middle of the same front (a hull's tip against a wall), with the wall's shape
// known: a 2 m thick, 10 m wide, 6 m tall box whose face is the plane of the car's front (Collision::
// mShapeOfAOnB, in the car's frame). The crush meets the whole front, as the 64 contacts' does.
Collision MakeWallColumnCollision()
{
    Collision collision = MakeFrontCollision(64);
    const double energy = collision.mCrushEnergyB;
    const double impulse = collision.TotalImpulse() / 2.0;
    collision.mContacts.resize(2);
    for (std::size_t i = 0; i < 2; ++i)
    {
        collision.mContacts[i].mLocalPointOnB = Vec3(cHalfExtents.x(), 0.0, i == 0 ? -0.6 : 0.6);
        collision.mContacts[i].mImpulse = impulse;
    }
    collision.mShapeOfAOnB.mCenter = Vec3(cHalfExtents.x() + 1.0, 0.0, 0.0);
    collision.mShapeOfAOnB.mHalfAxes = Vec3(1.0, 5.0, 3.0).asDiagonal();
    collision.mShapeOfAOnB.mKnown = true;
    collision.mCrushEnergyB = energy;
    return collision;
}

double MaxControl(const DeformableObject& inCar)
{
    double largest = 0.0;
    for (const ffd::FfdLattice& zone : inCar.GetDeformer().GetZones())
        for (const Vec3& control : zone.GetControlDisplacements())
            largest = std::max(largest, control.norm());
    return largest;
}

// The vertices a dent changed (position or normal), ascending.
std::vector<std::uint32_t> ChangedVertices(const DeformableObject& inBefore, const DeformableObject& inAfter)
{
    std::vector<std::uint32_t> changed;
    const ffd::FfdDeformer& a = inBefore.GetDeformer();
    const ffd::FfdDeformer& b = inAfter.GetDeformer();
    for (std::size_t v = 0; v < a.GetPositions().size(); ++v)
        if (a.GetPositions()[v] != b.GetPositions()[v] || a.GetNormals()[v] != b.GetNormals()[v])
            changed.push_back(static_cast<std::uint32_t>(v));
    return changed;
}

// The memory floor of a dent: read each changed vertex's rest position and a displacement, write its
// position and normal, through the same index list (the least any dent of these vertices must touch).
struct VertexFloor
{
    std::vector<std::uint32_t> mVertices;
    std::vector<Vec3> mRest, mDisplacement, mNormalIn, mPositions, mNormals;

    VertexFloor(const DeformableObject& inBefore, const DeformableObject& inAfter)
        : mVertices(ChangedVertices(inBefore, inAfter)), mRest(inBefore.GetDeformer().GetRestMesh().mPositions),
          mDisplacement(mRest.size(), Vec3(1.0e-3, 0.0, 0.0)), mNormalIn(inAfter.GetDeformer().GetNormals()),
          mPositions(mRest.size()), mNormals(mRest.size())
    {
    }
    void Run()
    {
        for (std::uint32_t v : mVertices)
        {
            mPositions[v] = mRest[v] + mDisplacement[v];
            mNormals[v] = mNormalIn[v];
        }
    }
};

void ApplyCase(BenchTable& ioTable, const std::string& inBenchmark, int inTriangles, int inZones, int inControls,
               int inContacts, int inRepetitions, ECrushModel inModel = ECrushModel::ImpulseFactor)
{
    const DeformableObject pristine = MakeCar(inTriangles, inZones, inControls, inModel);
    const Collision collision = MakeFrontCollision(inContacts);
    DeformableObject car = pristine;
    DeformableObject full = pristine;
    full.ApplyCollision(collision, ECollisionSide::B).Get();
    VertexFloor floor(pristine, full);
    ffd::DentReport report;
    // The incremental dent, a full recompute of the mesh after the same dent and the memory floor of the
    // vertices it changed, interleaved.
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions,
        {{[&] { car = pristine; }, [&] { report = car.ApplyCollision(collision, ECollisionSide::B).Get(); }},
         {[] {}, [&] { full.GetDeformer().RecomputeAll(); }},
         {[] {}, [&] { floor.Run(); }}});
    // A case that dents nothing times an early return, not a dent: refuse to print it.
    if (report.mVerticesMoved == 0)
        throw std::runtime_error("dent benchmark " + inBenchmark + ": the collision moved no vertex");
    const double ms = timing[0].mWallMs, full_ms = timing[1].mWallMs;
    const std::size_t points = car.DentFor(collision, ECollisionSide::B).size();

    const std::size_t triangles = pristine.GetDeformer().GetRestMesh().mTriangles.size();
    const std::array<int, 3>& n = pristine.GetDeformer().GetZones()[0].GetSettings().mControlCount;
    const std::string lattice = inControls > 0 ? std::to_string(inControls) + "^3"
                                               : std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" + std::to_string(n[2]);
    const std::string name = std::to_string(triangles / 1000) + "k_tris/" + std::to_string(inZones) + "_zone/" + lattice +
                             "/" + std::to_string(inContacts) + "_contacts" +
                             (inModel == ECrushModel::Campbell ? "/campbell" : "");
    const std::string extra = "vertices_updated=" + std::to_string(report.mVerticesMoved) + ";vertices=" +
                              std::to_string(pristine.GetDeformer().GetPositions().size()) + ";triangles_updated=" +
                              std::to_string(report.mTrianglesUpdated) + ";triangles=" + std::to_string(triangles) +
                              ";constrained_points=" + std::to_string(points) + ";scale=" + std::to_string(report.mScale) +
                              ";cpu_ms=" + FormatExtra(timing[0].mCpuMs) + ";full_recompute_ms=" + FormatExtra(full_ms) +
                              ";full_recompute_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";incremental_over_full=" +
                              FormatExtra(ms / full_ms) + ";max_control_m=" + FormatExtra(MaxControl(car)) +
                              ";vertices_changed=" + std::to_string(floor.mVertices.size()) + ";floor_ms=" +
                              FormatExtra(timing[2].mWallMs) + ";over_floor=" + FormatExtra(ms / timing[2].mWallMs);
    if (inModel == ECrushModel::Campbell)
    {
        // The crush's accuracy: the struck face's deepest inward move against the planned depth.
        double deepest = 0.0;
        const ffd::FfdDeformer& deformer = car.GetDeformer();
        for (std::size_t v = 0; v < deformer.GetPositions().size(); ++v)
            if (deformer.GetRestMesh().mPositions[v].x() == cHalfExtents.x())
                deepest = std::max(deepest, deformer.GetRestMesh().mPositions[v].x() - deformer.GetPositions()[v].x());
        ioTable.Add({inBenchmark, name, ms, std::abs(deepest - report.mMaxWanted) / report.mMaxWanted, "rel_crush_error",
                     extra + ";crush_m=" + FormatExtra(report.mMaxWanted)});
        return;
    }
    ioTable.Add({inBenchmark, name, ms, report.mMaxWanted > 0.0 ? report.mMaxPointError / report.mMaxWanted : 0.0,
                 "rel_contact_error", extra});
}

// The same dent on the calling thread alone and split over a 2-thread job system, interleaved.
void ThreadsCase(BenchTable& ioTable, int inTriangles, int inControls, int inContacts, int inRepetitions)
{
    const DeformableObject pristine = MakeCar(inTriangles, 1, inControls);
    const Collision collision = MakeFrontCollision(inContacts);
    const common::ThreadJobSystem two(2);
    DeformableObject alone = pristine, split = pristine;
    ffd::DentReport report;
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions, {{[&] { alone = pristine; },
                         [&] { report = alone.ApplyCollision(collision, ECollisionSide::B).Get(); }},
                        {[&]
                         {
                             split = pristine;
                             split.GetDeformer().SetJobSystem(&two.Get());
                         },
                         [&] { split.ApplyCollision(collision, ECollisionSide::B).Get(); }}});
    // The split dent must be the same bytes, or the timing compares different work.
    const bool same = alone.GetDeformer().GetPositions() == split.GetDeformer().GetPositions() &&
                      alone.GetDeformer().GetNormals() == split.GetDeformer().GetNormals();
    const std::string lattice = inControls > 0 ? std::to_string(inControls) + "^3" : "default";
    ioTable.Add({"dent_threads", std::to_string(inTriangles / 1000) + "k_tris/" + lattice + "/" + std::to_string(inContacts) +
                                     "_contacts/2_threads",
                 timing[1].mWallMs, same ? 0.0 : 1.0, "bytes_differ",
                 "one_thread_ms=" + FormatExtra(timing[0].mWallMs) + ";speedup=" + FormatExtra(timing[0].mWallMs / timing[1].mWallMs) +
                     ";game_thread_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";vertices_updated=" + std::to_string(report.mVerticesMoved)});
}

// Whether a dent's cost follows the vertices it updates, not the body's size: the same 64-contact crush
// (Campbell, default lattice) on a body of inSmall and of inLarge triangles, the two interleaved. Error: how
// far the time per updated vertex of the large body is from the small one's, (large / small) - 1; linear
// scaling is 0. Both bodies are the same box, so the large one updates about inLarge / inSmall times the
// vertices.
void ScalingCase(BenchTable& ioTable, int inSmall, int inLarge, int inRepetitions)
{
    const Collision collision = MakeFrontCollision(64);
    const DeformableObject small_pristine = MakeCar(inSmall, 1, 0, ECrushModel::Campbell);
    const DeformableObject large_pristine = MakeCar(inLarge, 1, 0, ECrushModel::Campbell);
    DeformableObject small = small_pristine, large = large_pristine;
    ffd::DentReport small_report, large_report;
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions, {{[&] { small = small_pristine; },
                         [&] { small_report = small.ApplyCollision(collision, ECollisionSide::B).Get(); }},
                        {[&] { large = large_pristine; },
                         [&] { large_report = large.ApplyCollision(collision, ECollisionSide::B).Get(); }}});
    if (small_report.mVerticesMoved == 0 || large_report.mVerticesMoved == 0)
        throw std::runtime_error("dent_scaling: the collision moved no vertex");
    const double small_per_vertex = timing[0].mCpuMs / small_report.mVerticesMoved;
    const double large_per_vertex = timing[1].mCpuMs / large_report.mVerticesMoved;
    const auto triangles = [](const DeformableObject& inObject) {
        return std::to_string(inObject.GetDeformer().GetRestMesh().mTriangles.size() / 1000) + "k";
    };
    ioTable.Add({"dent_scaling", triangles(large_pristine) + "_vs_" + triangles(small_pristine) + "_tris/campbell/64_contacts",
                 timing[1].mWallMs, large_per_vertex / small_per_vertex - 1.0, "rel_change_of_cpu_ms_per_updated_vertex",
                 "small_ms=" + FormatExtra(timing[0].mWallMs) + ";small_cpu_ms=" + FormatExtra(timing[0].mCpuMs) +
                     ";large_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";small_vertices_updated=" +
                     std::to_string(small_report.mVerticesMoved) + ";large_vertices_updated=" +
                     std::to_string(large_report.mVerticesMoved) + ";small_us_per_vertex=" +
                     FormatExtra(1000.0 * small_per_vertex) + ";large_us_per_vertex=" + FormatExtra(1000.0 * large_per_vertex)});
}

// What planning a Campbell crush costs beside applying it: PlanCampbellCrush alone (the footprint probe,
// the struck front's pass over the body's vertices and large triangles, the profile's depth, the cell) and
// the whole ApplyCollision (plan and control field), interleaved, on the box body of inTriangles with its
// default lattice. The box's front is flat and square to the crush, so the plan's depth must be the closed
// form's: the error is its distance from CampbellCrushDepth over the footprint's width. inWallFace: one
// contact column and the wall's shape (MakeWallColumnCollision), whose footprint is the whole front: the
// error is then the distance from the closed form over the body's width.
// inRounded: the same with the nose rounded by 0.3 m across the width (MakeCar), so that the face's footprint
// search integrates a profile at each candidate; no closed form there, so the error is how flat the wall left
// the front: the spread along the crush of the struck front's vertices the crush reached at the middle
// height (|z| < 0.3 m, rest depth behind the nose below the plan's depth less a spacing), relative to the depth.
void PlanCase(BenchTable& ioTable, int inTriangles, int inRepetitions, bool inWallFace = false, bool inRounded = false)
{
    const Collision collision = inWallFace ? MakeWallColumnCollision() : MakeFrontCollision(64);
    const DeformableObject pristine = MakeCar(inTriangles, 1, 0, ECrushModel::Campbell, inRounded ? 0.3 : 0.0);
    DeformableObject car = pristine;
    std::optional<CrushPlan> plan;
    ffd::DentReport report;
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions,
        {{[] {},
          [&]
          {
              plan = PlanCampbellCrush(collision, ECollisionSide::B, collision.mCrushEnergyB, pristine.GetMaterial(),
                                       pristine.GetUpAxis(), pristine.GetDeformer(), &pristine.GetCrushBody());
          }},
         {[&] { car = pristine; },
          [&] { report = car.ApplyCollision(collision, ECollisionSide::B).Get(); }}});
    if (!plan)
        throw std::runtime_error("crush_plan: the collision planned no crush");
    const double width = inWallFace ? 2.0 * cHalfExtents.y() : plan->mWidth;
    const double law = CampbellCrushDepth(pristine.GetMaterial(), width, collision.mCrushEnergyB);
    double error = std::abs(plan->mDepth - law) / law;
    if (inRounded)
    {
        const std::vector<Vec3>& rest = pristine.GetDeformer().GetRestMesh().mPositions;
        const std::vector<Vec3>& now = car.GetDeformer().GetPositions();
        const double spacing = pristine.GetDeformer().GetMinSpacing();
        double low = 1.0e9, high = -1.0e9;
        for (std::size_t v = 0; v < rest.size(); ++v)
            if (std::abs(rest[v].z()) < 0.3 && cHalfExtents.x() - rest[v].x() < plan->mDepth - spacing &&
                rest[v].x() > cHalfExtents.x() - 0.3 - 1.0e-9)
            {
                low = std::min(low, now[v].x());
                high = std::max(high, now[v].x());
            }
        error = (high - low) / plan->mDepth;
    }
    ioTable.Add({"crush_plan",
                 std::to_string(inTriangles / 1000) + "k_tris/campbell/" +
                     (inRounded ? "rounded_wall_face_1_column" : inWallFace ? "wall_face_1_column" : "64_contacts"),
                 timing[0].mWallMs, error, inRounded ? "front_spread_vs_depth" : "rel_depth_vs_flat_law",
                 "plan_cpu_ms=" + FormatExtra(timing[0].mCpuMs) + ";depth_m=" + FormatExtra(plan->mDepth) + ";width_m=" + FormatExtra(plan->mWidth) + ";apply_collision_ms=" + FormatExtra(timing[1].mWallMs) +
                     ";apply_collision_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";plan_share_cpu=" +
                     FormatExtra(timing[0].mCpuMs / timing[1].mCpuMs) + ";large_triangles=" +
                     std::to_string(pristine.GetCrushBody().mLargeTriangles.size()) + ";vertices_updated=" +
                     std::to_string(report.mVerticesMoved)});
}

// A plan on a body crushed before: the struck front and the footprint's probe must skip what an earlier
// crush moved away from them (the cells' boxes of current positions and of displacements), not scan every
// cell within the largest move of any vertex. The box body of inTriangles (default lattice) takes inDents of
// the same 64-contact front crush, then the plan of one more (its probe over the front face, and that probe
// beside a scan of every vertex and triangle), interleaved with the plan on the pristine body. Error: the
// share of 40 random probes of the dented front whose indexed answer differs from the full scan's (0: the
// skips are exact).
void DentedPlanCase(BenchTable& ioTable, int inTriangles, int inDents, int inRepetitions)
{
    const Collision collision = MakeFrontCollision(64);
    const DeformableObject pristine = MakeCar(inTriangles, 1, 0, ECrushModel::Campbell);
    DeformableObject dented = pristine;
    for (int i = 0; i < inDents; ++i)
        if (dented.ApplyCollision(collision, ECollisionSide::B).Get().mVerticesMoved == 0)
            throw std::runtime_error("crush_plan: an earlier crush moved nothing");
    ffd::SurfaceProbe face; // the front face seen along the crush, as the plan's footprint probe sees it
    face.mDirection = -Vec3::UnitX();
    face.mSide = Vec3::UnitY();
    face.mThird = -Vec3::UnitZ();
    face.mSideMin = -cHalfExtents.y();
    face.mSideMax = cHalfExtents.y();
    face.mThirdMin = -cHalfExtents.z();
    face.mThirdMax = cHalfExtents.z();
    std::optional<CrushPlan> plan_pristine, plan_dented;
    ffd::SurfaceProbeResult indexed, scanned;
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions,
        {{[] {},
          [&]
          {
              plan_pristine = PlanCampbellCrush(collision, ECollisionSide::B, collision.mCrushEnergyB,
                                                pristine.GetMaterial(), pristine.GetUpAxis(),
                                                pristine.GetDeformer(), &pristine.GetCrushBody());
          }},
         {[] {},
          [&]
          {
              plan_dented = PlanCampbellCrush(collision, ECollisionSide::B, collision.mCrushEnergyB,
                                              dented.GetMaterial(), dented.GetUpAxis(), dented.GetDeformer(),
                                              &dented.GetCrushBody());
          }},
         {[] {}, [&] { indexed = dented.GetDeformer().ProbeSurface(face); }},
         {[] {}, [&] { scanned = common::BruteForceProbe(dented.GetDeformer(), face); }}});
    if (!plan_pristine || !plan_dented)
        throw std::runtime_error("crush_plan: the collision planned no crush");
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> y(-1.0, 1.0), z(-0.8, 0.8), width(0.02, 1.5);
    int differing = 0, probes = 0;
    for (; probes < 40; ++probes)
    {
        ffd::SurfaceProbe probe = face;
        const double wy = width(random), wz = width(random), cy = y(random), cz = z(random);
        probe.mSideMin = cy - 0.5 * wy;
        probe.mSideMax = cy + 0.5 * wy;
        probe.mThirdMin = cz - 0.5 * wz;
        probe.mThirdMax = cz + 0.5 * wz;
        const ffd::SurfaceProbeResult a = dented.GetDeformer().ProbeSurface(probe);
        const ffd::SurfaceProbeResult b = common::BruteForceProbe(dented.GetDeformer(), probe);
        differing +=
            a.mFront == b.mFront && a.mVertexInside == b.mVertexInside && a.mMoved == b.mMoved ? 0 : 1;
    }
    differing += indexed.mFront == scanned.mFront && indexed.mMoved == scanned.mMoved ? 0 : 1;
    ioTable.Add(
        {"crush_plan",
         std::to_string(inTriangles / 1000) + "k_tris/campbell/64_contacts/after_" + std::to_string(inDents) +
             "_crushes",
         timing[1].mWallMs, static_cast<double>(differing) / (probes + 1), "share_of_probes_unlike_full_scan",
         "plan_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";pristine_plan_ms=" +
             FormatExtra(timing[0].mWallMs) + ";pristine_plan_cpu_ms=" + FormatExtra(timing[0].mCpuMs) +
             ";dented_over_pristine_cpu=" + FormatExtra(timing[1].mCpuMs / timing[0].mCpuMs) +
             ";face_probe_cpu_ms=" + FormatExtra(timing[2].mCpuMs) +
             ";full_scan_cpu_ms=" + FormatExtra(timing[3].mCpuMs) +
             ";full_scan_over_probe_cpu=" + FormatExtra(timing[3].mCpuMs / timing[2].mCpuMs) + ";crushed_m=" +
             FormatExtra(indexed.mFront - face.mDirection.dot(Vec3(cHalfExtents.x(), 0.0, 0.0)))});
}

} // namespace

void RunDentBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    const int repetitions = inOptions.mQuick ? 3 : 31;
    const int triangles = inOptions.mQuick ? 4000 : 50000;

    // The paper's figure: 38 contacts, 4,984 of 9,580 triangles updated in < 16 ms (Pentium IV).
    ApplyCase(ioTable, "paper_comparison", inOptions.mQuick ? 2000 : 9580, 1, 8, 38, repetitions);

    // A car-sized mesh in 1, 2 and 4 zones; collisions of 38 and 64 contacts.
    for (int zones : {1, 2, 4})
        for (int contacts : {38, 64})
            ApplyCase(ioTable, "apply_collision", triangles, zones, 8, contacts, repetitions);

    // Lattice resolution against time and error; 0: the default lattice (0.15 m control spacing).
    for (int controls : {4, 6, 8, 12, 16, 0})
        ApplyCase(ioTable, "lattice_resolution", triangles, 1, controls, 38, repetitions);
    ApplyCase(ioTable, "apply_collision", triangles, 1, 0, 64, repetitions);

    // Split over the host's job system (bitwise the same dent).
    ThreadsCase(ioTable, triangles, 8, 64, repetitions);
    ThreadsCase(ioTable, triangles, 0, 64, repetitions);

    // The default material's crush (Campbell's law) of the same collision: no solve, the control field
    // written from the footprint.
    for (int controls : {8, 16, 0})
        ApplyCase(ioTable, "apply_collision", triangles, 1, controls, 64, repetitions, ECrushModel::Campbell);

    // Its plan alone, beside the whole crush.
    PlanCase(ioTable, triangles, repetitions);
    PlanCase(ioTable, triangles, repetitions, true);
    PlanCase(ioTable, triangles, repetitions, true, true);
    // On a body crushed three times before.
    DentedPlanCase(ioTable, triangles, 3, repetitions);

    // The same crush on a body four times as fine: time per updated vertex (issue: linear in updated vertices).
    ScalingCase(ioTable, triangles, 4 * triangles, repetitions);

    // Its per-vertex kernel alone.
    RunTensorSumCase(ioTable, inOptions);
    RunWideImpactCases(ioTable, inOptions);
}

} // namespace crumple::bench
