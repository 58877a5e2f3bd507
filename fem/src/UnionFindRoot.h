// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace crumple::fem
{

/// Root of inItem in a union-find forest stored as parent indices, halving the path on the way (private to
/// the fracture code). Callers join by making the larger root point to the smaller, so a root is always the
/// smallest item of its set: the deterministic representative.
inline int UnionFindRoot(std::vector<int>& ioParent, int inItem)
{
    while (ioParent[inItem] != inItem)
    {
        ioParent[inItem] = ioParent[ioParent[inItem]];
        inItem = ioParent[inItem];
    }
    return inItem;
}

} // namespace crumple::fem
