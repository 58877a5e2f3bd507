// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RunRaceSession.h"
#include "RaceProps.h"

#include <cmath>
#include <cstdio>

namespace crumple::samples
{

int RunRaceSession(const char* inProgram, const RaceOptions& inOptions, const MakeRaceScene& inMakeScene)
{
    const auto fail = [inProgram](const Error& inError)
    {
        std::fprintf(stderr, "%s: %s\n", inProgram, inError.mMessage.c_str());
        return 2;
    };
    Result<std::unique_ptr<RaceScene>> made = inMakeScene({.mSpeed = inOptions.mSpeed,
                                                           .mThreads = inOptions.mThreads,
                                                           .mDeferDents = inOptions.mDeferDents,
                                                           .mDeferImpulses = inOptions.mDeferImpulses,
                                                           .mPropsOffThread = inOptions.mPropsOffThread,
                                                           .mAttach = true});
    if (!made)
        return fail(made.GetError());
    RaceScene& scene = *made.Get();
    plugin::DamageWorld& damage = *scene.GetDamage();
    RaceProps& props = *scene.GetProps();
    Result<std::unique_ptr<RaceSession>> created = RaceSession::Create(inOptions, damage, scene.GetNames());
    if (!created)
        return fail(created.GetError());
    RaceSession& session = *created.Get();
    if (Status recorded = props.AttachRecorder(&session.GetRecorder()); !recorded)
        return fail(recorded.GetError());
    session.PaintCar(*scene.GetCar(), "before.png");

    // A frame every 1/60 s, a picture every 0.1 s.
    const int frames = static_cast<int>(std::lround(inOptions.mDuration * 60.0));
    const RaceNewBodies name_pieces = [&session, &props](std::span<const RaceNewPiece> inPieces)
    {
        for (const RaceNewPiece& piece : inPieces)
            session.NamePieces(std::span<const plugin::BodyId>(&piece.mBody, 1),
                               props.GetName(piece.mProp) + " piece");
    };
    Status finished = Status::Ok();
    for (int frame = 0; frame < frames && finished; ++frame)
    {
        session.BeginFrame();
        finished = scene.StepFrame(name_pieces);
        session.EndFrame(scene.GetLastFrameCrumpleMs());
        if (finished && frame % 6 == 0)
            session.PaintFrame(*scene.GetCar(), scene.GetCarPose(), *scene.GetParked(), scene.GetParkedPose(),
                               props);
    }
    if (finished)
        finished = session.Finish(damage, *scene.GetCar(), *scene.GetParked(), props);
    if (!finished)
        return fail(finished.GetError());
    return 0;
}

} // namespace crumple::samples
