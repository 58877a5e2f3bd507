// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/gpu/EglContext.h>

#include <string>

namespace crumple::gpu
{

/// Loads one GL entry point into ioFunction (a PFNGL...PROC) with inLoad (a callable taking the name and
/// returning EglContext::GlProc); when the driver lacks it, appends its name to ioMissing (space separated),
/// so a loader can report every missing entry point at once.
template <class Load, class Function>
void LoadGlFunction(const Load& inLoad, const char* inName, Function& ioFunction, std::string& ioMissing)
{
    ioFunction = reinterpret_cast<Function>(inLoad(inName));
    if (ioFunction == nullptr)
    {
        if (!ioMissing.empty())
            ioMissing += ' ';
        ioMissing += inName;
    }
}

} // namespace crumple::gpu
