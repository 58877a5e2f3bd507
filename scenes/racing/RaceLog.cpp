// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RaceLog.h"

#include <algorithm>
#include <cstdio>

namespace crumple::samples
{

std::string RaceLog::Name(plugin::BodyId inBody) const
{
    const auto found = mNames.find(inBody);
    return found != mNames.end() ? found->second : "body " + std::to_string(inBody.mValue);
}

void RaceLog::OnCollision(const plugin::Collision& inCollision, std::span<const plugin::ObjectDent> inDents)
{
    ++mCount;
    if ((mUnlisted.contains(inCollision.mBodyA) || mUnlisted.contains(inCollision.mBodyB)) && inDents.empty())
    {
        ++mUnlistedCount;
        return;
    }
    double approach = 0.0;
    for (const plugin::CollisionContact& c : inCollision.mContacts)
        approach = std::max(approach, c.mApproachSpeed);
    std::uint32_t moved = 0;
    for (const plugin::ObjectDent& dent : inDents)
        moved += dent.mReport.mVerticesMoved;
    std::printf("t %6.3f s  %-12s x %-12s  %2zu contacts  impulse %8.1f N s  approach %5.2f m/s  %6u vertices dented\n",
                inCollision.mStartTime, Name(inCollision.mBodyA).c_str(), Name(inCollision.mBodyB).c_str(),
                inCollision.mContacts.size(), inCollision.TotalImpulse(), approach, moved);
}

double RaceLog::DeepestDent(const plugin::DeformableObject& inObject)
{
    const ffd::FfdDeformer& d = inObject.GetDeformer();
    double deepest = 0.0;
    for (std::size_t v = 0; v < d.GetPositions().size(); ++v)
        deepest = std::max(deepest, (d.GetPositions()[v] - d.GetRestMesh().mPositions[v]).norm());
    return deepest;
}

} // namespace crumple::samples
