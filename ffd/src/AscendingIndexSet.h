// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Assert.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// A set of indices below a fixed bound, one bit each: inserting is a bit set (a repeat costs nothing more and
/// needs no check), and the members come out ascending in one pass over the words between the smallest and
/// the largest inserted. A dent gathers the triangles and vertices whose normals change this way: each once,
/// in the mesh's memory order, however its cells handed them over. Taking the members empties the set.
class AscendingIndexSet
{
public:
    /// A set over inWords, which must be all zero (empty) and hold 64 bits for every index to be inserted;
    /// the caller keeps them between uses, zero again once the members are taken.
    explicit AscendingIndexSet(std::vector<std::uint64_t>& ioWords) : mWords(ioWords) {}

    void Insert(std::uint32_t inIndex)
    {
        const std::size_t word = inIndex >> 6;
        CRUMPLE_ASSERT(word < mWords.size(), "AscendingIndexSet::Insert: an index past the set's bound");
        mWords[word] |= std::uint64_t{1} << (inIndex & 63);
        mLowWord = word < mLowWord ? word : mLowWord;
        mHighWord = word > mHighWord ? word : mHighWord;
    }

    /// Inserts inIndices, ascending (a cell's list): the bits of one word are gathered in a register and
    /// stored once, instead of each insert waiting on the store of the one before.
    void InsertAscending(const std::uint32_t* inBegin, const std::uint32_t* inEnd)
    {
        if (inBegin == inEnd)
            return;
        CRUMPLE_ASSERT((inEnd[-1] >> 6) < mWords.size(), "AscendingIndexSet::InsertAscending: an index past the set's bound");
        std::size_t word = *inBegin >> 6;
        mLowWord = word < mLowWord ? word : mLowWord;
        std::uint64_t bits = 0;
        for (const std::uint32_t* index = inBegin; index != inEnd; ++index)
        {
            const std::size_t here = *index >> 6;
            if (here != word)
            {
                mWords[word] |= bits;
                word = here;
                bits = 0;
            }
            bits |= std::uint64_t{1} << (*index & 63);
        }
        mWords[word] |= bits;
        mHighWord = word > mHighWord ? word : mHighWord;
    }
    /// Appends the members to ioIndices in ascending order and empties the set.
    void TakeAscending(std::vector<std::uint32_t>& ioIndices);

private:
    std::vector<std::uint64_t>& mWords;
    std::size_t mLowWord = SIZE_MAX; ///< Words outside [mLowWord, mHighWord] are zero; empty when low > high
    std::size_t mHighWord = 0;
};

} // namespace crumple::ffd
