// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/fem/EImplicitPreconditioner.h>
#include <crumple/fem/EIntegrator.h>
#include <crumple/fem/GroundPlane.h>

namespace crumple::fem
{

/// Settings of a TetSolver (the material comes separately in FemMaterialSettings). Validated by
/// TetSolver::Create().
struct CRUMPLE_API TetSolverSettings
{
    /// Time integration; implicit is stable at game steps for any stiffness, symplectic is cheaper per
    /// sub-step
    EIntegrator mIntegrator = EIntegrator::ImplicitEuler;
    Vec3 mGravity = Vec3(0.0, 0.0, -9.81); ///< Acceleration of gravity (m/s^2), world frame, z up
    /// A ground the free nodes rest on (off by default; implicit Euler only; GroundPlane). SolveStatic() and
    /// ContactEffectiveMass() ignore it.
    GroundPlane mGround;

    /// Symplectic Euler: each sub-step is mStabilitySafetyFactor x the proven stable limit of
    /// StableTimeStep(), in (0, 1]. At 0.5 the stiffest mode has omega dt <= 1, so the paper's explicit-Euler
    /// instability cannot occur for the corotated model whatever E, rho and the mesh.
    double mStabilitySafetyFactor = 0.5;
    /// Symplectic Euler: a Step() that would need more sub-steps than this is refused (nothing changes)
    /// instead of being run unstably; use a smaller step, a softer material, coarser elements or the implicit
    /// integrator.
    int mMaxSubSteps = 10000;

    /// Implicit Euler and SolveStatic(): the preconditioner of conjugate gradient. The default factors the
    /// rest system once and reuses it (see EImplicitPreconditioner for its cost and memory); BlockJacobi
    /// needs no setup and no memory but many more iterations on stiff materials.
    EImplicitPreconditioner mPreconditioner = EImplicitPreconditioner::RestFactorization;
    /// Implicit Euler and SolveStatic(): conjugate gradient stops when |residual| <= tolerance x |right-hand
    /// side| (Euclidean norms over the free degrees of freedom), in (0, 1).
    double mCgRelativeTolerance = 1.0e-6;
    /// Implicit Euler: at most this many conjugate-gradient iterations per linear solve (>= 1); when reached,
    /// the step is kept (the truncated solution of an SPD system is still a descent step) and
    /// ETetStepEvent::SolverNotConverged is set.
    int mCgMaxIterations = 1000;
    /// Implicit Euler with RestFactorization, corotated model: when a conjugate-gradient solve has not
    /// converged after this many iterations, or sooner when from the second iteration on the rate of its last
    /// iteration says it would need more, the factor is
    /// refreshed at the current element frames (a numeric refactorisation, the ordering kept) and the solve
    /// goes on from where it stopped, with a preconditioner that is exact for the current linearisation. The
    /// factor then stays at those frames for the later solves and steps (solver state: copies and replays
    /// continue bit for bit); a crack or a change of anchors, which need a new factorisation, take the
    /// frames of the last element pass for it, where the next solve is linearised. A bent or
    /// crushed prop otherwise costs 5 to 20 iterations per solve (neighbouring elements turned apart, which
    /// the per-node rotation cannot follow). Whether it pays depends on what a refresh costs against an
    /// iteration, which varies with the mesh and the motion. Measured at 3: the Bullet racing fence (4,000
    /// tetrahedra, 5 refreshes) spent 63-76 instead of 72-80 ms in its FEM over the session, ODE's (28
    /// refreshes, 4x fewer iterations in a traced build) 390-496 instead of 376-475 ms; a soft rail of 6,400
    /// tetrahedra took a third of the iterations but 19 instead of 14 ms per step (crumple-bench --only
    /// fem_refresh), its refresh costing about 13 iterations. 0 (the default) never refreshes: results stay
    /// those of earlier versions bit for bit. With mCrackStressTolerance a cracking prop's links no longer
    /// depend on it (the racing fence breaks the same 156 links at 0, 3 and 6; the README's racing
    /// figures). >= 0. On the GPU (gpu::GpuTetSolver), which has no factor, the coarse space of its solves is
    /// turned with its aggregates before a step that follows a solve longer than this, so 0 there turns it
    /// before every step but the first (a positions readback and 0.2 ms of host work for 17,600 tetrahedra).
    int mFactorRefreshIterations = 0;
    /// With mFactorRefreshIterations > 0: also refresh the factor before a solve once the solves since its
    /// frames were last set have taken, together, more iterations beyond two each than a refresh costs
    /// (TetFactoredPreconditioner::GetRefreshCostInIterations, from operation counts: 5.7 iterations on the
    /// racing fence's 4,000 tetrahedra, 8.4 on a 6,400-tetrahedron rail, measured 5.4 and 10). A factor whose
    /// frames cost a few iterations per solve, too few to stop one (a fence settling after a hit at other
    /// frames than those of its last refresh: 4-5 iterations per step for a hundred steps), is then refreshed
    /// when the iterations it has cost add up to a refresh: rent or buy, at most twice the cost of the best
    /// choice in hindsight on that part of the solves; a refresh that bought nothing (pieces turning too fast
    /// between solves for any frames to fit: FactorRefreshLedger) makes the next wait longer. False (the
    /// default, and recordings made before it): only a long solve refreshes. The GPU solver, which has no
    /// factor, ignores it.
    bool mFactorRefreshByCost = false;
    /// Implicit Euler: at most this many Newton iterations (linear solves) per step, >= 1. The first is the
    /// classic one-solve linearised step; further ones re-evaluate forces and rotations at the new positions,
    /// which a rotating body needs (one solve stretches it by ~(omega h)^2 / 2 per step). Reaching the limit
    /// sets ETetStepEvent::SolverNotConverged and keeps the step.
    int mImplicitMaxIterations = 4;
    /// Implicit Euler: Newton stops when the energy of the remaining correction, 1/2 r^T A^-1 r with the
    /// momentum residual r = h f(x0 + h v1) + h f_ext - M (v1 - v0) and A^-1 estimated by the block-Jacobi
    /// inverse, is below this fraction of the step's kinetic energy scale (max of 1/2 m v^2 before and after,
    /// plus that of the load's impulse h f_ext). In (0, 1); 1e-3 bounds the energy a rotating stiff body can
    /// pick up per step to 0.1 %.
    double mImplicitTolerance = 1.0e-3;
    /// Implicit Euler, breakable material: Newton also goes on until the energy of the remaining correction
    /// could move no fracture group's largest principal stress by more than this fraction of the tensile
    /// strength (CrackSafeEnergy(): below f^2 sigma_t^2 kappa V_min / (2 E)), so that the links a step opens
    /// are those of its converged solution. The energy test above is relative to the step's energy scale,
    /// which a hit makes huge (an impulse on a few light nodes: 1.2e7 J at the racing fence's first contact),
    /// and alone it stopped where the links its error cracked depended on the engine, the ground's shape and
    /// the CG tolerance (the drive-through fence at 64 km/h: Bullet 1,228 links, ODE 834, 381 the same). With
    /// 0.5: 220 and 179, 178 the same (Bullet 220-228 at 0.3-1; on the scene's former plane ground the same
    /// 234 links at 0.02-0.2); 0.5 costs one Newton iteration more in a hit's steps (the README's racing
    /// figures). > 0; infinity leaves only the
    /// energy test (the behaviour before this setting, and that of recordings made before it).
    double mCrackStressTolerance = 0.5;

