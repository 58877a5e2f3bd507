// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/HeldFemProp.h>

#include <crumple/props/CollisionImpulses.h>

#include <string>

namespace crumple::props
{

namespace
{

// inSolver with its gravity and ground turned from the world frame into the frame of a body at inPose.
fem::TetSolverSettings InBodyFrame(const fem::TetSolverSettings& inSolver,
                                   const plugin::PropBodySettings& inBody)
{
    const Transform pose{inBody.mOrientation, inBody.mPosition};
    fem::TetSolverSettings solver = inSolver;
    solver.mGravity = pose.DirectionToBody(inSolver.mGravity);
    if (solver.mGround.mEnabled)
    {
        // n . (R x + t) = d  <=>  (R^T n) . x = d - n . t
        solver.mGround.mNormal = pose.DirectionToBody(inSolver.mGround.mNormal);
        solver.mGround.mOffset = inSolver.mGround.mOffset - inSolver.mGround.mNormal.dot(inBody.mPosition);
    }
    return solver;
}

} // namespace

fem::TetSolverSettings HeldPropSolverSettings()
{
    fem::TetSolverSettings solver;
    solver.mGravity = Vec3::Zero();
    solver.mFactorRefreshIterations = 6;
    solver.mFactorRefreshByCost = true;
    return solver;
}

Result<FemProp> MakeHeldFemProp(const fem::TetMesh& inBodyMesh, const fem::FemMaterialSettings& inMaterial,
                                std::span<const int> inAnchoredNodes, const fem::TetSolverSettings& inSolver,
                                double inContactSpread, const FemPropSettings& inPropSettings,
                                gpu::ComputeDeviceProvider* ioProvider)
{
    if (Status radius = CheckContactSpreadRadius(inContactSpread, "MakeHeldFemProp"); radius.HasError())
        return radius.GetError();
    if (Status valid = FemProp::CheckSettings(inPropSettings); valid.HasError())
        return valid.GetError();
    Result<fem::TetSolver> solver = fem::TetSolver::Create(inBodyMesh, inMaterial, inSolver);
    if (!solver)
        return solver.GetError();
    // intent: every anchor checked, then all set at once
    for (int node : inAnchoredNodes)
        if (node < 0 || node >= solver.Get().GetNodeCount())
            return MakeError(EError::OutOfRange, "MakeHeldFemProp: anchored node " + std::to_string(node) +
                                                     " is outside [0, " +
                                                     std::to_string(solver.Get().GetNodeCount()) + ")");
    if (Status fixed = solver.Get().SetNodesFixed(inAnchoredNodes, true); !fixed)
        return MakeError(fixed.GetError().mCode, "MakeHeldFemProp: anchoring: " + fixed.GetError().mMessage);
    // intent: under gravity the prop starts where it hangs on its anchors (its static equilibrium, worked out
    // on a copy), so that it settles and sleeps within a few steps instead of sagging for dozens; the prop is
    // the fresh solver moved there (no warm start, no element work), as a replay rebuilds it from its record.
    // Where the static solve does not converge the prop starts as made.
    if (!(inSolver.mGravity.array() == 0.0).all() && !inAnchoredNodes.empty())
    {
        fem::TetSolver hanging = solver.Get();
        if (hanging.SolveStatic().IsValid())
            (void)solver.Get().SetPositions(hanging.GetPositions()); // the copy's own, valid positions
    }
    FemProp prop = FemProp::FromSolver(ioProvider, std::move(solver).Get(), inPropSettings);
    (void)prop.SetContactSpread(inContactSpread); // checked above
    return prop;
}

Result<HeldProp>
AddHeldProp(PropWorld& ioProps, const fem::TetMesh& inMesh, const fem::FemMaterialSettings& inMaterial,
            std::span<const int> inAnchoredNodes, const Transform& inPose, double inShapeCellSize,
            const std::function<Result<plugin::BodyId>(const plugin::PropBodySettings&)>& inMakeBody,
            const fem::TetSolverSettings& inSolver, double inContactSpread,
            const FemPropSettings& inPropSettings, gpu::ComputeDeviceProvider* ioProvider)
{
    if (!inMakeBody)
        return MakeError(EError::InvalidArgument, "AddHeldProp: no function to make the engine body");
    Result<PropBody> made = MakePropBody(inMesh, inMaterial.mDensity, inPose, true, inShapeCellSize);
    if (!made)
        return made.GetError();
    Result<FemProp> prop =
        MakeHeldFemProp(made.Get().mMesh, inMaterial, inAnchoredNodes,
                        InBodyFrame(inSolver, made.Get().mBody), inContactSpread, inPropSettings, ioProvider);
    if (!prop)
        return prop.GetError();
    // intent: what AddProp would refuse of the prop itself (a failed or closed recorder) is refused before the
    // engine body exists, so bad state makes no body either
    if (Status can_add = ioProps.CheckCanAdd(prop.Get()); !can_add)
        return can_add.GetError();
    Result<plugin::BodyId> body = inMakeBody(made.Get().mBody);
    if (!body)
        return body.GetError();
    Result<PropId> added = ioProps.AddProp(body.Get(), std::move(prop).Get());
    if (!added)
        return added.GetError();
    return HeldProp{body.Get(), added.Get(), std::move(made).Get()};
}

} // namespace crumple::props
