// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/ESurfaceFormat.h>

namespace crumple::fem
{

const char* ToString(ESurfaceFormat inFormat)
{
    switch (inFormat)
    {
    case ESurfaceFormat::Obj:
        return "Obj";
    case ESurfaceFormat::Ply:
        return "Ply";
    }
    return "unknown";
}

const char* SurfaceFileExtension(ESurfaceFormat inFormat)
{
    switch (inFormat)
    {
    case ESurfaceFormat::Obj:
        return "obj";
    case ESurfaceFormat::Ply:
        return "ply";
    }
    return "unknown";
}

} // namespace crumple::fem
