// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "GlFunctions.h"

#include <crumple/gpu/LoadGlFunction.h>

namespace crumple::gpu
{

std::string GlFunctions::Load(EglContext::GlProc (*inLoad)(const char*))
{
    std::string missing;
    LoadGlFunction(inLoad, "glGetString", mGetString, missing);
    LoadGlFunction(inLoad, "glGetIntegerv", mGetIntegerv, missing);
    LoadGlFunction(inLoad, "glGetError", mGetError, missing);
    LoadGlFunction(inLoad, "glFinish", mFinish, missing);
    return missing;
}

} // namespace crumple::gpu
