// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/ReplayDamage.h>

#include <algorithm>
#include <string>

namespace crumple::plugin
{

Result<std::vector<ReplayedObject>> CreateReplayedObjects(const Replay& inReplay)
{
    std::vector<ReplayedObject> objects;
    for (const RecordedObject& record : inReplay.mObjects)
    {
        Result<DeformableObject> object = DeformableObject::Create(record.mSettings);
        if (!object)
            return MakeError(object.GetError().mCode,
                             "object " + std::to_string(record.mObject.mValue) + ": " + object.GetError().mMessage);
        // intent: a recording that began on an undamaged object (the usual case) needs no restore, which
        // would validate and recompute every vertex of the mesh for nothing
        const bool damaged = std::any_of(record.mInitialControls.begin(), record.mInitialControls.end(), [](const auto& inZone) {
            return std::any_of(inZone.begin(), inZone.end(), [](const Vec3& inControl) { return !inControl.isZero(0.0); });
        });
        const bool shaped = record.mInitialControls.size() == object.Get().GetDeformer().GetZones().size();
        if (damaged || !shaped)
            if (Status restored = object.Get().GetDeformer().SetControlDisplacements(record.mInitialControls); !restored)
                return MakeError(restored.GetError().mCode,
                                 "object " + std::to_string(record.mObject.mValue) + ": " + restored.GetError().mMessage);
        objects.push_back({record.mObject, record.mBody, record.mFirstCollision, std::move(object).Get()});
    }
    // Dispatch order of the live world: objects in id order, those of A before those of B.
    std::stable_sort(objects.begin(), objects.end(),
                     [](const ReplayedObject& a, const ReplayedObject& b) { return a.mObject < b.mObject; });
    return objects;
}

void ApplyReplayedCollisions(const Replay& inReplay, std::vector<ReplayedObject>& ioObjects,
                             const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision)
{
    for (std::size_t index = 0; index < inReplay.mCollisions.size(); ++index)
    {
        const Collision& collision = inReplay.mCollisions[index];
        for (const auto& [body, side] : {std::pair{collision.mBodyA, ECollisionSide::A}, std::pair{collision.mBodyB, ECollisionSide::B}})
            for (ReplayedObject& object : ioObjects)
                if (object.mBody == body && index >= object.mFirstCollision)
                    object.mDeformable.ApplyCollision(collision, side);
        if (inAfterCollision)
            inAfterCollision(index, ioObjects);
    }
}

Result<std::vector<ReplayedObject>> ReplayDamage(
    const Replay& inReplay, const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision)
{
    Result<std::vector<ReplayedObject>> objects = CreateReplayedObjects(inReplay);
    if (objects)
        ApplyReplayedCollisions(inReplay, objects.Get(), inAfterCollision);
    return objects;
}

} // namespace crumple::plugin
