// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"
#include "BrickBurst.h"
#include "CarFrontOnFenceCrawl.h"
#include "CarFrontOnFenceStall.h"
#include "CarOnHeldFence.h"
#include "PieceOnGround.h"
#include "ThreadJobSystem.h"
#include "WedgedPiece.h"
#include "WorldFixture.h"

#include <crumple/plugin/BaraffImpulse.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace crumple::bench
{

using namespace crumple::plugin;

namespace
{

constexpr double cBoxMass = 1200.0; // kg

// A 1,200 kg, 4 m x 2 m x 1.4 m box, its bottom face on z = 0, moving at inVelocity (m/s).
BodyState FallingBox(const Vec3& inVelocity)
{
    const double m = cBoxMass;
    BodyState box;
    box.mMass = m;
    box.mInverseInertiaWorld = Vec3(12.0 / (m * (4.0 + 1.96)), 12.0 / (m * (16.0 + 1.96)), 12.0 / (m * 20.0)).asDiagonal();
    box.mCenterOfMass = Vec3(0.0, 0.0, 0.7);
    box.mLinearVelocity = inVelocity;
    return box;
}

// inGrid x inGrid contacts spread over the box's 4 m x 2 m bottom (one at its centre for inGrid 1), normal +z,
// friction coefficient inFriction.
std::vector<ImpulseContact> BottomGrid(int inGrid, double inFriction)
{
    std::vector<ImpulseContact> contacts;
    for (int i = 0; i < inGrid; ++i)
        for (int k = 0; k < inGrid; ++k)
            contacts.push_back({Vec3(inGrid == 1 ? 0.0 : -2.0 + 4.0 * i / (inGrid - 1),
                                     inGrid == 1 ? 0.0 : -1.0 + 2.0 * k / (inGrid - 1), 0.0),
                                Vec3::UnitZ(), 0.0, inFriction});
    return contacts;
}

// N contacts in a grid on the bottom of a 1,200 kg, 4 m x 2 m box falling flat at 5 m/s on static ground.
void ImpulseCase(BenchTable& ioTable, int inGrid, int inRepetitions)
{
    const double m = cBoxMass, v = 5.0, e = 0.1;
    const BodyState box = FallingBox(Vec3(0.0, 0.0, -v));
    BodyState ground;
    ground.mMotionType = EMotionType::Static;
    const std::vector<ImpulseContact> contacts = BottomGrid(inGrid, 0.0);
    std::vector<double> impulses;
    constexpr int cInner = 20;
    const Timing timing = MedianTiming(inRepetitions, [] {}, [&] {
        for (int i = 0; i < cInner; ++i)
            impulses = SimultaneousImpulses(box, ground, contacts, e, 0.5);
    });
    const double ms = timing.mWallMs / cInner;
    double total = 0.0;
    for (double j : impulses)
        total += j;
    const double expected = (1.0 + e) * m * v;
    ioTable.Add({"impulse_solve", std::to_string(contacts.size()) + "_contacts", ms, std::abs(total - expected) / expected,
                 "rel_total_impulse", "analytic=(1+e)mv=" + std::to_string(expected) + ";cpu_ms=" + FormatExtra(timing.mCpuMs / cInner)});
}

// The same box landing flat while sliding at 10 m/s, friction 0.5 at each of its N contacts: every contact
// slides, so the contacts together take (1+e) m v_z along the normal and mu times that against the slide
// (the normals share the friction's pitching torque between front and back), whatever N.
void FrictionCase(BenchTable& ioTable, int inGrid, int inRepetitions)
{
    const double m = cBoxMass, v = 5.0, e = 0.1, mu = 0.5;
    const BodyState box = FallingBox(Vec3(10.0, 0.0, -v));
    BodyState ground;
    ground.mMotionType = EMotionType::Static;
    const std::vector<ImpulseContact> contacts = BottomGrid(inGrid, mu);
    std::vector<ContactImpulse> impulses;
    constexpr int cInner = 20;
    const Timing timing = MedianTiming(inRepetitions, [] {}, [&] {
        for (int i = 0; i < cInner; ++i)
            impulses = FrictionalImpulses(box, ground, contacts, e, 0.5);
    });
    double normal = 0.0;
    Vec3 friction = Vec3::Zero();
    for (const ContactImpulse& j : impulses)
    {
        normal += j.mNormal;
        friction += j.mFriction;
    }
    const double expected = (1.0 + e) * m * v;
    const double error = std::max(std::abs(normal - expected), (friction + mu * expected * Vec3::UnitX()).norm()) / expected;
    ioTable.Add({"friction_solve", std::to_string(contacts.size()) + "_sliding_contacts", timing.mWallMs / cInner, error,
                 "rel_impulse", "analytic=(1+e)mv=" + std::to_string(expected) + ",mu_times_it;cpu_ms=" + FormatExtra(timing.mCpuMs / cInner)});
}

// One contact set solved by projected Gauss-Seidel alone and with subspace steps, interleaved; the error of
// each is the struck body's velocity change against Gauss-Seidel run to convergence without a sweep bound
// (an independent answer: the same model, another path to it), relative to the largest of the two bodies'.
void FrictionCrawlCase(BenchTable& ioTable, const std::string& inName, const BodyState& inA,
                       const BodyState& inB, const std::vector<ImpulseContact>& inContacts,
                       double inRestitution, double inClosingSpeed, int inRepetitions)
{
    const auto change_of = [&](const std::vector<ContactImpulse>& inImpulses)
    {
        Eigen::Matrix<double, 12, 1> change = Eigen::Matrix<double, 12, 1>::Zero();
        for (std::size_t i = 0; i < inContacts.size(); ++i)
        {
            const Vec3 p = inImpulses[i].mNormal * inContacts[i].mNormal + inImpulses[i].mFriction;
            change.segment<3>(0) += inA.InverseMass() * p;
            change.segment<3>(3) +=
                inA.InverseInertia() * (inContacts[i].mPoint - inA.mCenterOfMass).cross(p);
            change.segment<3>(6) -= inB.InverseMass() * p;
            change.segment<3>(9) -=
                inB.InverseInertia() * (inContacts[i].mPoint - inB.mCenterOfMass).cross(p);
        }
        return change;
    };
    FrictionSolveStats reference_stats;
    const auto reference =
        change_of(FrictionalImpulses(inA, inB, inContacts, inRestitution, inClosingSpeed,
                                     {.mMaxSweeps = 1000000, .mSubspaceInterval = 0}, &reference_stats));
    if (!reference_stats.mConverged)
        throw std::runtime_error("friction_crawl " + inName + ": the reference did not converge");
    const FrictionSolveSettings plain{.mSubspaceInterval = 0}, subspace{};
    std::vector<ContactImpulse> plain_impulses, subspace_impulses;
    FrictionSolveStats plain_stats, subspace_stats;
    constexpr int cInner = 5;
    const std::vector<Timing> timing = InterleavedMedians(
        inRepetitions, {{[] {},
                         [&]
                         {
                             for (int i = 0; i < cInner; ++i)
                                 plain_impulses = FrictionalImpulses(inA, inB, inContacts, inRestitution,
                                                                     inClosingSpeed, plain, &plain_stats);
                         }},
                        {[] {},
                         [&]
                         {
                             for (int i = 0; i < cInner; ++i)
                                 subspace_impulses =
                                     FrictionalImpulses(inA, inB, inContacts, inRestitution, inClosingSpeed,
                                                        subspace, &subspace_stats);
                         }}});
    const double scale = std::max(reference.lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min());
    const double plain_error = (change_of(plain_impulses) - reference).lpNorm<Eigen::Infinity>() / scale;
    const double subspace_error =
        (change_of(subspace_impulses) - reference).lpNorm<Eigen::Infinity>() / scale;
    const std::string contacts = std::to_string(inContacts.size()) + "_contacts";
    ioTable.Add({"friction_crawl", inName + "/" + contacts + "/gauss_seidel", timing[0].mWallMs / cInner,
                 plain_error, "rel_velocity_change",
                 "sweeps=" + std::to_string(plain_stats.mSweeps) +
                     ";converged=" + std::to_string(plain_stats.mConverged) +
                     ";reference_sweeps=" + std::to_string(reference_stats.mSweeps) +
                     ";cpu_ms=" + FormatExtra(timing[0].mCpuMs / cInner)});
    ioTable.Add({"friction_crawl", inName + "/" + contacts + "/subspace_steps", timing[1].mWallMs / cInner,
                 subspace_error, "rel_velocity_change",
                 "sweeps=" + std::to_string(subspace_stats.mSweeps) +
                     ";subspace_steps=" + std::to_string(subspace_stats.mSubspaceSteps) +
                     ";converged=" + std::to_string(subspace_stats.mConverged) +
                     ";settled=" + std::to_string(subspace_stats.mSettled) +
                     ";cpu_ms=" + FormatExtra(timing[1].mCpuMs / cInner) +
                     ";speedup_cpu=" + FormatExtra(timing[0].mCpuMs / timing[1].mCpuMs) +
                     ";speedup_wall=" + FormatExtra(timing[0].mWallMs / timing[1].mWallMs)});
}

// Frames without impacts: an empty frame and a car resting on four wheel contacts.
void IdleCases(BenchTable& ioTable, int inRepetitions)
{
    common::WorldFixture fixture(50000);
    const ffd::FfdDeformer& car = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer();
    constexpr int cFrames = 1000;
    double time = 0.0;
    const Timing empty = MedianTiming(inRepetitions, [] {}, [&] {
        for (int i = 0; i < cFrames; ++i)
        {
            (void)fixture.mWorld.SubmitContacts({});
            fixture.mWorld.Update(time += 1.0 / 60.0);
        }
    });
    ioTable.Add({"frame_overhead", "no_contacts", empty.mWallMs / cFrames, 0.0, "none",
                 "vertex_evaluations=" + std::to_string(car.GetVertexEvaluationCount()) +
                     ";cpu_ms=" + FormatExtra(empty.mCpuMs / cFrames)});

    BodyState resting = fixture.CarState(0.0);
    resting.mLinearVelocity = Vec3(20.0, 0.0, -9.81 / 60.0);
    std::vector<ContactEvent> wheels;
    for (double x : {-1.4, 1.4})
        for (double y : {-0.8, 0.8})
        {
            ContactEvent contact;
            contact.mBodyA = fixture.mCar;
            contact.mBodyB = fixture.mFloor;
            contact.mPointOnA = contact.mPointOnB = Vec3(x - 2.1, y, -0.7);
            contact.mNormal = Vec3::UnitZ();
            wheels.push_back(contact);
        }
    const Timing resting_timing = MedianTiming(inRepetitions, [] {}, [&] {
        for (int i = 0; i < cFrames; ++i)
        {
            time += 1.0 / 60.0;
            for (ContactEvent& wheel : wheels)
                wheel.mTime = time;
            (void)fixture.mWorld.SetBodyState(fixture.mCar, resting);
            (void)fixture.mWorld.SubmitContacts(wheels);
            fixture.mWorld.Update(time);
        }
    });
    ioTable.Add({"frame_overhead", "4_resting_contacts", resting_timing.mWallMs / cFrames, 0.0, "none",
                 "vertex_evaluations=" + std::to_string(car.GetVertexEvaluationCount()) +
                     ";open_collisions=" + std::to_string(fixture.mWorld.GetOpenCollisionCount()) +
                     ";cpu_ms=" + FormatExtra(resting_timing.mCpuMs / cFrames)});
}

// One pair's manifold of N contacts in one step (a mesh-mesh contact) through DamageWorld::SubmitContacts,
// reduced to DamageWorldSettings::mMaxContactsPerPair before the solve: time of the submit against the
// error of the collision's impulse from the analytic (1 + e) m v of the face hit.
void ManifoldCase(BenchTable& ioTable, int inContacts, int inRepetitions)
{
    common::WorldFixture fixture(2000);
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(inContacts))));
    std::vector<ContactEvent> contacts;
    for (int i = 0; i < side; ++i)
        for (int k = 0; k < side; ++k)
            contacts.push_back(fixture.FrontContact(-0.8 + 1.6 * i / (side - 1), -0.6 + 1.2 * k / (side - 1), 0.0));
    struct Listener : DamageListener
    {
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override { mImpulse += inCollision.TotalImpulse(); }
        double mImpulse = 0.0;
    } listener;
    fixture.mWorld.AddListener(&listener);
    double time = 0.0;
    const Timing timing = MedianTiming(inRepetitions, [&] {
        (void)fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0));
        time += 1.0;
        for (ContactEvent& contact : contacts)
            contact.mTime = time;
    }, [&] { (void)fixture.mWorld.SubmitContacts(contacts); });
    listener.mImpulse = 0.0;
    fixture.mWorld.ResetDamage();
    (void)fixture.mWorld.Flush();
    listener.mImpulse = 0.0;
    (void)fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0));
    for (ContactEvent& contact : contacts)
        contact.mTime = time + 1.0;
    (void)fixture.mWorld.SubmitContacts(contacts);
    (void)fixture.mWorld.Flush();
    const double expected = (1.0 + fixture.mWorld.GetSettings().mRestitution) * fixture.mMass * 15.0;
    ioTable.Add({"manifold_submit", std::to_string(contacts.size()) + "_contacts_one_pair", timing.mWallMs,
                 std::abs(listener.mImpulse - expected) / expected, "rel_total_impulse",
                 "solved_contacts<=" + std::to_string(fixture.mWorld.GetSettings().mMaxContactsPerPair) +
                     ";cpu_ms=" + FormatExtra(timing.mCpuMs)});
}

