// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// A value per directed edge, kept in the start vertex's short list of outgoing edges and found by scanning
/// it: a mesh vertex has a handful, so this beats a hash map of edges (the flips' lookups were most of their
/// time in one). Erase swaps the last entry in, so an entry's place in its list is not stable.
template <class Value>
class OutgoingEdges
{
public:
    explicit OutgoingEdges(std::size_t inVertexCount) : mOut(inVertexCount) {}

    /// The edge's value, or null when no entry has it
    Value* Find(std::uint32_t inFrom, std::uint32_t inTo)
    {
        for (Entry& e : mOut[inFrom])
            if (e.mTo == inTo)
                return &e.mValue;
        return nullptr;
    }
    const Value* Find(std::uint32_t inFrom, std::uint32_t inTo) const
    {
        for (const Entry& e : mOut[inFrom])
            if (e.mTo == inTo)
                return &e.mValue;
        return nullptr;
    }

    /// Room for inCount entries from inFrom, so that adding them allocates once
    void Reserve(std::uint32_t inFrom, std::size_t inCount) { mOut[inFrom].reserve(inCount); }

    /// Adds an entry for an edge that has none (Find returned null)
    void Insert(std::uint32_t inFrom, std::uint32_t inTo, const Value& inValue) { mOut[inFrom].push_back({inTo, inValue}); }

    /// Removes the edge's entry, if any
    void Erase(std::uint32_t inFrom, std::uint32_t inTo)
    {
        std::vector<Entry>& out = mOut[inFrom];
        for (std::size_t i = 0; i < out.size(); ++i)
            if (out[i].mTo == inTo)
            {
                out[i] = out.back();
                out.pop_back();
                return;
            }
    }

private:
    struct Entry
    {
        std::uint32_t mTo;
        Value mValue;
    };
    std::vector<std::vector<Entry>> mOut; ///< Per start vertex, its outgoing edges
};

} // namespace crumple::ffd
