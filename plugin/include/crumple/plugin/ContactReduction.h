// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/Collision.h>

#include <cstddef>
#include <vector>

namespace crumple::plugin
{

/// Reduces one body pair's contacts of one step to at most inMaxContacts representatives, in linear time
/// (a mesh-mesh contact can report thousands; the simultaneous impulse solve is cubic in its contacts).
/// The kept set is, in the contact plane (normal: the contacts' mean normal), the extreme contact along
/// each of 8 directions (+-u, +-v and the diagonals), the deepest contact, then farthest-point samples
/// until the budget is used: it spans the same patch, so the pair's impulse and the dent's footprint keep
/// their extent. Deterministic: ties go to the lower index, and the kept contacts keep their order.
/// Sets no larger than inMaxContacts come back unchanged.
/// @param[in] inMaxContacts >= 9 (the extremes and the deepest)
CRUMPLE_API std::vector<CollisionContact> ReduceContacts(const std::vector<CollisionContact>& inContacts, std::size_t inMaxContacts);

} // namespace crumple::plugin
