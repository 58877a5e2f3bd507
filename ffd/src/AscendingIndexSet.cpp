// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "AscendingIndexSet.h"

#include <bit>

namespace crumple::ffd
{

void AscendingIndexSet::TakeAscending(std::vector<std::uint32_t>& ioIndices)
{
    if (mLowWord > mHighWord)
        return;
    std::size_t count = 0;
    for (std::size_t w = mLowWord; w <= mHighWord; ++w)
        count += static_cast<std::size_t>(std::popcount(mWords[w]));
    const std::size_t first = ioIndices.size();
    ioIndices.resize(first + count);
    std::uint32_t* out = ioIndices.data() + first;
    for (std::size_t w = mLowWord; w <= mHighWord; ++w)
    {
        // intent: lowest set bit first, cleared as it is taken
        for (std::uint64_t bits = mWords[w]; bits != 0; bits &= bits - 1)
            *out++ = static_cast<std::uint32_t>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
        mWords[w] = 0;
    }
    mLowWord = SIZE_MAX;
    mHighWord = 0;
}

} // namespace crumple::ffd
