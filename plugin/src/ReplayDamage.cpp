// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
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

Status ApplyReplayedCollisions(
    const Replay& inReplay, std::vector<ReplayedObject>& ioObjects,
    const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision)
{
    // intent: all refused before any is applied, so a bad replay changes no object
    for (std::size_t index = 0; index < inReplay.mCollisions.size(); ++index)
        if (Status valid = ValidateCollision(inReplay.mCollisions[index]); !valid)
            return MakeError(valid.GetError().mCode, "replayed collision " + std::to_string(index) + ": " +
                                                         valid.GetError().mMessage);
    for (std::size_t index = 0; index < inReplay.mCollisions.size(); ++index)
    {
        const Collision& collision = inReplay.mCollisions[index];
        for (const auto& [body, side] : {std::pair{collision.mBodyA, ECollisionSide::A}, std::pair{collision.mBodyB, ECollisionSide::B}})
            for (ReplayedObject& object : ioObjects)
                if (object.mBody == body && index >= object.mFirstCollision)
                {
                    // Validated above: the dent cannot be refused.
                    const Result<ffd::DentReport> dent = object.mDeformable.ApplyCollision(collision, side);
                    CRUMPLE_ASSERT(dent.IsValid(), "a validated collision was refused");
                }
        if (inAfterCollision)
            inAfterCollision(index, ioObjects);
    }
    return Status::Ok();
}

Result<std::vector<ReplayedObject>> ReplayDamage(
    const Replay& inReplay, const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision)
{
    Result<std::vector<ReplayedObject>> objects = CreateReplayedObjects(inReplay);
    if (!objects)
        return objects;
    if (Status applied = ApplyReplayedCollisions(inReplay, objects.Get(), inAfterCollision); !applied)
        return applied.GetError();
    return objects;
}

} // namespace crumple::plugin
