// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// BodyPairIndex: the flat table of body pairs a step's solve finds its batches and impact memories by.
#include "BodyPairIndex.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <utility>

using namespace crumple;
using namespace crumple::plugin;

TEST_CASE("A body pair index finds every pair it holds and no other", "[plugin][burst]")
{
    // 2,000 pairs filling the table to its bound (half its slots), ids dense and sparse, pairs i and i +
    // 1,000 of the same slots told apart only by their generations; the pairs turned round, and pairs never
    // inserted, are not found
    BodyPairIndex index;
    constexpr std::uint32_t cPairs = 2000;
    index.Reset(cPairs);
    const auto pair_of = [](std::uint32_t inI) {
        return std::pair{BodyId{inI % 50, inI / 1000}, BodyId{50 + (inI % 1000u) * 7919u % 100000u, inI % 3}};
    };
    for (std::uint32_t i = 0; i < cPairs; ++i)
    {
        const auto [a, b] = pair_of(i);
        const auto [value, inserted] = index.TryInsert(a, b, i);
        REQUIRE(inserted);
        CHECK(value == i);
    }
    std::uint32_t found = 0, misplaced = 0, turned = 0;
    for (std::uint32_t i = 0; i < cPairs; ++i)
    {
        const auto [a, b] = pair_of(i);
        found += index.Find(a, b) == i ? 1 : 0;
        misplaced += index.TryInsert(a, b, cPairs + i).first == i ? 0 : 1;
        turned += index.Find(b, a) == BodyPairIndex::cNone ? 0 : 1;
    }
    CHECK(found == cPairs);
    CHECK(misplaced == 0);
    CHECK(turned == 0);
    CHECK(index.Find(BodyId{0, 7}, BodyId{50, 0}) == BodyPairIndex::cNone);
    CHECK(BodyPairIndex().Find(BodyId{0, 0}, BodyId{1, 0}) == BodyPairIndex::cNone);
}