    /// Sleep: when the kinetic energy stays below 1/2 M_free mSleepSpeed^2 (M_free the mass of the free
    /// nodes, so mSleepSpeed is a root-mean-square speed in m/s) for mSleepStepCount consecutive steps in
    /// which no link broke, velocities are zeroed and Step() does nothing (no element work) until an input
    /// changes: an impulse, a force, gravity, a fixed node, new positions or velocities, or WakeUp(). A
    /// solver that nothing could move (no velocity, no load, no strain: a prop made at rest without gravity)
    /// sleeps at once, in the step that finds it so; one that has settled (kinetic energy under 1e-8 of the
    /// sleep energy for 3 steps in a row: round-off of a body in equilibrium, strained against its anchors)
    /// sleeps then, without waiting for mSleepStepCount. >= 0; 0 never sleeps.
    double mSleepSpeed = 1.0e-3;
    int mSleepStepCount = 30; ///< Consecutive quiet steps before sleeping, >= 1

    /// Divergence: a step has diverged when its end state has a NaN or Inf, or when its mechanical energy
    /// H = kinetic + elastic - sum f_ext . (x - X) (gravity included in f_ext) exceeds the energy H_ref of
    /// the last input change by more than mDivergenceEnergyRatio x C, C = kinetic + elastic + sum |f_ext . (x
    /// - X)| of the end state (the energy content). A passive system cannot gain energy without input:
    /// implicit Euler only loses it, symplectic Euler at the default safety factor fluctuates by well under
    /// half of C; a real blow-up makes H approach C and is caught. In (0, 1). The state is then restored to
    /// the start of the step and ETetStepEvent::Diverged reported.
    double mDivergenceEnergyRatio = 0.5;
    /// Divergence: a diverged step is retried from its start in 2, 4, ... 2^mMaxStepSplits equal pieces
    /// (implicit Euler: that many implicit steps; symplectic Euler: that many times the sub-steps, within
    /// mMaxSubSteps) before it is given up, restored and reported; the steps after it of the same length are
    /// reported diverged at once, from the same start, until an input changes (an impulse, a force, a fixed
    /// node, positions or velocities set, gravity). Fast rotation is what usually needs it:
    /// implicit Euler extrapolates a rotation along its tangent, which needs omega h below ~0.5 rad.
    /// In [0, 16].
    int mMaxStepSplits = 5;
};

} // namespace crumple::fem
