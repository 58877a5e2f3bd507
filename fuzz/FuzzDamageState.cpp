// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a saved damage state (DamageWorld::SaveDamage's output) loaded into a dented world. A state
// the world refuses must leave it byte-identical: the harness aborts (a finding) when it does not.
#include "FuzzWorld.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    static crumple::fuzz::FuzzWorld world = [] {
        crumple::fuzz::FuzzWorld dented; // built once: a car body with one dent
        dented.Dent();
        return dented;
    }();
    const std::vector<std::byte> before = world.Get().SaveDamage();
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(inData), inSize);
    if (world.Get().LoadDamage(bytes).HasError())
    {
        if (world.Get().SaveDamage() != before)
            std::abort(); // a refused state changed the world
        return 0;
    }
    // Accepted: put the dented state back for the next input.
    if (world.Get().LoadDamage(before).HasError())
        std::abort(); // the world's own state must load
    return 0;
}
