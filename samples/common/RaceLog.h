// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/DamageListener.h>
#include <crumple/plugin/DeformableObject.h>

#include <map>
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
    /// Largest vertex displacement of an object (m).
    static double DeepestDent(const plugin::DeformableObject& inObject);

private:
    std::string Name(plugin::BodyId inBody) const;

    std::map<plugin::BodyId, std::string> mNames;
    int mCount = 0;
};

} // namespace crumple::samples
