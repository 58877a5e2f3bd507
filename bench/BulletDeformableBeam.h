// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/TetSolver.h>

#include <memory>

namespace crumple::bench
{

/// Settings of a BulletDeformableBeam. The material (E, nu) comes from the TetSolver it copies; the solver
/// limits default to Bullet 3.24's own (btDeformableBodySolver: one Newton iteration, at most 300 CG
/// iterations per linear solve) so that the comparison is against Bullet as shipped.
struct BulletDeformableBeamSettings
{
    /// Fixed step (s), > 0: Step() calls stepSimulation(dt, 1, dt), one internal step
    double mTimeStep = 1.0 / 60.0;
    /// Rayleigh mass damping alpha (1/s), >= 0: btDeformableLinearElasticityForce's m_damping_alpha, the
    /// force -alpha m v, the same law as FemMaterialSettings::mMassDamping. Its stiffness damping
    /// m_damping_beta is 0.
    double mMassDamping = 0.0;
    int mMaxNewtonIterations = 1; ///< Newton iterations per step, >= 1 (Bullet's default 1)
    int mCgMaxIterations = 300;   ///< CG iterations per linear solve, >= 1 (Bullet's default 300)
};

/// The mesh of a Crumple TetSolver rebuilt as a Bullet 3.24 deformable body (btSoftBody in a
/// btDeformableMultiBodyDynamicsWorld, implicit btDeformableBodySolver, btDeformableLinearElasticityForce),
/// for benchmarking Crumple against Bullet on the same problem:
///  - nodes: the solver's rest positions (the body starts at rest), its tetrahedra in the same node order;
///  - masses: the solver's lumped masses, 0 (Bullet's anchor) where its inverse mass is 0;
///  - load: the solver's external forces, constant, through a btDeformableLagrangianForce of our own;
///  - elasticity: btDeformableLinearElasticityForce, linear elasticity in the element's corotated frame,
///    Lame parameters from the solver's material: the physics of EElasticModel::CorotatedLinear. (Bullet
///    extracts the element rotation only to 0.01 rad, btSoftBody::updateDeformation, so below that it is
///    plain linear elasticity; Crumple's corotated model agrees with it there to second order.)
///  - gravity zero.
/// Needs Bullet in double precision (BT_USE_DOUBLE_PRECISION, libBullet*-float64); the float build cannot be
/// linked into the same executable (same symbol names). Single-threaded; not copyable.
class BulletDeformableBeam
{
public:
    /// Builds the Bullet world. Refused when the solver has been fractured (its connectivity is no longer
    /// the mesh's), when a settings value is out of range, or when an element is degenerate.
    static Result<BulletDeformableBeam> Create(const fem::TetSolver& inSolver,
                                               const BulletDeformableBeamSettings& inSettings);

    BulletDeformableBeam(BulletDeformableBeam&& ioOther) noexcept;
    BulletDeformableBeam& operator=(BulletDeformableBeam&& ioOther) noexcept;
    ~BulletDeformableBeam();

    /// Advances by one fixed step of mTimeStep (s).
    void Step();

    /// Number of nodes #N (the TetSolver's)
    int GetNodeCount() const;
    /// Current position of node inNode (m, world)
    Vec3 GetPosition(int inNode) const;
    /// Rest position of node inNode (m, world)
    Vec3 GetRestPosition(int inNode) const;
    /// True when a node position is NaN or Inf
    bool HasNonFinitePosition() const;

private:
    struct World; // the Bullet objects (BulletDeformableBeam.cpp), kept out of this header
    explicit BulletDeformableBeam(std::unique_ptr<World> inWorld);

    std::unique_ptr<World> mWorld;
};

} // namespace crumple::bench
