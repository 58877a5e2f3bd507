// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/TetSolver.h>

#include <Eigen/Geometry>

#include <vector>

namespace crumple::test
{

/// The GPU solver's equations on the CPU in single precision, line by line as the two shaders do them
/// (element pass, then per-node gather in element order, then symplectic Euler): the "float build of the
/// same equations" the parity tests compare the GPU against. Built from a fem::TetSolver of the same prop,
/// which supplies masses, rest data, the stable sub-step and the anchoring.
class FloatTetReference
{
public:
    explicit FloatTetReference(const fem::TetSolver& inSolver);

    /// Adds an impulse (N s) to a free node.
    void ApplyImpulse(int inNode, const Vec3& inImpulse);
    /// inDeltaTime in ceil(dt / stable) sub-steps, as GpuTetSolver::Step.
    void Step(double inDeltaTime);
    /// Positions (m), #N
    std::vector<Vec3> GetPositions() const;

private:
    void SubStep(float inDeltaTime, float inDampingScale);

    std::vector<Eigen::Vector3f> mPositions, mVelocities, mCorners;
    std::vector<float> mInverseMasses;
    std::vector<std::array<int, 4>> mElements;
    std::vector<Eigen::Matrix3f> mRestInverse;
    std::vector<float> mRestVolumes;
    std::vector<Eigen::Quaternionf> mRotations;
    std::vector<std::uint32_t> mOffsets, mIncident;
    Eigen::Vector3f mGravity;
    float mLambda, mMu, mBeta;
    double mMassDamping, mStableTimeStep;
    bool mCorotated;
};

} // namespace crumple::test
