// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/CollisionImpulses.h>

#include <crumple/fem/BarycentricSearch.h>
#include <crumple/fem/TetSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace crumple::props
{

using fem::BarycentricHit;
using fem::BarycentricSearch;
using fem::TetIndices;
using fem::TetSolver;

Result<std::vector<NodalImpulse>> CollisionNodalImpulses(const plugin::Collision& inCollision,
                                                         plugin::BodyId inPropBody,
                                                         std::span<const TetIndices> inElementNodes,
                                                         std::span<const Vec3> inPositions)
{
    return CollisionNodalImpulses(inCollision, inPropBody, inElementNodes, inPositions, ContactSpread{});
}

namespace
{

// Shares of a contact at inPoint over the free nodes within inSpread.mRadius: mass x (1 - d^2/r^2)^2,
// normalised; empty when no free node is that close.
std::vector<std::pair<int, double>> FootprintShares(const Vec3& inPoint, std::span<const Vec3> inPositions,
                                                    const ContactSpread& inSpread)
{
    std::vector<std::pair<int, double>> shares;
    const double inverse_square = 1.0 / (inSpread.mRadius * inSpread.mRadius);
    double total = 0.0;
    for (std::size_t node = 0; node < inPositions.size(); ++node)
    {
        const double reach = (inPositions[node] - inPoint).squaredNorm() * inverse_square;
        if (reach >= 1.0 || !(inSpread.mInverseMasses[node] > 0.0))
            continue;
        const double falloff = 1.0 - reach;
        const double weight = inSpread.mMasses[node] * falloff * falloff;
        shares.emplace_back(static_cast<int>(node), weight);
        total += weight;
    }
    if (!(total > 0.0))
        return {};
    for (auto& share : shares)
        share.second /= total;
    return shares;
}

} // namespace

Status CheckContactSpreadRadius(double inRadius, const char* inWho)
{
    if (!std::isfinite(inRadius) || inRadius < 0.0)
        return MakeError(std::isfinite(inRadius) ? EError::InvalidArgument : EError::NonFinite,
                         std::string(inWho) + ": the contact spread radius must be finite and >= 0 m, not " +
                             std::to_string(inRadius));
    return Status::Ok();
}

Result<std::vector<NodalImpulse>> CollisionNodalImpulses(const plugin::Collision& inCollision,
                                                         plugin::BodyId inPropBody,
                                                         std::span<const TetIndices> inElementNodes,
                                                         std::span<const Vec3> inPositions,
                                                         const ContactSpread& inSpread)
{
    if (Status radius = CheckContactSpreadRadius(inSpread.mRadius, "CollisionNodalImpulses"); radius.HasError())
        return radius.GetError();
    const bool spreads = inSpread.mRadius > 0.0;
    if (spreads && (inSpread.mMasses.size() != inPositions.size() || inSpread.mInverseMasses.size() != inPositions.size()))
        return MakeError(EError::InvalidArgument, "CollisionNodalImpulses: a contact spread needs one mass and one inverse mass per node");
    // intent: a NaN mass would silently drop a contact back to its element, a negative one give negative shares
    for (std::size_t node = 0; spreads && node < inPositions.size(); ++node)
        if (!(std::isfinite(inSpread.mMasses[node]) && inSpread.mMasses[node] > 0.0) ||
            !(std::isfinite(inSpread.mInverseMasses[node]) && inSpread.mInverseMasses[node] >= 0.0))
            return MakeError(EError::InvalidArgument, "CollisionNodalImpulses: node " + std::to_string(node) +
                                                          " has a mass or inverse mass a contact spread cannot weigh by "
                                                          "(masses finite and > 0, inverse masses finite and >= 0)");
    const bool is_a = inCollision.mBodyA == inPropBody;
    if (!is_a && inCollision.mBodyB != inPropBody)
        return MakeError(EError::InvalidArgument, "CollisionNodalImpulses: body " +
                                                      std::to_string(inPropBody.mValue) +
                                                      " is not one of the collision's bodies");
    if (inElementNodes.empty() || inPositions.empty())
        return MakeError(EError::InvalidArgument, "CollisionNodalImpulses: the prop has no element");
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
        for (int node : inElementNodes[tet])
            if (node < 0 || static_cast<std::size_t>(node) >= inPositions.size())
                return MakeError(EError::OutOfRange, "CollisionNodalImpulses: element " + std::to_string(tet) + " names node " +
                                                         std::to_string(node) + " of " + std::to_string(inPositions.size()));

    // intent: every element's edge matrix inverted once for all contacts, and only when a contact needs its
    // element (one that spreads finds free nodes in reach without it). Create refuses only corners outside
    // the nodes, checked above, so building it late changes no answer.
    std::optional<BarycentricSearch> search;

    std::vector<NodalImpulse> impulses;
    impulses.reserve(4 * inCollision.mContacts.size()); // more when spread
    for (std::size_t index = 0; index < inCollision.mContacts.size(); ++index)
    {
        // The contact in the prop's body frame: +j n on A, -j n on B. Friction (mLocalFrictionOnA/B) stays out
        // for now: a held prop's body follows its struck nodes (PropWorld::UpdateContactVelocity), and with the
        // friction in them the racing fence's held body was driven into the ground at 17.9 m/s in Bullet (a
        // ground contact of 1,062 N s that was not there before), breaking twice the links at four times the
        // frame's cost. Measured with the friction in the nodes and the held body following the normal
        // impulses' nodes only: the racing fence was as before, but Bullet's fence drive-through broke 2,876
        // links against ODE's 828 (PropFenceTest), the engines' own friction against the held body differing.
        const plugin::CollisionContact& contact = inCollision.mContacts[index];
        const Vec3 point = is_a ? contact.mLocalPointOnA : contact.mLocalPointOnB;
        const Vec3 impulse = (is_a ? contact.mImpulse : -contact.mImpulse) *
                             (is_a ? contact.mLocalNormalOnA : contact.mLocalNormalOnB);
        if (!IsFinite(point) || !IsFinite(impulse))
            return MakeError(EError::NonFinite,
                             "CollisionNodalImpulses: contact " + std::to_string(index) + " is not finite");

        if (spreads)
        {
            const std::vector<std::pair<int, double>> shares = FootprintShares(point, inPositions, inSpread);
            for (const auto& [node, share] : shares)
                impulses.push_back({node, share * impulse});
            if (!shares.empty())
                continue;
        }

        if (!search)
        {
            Result<BarycentricSearch> made = BarycentricSearch::Create(inElementNodes, inPositions);
            if (!made)
                return MakeError(made.GetError().mCode, "CollisionNodalImpulses: " + made.GetError().mMessage);
            search.emplace(std::move(made).Get());
        }
        // The element whose smallest barycentric weight is largest: the containing one if any.
        const BarycentricHit hit = search->FindBest(point);
        if (hit.mElement < 0)
            return MakeError(EError::InvalidArgument, "CollisionNodalImpulses: every element is degenerate");
        const int best = hit.mElement;
        std::array<double, 4> best_weights = hit.mWeights;

        // Outside the element: clamp and renormalise so the impulse stays on its nodes, in full.
        double total = 0.0;
        for (double& weight : best_weights)
            total += (weight = std::max(weight, 0.0));
        for (int corner = 0; corner < 4; ++corner)
            impulses.push_back({inElementNodes[best][corner], best_weights[corner] / total * impulse});
    }
    return impulses;
}

Status CheckNodalImpulses(std::span<const NodalImpulse> inImpulses, std::span<const Vec3> inVelocities,
                          std::span<const double> inInverseMasses, double inLimit)
{
    const auto within = [inLimit](const Vec3& inVelocity)
    { return IsFinite(inVelocity) && inVelocity.cwiseAbs().maxCoeff() <= inLimit; };
    // intent: each struck node's velocity after each of its impulses, added in order as the solver will add
    // them: a solver refuses an impulse that leaves a node too fast on the way, even where a later one would
    // bring it back (two pushes of 0.6e100 m/s and one pull: the second was refused after the first landed)
    std::map<int, Vec3> after;
    int passed_on_the_way = -1;
    for (const NodalImpulse& impulse : inImpulses)
    {
        const auto node = static_cast<std::size_t>(impulse.mNode);
        if (impulse.mNode < 0 || node >= inVelocities.size() || node >= inInverseMasses.size())
            return MakeError(EError::OutOfRange, "CheckNodalImpulses: no node " + std::to_string(impulse.mNode));
        const auto [entry, inserted] = after.try_emplace(impulse.mNode, inVelocities[node]);
        entry->second += inInverseMasses[node] * impulse.mImpulse;
        if (passed_on_the_way < 0 && !within(entry->second))
            passed_on_the_way = impulse.mNode;
    }
    for (const auto& [node, velocity] : after)
        if (!within(velocity))
            return MakeError(IsFinite(velocity) ? EError::OutOfRange : EError::NonFinite,
                             "CheckNodalImpulses: the impulses would leave node " + std::to_string(node) +
                                 " moving faster than its solver holds");
    if (passed_on_the_way >= 0)
        return MakeError(EError::OutOfRange,
                         "CheckNodalImpulses: the impulses would take node " +
                             std::to_string(passed_on_the_way) +
                             " faster than its solver holds before the last of them lands");
    return Status::Ok();
}

Status ApplyCollision(TetSolver& ioSolver, const plugin::Collision& inCollision, plugin::BodyId inPropBody)
{
    Result<std::vector<NodalImpulse>> impulses =
        CollisionNodalImpulses(inCollision, inPropBody, ioSolver.GetElementNodes(), ioSolver.GetPositions());
    if (impulses.HasError())
        return impulses.GetError();
    if (Status fits = CheckNodalImpulses(impulses.Get(), ioSolver.GetVelocities(), ioSolver.GetInverseMasses(),
                                         TetSolver::cMaxStateMagnitude);
        fits.HasError())
        return fits;
    // Every node index comes from the solver's own connectivity and every velocity stays finite: nothing below
    // can be refused, so the collision applies in full.
    for (const NodalImpulse& impulse : impulses.Get())
        if (Status status = ioSolver.ApplyImpulse(impulse.mNode, impulse.mImpulse); status.HasError())
            return status;
    return Status::Ok();
}

} // namespace crumple::props
