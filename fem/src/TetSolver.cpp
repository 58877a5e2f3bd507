// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/base/TimeStep.h>
#include <crumple/fem/CrackSafeEnergy.h>
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/OpenCracks.h>
#include <crumple/fem/StableTimeStep.h>
#include <crumple/fem/TetSolver.h>

#include "ConjugateGradient.h"
#include "TetElementPass.h"
#include "TetFactoredPreconditioner.h"
#include "TetGroundContact.h"
#include "TetPreconditioner.h"
#include "TetSolveScratch.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace crumple::fem
{

namespace
{

// Within TetSolver::cMaxStateMagnitude in every coordinate (and so finite): squares, energies and their sums
// over the nodes stay finite.
bool WithinStateBound(const Vec3& inValue)
{
    return IsFinite(inValue) && inValue.cwiseAbs().maxCoeff() <= TetSolver::cMaxStateMagnitude;
}

bool AllWithinStateBound(std::span<const Vec3> inValues)
{
    return std::all_of(inValues.begin(), inValues.end(), [](const Vec3& inValue) { return WithinStateBound(inValue); });
}

// "TetSolverSettings.mX = v: reason", the message of every refused setting.
Error SettingError(const char* inField, double inValue, const char* inReason)
{
    std::ostringstream message;
    message << "TetSolverSettings." << inField << " = " << inValue << ": " << inReason;
    return MakeError(std::isfinite(inValue) ? EError::InvalidArgument : EError::NonFinite, message.str());
}

// The ground: a unit normal, a finite offset and friction, and the implicit integrator (the only one that
// holds nodes on it).
Status ValidateGround(const TetSolverSettings& inSettings)
{
    const GroundPlane& ground = inSettings.mGround;
    if (!ground.mEnabled)
        return Status::Ok();
    if (!IsFinite(ground.mNormal) || !(std::abs(ground.mNormal.norm() - 1.0) <= 1.0e-9))
        return MakeError(
            IsFinite(ground.mNormal) ? EError::InvalidArgument : EError::NonFinite,
            "TetSolverSettings.mGround.mNormal must be a finite unit vector (length 1 within 1e-9)");
    if (!(std::abs(ground.mOffset) <= TetSolver::cMaxStateMagnitude))
        return SettingError("mGround.mOffset", ground.mOffset,
                            "must be finite, within 1e100 m (cMaxStateMagnitude)");
    if (!(ground.mFriction >= 0.0) || !std::isfinite(ground.mFriction))
        return SettingError("mGround.mFriction", ground.mFriction, "must be finite and >= 0");
    if (inSettings.mIntegrator != EIntegrator::ImplicitEuler)
        return MakeError(
            EError::InvalidArgument,
            "TetSolverSettings.mGround needs EIntegrator::ImplicitEuler (the symplectic integrator holds "
            "no node on a ground)");
    return Status::Ok();
}

Status ValidateSettings(const TetSolverSettings& inSettings)
{
    if (inSettings.mIntegrator != EIntegrator::SymplecticEuler &&
        inSettings.mIntegrator != EIntegrator::ImplicitEuler)
        return SettingError("mIntegrator", static_cast<double>(inSettings.mIntegrator),
                            "is not an EIntegrator");
    if (!IsFinite(inSettings.mGravity))
        return MakeError(EError::NonFinite, "TetSolverSettings.mGravity must be finite");
    // intent: the bound SetGravity holds it to (a gravity of 1e150 m/s^2 took nodes past every velocity
    // bound)
    if (!(inSettings.mGravity.cwiseAbs().maxCoeff() <= TetSolver::cMaxStateMagnitude))
        return MakeError(EError::OutOfRange,
                         "TetSolverSettings.mGravity beyond 1e100 m/s^2 (cMaxStateMagnitude)");
    if (inSettings.mPreconditioner != EImplicitPreconditioner::RestFactorization &&
        inSettings.mPreconditioner != EImplicitPreconditioner::BlockJacobi)
        return SettingError("mPreconditioner", static_cast<double>(inSettings.mPreconditioner),
                            "is not an EImplicitPreconditioner");
    if (!(inSettings.mStabilitySafetyFactor > 0.0 && inSettings.mStabilitySafetyFactor <= 1.0))
        return SettingError("mStabilitySafetyFactor", inSettings.mStabilitySafetyFactor,
                            "must lie in (0, 1]; above 1 symplectic Euler is not proven stable");
    if (inSettings.mMaxSubSteps < 1)
        return SettingError("mMaxSubSteps", inSettings.mMaxSubSteps, "must be >= 1");
    if (!(inSettings.mCgRelativeTolerance > 0.0 && inSettings.mCgRelativeTolerance < 1.0))
        return SettingError("mCgRelativeTolerance", inSettings.mCgRelativeTolerance, "must lie in (0, 1)");
    if (inSettings.mCgMaxIterations < 1)
        return SettingError("mCgMaxIterations", inSettings.mCgMaxIterations, "must be >= 1");
    if (inSettings.mFactorRefreshIterations < 0)
        return SettingError("mFactorRefreshIterations", inSettings.mFactorRefreshIterations, "must be >= 0");
    if (inSettings.mImplicitMaxIterations < 1)
        return SettingError("mImplicitMaxIterations", inSettings.mImplicitMaxIterations, "must be >= 1");
    if (!(inSettings.mImplicitTolerance > 0.0 && inSettings.mImplicitTolerance < 1.0))
        return SettingError("mImplicitTolerance", inSettings.mImplicitTolerance, "must lie in (0, 1)");
    if (!(inSettings.mCrackStressTolerance > 0.0))
        return SettingError("mCrackStressTolerance", inSettings.mCrackStressTolerance,
                            "must be > 0 (a fraction of the tensile strength; infinity for no bound)");
    if (!(inSettings.mSleepSpeed >= 0.0) || !std::isfinite(inSettings.mSleepSpeed))
        return SettingError("mSleepSpeed", inSettings.mSleepSpeed, "must be finite and >= 0 m/s");
    if (inSettings.mSleepStepCount < 1)
        return SettingError("mSleepStepCount", inSettings.mSleepStepCount, "must be >= 1");
    if (inSettings.mMaxStepSplits < 0 || inSettings.mMaxStepSplits > 16)
        return SettingError("mMaxStepSplits", inSettings.mMaxStepSplits, "must lie in [0, 16]");
    if (!(inSettings.mDivergenceEnergyRatio > 0.0 && inSettings.mDivergenceEnergyRatio < 1.0))
        return SettingError("mDivergenceEnergyRatio", inSettings.mDivergenceEnergyRatio,
                            "must lie in (0, 1); at 1 or more a blow-up is never detected");
    return ValidateGround(inSettings);
}

Status CheckNode(int inNode, int inNodeCount, const char* inCaller)
{
    if (inNode < 0 || inNode >= inNodeCount)
        return MakeError(EError::OutOfRange, std::string("TetSolver::") + inCaller + ": node " +
                                                 std::to_string(inNode) + " is outside [0, " +
                                                 std::to_string(inNodeCount) + ")");
    return Status::Ok();
}

bool AllFinite(std::span<const Vec3> inValues)
{
    for (const Vec3& value : inValues)
        if (!IsFinite(value))
            return false;
    return true;
}

// Smallest energy content the divergence test compares against (J): keeps a body exactly at rest from
// flagging round-off.
constexpr double cEnergyFloor = 1.0e-12;

} // namespace

Result<TetSolver> TetSolver::Create(const TetMesh& inMesh, const FemMaterialSettings& inMaterial,
                                    const TetSolverSettings& inSettings)
{
    Result<FemMaterial> material = FemMaterial::Create(inMaterial);
    if (material.HasError())
        return material.GetError();
    if (Status status = ValidateSettings(inSettings); status.HasError())
        return status.GetError();
    TetSolver solver(inMesh, material.Get(), inSettings);
    // intent: a mesh of 1e-104 m elements has subnormal node masses (infinite inverses) and one of 1e102 m
    // elements masses near the double range: every step of either diverged to NaN. Such a body is refused
    // here, naming the node, rather than made and never stepped.
    for (std::size_t node = 0; node < solver.mMasses.size(); ++node)
        if (!std::isnormal(solver.mMasses[node]) || !std::isfinite(solver.mInverseMasses[node]) ||
            !(solver.mMasses[node] <= cMaxStateMagnitude))
            return MakeError(
                EError::DegenerateGeometry,
                "TetSolver::Create: node " + std::to_string(node) + " has a mass of " +
                    std::to_string(solver.mMasses[node]) +
                    " kg, outside what a step can hold (its elements are too small or too large for "
                    "the material's density)");
    return solver;
}

TetSolver::TetSolver(const TetMesh& inMesh, const FemMaterial& inMaterial,
                     const TetSolverSettings& inSettings)
    : mMesh(inMesh), mMaterial(inMaterial), mSettings(inSettings)
{
    // Per-element rest data and per-node lumped masses.
    mElementNodes = mMesh.GetTets();
    mNodeRestPositions = mMesh.GetRestPositions();
    mRest = TetRestData(mMesh);
    // intent: a valid mesh and material cannot be refused (Create checked both)
    Result<std::vector<double>> masses = LumpedNodeMass(mElementNodes, mRest, mMesh.GetNodeCount(), mMaterial.GetSettings().mDensity);
    CRUMPLE_ASSERT(masses.IsValid(), "the mesh's own masses were refused");
    mMasses = masses.IsValid() ? std::move(masses).Get() : std::vector<double>(static_cast<std::size_t>(mMesh.GetNodeCount()), 1.0);
    mInverseMasses.resize(mMasses.size());
    mFree.assign(mMasses.size(), 1);
    for (std::size_t node = 0; node < mMasses.size(); ++node)
    {
        mInverseMasses[node] = 1.0 / mMasses[node];
        mFreeMass += mMasses[node];
    }

    // State at rest.
    mPositions = mMesh.GetRestPositions();
    mVelocities.assign(mPositions.size(), Vec3::Zero());
    mExternalForces.assign(mPositions.size(), Vec3::Zero());
    mRotations.assign(mRest.size(), Quat::Identity());
    mStableTimeStep = StableTimeStep(mRest, mMaterial, mSettings.mStabilitySafetyFactor);
    mForces.resize(mPositions.size());
    mLinearization.resize(mRest.size());

    // Plasticity and fracture state only for materials that have them: nothing to pay otherwise.
    if (mMaterial.IsPlastic())
        mPlasticStrains.assign(mRest.size(), Mat3::Zero());
    if (mMaterial.IsBreakable())
    {
        mLinks = BuildFractureLinks(mMesh);
        mBroken.assign(mLinks.GetLinkCount(), 0);
        mElementStress.resize(mRest.size());
        mPrincipal.resize(mLinks.GetGroupCount());
        mCrackSafeEnergy = CrackSafeEnergy(mMaterial.GetSettings(), SmallestGroupVolume(mLinks, mMesh),
                                           mSettings.mCrackStressTolerance);
        // Groups that touch only along an edge or at a corner have no face to judge a crack by, and such a
        // joint carries no stress: they are separate pieces from the start.
        Result<FractureConnectivity> intact = FractureTopology(mMesh, mLinks, mBroken);
        CRUMPLE_ASSERT(intact.IsValid(), "the mesh's own links were refused");
        if (intact.IsValid() && intact.Get().mNodeOrigin.size() != mPositions.size())
            Reconnect(intact.Get());
    }
}

TetElementPassInput TetSolver::PassInput() const
{
    TetElementPassInput input = EveryElementInput();
    if (!mElementActiveValid)
    {
        // Elements with a free corner; the flags stay empty while that is every element (no test per
        // element in the passes then).
        mElementActive.assign(mElementNodes.size(), 0);
        mActiveElementCount = 0;
        for (std::size_t tet = 0; tet < mElementNodes.size(); ++tet)
        {
            const TetIndices& nodes = mElementNodes[tet];
            mElementActive[tet] = mFree[nodes[0]] | mFree[nodes[1]] | mFree[nodes[2]] | mFree[nodes[3]];
            mActiveElementCount += mElementActive[tet];
        }
        if (mActiveElementCount == mElementNodes.size())
            mElementActive.clear();
        mElementActiveValid = true;
    }
    input.mElementActive = mElementActive;
    return input;
}

TetElementPassInput TetSolver::EveryElementInput() const
{
    return TetElementPassInput{mElementNodes,
                               mRest,
                               &mMaterial.GetMaterialMatrix(),
                               mMaterial.GetLambda(),
                               mMaterial.GetShearModulus(),
                               mMaterial.GetSettings().mModel,
                               mPlasticStrains};
}

TetElementPassInput TetSolver::ParallelPassInput()
{
    TetElementPassInput input = PassInput();
    if (mJobs != nullptr && mJobs->mParallelFor != nullptr && mJobs->mWorkerCount > 1)
    {
        TetPassParallel& parallel = mWorkspace.Get().mParallel;
        parallel.mJobs = mJobs;
        parallel.Prepare(mElementNodes, static_cast<int>(mPositions.size()));
        input.mParallel = &parallel;
    }
    return input;
}

void TetSolver::SetJobSystem(const JobSystem* inJobs)
{
    mJobs = inJobs;
}

void TetSolver::AfterSubStep(double inDeltaTime)
{
    // Plastic flow and fracture on the state at the end of each (sub-)step: a crack must open while the stress
    // peak passes, before the wave that carries it reaches the rest of the body. The corotated frames are
    // those of the forces just computed (symplectic) or of the last Newton iteration (implicit).
    if (mMaterial.IsPlastic())
        mStepPlasticElements += FlowPlastically(inDeltaTime);
    if (mMaterial.IsBreakable())
        mStepBrokenLinks += Fracture();
}

void TetSolver::SaveShape(ShapeState& outShape) const
{
    outShape.mElementNodes = mElementNodes;
    outShape.mNodeRestPositions = mNodeRestPositions;
    outShape.mMasses = mMasses;
    outShape.mInverseMasses = mInverseMasses;
    outShape.mFree = mFree;
    outShape.mExternalForces = mExternalForces;
    outShape.mPlasticStrains = mPlasticStrains;
    outShape.mBroken = mBroken;
    outShape.mPrincipal = mPrincipal;
    outShape.mFreeMass = mFreeMass;
}

void TetSolver::RestoreShape(const ShapeState& inShape)
{
    mForcesCached = false;
    mElementNodes = inShape.mElementNodes;
    mNodeRestPositions = inShape.mNodeRestPositions;
    mMasses = inShape.mMasses;
    mInverseMasses = inShape.mInverseMasses;
    mFree = inShape.mFree;
    mElementActiveValid = false;
    mExternalForces = inShape.mExternalForces;
    mPlasticStrains = inShape.mPlasticStrains;
    mBroken = inShape.mBroken;
    mPrincipal = inShape.mPrincipal;
    mFreeMass = inShape.mFreeMass;
    mForces.resize(mMasses.size());
}

std::vector<double> TetSolver::ElementMasses() const
{
    std::vector<double> masses(mRest.size());
    for (std::size_t tet = 0; tet < mRest.size(); ++tet)
        masses[tet] = mMaterial.GetSettings().mDensity * mRest[tet].mRestVolume;
    return masses;
}

int TetSolver::FlowPlastically(double inDeltaTime)
{
    const int flowed = TetPlasticFlow(PassInput(), mPositions, mRotations, mMaterial.GetShearModulus(),
                                      mMaterial.GetSettings(), inDeltaTime, mPlasticStrains);
    mElementWork += mActiveElementCount;
    if (flowed > 0)
        mForcesCached = false; // the rest shape changed: the forces at these positions did too
    return flowed;
}

int TetSolver::Fracture()
{
    // Rankine's criterion on every group's mean stress, then node duplication along the opened links.
    // intent: where the implicit step's last force pass was at these positions (no plastic flow or ground
    // move since), its stresses stand, and only the elements it skipped are evaluated here
    const TetElementPassInput input = PassInput();
    const bool from_pass = mStressFromPass && mForcesCached;
    mStressFromPass = false;
    TetCauchyStress(input, mPositions, mRotations, mElementStress, from_pass);
    mElementWork += from_pass ? mRest.size() - mActiveElementCount : mRest.size(); // see TetCauchyStress
    const Status judged = GroupPrincipalStress(mLinks, mElementStress, mRest, mPrincipal);
    CRUMPLE_ASSERT(judged.IsValid(), "the solver's own groups were refused");
    if (!judged.IsValid())
        return 0;
    const FemMaterialSettings& material = mMaterial.GetSettings();
    // intent: the solver's own links, stresses and connectivity always fit (the checks cost a fraction of the
    // stress pass above)
    const Result<int> opened = OpenCracks(mLinks, mPrincipal, mElementNodes, mPositions, material.mTensileStrength,
                                          material.mFractureMode, mBroken);
    CRUMPLE_ASSERT(opened.IsValid(), "the solver's own crack inputs were refused");
    if (!opened.IsValid() || opened.Get() == 0)
        return 0;
    const Result<FractureConnectivity> cracked = FractureTopology(mMesh, mLinks, mBroken);
    CRUMPLE_ASSERT(cracked.IsValid(), "the solver's own links were refused");
    if (cracked.IsValid())
        Reconnect(cracked.Get());
    return opened.Get();
}

// Moves the node state onto a new connectivity. Breaking only splits nodes, so every new node is a copy of
// the old node at the same element corner; an external force is shared among the copies by mass.
void TetSolver::Reconnect(const FractureConnectivity& inConnectivity)
{
    mForcesCached = false;
    const std::size_t new_count = inConnectivity.mNodeOrigin.size();
    std::vector<int> old_of_new(new_count, -1);
    for (std::size_t tet = 0; tet < mElementNodes.size(); ++tet)
        for (int corner = 0; corner < 4; ++corner)
            old_of_new[inConnectivity.mElementNodes[tet][corner]] = mElementNodes[tet][corner];

    Result<std::vector<double>> lumped = LumpedNodeMass(inConnectivity.mElementNodes, mRest, static_cast<int>(new_count),
                                                        mMaterial.GetSettings().mDensity);
    CRUMPLE_ASSERT(lumped.IsValid(), "FractureTopology's connectivity was refused");
    if (!lumped.IsValid())
        return; // cannot happen: FractureTopology numbers every node below its count
    std::vector<double> masses = std::move(lumped).Get();

    std::vector<Vec3> positions(new_count), velocities(new_count), forces(new_count), rest(new_count);
    std::vector<double> inverse_masses(new_count);
    std::vector<std::uint8_t> free(new_count);
    mFreeMass = 0.0;
    for (std::size_t node = 0; node < new_count; ++node)
    {
        const int old = old_of_new[node];
        positions[node] = mPositions[old];
        velocities[node] = mVelocities[old];
        forces[node] = mExternalForces[old] * (masses[node] / mMasses[old]);
        rest[node] = mNodeRestPositions[old];
        free[node] = mFree[old];
        inverse_masses[node] = free[node] != 0 ? 1.0 / masses[node] : 0.0;
        if (free[node] != 0)
            mFreeMass += masses[node];
    }
    mElementNodes = inConnectivity.mElementNodes;
    mPositions = std::move(positions);
    mVelocities = std::move(velocities);
    mExternalForces = std::move(forces);
    mNodeRestPositions = std::move(rest);
    mMasses = std::move(masses);
    mInverseMasses = std::move(inverse_masses);
    mFree = std::move(free);
    mElementActiveValid = false;
    FollowFramesAfterNewSystem();
    mForces.resize(new_count);
    mReferenceValid = false; // the energy bookkeeping restarts on the new topology
}

std::vector<TetFragment> TetSolver::ComputeFragments() const
{
    if (mMaterial.IsBreakable())
        return TetFragments(mLinks, mElementNodes, ElementMasses(), mPositions, mInverseMasses);
    // An unbreakable prop keeps no links; build them here only for the element groups.
    return TetFragments(BuildFractureLinks(mMesh), mElementNodes, ElementMasses(), mPositions, mInverseMasses);
}

int TetSolver::GetBrokenLinkCount() const
{
    int count = 0;
    for (std::uint8_t broken : mBroken)
        count += broken != 0 ? 1 : 0;
    return count;
}

void TetSolver::InputChanged()
{
    mStepper.Wake();
    mReferenceValid = false;
}

bool TetSolver::FixNode(int inNode, bool inFixed)
{
    const bool was_fixed = mInverseMasses[inNode] == 0.0;
    if (was_fixed != inFixed)
        mFreeMass += inFixed ? -mMasses[inNode] : mMasses[inNode];
    mInverseMasses[inNode] = inFixed ? 0.0 : 1.0 / mMasses[inNode];
    mFree[inNode] = inFixed ? 0 : 1;
    mElementActiveValid = false;
    if (inFixed)
        mVelocities[inNode].setZero();
    return was_fixed != inFixed;
}

void TetSolver::FollowFramesAfterNewSystem()
{
    // intent: mRotations has one frame per element from Create on (a crack keeps the elements)
    if (RefreshesFactor())
        KeepFactorFrames(mRotations);
}

void TetSolver::AnchorsChanged()
{
    FollowFramesAfterNewSystem();
    mPassEnergyValid = false; // the passes skip other elements now
}

Status TetSolver::SetNodeFixed(int inNode, bool inFixed)
{
    if (Status status = CheckNode(inNode, GetNodeCount(), "SetNodeFixed"); status.HasError())
        return status;
    if (FixNode(inNode, inFixed))
        AnchorsChanged();
    InputChanged();
    return Status::Ok();
}

Status TetSolver::SetNodesFixed(std::span<const int> inNodes, bool inFixed)
{
    // intent: every node checked before any changes
    for (int node : inNodes)
        if (Status status = CheckNode(node, GetNodeCount(), "SetNodesFixed"); status.HasError())
            return status;
    if (inNodes.empty())
        return Status::Ok();
    bool changed = false;
    for (int node : inNodes)
        changed = FixNode(node, inFixed) || changed;
    if (changed)
        AnchorsChanged();
    InputChanged();
    return Status::Ok();
}

Status TetSolver::ApplyImpulse(int inNode, const Vec3& inImpulse)
{
    if (Status status = CheckNode(inNode, GetNodeCount(), "ApplyImpulse"); status.HasError())
        return status;
    if (!IsFinite(inImpulse))
        return MakeError(EError::NonFinite, "TetSolver::ApplyImpulse: impulse on node " +
                                                std::to_string(inNode) + " must be finite");
    const Vec3 velocity = mVelocities[inNode] + mInverseMasses[inNode] * inImpulse;
    if (!WithinStateBound(velocity))
        return MakeError(IsFinite(velocity) ? EError::OutOfRange : EError::NonFinite,
                         "TetSolver::ApplyImpulse: the impulse on node " + std::to_string(inNode) +
                             " would leave it moving faster than 1e100 m/s (cMaxStateMagnitude)");
    mVelocities[inNode] = velocity;
    InputChanged();
    return Status::Ok();
}

Status TetSolver::SetExternalForce(int inNode, const Vec3& inForce)
{
    if (Status status = CheckNode(inNode, GetNodeCount(), "SetExternalForce"); status.HasError())
        return status;
    if (!IsFinite(inForce))
        return MakeError(EError::NonFinite, "TetSolver::SetExternalForce: force on node " +
                                                std::to_string(inNode) + " must be finite");
    if (!WithinStateBound(inForce))
        return MakeError(EError::OutOfRange, "TetSolver::SetExternalForce: force on node " + std::to_string(inNode) +
                                                 " beyond 1e100 N (cMaxStateMagnitude)");
    mExternalForces[inNode] = inForce;
    InputChanged();
    return Status::Ok();
}

void TetSolver::ClearExternalForces()
{
    for (Vec3& force : mExternalForces)
        force.setZero();
    InputChanged();
}

Status TetSolver::SetGravity(const Vec3& inGravity)
{
    if (!IsFinite(inGravity))
        return MakeError(EError::NonFinite, "TetSolver::SetGravity: gravity must be finite");
    if (!WithinStateBound(inGravity))
        return MakeError(EError::OutOfRange, "TetSolver::SetGravity: gravity beyond 1e100 m/s^2 (cMaxStateMagnitude)");
    mSettings.mGravity = inGravity;
    InputChanged();
    return Status::Ok();
}

Status TetSolver::SetPositions(std::span<const Vec3> inPositions)
{
    if (inPositions.size() != mPositions.size())
        return MakeError(EError::InvalidArgument,
                         "TetSolver::SetPositions: " + std::to_string(inPositions.size()) +
                             " positions for " + std::to_string(mPositions.size()) + " nodes");
    if (!AllFinite(inPositions))
        return MakeError(EError::NonFinite, "TetSolver::SetPositions: positions must be finite");
    if (!AllWithinStateBound(inPositions))
        return MakeError(EError::OutOfRange, "TetSolver::SetPositions: a position beyond 1e100 m (cMaxStateMagnitude)");
    std::copy(inPositions.begin(), inPositions.end(), mPositions.begin());
    mPassEnergyValid = false;
    InputChanged();
    return Status::Ok();
}

Status TetSolver::SetVelocities(std::span<const Vec3> inVelocities)
{
    if (inVelocities.size() != mVelocities.size())
        return MakeError(EError::InvalidArgument,
                         "TetSolver::SetVelocities: " + std::to_string(inVelocities.size()) +
                             " velocities for " + std::to_string(mVelocities.size()) + " nodes");
    if (!AllFinite(inVelocities))
        return MakeError(EError::NonFinite, "TetSolver::SetVelocities: velocities must be finite");
    if (!AllWithinStateBound(inVelocities))
        return MakeError(EError::OutOfRange, "TetSolver::SetVelocities: a velocity beyond 1e100 m/s (cMaxStateMagnitude)");
    for (std::size_t node = 0; node < mVelocities.size(); ++node)
        mVelocities[node] = mInverseMasses[node] > 0.0 ? inVelocities[node] : Vec3::Zero();
    InputChanged();
    return Status::Ok();
}

void TetSolver::WakeUp()
{
    mStepper.Wake();
}

void TetSolver::LoadForces(std::vector<Vec3>& outForces) const
{
    outForces.resize(mPositions.size());
    for (std::size_t node = 0; node < mPositions.size(); ++node)
        outForces[node] = mInverseMasses[node] > 0.0
                              ? Vec3(mExternalForces[node] + mMasses[node] * mSettings.mGravity)
                              : Vec3::Zero();
}

void TetSolver::ElasticForces(std::vector<Vec3>& outForces) const
{
    outForces.resize(mPositions.size());
    std::vector<Quat> rotations = mRotations;
    const TetElementPassInput input = EveryElementInput();
    TetElasticForces(input, mPositions, {}, 0.0, rotations, {}, outForces);
}

double TetSolver::KineticEnergy() const
{
    double energy = 0.0;
    for (std::size_t node = 0; node < mVelocities.size(); ++node)
        energy += 0.5 * mMasses[node] * mVelocities[node].squaredNorm();
    return energy;
}

double TetSolver::ElasticEnergy() const
{
    std::vector<Quat> rotations = mRotations;
    const TetElementPassInput input = EveryElementInput();
    return TetElasticEnergy(input, mPositions, rotations);
}

double TetSolver::ExternalPotentialEnergy() const
{
    double potential = 0.0;
    double magnitude = 0.0;
    ExternalPotential(potential, magnitude);
    return potential;
}

void TetSolver::ExternalPotential(double& outPotential, double& outMagnitude) const
{
    // -sum f . (x - X) over free nodes in node order, and sum |f . (x - X)| beside it.
    outPotential = 0.0;
    outMagnitude = 0.0;
    const std::vector<Vec3>& rest = mNodeRestPositions;
    for (std::size_t node = 0; node < mPositions.size(); ++node)
        if (mInverseMasses[node] > 0.0)
        {
            const double work = (mExternalForces[node] + mMasses[node] * mSettings.mGravity)
                                    .dot(mPositions[node] - rest[node]);
            outPotential -= work;
            outMagnitude += std::abs(work);
        }
}

TetSolver::EnergyParts TetSolver::MeasuredOrPassEnergy()
{
    if (!mPassEnergyValid)
        return MeasureEnergy();
    EnergyParts parts;
    parts.mKinetic = KineticEnergy();
    parts.mElastic = mPassEnergy;
    ExternalPotential(parts.mPotential, parts.mPotentialMagnitude);
    return parts;
}

TetSolver::EnergyParts TetSolver::MeasureEnergy()
{
    EnergyParts parts;
    parts.mKinetic = KineticEnergy();
    const TetElementPassInput input = PassInput();
    parts.mElastic = TetElasticEnergy(input, mPositions, mRotations);
    mElementWork += mActiveElementCount;
    ExternalPotential(parts.mPotential, parts.mPotentialMagnitude);
    return parts;
}

void TetSolver::StepSymplectic(double inDeltaTime, int inSubSteps)
{
    const double dt = inDeltaTime / inSubSteps;
    const FemMaterialSettings& material = mMaterial.GetSettings();
    const double damping_scale = 1.0 / (1.0 + material.mMassDamping * dt);
    const bool viscous = material.mStiffnessDamping > 0.0;
    for (int sub_step = 0; sub_step < inSubSteps; ++sub_step)
    {
        const TetElementPassInput input = ParallelPassInput(); // fracture may have changed the connectivity
        // Element pass: elastic (+ viscous) forces at the current state.
        TetElasticForces(input, mPositions,
                         viscous ? std::span<const Vec3>(mVelocities) : std::span<const Vec3>(),
                         material.mStiffnessDamping, mRotations, {}, mForces);
        mElementWork += mActiveElementCount;

        // Node pass (the paper's order): v += dt a, mass damping applied implicitly, x += dt v.
        for (std::size_t node = 0; node < mPositions.size(); ++node)
        {
            const double inverse_mass = mInverseMasses[node];
            if (inverse_mass == 0.0)
                continue;
            const Vec3 acceleration =
                inverse_mass * (mForces[node] + mExternalForces[node]) + mSettings.mGravity;
            mVelocities[node] = (mVelocities[node] + dt * acceleration) * damping_scale;
            mPositions[node] += dt * mVelocities[node];
        }
        AfterSubStep(dt);
    }
}

// Backward Euler with Rayleigh damping C_d = alpha M + beta K: find v1 with
//   r(v1) = h (f(x0 + h v1) + f_ext - alpha M v1 - beta K v1) - M (v1 - v0) = 0.
// Newton on v1 with the Jacobian -A, A = (1 + h alpha) M + (h^2 + h beta) K(x), K the linearised stiffness at
// the current iterate (R K0 R^T for the corotated model). The first iteration linearises at x0, which is the
// classic one-solve step of Baraff & Witkin 1998: A dv = h (f(x0) + f_ext - alpha M v0 - (h + beta) K v0).
// One solve misses the second-order stretch of a rotation extrapolated along its tangent (x0 + h v): a body
// spinning at w gets a strain of about (w h)^2 / 2 per step, and for stiff materials that elastic energy
// dwarfs the kinetic one, so the step is iterated (re-evaluating forces and rotations at x0 + h v1) until the
// energy of the remaining correction, 1/2 r^T A^-1 r, is below mImplicitTolerance of the step's kinetic
// energy scale. For the stretch delta of a rotating element, r = h k delta and A ~ h^2 k, so that energy is
// the spurious elastic energy k delta^2 / 2 itself.
void TetSolver::StepImplicit(double inDeltaTime, TetStepResult& ioResult)
{
    const double h = inDeltaTime;
    const FemMaterialSettings& material = mMaterial.GetSettings();
    const double mass_scale = 1.0 + h * material.mMassDamping;
    const double stiffness_scale = h * h + h * material.mStiffnessDamping;
    const TetElementPassInput input = ParallelPassInput();
    const std::size_t node_count = mPositions.size();
    TetSolveScratch& scratch = mWorkspace.Get();
    scratch.Resize(node_count);
    mStartPositions = mPositions;
    mStartVelocities = mVelocities;
    const std::vector<Vec3>& x0 = mStartPositions;
    // intent: a breakable corotated solver's passes also give the elements' Cauchy stress, and the last one
    // is at the step's final positions, where Fracture() judges it
    const std::span<Mat3> pass_stress =
        mMaterial.IsBreakable() && mMaterial.GetSettings().mModel == EElasticModel::CorotatedLinear
            ? std::span<Mat3>(mElementStress)
            : std::span<Mat3>{};
    mStressFromPass = false;
    const std::vector<Vec3>& v0 = mStartVelocities;
    // The nodes the ground holds through this step, their normal velocity in the iterate set to end it on the
    // ground, if it has one (the filter below is on for the whole step with one: nodes may join in a Newton
    // update).
    const GroundPlane& ground = mSettings.mGround;
    if (ground.mEnabled)
    {
        scratch.mGroundHeld.resize(node_count);
        scratch.mGroundImpulses.resize(node_count);
        HoldGroundNodes(ground, mFree, mNodeRestPositions, x0, h, scratch.mGroundHeld, mVelocities);
    }
    const std::uint8_t* held = ground.mEnabled ? scratch.mGroundHeld.data() : nullptr;
    std::uint64_t products = 0;

    // Matrix-free system operator A, masked to the free nodes (one captured pointer: std::function keeps it
    // without allocating).
    struct SystemContext
    {
        TetSolver* mSolver;
        const TetElementPassInput* mInput;
        double mMassScale;
        double mStiffnessScale;
        std::uint64_t* mProducts;
        const std::uint8_t* mGroundHeld; // null without a ground
        const Vec3* mGroundNormal;
    } context{this, &input, mass_scale, stiffness_scale, &products, held, &ground.mNormal};
    const LinearOperator3 system = [ctx = &context](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        const TetSolver& solver = *ctx->mSolver;
        TetStiffnessProduct(*ctx->mInput, solver.mLinearization, inX, outY);
        ++*ctx->mProducts;
        for (std::size_t node = 0; node < outY.size(); ++node)
            outY[node] = solver.mFree[node] != 0 ? Vec3(ctx->mMassScale * solver.mMasses[node] * inX[node] +
                                                        ctx->mStiffnessScale * outY[node])
                                                 : Vec3::Zero();
        if (ctx->mGroundHeld != nullptr)
            FilterGroundNormal(*ctx->mGroundNormal, {ctx->mGroundHeld, outY.size()}, outY);
    };

    // The factored rest system when it applies (built on the first step, after fracture, anchoring or a new
    // step length; at the frames of its last refresh for a refreshing solver), else block Jacobi rebuilt per
    // Newton iteration.
    const bool refreshing = RefreshesFactor();
    TetFactoredPreconditioner* factored = FactoredRestSystem(input, mass_scale, stiffness_scale);
    TetPreconditioner& jacobi = scratch.mJacobi;
    // intent: chosen at each application, so that a factor lost in a failed refresh hands over to block
    // Jacobi for the rest of the step (one captured pointer: std::function keeps it without allocating)
    struct PreconditionerChoice
    {
        TetFactoredPreconditioner** mFactored;
        const TetPreconditioner* mJacobi;
        const std::uint8_t* mGroundHeld; // null without a ground
        const Vec3* mGroundNormal;
    } choice{&factored, &jacobi, held, &ground.mNormal};
    const LinearOperator3 preconditioner = [ctx = &choice](std::span<const Vec3> inR, std::span<Vec3> outZ)
    {
        if (*ctx->mFactored != nullptr)
            (*ctx->mFactored)->Apply(inR, outZ);
        else
            ctx->mJacobi->Apply(inR, outZ);
        if (ctx->mGroundHeld != nullptr)
            FilterGroundNormal(*ctx->mGroundNormal, {ctx->mGroundHeld, outZ.size()}, outZ);
    };

    // Energy scale of the step (J): kinetic energy at the start, relative to the free centre of mass when
    // nothing is anchored (a translation must not loosen the test), plus that of the load's impulse over the
    // step.
    double load_energy = 0.0, start_energy = 0.0, free_mass = 0.0;
    Vec3 momentum = Vec3::Zero();
    bool anchored = false;
    for (std::size_t node = 0; node < node_count; ++node)
    {
        if (mFree[node] == 0)
        {
            anchored = true;
            continue;
        }
        const double m = mMasses[node];
        free_mass += m;
        momentum += m * v0[node];
        start_energy += 0.5 * m * v0[node].squaredNorm();
        load_energy +=
            0.5 * m * (h * (mInverseMasses[node] * mExternalForces[node] + mSettings.mGravity)).squaredNorm();
    }
    if (!anchored && free_mass > 0.0)
        start_energy = std::max(0.0, start_energy - 0.5 * momentum.squaredNorm() / free_mass);
    const double energy_scale = start_energy + load_energy + cEnergyFloor;

    // Newton's line search (see LineSearchMerit): the merit at the last accepted iterate, where there is one.
    // Not with a ground: a node the update takes through it is projected onto it, which moves the merit by
    // more than the update did.
    const bool line_search = held == nullptr;
    double last_merit = 0.0;
    bool has_last_merit = false;
    if (line_search)
        scratch.mLineStart.resize(node_count);
    bool converged = false;
    for (int iteration = 0; iteration <= mSettings.mImplicitMaxIterations; ++iteration)
    {
        // Forces, linearisation and elastic energy at the current iterate (x0 itself on the first pass). The
        // last pass of a step is always at its final positions: Step() reads the energy from it, and the next
        // step starts from it when nothing has moved the nodes or changed the shape since (one element pass
        // of the two a step needs).
        const bool first = iteration == 0;
        const bool cached = first && mForcesCached && mForcePositions == mPositions;
        if (!cached)
        {
            TetElasticForces(input, mPositions, {}, 0.0, mRotations, mLinearization, mForces, &mPassEnergy,
                             pass_stress);
            mElementWork += mActiveElementCount;
            mStressFromPass = !pass_stress.empty();
        }
        mPassEnergyValid = true;
        // Backtracking: where the update raised the merit, halve it (at most cMaxLineSearchHalvings times)
        // and evaluate again. Newton's step is a descent direction of the merit; taken whole from far away
        // (a fast-spinning piece extrapolated along its tangents) it overshoots, and the next iterations
        // swing instead of converging (the step then diverges and is split).
        if (line_search && !first)
        {
            double merit = LineSearchMerit(h, v0);
            for (int halving = 0; has_last_merit && halving < cMaxLineSearchHalvings &&
                                  merit > last_merit + cLineSearchSlack * std::abs(last_merit);
                 ++halving)
            {
                for (std::size_t node = 0; node < node_count; ++node)
                    if (mFree[node] != 0)
                    {
                        scratch.mDeltaV[node] *= 0.5;
                        mVelocities[node] = scratch.mLineStart[node] + scratch.mDeltaV[node];
                        mPositions[node] = x0[node] + h * mVelocities[node];
                    }
                TetElasticForces(input, mPositions, {}, 0.0, mRotations, mLinearization, mForces,
                                 &mPassEnergy, pass_stress);
                mElementWork += mActiveElementCount;
                ++ioResult.mLineSearchHalvings;
                merit = LineSearchMerit(h, v0);
            }
            last_merit = merit;
            has_last_merit = true;
        }
        if (first || material.mStiffnessDamping > 0.0)
        {
            TetStiffnessProduct(input, mLinearization, mVelocities, scratch.mKv);
            mElementWork += mActiveElementCount;
        }

        // Residual r(v) on the free nodes; on the first pass linearised at x0 (the extra -h K v0 term).
        for (std::size_t node = 0; node < node_count; ++node)
        {
            if (mFree[node] == 0)
            {
                scratch.mResidual[node].setZero();
                continue;
            }
            const double m = mMasses[node];
            scratch.mResidual[node] =
                h * (mForces[node] + mExternalForces[node] + m * mSettings.mGravity -
                     material.mMassDamping * m * mVelocities[node] -
                     ((first ? h : 0.0) + material.mStiffnessDamping) * scratch.mKv[node]) -
                m * (mVelocities[node] - v0[node]);
        }

        // The ground takes the normal part of its held nodes' residual (their impulse from it), unless it
        // would pull: that node leaves it for the rest of the step.
        if (held != nullptr)
        {
            ReleasePulledNodes(ground.mNormal, scratch.mResidual, scratch.mGroundHeld);
            TakeGroundImpulses(ground.mNormal, scratch.mGroundHeld, scratch.mResidual,
                               scratch.mGroundImpulses);
        }

        // The factored preconditioner follows the element frames just updated.
        if (factored != nullptr)
            factored->SetNodeRotations(mElementNodes, mRotations,
                                       material.mModel == EElasticModel::CorotatedLinear);

        // Converged when the energy of the remaining Newton correction, 1/2 r^T A^-1 r (A^-1 estimated by the
        // preconditioner), is a small fraction of the step's energy scale and, for a breakable material, too
        // small to move a group's stress by more than mCrackStressTolerance of the strength (its elastic
        // part, h^2 dv^T K dv / 2, is the strain energy of the remaining position error).
        if (!first)
        {
            preconditioner(scratch.mResidual, scratch.mPreconditioned);
            double residual_energy = 0.0;
            for (std::size_t node = 0; node < node_count; ++node)
                residual_energy += 0.5 * scratch.mResidual[node].dot(scratch.mPreconditioned[node]);
            if (residual_energy <= std::min(mSettings.mImplicitTolerance * energy_scale, mCrackSafeEnergy))
            {
                converged = true;
                break;
            }
        }
        if (iteration == mSettings.mImplicitMaxIterations)
            break;

        // Block Jacobi at this linearisation: its diagonal blocks plus the rigid coarse space.
        const auto build_jacobi = [&]
        {
            TetStiffnessDiagonal(input, mLinearization, scratch.mBlocks);
            mElementWork += mActiveElementCount;
            for (std::size_t node = 0; node < node_count; ++node)
                scratch.mBlocks[node] =
                    mass_scale * mMasses[node] * Mat3::Identity() + stiffness_scale * scratch.mBlocks[node];
            jacobi.Build(system, scratch.mBlocks, mPositions, mFree);
        };
        if (factored == nullptr)
            build_jacobi();

        // Solve A dv = r, then v += dv and x = x0 + h v on the free nodes. A solve the factor's frames no
        // longer fit stops after mFactorRefreshIterations, or as soon as its rate says it would need more,
        // refreshes the factor at this linearisation's frames and goes on from where it stopped.
        std::fill(scratch.mDeltaV.begin(), scratch.mDeltaV.end(), Vec3::Zero());
        // A factor whose frames cost a few iterations per solve, too few to stop one, is refreshed once the
        // iterations it has cost add up to a refresh (mFactorRefreshByCost).
        if (refreshing && factored != nullptr && mSettings.mFactorRefreshByCost &&
            mRefreshLedger.ShouldRefresh(factored->GetRefreshCostInIterations()) &&
            !RefreshFactor(*factored, input, mass_scale, stiffness_scale, true))
        {
            factored = nullptr;
            build_jacobi();
        }
        const int budget = mSettings.mCgMaxIterations;
        const int first_budget = refreshing && factored != nullptr ? std::min(budget, mSettings.mFactorRefreshIterations) : budget;
        const bool may_refresh = first_budget < budget;
        ConjugateGradientResult cg =
            ConjugateGradient(system, preconditioner, scratch.mResidual, mSettings.mCgRelativeTolerance,
                              first_budget, scratch.mDeltaV, scratch.mCg, may_refresh ? first_budget : 0);
        if (may_refresh && !cg.mConverged && (cg.mIterations == first_budget || cg.mPredictedLong))
        {
            if (!RefreshFactor(*factored, input, mass_scale, stiffness_scale))
            {
                // Round-off failed both factorisations: block Jacobi at this linearisation from here on.
                factored = nullptr;
                build_jacobi();
            }
            const ConjugateGradientResult rest =
                ConjugateGradient(system, preconditioner, scratch.mResidual, mSettings.mCgRelativeTolerance,
                                  budget - cg.mIterations, scratch.mDeltaV, scratch.mCg);
            cg = {cg.mIterations + rest.mIterations, rest.mRelativeResidual, rest.mConverged};
            mRefreshLedger.CountSolve(rest.mIterations);
        }
        else if (refreshing && factored != nullptr)
            mRefreshLedger.CountSolve(cg.mIterations);
        ioResult.mSolverIterations += cg.mIterations;
        ioResult.mSolverResidual = std::max(ioResult.mSolverResidual, cg.mRelativeResidual);
        if (!cg.mConverged)
            ioResult.mEvents = ioResult.mEvents | ETetStepEvent::SolverNotConverged;
        mPassEnergyValid = false; // the positions move
        if (line_search)
            std::copy(mVelocities.begin(), mVelocities.end(), scratch.mLineStart.begin());
        for (std::size_t node = 0; node < node_count; ++node)
            if (mFree[node] != 0)
            {
                mVelocities[node] += scratch.mDeltaV[node];
                mPositions[node] = x0[node] + h * mVelocities[node];
            }
        if (held != nullptr)
            HoldCrossingNodes(ground, mFree, mNodeRestPositions, x0, h, scratch.mGroundHeld, mPositions,
                              mVelocities);
        ++ioResult.mNewtonIterations;
    }
    mElementWork += products * mActiveElementCount;
    if (!converged)
        ioResult.mEvents = ioResult.mEvents | ETetStepEvent::SolverNotConverged;

    // The ground's friction and the nodes that ended below it; positions it moved are not those of the last
    // pass.
    bool ground_moved = false;
    if (ground.mEnabled)
    {
        ground_moved =
            FinishGroundStep(ground, mFree, mNodeRestPositions, scratch.mGroundHeld, scratch.mGroundImpulses,
                             mMasses, scratch.mResidual, mPositions, mVelocities);
        if (ground_moved)
            mPassEnergyValid = false;
    }

    // The last pass was at the final positions: keep them as the key of mForces, mLinearization, mRotations.
    mForcePositions = mPositions;
    mForcesCached = !ground_moved;
}

double TetSolver::LineSearchMerit(double inDeltaTime, std::span<const Vec3> inStartVelocities) const
{
    const double h = inDeltaTime;
    const double mass_damping = mMaterial.GetSettings().mMassDamping;
    double merit = mPassEnergy;
    for (std::size_t node = 0; node < mVelocities.size(); ++node)
    {
        if (mFree[node] == 0)
            continue;
        const double m = mMasses[node];
        const Vec3& v = mVelocities[node];
        merit += 0.5 * m * (v - inStartVelocities[node]).squaredNorm() +
                 0.5 * h * mass_damping * m * v.squaredNorm() -
                 h * v.dot(mExternalForces[node] + m * mSettings.mGravity);
    }
    return merit;
}

double TetSolver::GetFactorRefreshCost() const
{
    const TetSolveScratch* scratch = mWorkspace.Find();
    return scratch != nullptr ? scratch->mFactor.GetRefreshCostInIterations() : 0.0;
}

bool TetSolver::RefreshesFactor() const
{
    return mMaterial.GetSettings().mModel == EElasticModel::CorotatedLinear && mSettings.mFactorRefreshIterations > 0 &&
           mSettings.mPreconditioner == EImplicitPreconditioner::RestFactorization;
}

TetFactoredPreconditioner* TetSolver::FactoredRestSystem(const TetElementPassInput& inInput, double inMassScale,
                                                         double inStiffnessScale)
{
    if (mSettings.mPreconditioner != EImplicitPreconditioner::RestFactorization)
        return nullptr;
    TetFactoredPreconditioner& factor = mWorkspace.Get().mFactor;
    if (!factor.Matches(mElementNodes, mFree, inMassScale, inStiffnessScale))
    {
        // intent: the implicit system of a refreshing solver is factored at mFactorFrames, those of its last
        // refresh, crack or change of anchors (solver state: Prepare, a copy and a replay factor alike); the
        // static one (mass scale 0) at rest. A breakable solver refactors after every crack and a refreshing
        // one at every refresh: both keep their elements' rest stiffness.
        const bool framed = inMassScale > 0.0 && RefreshesFactor();
        factor.Precompute(inInput, mMasses, mFree, inMassScale, inStiffnessScale, mMaterial.IsBreakable() || RefreshesFactor(),
                          framed ? std::span<const Quat>(mFactorFrames) : std::span<const Quat>{});
        ++mFactorizationCount;
    }
    return factor.IsFactored() ? &factor : nullptr;
}

void TetSolver::KeepFactorFrames(std::span<const Quat> inFrames, bool inByCost)
{
    // intent: the first change in a step keeps the step's start frames, which a restored step gets back
    if (!mFactorFramesSaved)
    {
        mSavedFactorFrames = mFactorFrames;
        mFactorFramesSaved = true;
    }
    mFactorFrames.assign(inFrames.begin(), inFrames.end());
    mRefreshLedger.FramesSet(inByCost);
}

bool TetSolver::RefreshFactor(TetFactoredPreconditioner& ioFactor, const TetElementPassInput& inInput,
                              double inMassScale, double inStiffnessScale, bool inByCost)
{
    KeepFactorFrames(mRotations, inByCost);
    if (ioFactor.Refresh(inInput, mMasses, mFactorFrames))
    {
        ++mFactorRefreshCount;
        return true;
    }
    // intent: a system that was positive definite at its old frames is so at any (congruent blocks plus the
    // masses); should round-off still fail it, the rest factor, which factored before, takes over
    mFactorFrames.clear();
    ++mFactorizationCount;
    if (!ioFactor.Precompute(inInput, mMasses, mFree, inMassScale, inStiffnessScale, true))
        return false;
    ioFactor.SetNodeRotations(mElementNodes, mRotations, true);
    return true;
}

// The CPU side of TetStepper's policy: arrays in place, divergence as a non-finite state or an energy gain.
class TetSolver::StepBackend final : public TetStepBackend
{
public:
    explicit StepBackend(TetSolver& ioSolver) : mSolver(ioSolver) {}

    Result<int> SubStepsFor(double inDeltaTime) const override
    {
        if (!IsExplicit())
            return 1;
        return mSolver.SymplecticSubSteps(inDeltaTime);
    }

    bool IsExplicit() const override { return mSolver.mSettings.mIntegrator == EIntegrator::SymplecticEuler; }

    Status SaveStepStart() override
    {
        // Energy reference after the last input change, and a copy of the state to restore on divergence.
        TetSolver& s = mSolver;
        if (!s.mReferenceValid)
        {
            // intent: after an impulse or a force (the inputs of a hit) the elastic energy of the positions
            // is the last pass's, which nothing has moved since: no pass of its own
            const EnergyParts parts = s.MeasuredOrPassEnergy();
            s.mReferenceEnergy = parts.mKinetic + parts.mElastic + parts.mPotential;
            s.mReferenceValid = true;
        }
        s.mSavedPositions = s.mPositions;
        s.mSavedVelocities = s.mVelocities;
        s.mSavedRotations = s.mRotations;
        s.mFactorFramesSaved = false;
        s.mSavedRefreshLedger = s.mRefreshLedger;
        if (ChangesShape())
            s.SaveShape(s.mSavedShape);
        s.mPassEnergyValid = false;
        return Status::Ok();
    }

    void RestoreStepStart() override
    {
        TetSolver& s = mSolver;
        if (ChangesShape())
            s.RestoreShape(s.mSavedShape);
        s.mStepPlasticElements = 0;
        s.mStepBrokenLinks = 0;
        s.mPositions = s.mSavedPositions;
        s.mVelocities = s.mSavedVelocities;
        s.mRotations = s.mSavedRotations;
        s.mRefreshLedger = s.mSavedRefreshLedger;
        s.mPassEnergyValid = false; // the attempt's passes saw the positions it threw away
        if (s.mFactorFramesSaved)
        {
            // intent: the factor goes back to the step's start frames too, so the next attempt or step
            // repeats this one bit for bit
            s.mFactorFrames.swap(s.mSavedFactorFrames);
            s.mFactorFramesSaved = false;
            s.mWorkspace.Get().mFactor.Invalidate();
        }
    }

    TetStepAttempt Attempt(double inDeltaTime, int inPieces, TetStepResult& ioResult) override
    {
        TetSolver& s = mSolver;
        s.mStepPlasticElements = 0;
        s.mStepBrokenLinks = 0;
        if (IsExplicit())
            s.StepSymplectic(inDeltaTime, inPieces);
        else
            for (int piece = 0; piece < inPieces; ++piece)
            {
                s.StepImplicit(inDeltaTime / inPieces, ioResult);
                const int changed = s.mStepPlasticElements + s.mStepBrokenLinks;
                s.AfterSubStep(inDeltaTime / inPieces);
                if (s.mStepPlasticElements + s.mStepBrokenLinks != changed)
                    s.mPassEnergyValid = false; // plastic flow or a crack changed the energy of these positions
            }

        // Divergence: non-finite state or energy gained beyond the bound (see mDivergenceEnergyRatio).
        TetStepAttempt attempt;
        attempt.mDiverged = !AllFinite(s.mPositions) || !AllFinite(s.mVelocities);
        if (!attempt.mDiverged)
        {
            const EnergyParts parts = s.MeasuredOrPassEnergy();
            const double energy = parts.mKinetic + parts.mElastic + parts.mPotential;
            const double content = parts.mKinetic + parts.mElastic + parts.mPotentialMagnitude;
            attempt.mDiverged = !std::isfinite(energy) ||
                                energy - s.mReferenceEnergy > s.mSettings.mDivergenceEnergyRatio * std::max(content, cEnergyFloor);
            attempt.mKineticEnergy = parts.mKinetic;
            attempt.mEnergy = energy;
        }
        attempt.mPlasticElements = s.mStepPlasticElements;
        attempt.mBrokenLinks = s.mStepBrokenLinks;
        return attempt;
    }

    void DescribeRestored(TetStepResult& ioResult) const override
    {
        ioResult.mKineticEnergy = mSolver.KineticEnergy();
        ioResult.mEnergy = mSolver.mReferenceEnergy;
    }

    bool IsAtRestUnloaded() const override
    {
        const TetSolver& s = mSolver;
        const bool pulled = !s.mSettings.mGravity.isZero(0.0) &&
                            std::find(s.mFree.begin(), s.mFree.end(), std::uint8_t{1}) != s.mFree.end();
        return !pulled && s.IsStillAndUnstrained();
    }

    double FreeMass() const override { return mSolver.mFreeMass; }

    void FallAsleep() override
    {
        for (Vec3& velocity : mSolver.mVelocities)
            velocity.setZero();
        mSolver.mReferenceValid = false;
    }

private:
    bool ChangesShape() const { return mSolver.mMaterial.IsPlastic() || mSolver.mMaterial.IsBreakable(); }

    TetSolver& mSolver;
};

Status TetSolver::Prepare(double inDeltaTime)
{
    if (Status valid = CheckTimeStep(inDeltaTime, "TetSolver::Prepare"); !valid)
        return valid;
    mWorkspace.Get().Resize(mPositions.size());
    if (mSettings.mIntegrator == EIntegrator::ImplicitEuler)
    {
        // The scales StepImplicit uses for a step of this length.
        const FemMaterialSettings& material = mMaterial.GetSettings();
        (void)FactoredRestSystem(ParallelPassInput(), 1.0 + inDeltaTime * material.mMassDamping,
                                 inDeltaTime * inDeltaTime + inDeltaTime * material.mStiffnessDamping);
    }
    return Status::Ok();
}

Result<int> TetSolver::SymplecticSubSteps(double inDeltaTime) const
{
    const double count = std::ceil(inDeltaTime / mStableTimeStep);
    if (!(count <= static_cast<double>(mSettings.mMaxSubSteps)))
    {
        std::ostringstream message;
        message << "TetSolver::Step: " << inDeltaTime << " s needs " << count << " symplectic sub-steps of at most "
                << mStableTimeStep << " s, more than TetSolverSettings.mMaxSubSteps = " << mSettings.mMaxSubSteps
                << "; use a smaller step, a softer material, coarser elements or EIntegrator::ImplicitEuler";
        return MakeError(EError::InvalidArgument, message.str());
    }
    return std::max(1, static_cast<int>(count));
}

Status TetSolver::CheckStep(double inDeltaTime) const
{
    if (Status valid = CheckTimeStep(inDeltaTime, "TetSolver::Step"); !valid)
        return valid;
    if (mSettings.mIntegrator != EIntegrator::SymplecticEuler)
        return Status::Ok();
    Result<int> count = SymplecticSubSteps(inDeltaTime);
    return count.HasError() ? Status(count.GetError()) : Status::Ok();
}

bool TetSolver::IsStillAndUnstrained() const
{
    // intent: exact comparisons, velocities first (a moving prop answers at its first moving node)
    for (const Vec3& velocity : mVelocities)
        if (!(velocity.array() == 0.0).all())
            return false;
    for (const Vec3& force : mExternalForces)
        if (!(force.array() == 0.0).all())
            return false;
    for (const Mat3& plastic : mPlasticStrains)
        if (!(plastic.array() == 0.0).all())
            return false;
    return std::equal(mPositions.begin(), mPositions.end(), mNodeRestPositions.begin(), mNodeRestPositions.end(),
                      [](const Vec3& inA, const Vec3& inB) { return (inA.array() == inB.array()).all(); });
}

Result<TetStepResult> TetSolver::Step(double inDeltaTime)
{
    StepBackend backend(*this);
    return mStepper.Step(backend, mSettings, inDeltaTime, "TetSolver");
}

// Static equilibrium f_elastic(x) + f_load = 0 by repeated linearisation: K(x_k) dx = f_elastic(x_k) +
// f_load, x_{k+1} = x_k + dx. For the corotated model K(x) = R K0 R^T lags the rotation (a fixed point
// iteration that converges for moderate rotations); for St. Venant-Kirchhoff it is the tangent with its
// stress term made PSD.
Result<TetStaticResult> TetSolver::SolveStatic(int inMaxIterations, double inRelativeTolerance,
                                               int inMaxCgIterations)
{
    if (inMaxIterations < 1 || inMaxCgIterations < 1)
        return MakeError(EError::InvalidArgument, "TetSolver::SolveStatic: iteration counts " +
                                                      std::to_string(inMaxIterations) + ", " +
                                                      std::to_string(inMaxCgIterations) + " must be >= 1");
    if (!(inRelativeTolerance > 0.0 && inRelativeTolerance < 1.0))
        return MakeError(EError::InvalidArgument, "TetSolver::SolveStatic: the tolerance must lie in (0, 1)");
    const std::size_t node_count = mPositions.size();
    if (std::none_of(mInverseMasses.begin(), mInverseMasses.end(),
                     [](double inValue) { return inValue == 0.0; }))
        return MakeError(EError::InvalidArgument,
                         "TetSolver::SolveStatic: no node is fixed; a free body has no static "
                         "equilibrium under load (anchor nodes with SetNodeFixed)");

    // The load, and the force scale the residual is measured against.
    std::vector<Vec3> load;
    LoadForces(load);
    double load_norm = 0.0;
    for (const Vec3& force : load)
        load_norm += force.squaredNorm();
    load_norm = std::sqrt(load_norm);

    // Keep the state to restore when the iteration fails (with the last step's force pass, which the next
    // step takes as its first when the nodes have not moved).
    mSavedPositions = mPositions;
    mSavedRotations = mRotations;
    std::vector<Vec3> saved_forces = mForces;
    std::vector<TetLinearization> saved_linearization = mLinearization;

    const TetElementPassInput input = ParallelPassInput();
    TetStaticResult result;
    TetSolveScratch& scratch = mWorkspace.Get();
    scratch.Resize(node_count);
    std::vector<Vec3>& residual = scratch.mResidual;
    std::vector<Vec3>& delta_x = scratch.mDeltaV;

    // Stiffness operator K, masked to the free nodes (one captured pointer: no allocation).
    struct StiffnessContext
    {
        TetSolver* mSolver;
        const TetElementPassInput* mInput;
        std::uint64_t mProducts;
    } context{this, &input, 0};
    const LinearOperator3 stiffness = [ctx = &context](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        TetStiffnessProduct(*ctx->mInput, ctx->mSolver->mLinearization, inX, outY);
        ++ctx->mProducts;
        for (std::size_t node = 0; node < outY.size(); ++node)
            if (ctx->mSolver->mFree[node] == 0)
                outY[node].setZero();
    };

    // The factored rest stiffness K0 when the anchors hold every rigid mode, else block Jacobi with the rigid
    // coarse space rebuilt per linearisation.
    TetFactoredPreconditioner* factored = FactoredRestSystem(input, 0.0, 1.0);
    const LinearOperator3 preconditioner =
        factored != nullptr ? factored->AsOperator() : scratch.mJacobi.AsOperator();
    double scale = load_norm;
    for (int iteration = 0;; ++iteration)
    {
        // Residual force on the free nodes at the current linearisation point.
        TetElasticForces(input, mPositions, {}, 0.0, mRotations, mLinearization, mForces);
        mElementWork += mActiveElementCount;
        double residual_norm = 0.0;
        for (std::size_t node = 0; node < node_count; ++node)
        {
            residual[node] = mInverseMasses[node] > 0.0 ? Vec3(mForces[node] + load[node]) : Vec3::Zero();
            residual_norm += residual[node].squaredNorm();
        }
        residual_norm = std::sqrt(residual_norm);
        if (iteration == 0 && !(scale > 0.0))
            scale = residual_norm; // unloaded: relax towards the rest shape
        result.mRelativeResidual = scale > 0.0 ? residual_norm / scale : 0.0;
        result.mIterations = iteration;
        if (!std::isfinite(residual_norm))
            break;
        if (result.mRelativeResidual <= inRelativeTolerance)
        {
            // Converged: at rest in equilibrium.
            for (Vec3& velocity : mVelocities)
                velocity.setZero();
            mPassEnergyValid = false; // the nodes moved since the last step's pass
            InputChanged();
            return result;
        }
        if (iteration == inMaxIterations)
            break;

        // Solve K dx = residual on the free nodes.
        context.mProducts = 0;
        if (factored != nullptr)
            factored->SetNodeRotations(mElementNodes, mRotations,
                                       mMaterial.GetSettings().mModel == EElasticModel::CorotatedLinear);
        else
        {
            TetStiffnessDiagonal(input, mLinearization, scratch.mBlocks);
            mElementWork += mActiveElementCount;
            scratch.mJacobi.Build(stiffness, scratch.mBlocks, mPositions, mFree);
        }
        std::fill(delta_x.begin(), delta_x.end(), Vec3::Zero());
        const ConjugateGradientResult cg = ConjugateGradient(stiffness, preconditioner, residual,
                                                             0.5 * inRelativeTolerance, inMaxCgIterations,
                                                             delta_x, scratch.mCg);
        mElementWork += context.mProducts * mActiveElementCount;
        result.mSolverIterations += cg.mIterations;
        for (std::size_t node = 0; node < node_count; ++node)
            mPositions[node] += delta_x[node];
    }

    // Not converged: put everything back, the force pass the next step may take as its first included.
    mPositions = mSavedPositions;
    mRotations = mSavedRotations;
    mForces = std::move(saved_forces);
    mLinearization = std::move(saved_linearization);
    std::ostringstream message;
    message << "TetSolver::SolveStatic: no equilibrium after " << result.mIterations << " linearisations and "
            << result.mSolverIterations << " CG iterations (relative residual " << result.mRelativeResidual
            << " > " << inRelativeTolerance
            << "); the load may be too large for the anchoring, or raise the limits";
    return MakeError(EError::InvalidArgument, message.str());
}

} // namespace crumple::fem
