// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ScratchDirectory.h"
#include "WorldFixture.h"

#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/PropWorld.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace crumple::test
{

/// The wall fixture with a damage recorder writing ScratchDirectory() / inName and a PropWorld recording into
/// it from the start (attached before any prop, hit or removal): the setup of the props' recording cases.
struct RecordedPropWorld
{
    explicit RecordedPropWorld(const std::string& inName, const props::PropWorldSettings& inSettings = {})
        : mPath(common::ScratchDirectory() / inName)
    {
        mRecorder = std::move(plugin::DamageRecorder::Create(mPath, mFixture.mWorld).Get());
        mProps = props::PropWorld::Create(mFixture.mWorld, inSettings).Get();
        REQUIRE(mProps->AttachRecorder(mRecorder.get()).IsValid());
    }

    /// Detaches the recorder and closes its file: mPath then holds the whole recording.
    void Finish()
    {
        REQUIRE(mProps->AttachRecorder(nullptr).IsValid());
        REQUIRE(mRecorder->Close().IsValid());
    }

    std::filesystem::path mPath;
    common::WorldFixture mFixture;
    std::unique_ptr<plugin::DamageRecorder> mRecorder; ///< Destroyed after the props (declared before them)
    std::unique_ptr<props::PropWorld> mProps;
};

} // namespace crumple::test
