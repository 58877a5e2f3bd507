// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/JobSystem.h>
#include <crumple/base/Result.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/plugin/Ids.h>
#include <crumple/plugin/ReplayFormat.h>
#include <crumple/props/FemProp.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace crumple::props
{

// (clang-format would take each tag's comment above it for a trailing comment of the tag before)
// clang-format off
/// The extension-record tags crumple::props writes into a damage recording (plugin::RecordedExtension).
enum class EPropRecord : std::uint32_t
{
    /// A prop joined: its body, backend, mesh, material, solver settings and state (PropSetup)
    Added = 0x50524f50u, // "PROP"
    /// Every prop stepped by a time step (f64 seconds)
    Step = 0x50535450u, // "PSTP"
    /// Pieces left a prop (PropWorld::TakeLooseFragments): u32 prop index, u32 node count, the u32 nodes fixed
    Loose = 0x504c4f53u, // "PLOS"
    /// No payload, before any prop: the props were stepped off the game's thread (PropWorldSettings::
    /// mStepOffThread), so every collision reached them at the next step record, not where it was recorded
    Queued = 0x50515545u, // "PQUE"
    /// A prop left (PropWorld::RemoveProp): u32 prop index. A replayer older than the record (before a653e03)
    /// passes over it as another layer's and steps the prop on.
    Removed = 0x5052454du, // "PREM"
};
// clang-format on

/// A prop as recorded when it joined a PropWorld: enough to rebuild its solver bit for bit. The state is
/// the solver's at that moment (positions, velocities, anchors, external forces, gravity) before its first
/// step: a stepped solver also carries warm starts (element rotations) and sleep and energy history that a
/// rebuilt one would not have, so MakePropSetup refuses it.
struct CRUMPLE_API PropSetup
{
    plugin::BodyId mBody;                  ///< The body the prop is bound to
    EFemBackend mBackend = EFemBackend::Cpu; ///< The backend it ran on live
    std::vector<Vec3> mRestPositions;      ///< #N rest mesh positions (m, body frame)
    std::vector<fem::TetIndices> mTets;    ///< #T elements
    std::vector<int> mGroups;              ///< #T element groups
    fem::FemMaterialSettings mMaterial;
    fem::TetSolverSettings mSettings;      ///< Gravity as last set
    std::vector<Vec3> mPositions;          ///< #N solver nodes (m, body frame; a breakable mesh may have more
                                           ///< than its rest mesh: pieces touching along an edge are apart)
    std::vector<Vec3> mVelocities;         ///< #N (m/s)
    std::vector<std::uint8_t> mAnchored;   ///< #N, 1 where the node is fixed
    std::vector<Vec3> mExternalForces;     ///< #N (N)
    double mContactSpread = 0.0;           ///< FemProp::GetContactSpread (m; written only when not 0)
};

/// The setup of a CPU solver bound to inBody; refused once the solver has stepped or solved statics.
CRUMPLE_API Result<PropSetup> MakePropSetup(plugin::BodyId inBody, EFemBackend inBackend, const fem::TetSolver& inSolver);
/// The setup of a prop on either backend bound to inBody, refused once it has stepped. A GPU prop's state is
/// read back as the GPU holds it (float); positions still at the rest mesh's (as floats) are recorded as the
/// rest mesh's, so a rebuilt prop starts from exactly the same state (RebuildProp, then FemProp::FromSolver).
CRUMPLE_API Result<PropSetup> MakePropSetup(plugin::BodyId inBody, const FemProp& inProp);

/// Refused when the per-node arrays (positions, velocities, anchors, external forces) differ in size, or the
/// groups are neither empty nor one per element. Changes nothing.
CRUMPLE_API Status ValidatePropSetupSizes(const PropSetup& inSetup);
/// Bytes of a PropSetup (little-endian) and back; encoding refuses what ValidatePropSetupSizes refuses and a
/// contact spread radius that is not finite and >= 0,
/// decoding checks sizes and finite values, and the mesh, material and settings are validated again when the
/// solver is rebuilt (RebuildProp).
CRUMPLE_API Result<std::vector<std::byte>> EncodePropSetup(const PropSetup& inSetup);
CRUMPLE_API Result<PropSetup> DecodePropSetup(std::span<const std::byte> inBytes);

/// A CPU solver in the recorded state (for a GPU prop, the state its GPU solver is made from). Refused for
/// what ValidatePropSetupSizes refuses, and for a mesh, material, settings or state its solver refuses.
CRUMPLE_API Result<fem::TetSolver> RebuildProp(const PropSetup& inSetup);

/// A prop rebuilt from a recording and replayed: its final state.
struct CRUMPLE_API ReplayedProp
{
    plugin::BodyId mBody;
    EFemBackend mRecordedBackend = EFemBackend::Cpu;
    /// On the backend it ran on live, where the replayer has it; a GPU prop without a device replays on the CPU
    /// (mProp.GetBackend() and GetFallbackReason() say so): close, not bitwise
    FemProp mProp;
    /// Removed live (PropWorld::RemoveProp, a Removed record): mProp is as it was then, and it took no
    /// collision or step after it
    bool mRemoved = false;
};

/// Replays the props of a recording without an engine: each prop is rebuilt when it joined, on its recorded
/// backend (a GPU prop on a device of ioProvider, which makes its context only then; null, or no device: on
/// the CPU), takes the recorded collisions with its body (FemProp::ApplyCollision) and the recorded steps, in
/// the recorded order (after a Queued record, each collision at the first step recorded after it; those after
/// the last step never reach a prop, as live); a prop removed live stops at its Removed record. CPU props end
/// bitwise as they did live, and GPU props on the same device and driver. Refused with a message naming the
/// record on a corrupt or inconsistent prop record (among them a second prop for the same body while the
/// first is not removed, a removal or loose piece of no prop or of a removed one, or records whose collision
/// counts go back), and where a CPU
/// prop breaks otherwise than it did live: a recorded loose piece that is none of
/// its pieces as replayed (a recording made by a build of Crumple whose FEM gives other results; before, such
/// a replay fixed those nodes and went on, or stopped at a node past the prop's count).
/// inJobs (null: serial): the CPU props' element passes run on the host's job system
/// (fem::TetSolver::SetJobSystem), bitwise the same for any number of workers; it must outlive the call, and
/// the props handed back keep no pointer to it (they step serially unless given one again).
CRUMPLE_API Result<std::vector<ReplayedProp>> ReplayProps(const plugin::Replay& inReplay,
                                                          gpu::ComputeDeviceProvider* ioProvider = nullptr,
                                                          const JobSystem* inJobs = nullptr);

} // namespace crumple::props