// A brick wall bursting in one engine step (common::MakeBrickBurst: 16 x 10 bricks, 1,240 contacts of 310
// pairs) through DamageWorld::SubmitContacts, its pairs' solves inline and split over a host's 2 workers
// (ThreadJobSystem, the caller one of them), interleaved; thread CPU is the calling thread's. The error: how
// many contacts' impulses differ from the inline solve's in any bit (the split must not change one).
void BurstCase(BenchTable& ioTable, int inRepetitions)
{
    common::ThreadJobSystem two_workers(2);
    struct Side
    {
        const JobSystem* mJobs = nullptr;
        common::BrickBurst mBurst;
        std::vector<Collision> mCollisions;
    };
    struct Heard : DamageListener
    {
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
        {
            mCollisions->push_back(inCollision);
        }
        std::vector<Collision>* mCollisions = nullptr;
    };
    Side sides[2];
    sides[1].mJobs = &two_workers.Get();
    const auto prepare = [&](Side& ioSide)
    {
        DamageWorldSettings settings;
        settings.mJobs = ioSide.mJobs;
        ioSide.mBurst = common::MakeBrickBurst(16, 10, 7, settings);
    };
    const auto submit = [&](Side& ioSide)
    {
        if (Status submitted = ioSide.mBurst.mWorld->SubmitContacts(ioSide.mBurst.mContacts, 1.0 / 240.0);
            !submitted)
            throw std::runtime_error("contact_burst: " + submitted.GetError().mMessage);
    };
    const std::vector<Timing> timing =
        InterleavedMedians(inRepetitions, {{[&] { prepare(sides[0]); }, [&] { submit(sides[0]); }},
                                           {[&] { prepare(sides[1]); }, [&] { submit(sides[1]); }}});
    std::size_t contacts = 0;
    for (Side& side : sides)
    {
        Heard heard;
        heard.mCollisions = &side.mCollisions;
        side.mBurst.mWorld->AddListener(&heard);
        (void)side.mBurst.mWorld->Flush();
        side.mBurst.mWorld->RemoveListener(&heard);
    }
    int differing = sides[0].mCollisions.size() == sides[1].mCollisions.size() ? 0 : 1;
    for (std::size_t i = 0; i < std::min(sides[0].mCollisions.size(), sides[1].mCollisions.size()); ++i)
    {
        const std::vector<CollisionContact>& a = sides[0].mCollisions[i].mContacts;
        const std::vector<CollisionContact>& b = sides[1].mCollisions[i].mContacts;
        contacts += a.size();
        differing += static_cast<int>(std::max(a.size(), b.size()) - std::min(a.size(), b.size()));
        for (std::size_t c = 0; c < std::min(a.size(), b.size()); ++c)
            differing += std::memcmp(&a[c].mImpulse, &b[c].mImpulse, sizeof(double)) != 0 ||
                                 std::memcmp(a[c].mFrictionImpulse.data(), b[c].mFrictionImpulse.data(),
                                             sizeof(Vec3)) != 0
                             ? 1
                             : 0;
    }
    const std::string name = "16x10_bricks/" + std::to_string(sides[0].mBurst.mContacts.size()) + "_contacts";
    ioTable.Add(
        {"contact_burst", name + "/inline", timing[0].mWallMs, 0.0, "none",
         "pushing_contacts=" + std::to_string(contacts) + ";cpu_ms=" + FormatExtra(timing[0].mCpuMs)});
    ioTable.Add({"contact_burst", name + "/2_workers", timing[1].mWallMs, static_cast<double>(differing),
                 "differing_contacts",
                 "cpu_ms=" + FormatExtra(timing[1].mCpuMs) +
                     ";speedup_cpu=" + FormatExtra(timing[0].mCpuMs / timing[1].mCpuMs) +
                     ";speedup_wall=" + FormatExtra(timing[0].mWallMs / timing[1].mWallMs)});
}

} // namespace

void RunImpulseBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    const int repetitions = inOptions.mQuick ? 3 : 51;
    for (int grid : {1, 2, 6, 8})
        ImpulseCase(ioTable, grid, repetitions);
    for (int grid : {2, 4, 8})
        FrictionCase(ioTable, grid, repetitions);
    // Gauss-Seidel's slow cases: the piece wedged in the racing fence (the solve that ended at the sweep
    // bound at the fence hit), the car pressing the held fence just before (no exact answer for its states:
    // settled at a least-squares point), ODE's piece on the ground (one contact must let go) and the
    // sliding box's grids, each contact sliding.
    const common::WedgedPiece wedged = common::MakeWedgedPiece();
    FrictionCrawlCase(ioTable, "wedged_piece", wedged.mFence, wedged.mPiece, wedged.mContacts,
                      wedged.mRestitution, wedged.mClosingSpeed, repetitions);
    const common::CarOnHeldFence pressing = common::MakeCarOnHeldFence();
    FrictionCrawlCase(ioTable, "car_on_held_fence", pressing.mCar, pressing.mFence, pressing.mContacts,
                      pressing.mRestitution, pressing.mClosingSpeed, repetitions);
    // The car's front breaking into the held fence: Gauss-Seidel stalls and every subspace step is refused
    // (the stall stop's case).
    const common::CarFrontOnFenceStall stalling = common::MakeCarFrontOnFenceStall();
    FrictionCrawlCase(ioTable, "car_front_on_fence_stall", stalling.mCar, stalling.mFence, stalling.mContacts,
                      stalling.mRestitution, stalling.mClosingSpeed, repetitions);
    // The car's front pressing into the moving fence: Gauss-Seidel crawls without stalling (2,242 sweeps to
    // converge); the subspace steps converge after 621 (they stopped at the 1,000-sweep bound until Newton
    // stopped creeping towards least-squares points).
    const common::CarFrontOnFenceCrawl crawling = common::MakeCarFrontOnFenceCrawl();
    FrictionCrawlCase(ioTable, "car_front_on_fence_crawl", crawling.mCar, crawling.mFence, crawling.mContacts,
                      crawling.mRestitution, crawling.mClosingSpeed, repetitions);
    const common::PieceOnGround resting = common::MakePieceOnGround();
    FrictionCrawlCase(ioTable, "piece_on_ground", resting.mGround, resting.mPiece, resting.mContacts,
                      resting.mRestitution, resting.mClosingSpeed, repetitions);
    BodyState ground;
    ground.mMotionType = EMotionType::Static;
    for (int grid : {2, 4, 8})
        FrictionCrawlCase(ioTable, "sliding_box", FallingBox(Vec3(10.0, 0.0, -5.0)), ground,
                          BottomGrid(grid, 0.5), 0.1, 0.5, repetitions);
    for (int contacts : {10, 100, 1000, 10000})
        ManifoldCase(ioTable, contacts, inOptions.mQuick ? 3 : 11);
    IdleCases(ioTable, repetitions);
    BurstCase(ioTable, repetitions);
}

} // namespace crumple::bench
