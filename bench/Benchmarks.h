// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "BenchTable.h"

namespace crumple::bench
{

/// Run-wide options.
struct BenchOptions
{
    bool mQuick = false; ///< Few repetitions and small meshes: a smoke run for the test suite
};

/// Dent application on a car-sized mesh: contacts, zones and lattice resolution against time and error.
void RunDentBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// The dent's per-vertex kernel, the B-spline sum in AVX lanes against the scalar one (part of the dent group).
void RunTensorSumCase(BenchTable& ioTable, const BenchOptions& inOptions);
/// Rows wide_impact: ffd::InterpolateWideImpact on a car front's random contacts and on a ring of contacts
void RunWideImpactCases(BenchTable& ioTable, const BenchOptions& inOptions);

/// Simultaneous Baraff impulses against the analytic impulse, and the cost of frames without impacts.
void RunImpulseBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// Per engine step with the Bullet/ODE adapter attached, against the bare engine step of the same scene in
/// the same run: no contacts, resting contacts only, and a wall crash.
void RunAdapterBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// Worst, 99th-percentile and median frame of a crash at 60 Hz, bare engine and Crumple attached, in lockstep.
void RunFrameBudgetBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// The racing samples' course (BulletRaceScene, OdeRaceScene) at 60 Hz, bare engine and Crumple attached in
/// lockstep: worst and 99th-percentile frame of each side (part of the frame_budget group).
void RunRaceFrameBudgetBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// The steel cantilever of the FEM issue on meshes of about 1k, 10k and 100k tetrahedra: time of one 1/60 s
/// Step() against the error of the tip deflection (Timoshenko) for explicit and implicit Euler and the linear
/// (St. Venant-Kirchhoff) and corotated models, and the static solve as the discretisation reference. Cases
/// over a time budget are reported with an extrapolated time and no error, never dropped. And fem_realtime: 10
/// implicit corotated steps of 1/60 s with the factored preconditioner on one thread and on all cores, and
/// block Jacobi, interleaved, against a solve converged to round-off. Empty without crumple::fem.
void RunFemBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// The factored preconditioner refreshed at the element frames (TetSolverSettings::mFactorRefreshIterations =
/// 3, 6, and 6 with mFactorRefreshByCost) against the rest factor alone, on a soft rail (about 800 and 6,400
/// tetrahedra; --quick the first) pushed in its middle for six 1/240 s steps, then swinging and settling for
/// 42 more, the four stepped in turn: time per step and conjugate-gradient iterations of each, the refresh's
/// cost in iterations (TetSolver::GetFactorRefreshCost); error: the largest distance of a node from a solve
/// converged to round-off, over the largest displacement. Empty without crumple::fem.
void RunFemRefreshBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// The crack-safe Newton bound (TetSolverSettings::mCrackStressTolerance, default 0.5) against the energy
/// test alone, and with the held props' factor refreshes (after 6 iterations; and by cost), on the pushed
/// wooden rail (scenes/PushedRail.h; 200 and 300 N s per push step, --quick the first), the four stepped in
/// turn: time per step in thread CPU and wall time, Newton and CG iterations, refreshes;
/// error: the links whose state differs from a solve converged to round-off, over the links it cracked. Empty
/// without crumple::fem.
void RunCrackBoundBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// The mass a held prop body stands in with (TetSolver::ContactEffectiveMass) at a fence's struck rail,
/// factored and block Jacobi alternated, in thread CPU and wall time; error: against the mass one converged
/// implicit step shows a small impulse.
void RunContactMassBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// A ground (TetSolverSettings::mGround) against none: a level wooden rail anchored only along the top edge
/// of one end, 0.55 m up, swings down under gravity for 10 s (--quick 3 s) of 1/240 s steps, the two stepped
/// alternately: FEM steps awake, time per awake step and in all (thread CPU and wall); error: the grounded
/// rail's resting centre height against a rigid rail's. Empty without crumple::fem.
void RunGroundBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// Crumple's implicit FEM against Bullet's implicit deformable solver on the identical cantilever, 1k, 10k
/// and 100k tets (--quick: 1k): runs crumple-bench-fem-vs-bullet beside this program (it links Bullet's
/// double build) and takes its rows. Empty, with a note, where that program is not built.
void RunFemVsBulletBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// The two-way FEM barrier coupling of crumple-crash: a car stopped by a steel barrier at three engine steps,
/// time per step against the crush's error relative to Campbell's line. Empty without crumple-crash.
void RunBarrierBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// A car at 64 km/h through a held wooden fence (a prop: FEM, fracture, pieces made engine bodies) in Bullet
/// and ODE, interleaved with the same drive without the fence: CPU time per engine step of each, the fence's
/// FEM per step (one prop), handing pieces over (finding them, their rigid bodies, the engine's bodies: in
/// all and per body made) and its shape updates; error: the engine's change of the
/// car's momentum against Crumple's impulses on it. And fence_spread (not with --quick): the same hit with
/// the conjugate-gradient tolerance at 1e-6, 1e-7 and 1e-8 and with the factor refresh, links broken and the
/// car's loss of speed of each; error: the spread of that loss. Empty without crumple::props or an engine.
void RunPropBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);
/// The same 64 km/h drive-through in Bullet with the fence's FEM on the CPU and on the GPU backend (llvmpipe
/// where there is no GPU), alternated: game-thread CPU per step, the FEM's share, wall time, links broken and
/// pieces; error: the GPU's car loss of speed against the CPU's. Empty, with a note, without a device.
void RunPropGpuBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// Full-width rigid-wall crashes of the box car and the shipped meshes in Bullet and ODE at 20-64 km/h with the
/// default material: median run time of a 0.3 s crash against the worst crush error relative to Campbell's law
/// for the body's mass and width (and, in extra, to the oracle's mid-size line). Empty without crumple-crash.
void RunCrushBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

/// The FEM on the CPU (double) and as compute shaders (float) in one run: time per 1/60 s step of the steel
/// cantilever against tet count (1k to 1M) and the tip error of each, explicit, and the implicit step side by
/// side (gpu_implicit rows, GpuImplicitBenchmarks.h); without an EGL device it says so.
void RunGpuBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions);

} // namespace crumple::bench
