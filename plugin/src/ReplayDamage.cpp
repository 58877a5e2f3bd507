// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/ReplayDamage.h>

#include <algorithm>
#include <string>

namespace crumple::plugin
{

Result<std::vector<ReplayedObject>> ReplayDamage(
    const Replay& inReplay, const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision)
{
    std::vector<ReplayedObject> objects;
    for (const RecordedObject& record : inReplay.mObjects)
    {
        Result<DeformableObject> object = DeformableObject::Create(record.mSettings);
        if (!object)
            return MakeError(object.GetError().mCode,
                             "object " + std::to_string(record.mObject.mValue) + ": " + object.GetError().mMessage);
        if (Status restored = object.Get().GetDeformer().SetControlDisplacements(record.mInitialControls); !restored)
            return MakeError(restored.GetError().mCode,
                             "object " + std::to_string(record.mObject.mValue) + ": " + restored.GetError().mMessage);
        objects.push_back({record.mObject, record.mBody, record.mFirstCollision, std::move(object).Get()});
    }
    // Dispatch order of the live world: objects in id order, those of A before those of B.
    std::stable_sort(objects.begin(), objects.end(),
                     [](const ReplayedObject& a, const ReplayedObject& b) { return a.mObject < b.mObject; });
    for (std::size_t index = 0; index < inReplay.mCollisions.size(); ++index)
    {
        const Collision& collision = inReplay.mCollisions[index];
        for (const auto& [body, side] : {std::pair{collision.mBodyA, ECollisionSide::A}, std::pair{collision.mBodyB, ECollisionSide::B}})
            for (ReplayedObject& object : objects)
                if (object.mBody == body && index >= object.mFirstCollision)
                    object.mDeformable.ApplyCollision(collision, side);
        if (inAfterCollision)
            inAfterCollision(index, objects);
    }
    return objects;
}

} // namespace crumple::plugin
