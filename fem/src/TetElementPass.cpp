// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetElementPass.h"

#include "TetPassParallel.h"

#include <crumple/fem/DeformationGradient.h>
#include <crumple/fem/FirstPiolaStress.h>
#include <crumple/fem/MaterialStress.h>
#include <crumple/fem/ModelStrain.h>
#include <crumple/fem/PlasticFlow.h>
#include <crumple/fem/PolarRotation.h>
#include <crumple/fem/StrainEnergyDensity.h>
#include <crumple/fem/TetNodalForces.h>

#include <Eigen/Eigenvalues>

namespace crumple::fem
{

namespace
{

// The isotropic stress C:eps = lambda tr(eps) I + 2 mu eps of a symmetric strain: what MaterialStress computes
// with the 6 x 6 Voigt product, in 12 instead of 36 multiplications and inlined. Equal to it up to round-off
// only, so it is used where round-off is already at the solver's tolerance: the implicit solve's stiffness
// product (the forces keep MaterialStress).
inline Mat3 IsotropicStress(double inLambda, double inShearModulus, const Mat3& inStrain)
{
    Mat3 stress = (2.0 * inShearModulus) * inStrain;
    stress.diagonal().array() += inLambda * inStrain.trace();
    return stress;
}

// The deformation gradient F = D_s D_m^-1 of the corner values inX (positions or velocities), inlined.
inline Mat3 InlineDeformationGradient(const Vec3& inX0, const Vec3& inX1, const Vec3& inX2, const Vec3& inX3,
                                      const Mat3& inRestEdgeInverse)
{
    Mat3 edges;
    edges.col(0) = inX1 - inX0;
    edges.col(1) = inX2 - inX0;
    edges.col(2) = inX3 - inX0;
    return edges * inRestEdgeInverse;
}

// The corner forces of the first Piola-Kirchhoff stress inP: f_i = -V0 P D_m^-T column i (i = 1..3), corner 0
// minus their sum (TetNodalForces, inlined).
inline std::array<Vec3, 4> StressCornerForces(const Mat3& inP, const TetElementRest& inRest)
{
    const Mat3 h = -inRest.mRestVolume * (inP * inRest.mRestEdgeInverse.transpose());
    const Vec3 f1 = h.col(0);
    const Vec3 f2 = h.col(1);
    const Vec3 f3 = h.col(2);
    return {-(f1 + f2 + f3), f1, f2, f3};
}

// Elements per piece of a parallel element pass: below this, handing a piece to a worker and gathering its
// corners costs more than it saves (measured: a 1,125-tet beam stepped 30 % slower on 2 threads with 256).
constexpr std::size_t cMinElementsPerPiece = 2048;

// Runs inKernel(tet, energy) -> the element's four corner values for every element and sums them onto the
// nodes, outValues[n] = sum over the elements at n in element order; returns the sum of the elements'
// energies in element order. Serial: scattered as they come. With inInput.mParallel: the elements in pieces
// on the host's jobs, then gathered per node (TetPassParallel), bitwise the same.
template <class Kernel>
double RunElementPass(const TetElementPassInput& inInput, std::span<Vec3> outValues, const Kernel& inKernel)
{
    double energy = 0.0;
    if (inInput.mParallel == nullptr ||
        PieceCount(inInput.mParallel->mJobs, inInput.mTets.size(), cMinElementsPerPiece) <= 1)
    {
        for (Vec3& value : outValues)
            value.setZero();
        for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
        {
            if (!inInput.IsActive(tet))
                continue;
            double element_energy = 0.0;
            const std::array<Vec3, 4> corners = inKernel(tet, element_energy);
            const TetIndices& nodes = inInput.mTets[tet];
            for (int corner = 0; corner < 4; ++corner)
                outValues[nodes[corner]] += corners[corner];
            energy += element_energy;
        }
        return energy;
    }
    TetPassParallel& parallel = *inInput.mParallel;
    parallel.ForPieces(inInput.mTets.size(), cMinElementsPerPiece,
                       [&](std::size_t inFirst, std::size_t inLast)
                       {
                           for (std::size_t tet = inFirst; tet < inLast; ++tet)
                           {
                               // intent: a skipped element's slots hold zeros, and x + 0 is x for every sum
                               // that starts at +0: the gather adds what the serial scatter adds
                               if (inInput.IsActive(tet))
                                   parallel.mCorners[tet] = inKernel(tet, parallel.mElementEnergy[tet]);
                               else
                               {
                                   parallel.mCorners[tet].fill(Vec3::Zero());
                                   parallel.mElementEnergy[tet] = 0.0;
                               }
                           }
                       });
    parallel.Gather(outValues);
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
        energy += parallel.mElementEnergy[tet];
    return energy;
}

// dP of the linearisation applied to dF.
Mat3 LinearizedStress(const TetLinearization& inLinearization, const Matrix6& inMaterialMatrix,
                      const Mat3& inDeltaF)
{
    const Mat3& frame = inLinearization.mFrame;
    const Mat3 local = frame.transpose() * inDeltaF;
    const Mat3 strain = 0.5 * (local + local.transpose());
    return frame * MaterialStress(inMaterialMatrix, strain) + inDeltaF * inLinearization.mStress;
}

// The positive semi-definite part of a symmetric matrix (negative eigenvalues set to zero).
Mat3 PositivePart(const Mat3& inSymmetric)
{
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(inSymmetric);
    const Vec3 clamped = eigen.eigenvalues().cwiseMax(0.0);
    return eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

// The deformation gradient of element inTet and, for the corotated model, its rotation (warm-started polar
// decomposition, stored back); identity for St. Venant-Kirchhoff.
struct ElementFrame
{
    Mat3 mF;
    Mat3 mRotation;
};

ElementFrame CurrentFrame(const TetElementPassInput& inInput, std::span<const Vec3> inPositions, std::size_t inTet,
                          std::span<Quat> ioRotations)
{
    const TetIndices& n = inInput.mTets[inTet];
    ElementFrame frame{DeformationGradient(inPositions[n[0]], inPositions[n[1]], inPositions[n[2]], inPositions[n[3]],
                                           inInput.mRest[inTet].mRestEdgeInverse),
                       Mat3::Identity()};
    if (inInput.mModel == EElasticModel::CorotatedLinear)
    {
        ioRotations[inTet] = PolarRotation(frame.mF, ioRotations[inTet], frame.mRotation);
    }
    return frame;
}

} // namespace

void TetElasticForces(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                      std::span<const Vec3> inVelocities, double inStiffnessDamping,
                      std::span<Quat> ioRotations, std::span<TetLinearization> outLinearization,
                      std::span<Vec3> outForces, double* outElasticEnergy, std::span<Mat3> outCauchyStress)
{
    const Matrix6& c = *inInput.mMaterialMatrix;
    const bool corotated = inInput.mModel == EElasticModel::CorotatedLinear;
    const bool viscous = !inVelocities.empty() && inStiffnessDamping > 0.0;
    const bool with_energy = outElasticEnergy != nullptr;
    const auto element = [&](std::size_t tet, double& outEnergy) -> std::array<Vec3, 4>
    {
        const TetIndices& n = inInput.mTets[tet];
        const TetElementRest& rest = inInput.mRest[tet];
        if (corotated)
        {
            // Corotated, written out (the force pass runs twice per implicit step and every explicit
            // sub-step): F, its rotation R, P = R C:(sym(R^T F) - I - eps_p), plus the viscous stress
            // R beta C:sym(R^T dF/dt). The same operations in the same order as the general kernels
            // (FirstPiolaStress, TetNodalForces, StrainEnergyDensity), so the results are bitwise theirs:
            // explicit runs (crash barriers) are chaotic enough that round-off would move their outcome.
            const Mat3 f = InlineDeformationGradient(inPositions[n[0]], inPositions[n[1]], inPositions[n[2]],
                                                     inPositions[n[3]], rest.mRestEdgeInverse);
            Mat3 r;
            ioRotations[tet] = PolarRotation(f, ioRotations[tet], r);
            const Mat3 unrotated = r.transpose() * f;
            Mat3 strain = 0.5 * (unrotated + unrotated.transpose()) - Mat3::Identity();
            if (!inInput.mPlasticStrains.empty())
                strain -= inInput.mPlasticStrains[tet];
            const Mat3 stress = MaterialStress(c, strain);
            if (with_energy)
                outEnergy = rest.mRestVolume * (0.5 * stress.cwiseProduct(strain).sum()); // V0 sigma : e / 2
            Mat3 p = r * stress;
            if (!outCauchyStress.empty())
                outCauchyStress[tet] = p * r.transpose(); // R sigma R^T (each element written by one piece)
            if (viscous)
            {
                const Mat3 f_dot = InlineDeformationGradient(inVelocities[n[0]], inVelocities[n[1]],
                                                             inVelocities[n[2]], inVelocities[n[3]],
                                                             rest.mRestEdgeInverse);
                const Mat3 rate = r.transpose() * f_dot;
                p += r * (inStiffnessDamping * MaterialStress(c, 0.5 * (rate + rate.transpose())));
            }
            if (!outLinearization.empty())
            {
                outLinearization[tet].mFrame = r;
                outLinearization[tet].mStress.setZero();
            }
            return StressCornerForces(p, rest);
        }

        // St. Venant-Kirchhoff through the general kernels: deformation gradient, frame F (rotation identity).
        const auto [f, r] = CurrentFrame(inInput, inPositions, tet, ioRotations);

        // Elastic stress, plus the viscous stress beta C:strain_rate in the same frame.
        const Mat3 plastic = inInput.PlasticStrain(tet);
        Mat3 p = FirstPiolaStress(inInput.mModel, f, r, c, plastic);
        if (with_energy)
            outEnergy = rest.mRestVolume * StrainEnergyDensity(inInput.mModel, f, r, c, plastic);
        if (viscous)
        {
            const Mat3 f_dot = DeformationGradient(inVelocities[n[0]], inVelocities[n[1]], inVelocities[n[2]],
                                                   inVelocities[n[3]], rest.mRestEdgeInverse);
            const Mat3 local = f.transpose() * f_dot;
            p += f * (inStiffnessDamping * MaterialStress(c, 0.5 * (local + local.transpose())));
        }

        // Linearisation around this state for the implicit solve.
        if (!outLinearization.empty())
        {
            TetLinearization& lin = outLinearization[tet];
            lin.mFrame = f;
            lin.mStress = PositivePart(MaterialStress(c, ModelStrain(inInput.mModel, f, r) - plastic));
        }
        return TetNodalForces(p, rest.mRestEdgeInverse, rest.mRestVolume);
    };
    const double energy = RunElementPass(inInput, outForces, element);
    if (with_energy)
        *outElasticEnergy = energy;
}

void TetStiffnessProduct(const TetElementPassInput& inInput,
                         std::span<const TetLinearization> inLinearization, std::span<const Vec3> inDirection,
                         std::span<Vec3> outProduct)
{
    // The hot loop of every implicit solve (one pass per conjugate-gradient iteration): the element kernel is
    // written out here so that it inlines, with the isotropic stress instead of the Voigt product.
    const bool corotated = inInput.mModel == EElasticModel::CorotatedLinear;
    const double lambda = inInput.mLambda;
    const double mu = inInput.mShearModulus;
    const auto element = [&](std::size_t tet, double&) -> std::array<Vec3, 4>
    {
        // dF = D_s(d) D_m^-1 from the corner directions.
        const TetIndices& n = inInput.mTets[tet];
        const TetElementRest& rest = inInput.mRest[tet];
        const Mat3 delta_f = InlineDeformationGradient(inDirection[n[0]], inDirection[n[1]], inDirection[n[2]],
                                                       inDirection[n[3]], rest.mRestEdgeInverse);

        // dP = frame C:sym(frame^T dF) (+ dF S for St. Venant-Kirchhoff), as LinearizedStress.
        const TetLinearization& lin = inLinearization[tet];
        const Mat3 local = lin.mFrame.transpose() * delta_f;
        Mat3 delta_p = lin.mFrame * IsotropicStress(lambda, mu, 0.5 * (local + local.transpose()));
        if (!corotated)
            delta_p += delta_f * lin.mStress;

        // K d = -df: the corner forces of -dP.
        return StressCornerForces(-delta_p, rest);
    };
    RunElementPass(inInput, outProduct, element);
}

void TetStiffnessDiagonal(const TetElementPassInput& inInput,
                          std::span<const TetLinearization> inLinearization, std::span<Mat3> outBlocks)
{
    for (Mat3& block : outBlocks)
        block.setZero();
    const Matrix6& c = *inInput.mMaterialMatrix;
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        if (!inInput.IsActive(tet))
            continue;
        // Shape-function gradients g_a: rows of D_m^-1 for corners 1..3, minus their sum for corner 0.
        const TetIndices& n = inInput.mTets[tet];
        const TetElementRest& rest = inInput.mRest[tet];
        const Mat3& dm_inverse = rest.mRestEdgeInverse;
        std::array<Vec3, 4> g;
        g[1] = dm_inverse.row(0).transpose();
        g[2] = dm_inverse.row(1).transpose();
        g[3] = dm_inverse.row(2).transpose();
        g[0] = -(g[1] + g[2] + g[3]);

        // Column j of K_aa: move corner a along e_j (dF = e_j g_a^T), force on a is -V0 dP g_a.
        for (int corner = 0; corner < 4; ++corner)
            for (int axis = 0; axis < 3; ++axis)
            {
                const Mat3 delta_f = Vec3::Unit(axis) * g[corner].transpose();
                const Mat3 delta_p = LinearizedStress(inLinearization[tet], c, delta_f);
                outBlocks[n[corner]].col(axis) += rest.mRestVolume * (delta_p * g[corner]);
            }
    }
}

double TetElasticEnergy(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                        std::span<Quat> ioRotations)
{
    const Matrix6& c = *inInput.mMaterialMatrix;
    double energy = 0.0;
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        if (!inInput.IsActive(tet))
            continue;
        const auto [f, r] = CurrentFrame(inInput, inPositions, tet, ioRotations);
        energy += inInput.mRest[tet].mRestVolume * StrainEnergyDensity(inInput.mModel, f, r, c, inInput.PlasticStrain(tet));
    }
    return energy;
}

