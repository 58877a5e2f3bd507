// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// The preset materials of destructible props (MakePropMaterialPreset), after the materials the GPU
/// destruction paper (Morris & Anderson, section V) shows: each pairs physical constants with broken-edge
/// parameters.
enum class EPropMaterial : std::uint8_t
{
    Glass,  ///< Soda-lime window glass: brittle, square shards
    Wood,   ///< Softwood planks (spruce / pine along the grain): long sections with splintered long edges
    Brick,  ///< Clay-brick masonry: brick-sized sections with straight edges, breaking at the mortar joints
    Rubber, ///< Soft rubber: large sections, deforms a lot and hardly tears
    Steel,  ///< Structural steel S235: stiff, yields plastically before it tears
};

/// Short name of an EPropMaterial ("Glass", ...), for messages and sample menus; "unknown" otherwise.
CRUMPLE_API const char* ToString(EPropMaterial inMaterial);

} // namespace crumple::fem
