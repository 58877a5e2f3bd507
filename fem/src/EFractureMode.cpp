// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EFractureMode.h>

namespace crumple::fem
{

const char* ToString(EFractureMode inMode)
{
    switch (inMode)
    {
    case EFractureMode::CrackPlane:
        return "CrackPlane";
    case EFractureMode::DetachGroup:
        return "DetachGroup";
    }
    return "unknown";
}

} // namespace crumple::fem
