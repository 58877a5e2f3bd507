// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// One engine step's contacts of a body pair, grouped for the joint impulse solve. Private to the plugin.

#include <crumple/plugin/Collision.h>
#include <crumple/plugin/ContactEvent.h>
#include <crumple/plugin/Ids.h>

#include <span>
#include <vector>

namespace crumple::plugin
{

/// The contacts of one body pair at one time, A the lower id.
struct ContactBatch
{
    BodyId mA;          ///< The pair's lower id
    BodyId mB;          ///< Its higher id
    double mTime = 0.0; ///< The first contact's time (s)
    /// In arrival order, normals from B to A, points on the surfaces
    std::vector<CollisionContact> mContacts;
};

/// An engine contact turned to the canonical orientation (A = the lower id: a flipped normal, swapped points)
/// with its points moved onto the bodies' surfaces (SurfaceContactPoints).
struct OrientedContact
{
    BodyId mA;                 ///< The lower id
    BodyId mB;                 ///< The higher id
    CollisionContact mContact; ///< Its normal from B to A, its points on A's and B's surfaces
};
OrientedContact CanonicalContact(const ContactEvent& inEvent);

/// Groups inContacts into batches: each contact turned to the canonical orientation (CanonicalContact) and
/// added to the first batch, in order of creation, of its pair whose time is within inSameStepTime of its
/// own, or to a new one. The batches come in the order of their first contacts. A pair's batches are found
/// through an index (BodyPairIndex), not by scanning every batch: a brick wall bursting reports hundreds of
/// pairs in one step.
std::vector<ContactBatch> GroupContactBatches(std::span<const ContactEvent> inContacts,
                                              double inSameStepTime);

} // namespace crumple::plugin
