// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FloatTetReference.h"

#include <cmath>

namespace crumple::test
{

namespace
{

using Vec3f = Eigen::Vector3f;
using Mat3f = Eigen::Matrix3f;

// fem::PolarRotation in float, with the shader's tolerances.
Eigen::Quaternionf PolarRotationFloat(const Mat3f& inF, Eigen::Quaternionf inQ)
{
    Eigen::Quaternionf q = inQ.normalized();
    for (int iteration = 0; iteration < 8; ++iteration)
    {
        const Mat3f b = q.toRotationMatrix().transpose() * inF;
        const Vec3f g(b(2, 1) - b(1, 2), b(0, 2) - b(2, 0), b(1, 0) - b(0, 1));
        const float trace = b(0, 0) + b(1, 1) + b(2, 2);
        const float h00 = trace - b(0, 0), h11 = trace - b(1, 1), h22 = trace - b(2, 2);
        const float h01 = -0.5f * (b(0, 1) + b(1, 0)), h02 = -0.5f * (b(0, 2) + b(2, 0)),
                    h12 = -0.5f * (b(1, 2) + b(2, 1));
        const float c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
        const float c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
        const float det = h00 * c00 + h01 * c01 + h02 * c02;
        const bool newton = h00 > 0.0f && c22 > 0.0f && det > 0.0f;
        const Vec3f omega = newton ? Vec3f(c00 * g[0] + c01 * g[1] + c02 * g[2], c01 * g[0] + c11 * g[1] + c12 * g[2],
                                           c02 * g[0] + c12 * g[1] + c22 * g[2]) /
                                         det
                                   : Vec3f(g / (std::abs(trace) + 1.0e-9f));
        const float angle = omega.norm();
        if (!(angle > 1.0e-7f))
            break;
        q = q * Eigen::Quaternionf(1.0f, 0.5f * omega[0], 0.5f * omega[1], 0.5f * omega[2]);
        q.normalize();
        if (newton && angle < 1.0e-4f)
            break;
    }
    return q;
}

Mat3f Stress(const Mat3f& inStrain, float inLambda, float inMu)
{
    return inLambda * inStrain.trace() * Mat3f::Identity() + 2.0f * inMu * inStrain;
}

} // namespace

FloatTetReference::FloatTetReference(const fem::TetSolver& inSolver)
{
    const fem::FemMaterial& material = inSolver.GetMaterial();
    mLambda = static_cast<float>(material.GetLambda());
    mMu = static_cast<float>(material.GetShearModulus());
    mBeta = static_cast<float>(material.GetSettings().mStiffnessDamping);
    mMassDamping = material.GetSettings().mMassDamping;
    mCorotated = material.GetSettings().mModel == fem::EElasticModel::CorotatedLinear;
    mStableTimeStep = inSolver.GetStableTimeStep();
    mGravity = inSolver.GetSettings().mGravity.cast<float>();
    for (int node = 0; node < inSolver.GetNodeCount(); ++node)
    {
        mPositions.push_back(inSolver.GetPositions()[node].cast<float>());
        mVelocities.push_back(inSolver.GetVelocities()[node].cast<float>());
        mInverseMasses.push_back(static_cast<float>(inSolver.GetInverseMasses()[node]));
    }
    for (std::size_t tet = 0; tet < inSolver.GetElementNodes().size(); ++tet)
    {
        mElements.push_back(inSolver.GetElementNodes()[tet]);
        mRestInverse.push_back(inSolver.GetElementRest()[tet].mRestEdgeInverse.cast<float>());
        mRestVolumes.push_back(static_cast<float>(inSolver.GetElementRest()[tet].mRestVolume));
        mRotations.push_back(Eigen::Quaternionf::Identity());
    }
    mCorners.resize(4 * mElements.size());
    mOffsets.assign(mPositions.size() + 1, 0);
    for (const auto& element : mElements)
        for (int node : element)
            ++mOffsets[node + 1];
    for (std::size_t node = 0; node < mPositions.size(); ++node)
        mOffsets[node + 1] += mOffsets[node];
    mIncident.resize(4 * mElements.size());
    std::vector<std::uint32_t> cursor(mOffsets.begin(), mOffsets.end() - 1);
    for (std::size_t tet = 0; tet < mElements.size(); ++tet)
        for (int corner = 0; corner < 4; ++corner)
            mIncident[cursor[mElements[tet][corner]]++] = static_cast<std::uint32_t>(4 * tet + corner);
}

void FloatTetReference::ApplyImpulse(int inNode, const Vec3& inImpulse)
{
    const Vec3 updated = mVelocities[inNode].cast<double>() + static_cast<double>(mInverseMasses[inNode]) * inImpulse;
    mVelocities[inNode] = updated.cast<float>();
}

void FloatTetReference::Step(double inDeltaTime)
{
    const int sub_steps = std::max(1, static_cast<int>(std::ceil(inDeltaTime / mStableTimeStep)));
    const double dt = inDeltaTime / sub_steps;
    const float damping_scale = static_cast<float>(1.0 / (1.0 + mMassDamping * dt));
    for (int sub_step = 0; sub_step < sub_steps; ++sub_step)
        SubStep(static_cast<float>(dt), damping_scale);
}

void FloatTetReference::SubStep(float inDeltaTime, float inDampingScale)
{
    // Element pass.
    for (std::size_t tet = 0; tet < mElements.size(); ++tet)
    {
        const auto& n = mElements[tet];
        Mat3f edges;
        edges << mPositions[n[1]] - mPositions[n[0]], mPositions[n[2]] - mPositions[n[0]],
            mPositions[n[3]] - mPositions[n[0]];
        const Mat3f f = edges * mRestInverse[tet];
        Mat3f frame, strain;
        if (mCorotated)
        {
            mRotations[tet] = PolarRotationFloat(f, mRotations[tet]);
            frame = mRotations[tet].toRotationMatrix();
            const Mat3f u = frame.transpose() * f;
            strain = 0.5f * (u + u.transpose()) - Mat3f::Identity();
        }
        else
        {
            frame = f;
            strain = 0.5f * (f.transpose() * f - Mat3f::Identity());
        }
        Mat3f p = frame * Stress(strain, mLambda, mMu);
        if (mBeta > 0.0f)
        {
            Mat3f rates;
            rates << mVelocities[n[1]] - mVelocities[n[0]], mVelocities[n[2]] - mVelocities[n[0]],
                mVelocities[n[3]] - mVelocities[n[0]];
            const Mat3f local = frame.transpose() * (rates * mRestInverse[tet]);
            p += frame * (mBeta * Stress(0.5f * (local + local.transpose()), mLambda, mMu));
        }
        const Mat3f h = -mRestVolumes[tet] * (p * mRestInverse[tet].transpose());
        mCorners[4 * tet] = -(h.col(0) + h.col(1) + h.col(2));
        mCorners[4 * tet + 1] = h.col(0);
        mCorners[4 * tet + 2] = h.col(1);
        mCorners[4 * tet + 3] = h.col(2);
    }
    // Node pass.
    for (std::size_t node = 0; node < mPositions.size(); ++node)
    {
        if (mInverseMasses[node] == 0.0f)
            continue;
        Vec3f force = Vec3f::Zero();
        for (std::uint32_t entry = mOffsets[node]; entry < mOffsets[node + 1]; ++entry)
            force += mCorners[mIncident[entry]];
        const Vec3f acceleration = mInverseMasses[node] * force + mGravity;
        mVelocities[node] = (mVelocities[node] + inDeltaTime * acceleration) * inDampingScale;
        mPositions[node] += inDeltaTime * mVelocities[node];
    }
}

std::vector<Vec3> FloatTetReference::GetPositions() const
{
    std::vector<Vec3> positions;
    for (const Vec3f& x : mPositions)
        positions.push_back(x.cast<double>());
    return positions;
}

} // namespace crumple::test
