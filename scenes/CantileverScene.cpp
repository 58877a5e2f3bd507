// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CantileverScene.h"

#include <crumple/fem/TetGrid.h>

#include <cmath>
#include <numbers>

namespace crumple::common
{

using namespace crumple::fem;

FemMaterialSettings CantileverSteel()
{
    FemMaterialSettings steel;
    steel.mYoungsModulus = 200.0e9;
    steel.mPoissonRatio = 0.3;
    steel.mDensity = 7850.0;
    return steel;
}

TetSolverSettings CantileverSolverSettings()
{
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mMaxSubSteps = 1000000;
    settings.mSleepSpeed = 0.0;
    return settings;
}

Result<CantileverScene> CantileverScene::Create(const CantileverSettings& inSettings)
{
    TetGridSettings grid;
    grid.mSize = Vec3(inSettings.mLength, inSettings.mSide, inSettings.mSide);
    grid.mCellCount = {inSettings.mLengthCells, inSettings.mSectionCells, inSettings.mSectionCells};
    Result<TetMesh> mesh = TetGrid(grid);
    if (!mesh)
        return mesh.GetError();
    Result<TetSolver> solver = TetSolver::Create(mesh.Get(), inSettings.mMaterial, inSettings.mSolver);
    if (!solver)
        return solver.GetError();
    CantileverScene scene(inSettings, std::move(solver).Get());

    // Clamp x = 0; the tip load by trapezoidal area weights over the tip face.
    const int n = inSettings.mSectionCells;
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
        {
            if (Status fixed = scene.mSolver.SetNodeFixed(TetGridNode(grid.mCellCount, 0, j, k), true);
                !fixed)
                return fixed.GetError();
            scene.mTip.push_back(TetGridNode(grid.mCellCount, inSettings.mLengthCells, j, k));
            scene.mWeights.push_back((j == 0 || j == n ? 0.5 : 1.0) * (k == 0 || k == n ? 0.5 : 1.0) /
                                     (n * n));
        }
    for (std::size_t i = 0; i < scene.mTip.size(); ++i)
        if (Status force = scene.mSolver.SetExternalForce(
                scene.mTip[i], Vec3(0.0, 0.0, -inSettings.mLoad * scene.mWeights[i]));
            !force)
            return force.GetError();
    return scene;
}

double CantileverScene::TipDeflection() const
{
    return TipDeflection(mSolver.GetPositions());
}

double CantileverScene::TipDeflection(std::span<const Vec3> inPositions) const
{
    double deflection = 0.0;
    for (std::size_t i = 0; i < mTip.size(); ++i)
    {
        const int node = mTip[i];
        deflection -= mWeights[i] * (inPositions[node].z() - mSolver.GetMesh().GetRestPositions()[node].z());
    }
    return deflection;
}

double CantileverInertia(const CantileverSettings& inSettings)
{
    const double side = inSettings.mSide;
    return side * side * side * side / 12.0;
}

double TimoshenkoDeflection(const CantileverSettings& inSettings)
{
    const FemMaterialSettings& material = inSettings.mMaterial;
    const double length = inSettings.mLength;
    const double shear = material.mYoungsModulus / (2.0 * (1.0 + material.mPoissonRatio));
    return inSettings.mLoad * length * length * length /
               (3.0 * material.mYoungsModulus * CantileverInertia(inSettings)) +
           inSettings.mLoad * length / (5.0 / 6.0 * shear * inSettings.mSide * inSettings.mSide);
}

double EulerBernoulliFrequency(const CantileverSettings& inSettings)
{
    const FemMaterialSettings& material = inSettings.mMaterial;
    const double length = inSettings.mLength;
    const double area = inSettings.mSide * inSettings.mSide;
    const double beta = 1.875104069;
    return beta * beta / (2.0 * std::numbers::pi) *
           std::sqrt(material.mYoungsModulus * CantileverInertia(inSettings) /
                     (material.mDensity * area * length * length * length * length));
}

double ShearCorrectedFrequency(const CantileverSettings& inSettings)
{
    const FemMaterialSettings& material = inSettings.mMaterial;
    const double shear = material.mYoungsModulus / (2.0 * (1.0 + material.mPoissonRatio));
    const double f_shear = std::sqrt(5.0 / 6.0 * shear / material.mDensity) / (4.0 * inSettings.mLength);
    const double f_bending = EulerBernoulliFrequency(inSettings);
    return 1.0 / std::sqrt(1.0 / (f_bending * f_bending) + 1.0 / (f_shear * f_shear));
}

} // namespace crumple::common
