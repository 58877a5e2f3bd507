// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/EElasticModel.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetLinearization.h>

#include <cstdint>
#include <span>

namespace crumple::fem
{

/// What every element pass reads: connectivity, rest data and material (private to the solvers).
struct TetPassParallel;

struct TetElementPassInput
{
    std::span<const TetIndices> mTets;        ///< #T element -> node indices
    std::span<const TetElementRest> mRest;    ///< #T rest data
    const Matrix6* mMaterialMatrix = nullptr; ///< C (Pa)
    double mLambda = 0.0;                     ///< First Lame parameter of C (Pa)
    double mShearModulus = 0.0;               ///< Second Lame parameter mu of C (Pa)
    EElasticModel mModel = EElasticModel::CorotatedLinear;
    /// #T plastic strains (in the model's frame), or empty when the material has no plasticity
    std::span<const Mat3> mPlasticStrains;

    /// The host's jobs and the gather scratch for the force and stiffness-product passes, or null to run them
    /// serially; either way the results are bitwise the same (TetPassParallel)
    TetPassParallel* mParallel = nullptr;

    /// #T flags, 1 for an element with a free corner, or empty when every element has one. The force,
    /// stiffness, energy and plastic-flow passes skip the others (every corner anchored: a piece handed to the
    /// engine, fixed in place), which then add nothing to any node, have no energy, do not flow and keep their
    /// frames. TetCauchyStress evaluates every element (a group's mean stress weighs all of its elements).
    std::span<const std::uint8_t> mElementActive = {};

    /// True when the passes evaluate element inTet
    bool IsActive(std::size_t inTet) const { return mElementActive.empty() || mElementActive[inTet] != 0; }

    /// Plastic strain of element inTet (zero without plasticity)
    Mat3 PlasticStrain(std::size_t inTet) const
    {
        return mPlasticStrains.empty() ? Mat3(Mat3::Zero()) : mPlasticStrains[inTet];
    }
};

/// Elastic forces plus, when inVelocities is not empty and inStiffnessDamping > 0, the Kelvin-Voigt viscous
/// forces of stress inStiffnessDamping C:strain_rate. Updates the corotated frames (warm-started polar
/// decompositions) and, when outLinearization is not empty, the per-element linearisation for
/// StiffnessProduct. Serial, element order.
/// @param[in]  inPositions        #N (m)
/// @param[in]  inVelocities       #N (m/s) or empty
/// @param[in]  inStiffnessDamping beta (s)
/// @param[in,out] ioRotations     #T element rotations (unit quaternions; untouched by St. Venant-Kirchhoff)
/// @param[out] outLinearization   #T or empty
/// @param[out] outForces          #N (N), overwritten
/// @param[out] outElasticEnergy   when not null, the elastic energy sum V0 psi(F) at inPositions (J), as
///                                TetElasticEnergy computes it, from the same F and rotations (saves a pass)
/// @param[out] outCauchyStress    #T or empty; corotated model only: each evaluated element's Cauchy stress
///                                R C:(eps - eps_p) R^T (Pa), as TetCauchyStress gives it, from this pass's
///                                F and rotations (an implicit step's last pass is at its final positions,
///                                where fracture judges the stress: saves a pass); the skipped elements' are
///                                left as they were
void TetElasticForces(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                      std::span<const Vec3> inVelocities, double inStiffnessDamping,
                      std::span<Quat> ioRotations, std::span<TetLinearization> outLinearization,
                      std::span<Vec3> outForces, double* outElasticEnergy = nullptr,
                      std::span<Mat3> outCauchyStress = {});

/// Product of the linearised stiffness K (= -df/dx) with a direction: outProduct = K inDirection.
/// @param[in]  inLinearization  #T from TetElasticForces
/// @param[in]  inDirection      #N (m or m/s)
/// @param[out] outProduct       #N (N or N/s), overwritten
void TetStiffnessProduct(const TetElementPassInput& inInput,
                         std::span<const TetLinearization> inLinearization, std::span<const Vec3> inDirection,
                         std::span<Vec3> outProduct);

/// The 3x3 diagonal blocks K_aa of the linearised stiffness (N/m), for block-Jacobi preconditioning.
/// @param[out] outBlocks  #N, overwritten
void TetStiffnessDiagonal(const TetElementPassInput& inInput,
                          std::span<const TetLinearization> inLinearization, std::span<Mat3> outBlocks);

/// One step of plasticity (PlasticFlow) for every element at the current positions; updates the corotated
/// frames (warm-started).
/// @param[in]     inPositions        #N (m)
/// @param[in,out] ioRotations        #T element rotations (unit quaternions)
/// @param[in]     inShearModulus     mu (Pa)
/// @param[in]     inMaterial         yield stress, creep rate, plastic strain cap
/// @param[in]     inDeltaTime        dt (s)
/// @param[in,out] ioPlasticStrains   #T plastic strains
/// @return number of elements that flowed
int TetPlasticFlow(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                   std::span<Quat> ioRotations, double inShearModulus, const FemMaterialSettings& inMaterial,
                   double inDeltaTime, std::span<Mat3> ioPlasticStrains);

/// Cauchy stress of every element in world axes (Pa): R C:(eps - eps_p) R^T for the corotated model,
/// F S F^T / det F for St. Venant-Kirchhoff. Updates the corotated frames (warm-started).
/// @param[in]     inPositions  #N (m)
/// @param[in,out] ioRotations  #T element rotations (unit quaternions)
/// @param[out]    outStress    #T symmetric 3 by 3, overwritten (with inSkippedOnly, only the elements the
///                             other passes skip: the rest came from TetElasticForces' outCauchyStress)
void TetCauchyStress(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                     std::span<Quat> ioRotations, std::span<Mat3> outStress, bool inSkippedOnly = false);

/// Elastic energy sum V0 psi(F) (J); updates the corotated frames (warm-started) when ioRotations is
/// writable.
/// @param[in]     inPositions  #N (m)
/// @param[in,out] ioRotations  #T element rotations (unit quaternions; untouched by St. Venant-Kirchhoff)
double TetElasticEnergy(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                        std::span<Quat> ioRotations);

} // namespace crumple::fem
