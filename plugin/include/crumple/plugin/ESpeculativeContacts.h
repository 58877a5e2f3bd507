// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace crumple::plugin
{

/// How the engine's solver treats a contact it reports before touching (a gap g within its contact margin,
/// ContactEvent::mPenetrationDepth < 0) whose approach v closes the gap within the step (v > g / dt):
/// Crumple's impulses must take from the bodies what the engine takes. Engines that report only touching
/// contacts (ODE) are the same under both.
enum class ESpeculativeContacts : std::uint8_t
{
    /// The engine stops the approach at the surface in this step (it resolves only the approach beyond g /
    /// dt) and takes the rest, rebound included, with the next step's contact: Bullet's sequential-impulse
    /// solver.
    StopAtSurface,
    /// The engine resolves the predicted hit in this step, rebound included, from where the bodies are:
    /// Jolt's and Box2D's speculative contacts. With StopAtSurface such an engine's hit would lose the
    /// approach the gap stood for (g / dt of it: behind a 1 cm gap at 120 Hz, 1.2 m/s, a fifth of a 20 km/h
    /// hit).
    ResolveWhole,
};

} // namespace crumple::plugin
