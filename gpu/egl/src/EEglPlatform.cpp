// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/EEglPlatform.h>

namespace crumple::gpu
{

const char* ToString(EEglPlatform inPlatform)
{
    switch (inPlatform)
    {
    case EEglPlatform::Any:
        return "any";
    case EEglPlatform::Device:
        return "device";
    case EEglPlatform::Surfaceless:
        return "surfaceless";
    }
    return "unknown";
}

} // namespace crumple::gpu
