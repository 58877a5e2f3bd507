// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/DamageListener.h>
#include <crumple/plugin/DeformableObject.h>

#include <map>
#include <set>
#include <string>

namespace crumple::samples
{

/// Prints one line per dispatched collision, naming the bodies a sample cares about.
class RaceLog : public plugin::DamageListener
{
public:
    explicit RaceLog(std::map<plugin::BodyId, std::string> inNames) : mNames(std::move(inNames)) {}

    void OnCollision(const plugin::Collision& inCollision, std::span<const plugin::ObjectDent> inDents) override;

    int GetCount() const { return mCount; }
    /// Names a body (or renames it). The collisions of an unlisted body (the props' flying pieces: hundreds,
    /// mostly with the ground) are counted but get no line, unless the other body has a deformable object.
    void SetName(plugin::BodyId inBody, std::string inName, bool inListed = true)
    {
        mNames[inBody] = std::move(inName);
        if (!inListed)
            mUnlisted.insert(inBody);
    }
    /// Collisions that got no line (GetCount() counts them too)
    int GetUnlistedCount() const { return mUnlistedCount; }
    /// Largest vertex displacement of an object (m).
    static double DeepestDent(const plugin::DeformableObject& inObject);

private:
    std::string Name(plugin::BodyId inBody) const;

    std::map<plugin::BodyId, std::string> mNames;
    std::set<plugin::BodyId> mUnlisted;
    int mCount = 0;
    int mUnlistedCount = 0;
};

} // namespace crumple::samples
