// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetSolver.h>

#include <span>
#include <utility>
#include <vector>

namespace crumple::common
{

/// The steel of the FEM issue: E = 200 GPa, nu = 0.3, rho = 7850 kg/m^3, undamped, the default elastic model.
fem::FemMaterialSettings CantileverSteel();

/// Default TetSolverSettings with gravity and sleep off and mMaxSubSteps = 10^6 (explicit steps of a fine
/// steel mesh take tens of thousands of sub-steps).
fem::TetSolverSettings CantileverSolverSettings();

/// The steel cantilever of the FEM issue: a beam of mLength x mSide x mSide along x, cut into
/// mLengthCells x mSectionCells x mSectionCells five-tet cells (TetGrid), clamped at x = 0 (every node of
/// that face anchored) and loaded by mLoad downwards (-z) at the tip, spread over the tip face by
/// trapezoidal area weights. No gravity, no sleep. Used by the cantilever test and the FEM benchmark.
struct CantileverSettings
{
    double mLength = 1.0;                                   ///< Beam length along x (m)
    double mSide = 0.1;                                     ///< Side of the square section (m)
    double mLoad = 1000.0;                                  ///< Total tip load (N), applied downwards (-z)
    int mLengthCells = 10;                                  ///< Cells along the length, >= 1
    int mSectionCells = 1;                                  ///< Cells along each side of the section, >= 1
    fem::FemMaterialSettings mMaterial = CantileverSteel(); ///< The beam's material
    fem::TetSolverSettings mSolver = CantileverSolverSettings(); ///< Integrator and solver settings
};

/// A cantilever ready to step or solve, with the tip load set.
class CantileverScene
{
public:
    /// Builds the mesh and solver, anchors the clamped face and sets the tip load; refused when the mesh,
    /// material or solver settings are.
    static Result<CantileverScene> Create(const CantileverSettings& inSettings);

    /// Area-weighted mean vertical displacement of the tip face (m, positive down)
    double TipDeflection() const;
    /// The same of inPositions (#N, m: another solver's state of this beam, e.g. read back from the GPU)
    double TipDeflection(std::span<const Vec3> inPositions) const;

    /// The beam's solver: step it, solve statics, read positions
    fem::TetSolver& GetSolver() { return mSolver; }
    const fem::TetSolver& GetSolver() const { return mSolver; }
    /// The settings it was built from
    const CantileverSettings& GetSettings() const { return mSettings; }
    /// Tip-face nodes, (n+1)^2 for n section cells
    const std::vector<int>& GetTipNodes() const { return mTip; }

private:
    CantileverScene(const CantileverSettings& inSettings, fem::TetSolver inSolver)
        : mSettings(inSettings), mSolver(std::move(inSolver))
    {
    }

    CantileverSettings mSettings;
    fem::TetSolver mSolver;
    std::vector<int> mTip;        ///< Tip-face nodes
    std::vector<double> mWeights; ///< Their area weights, summing to 1
};

/// Second moment of area of the square section, side^4 / 12 (m^4).
double CantileverInertia(const CantileverSettings& inSettings);

/// Timoshenko static tip deflection P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6 (m, positive down).
double TimoshenkoDeflection(const CantileverSettings& inSettings);

/// Euler-Bernoulli first bending frequency (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)) (Hz).
double EulerBernoulliFrequency(const CantileverSettings& inSettings);

/// Dunkerley combination of the Euler-Bernoulli frequency with that of a pure shear cantilever,
/// 1/f^2 = 1/f_EB^2 + 1/f_s^2, f_s = sqrt(kappa G / rho) / (4 L): an estimate of the Timoshenko frequency
/// (Hz).
double ShearCorrectedFrequency(const CantileverSettings& inSettings);

} // namespace crumple::common
