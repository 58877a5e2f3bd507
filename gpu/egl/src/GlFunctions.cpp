// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "GlFunctions.h"

namespace crumple::gpu
{

namespace
{

/// Loads one entry point into ioFunction and records its name in ioMissing when absent.
template <class Function>
void LoadOne(EglContext::GlProc (*inLoad)(const char*), const char* inName, Function& ioFunction,
             std::string& ioMissing)
{
    ioFunction = reinterpret_cast<Function>(inLoad(inName));
    if (ioFunction == nullptr)
    {
        if (!ioMissing.empty())
            ioMissing += ' ';
        ioMissing += inName;
    }
}

} // namespace

std::string GlFunctions::Load(EglContext::GlProc (*inLoad)(const char*))
{
    std::string missing;
    LoadOne(inLoad, "glGetString", mGetString, missing);
    LoadOne(inLoad, "glGetIntegerv", mGetIntegerv, missing);
    LoadOne(inLoad, "glGetError", mGetError, missing);
    LoadOne(inLoad, "glFinish", mFinish, missing);
    return missing;
}

} // namespace crumple::gpu