int TetPlasticFlow(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                   std::span<Quat> ioRotations, double inShearModulus, const FemMaterialSettings& inMaterial,
                   double inDeltaTime, std::span<Mat3> ioPlasticStrains)
{
    int flowed = 0;
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        if (!inInput.IsActive(tet))
            continue;
        const auto [f, r] = CurrentFrame(inInput, inPositions, tet, ioRotations);
        const Mat3 updated = PlasticFlow(ModelStrain(inInput.mModel, f, r), ioPlasticStrains[tet], inShearModulus,
                                         inMaterial, inDeltaTime);
        if (updated != ioPlasticStrains[tet])
        {
            ioPlasticStrains[tet] = updated;
            ++flowed;
        }
    }
    return flowed;
}

void TetCauchyStress(const TetElementPassInput& inInput, std::span<const Vec3> inPositions,
                     std::span<Quat> ioRotations, std::span<Mat3> outStress, bool inSkippedOnly)
{
    const Matrix6& c = *inInput.mMaterialMatrix;
    const bool corotated = inInput.mModel == EElasticModel::CorotatedLinear;
    // intent: every element, skipped ones too: a group's mean stress, which fracture judges, weighs all its
    // elements (once per step, for breakable materials only)
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        if (inSkippedOnly && inInput.IsActive(tet))
            continue;
        const auto [f, r] = CurrentFrame(inInput, inPositions, tet, ioRotations);
        if (corotated)
        {
            // Small strain in the rotated frame: the Cauchy stress is the rotated linear stress.
            const Mat3 local = MaterialStress(c, ModelStrain(inInput.mModel, f, r) - inInput.PlasticStrain(tet));
            outStress[tet] = r * local * r.transpose();
        }
        else
        {
            // sigma = F S F^T / J; an inverted element (J <= 0) has no meaningful Cauchy stress: use S.
            const Mat3 s = MaterialStress(c, ModelStrain(inInput.mModel, f, Mat3::Identity()) -
                                                 inInput.PlasticStrain(tet));
            const double j = f.determinant();
            outStress[tet] = j > 0.0 ? Mat3(f * s * f.transpose() / j) : s;
        }
    }
}

} // namespace crumple::fem
