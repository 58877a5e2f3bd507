// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box: the bit set a dent gathers its triangles and normals in hands back each inserted index once, in
// ascending order, and is empty (its words zero) afterwards, so the next dent starts clean.
#include "AscendingIndexSet.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

using namespace crumple::ffd;

TEST_CASE("An ascending index set gives back its members once each, ascending, and empties", "[ffd]")
{
    std::mt19937_64 random(9);
    for (std::uint32_t bound : {1u, 63u, 64u, 65u, 1000u, 50000u})
    {
        std::vector<std::uint64_t> words((bound + 63) / 64, 0);
        for (int round = 0; round < 20; ++round)
        {
            // intent: clustered and scattered inserts with repeats, the first and the last index included
            std::set<std::uint32_t> reference;
            AscendingIndexSet set(words);
            const int count = static_cast<int>(random() % 300);
            const std::uint32_t centre = static_cast<std::uint32_t>(random() % bound);
            for (int i = 0; i < count; ++i)
            {
                std::uint32_t index = static_cast<std::uint32_t>(random() % bound);
                if (i % 2 == 0)
                    index = std::min(bound - 1, centre + static_cast<std::uint32_t>(random() % 70));
                if (i == 0)
                    index = 0;
                if (i == 1)
                    index = bound - 1;
                set.Insert(index);
                set.Insert(index);
                reference.insert(index);
            }
            std::vector<std::uint32_t> taken{7u}; // appended after what is there
            set.TakeAscending(taken);
            std::vector<std::uint32_t> expected{7u};
            expected.insert(expected.end(), reference.begin(), reference.end());
            CHECK(taken == expected);
            CHECK(std::all_of(words.begin(), words.end(), [](std::uint64_t inWord) { return inWord == 0; }));
            // Taking again gives nothing.
            std::vector<std::uint32_t> again;
            set.TakeAscending(again);
            CHECK(again.empty());
        }
    }
}
