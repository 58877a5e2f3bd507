// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EPropMaterial.h>

namespace crumple::fem
{

const char* ToString(EPropMaterial inMaterial)
{
    switch (inMaterial)
    {
    case EPropMaterial::Glass:
        return "Glass";
    case EPropMaterial::Wood:
        return "Wood";
    case EPropMaterial::Brick:
        return "Brick";
    case EPropMaterial::Rubber:
        return "Rubber";
    case EPropMaterial::Steel:
        return "Steel";
    }
    return "unknown";
}

} // namespace crumple::fem
