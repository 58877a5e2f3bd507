// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ComputeGlFunctions.h"

#include <crumple/gpu/LoadGlFunction.h>

namespace crumple::gpu
{

namespace
{

// One entry point through the context (see LoadGlFunction).
template <class Function>
void LoadOne(const EglContext& inContext, const char* inName, Function& ioFunction, std::string& ioMissing)
{
    LoadGlFunction([&inContext](const char* inProc) { return inContext.GetProcAddress(inProc); }, inName, ioFunction,
                   ioMissing);
}

} // namespace

std::string ComputeGlFunctions::Load(const EglContext& inContext)
{
    std::string missing;
    LoadOne(inContext, "glGetError", mGetError, missing);
    LoadOne(inContext, "glFinish", mFinish, missing);
    LoadOne(inContext, "glCreateShader", mCreateShader, missing);
    LoadOne(inContext, "glShaderSource", mShaderSource, missing);
    LoadOne(inContext, "glCompileShader", mCompileShader, missing);
    LoadOne(inContext, "glGetShaderiv", mGetShaderiv, missing);
    LoadOne(inContext, "glGetShaderInfoLog", mGetShaderInfoLog, missing);
    LoadOne(inContext, "glDeleteShader", mDeleteShader, missing);
    LoadOne(inContext, "glCreateProgram", mCreateProgram, missing);
    LoadOne(inContext, "glAttachShader", mAttachShader, missing);
    LoadOne(inContext, "glLinkProgram", mLinkProgram, missing);
    LoadOne(inContext, "glGetProgramiv", mGetProgramiv, missing);
    LoadOne(inContext, "glGetProgramInfoLog", mGetProgramInfoLog, missing);
    LoadOne(inContext, "glDeleteProgram", mDeleteProgram, missing);
    LoadOne(inContext, "glUseProgram", mUseProgram, missing);
    LoadOne(inContext, "glGetUniformLocation", mGetUniformLocation, missing);
    LoadOne(inContext, "glUniform1i", mUniform1i, missing);
    LoadOne(inContext, "glUniform1ui", mUniform1ui, missing);
    LoadOne(inContext, "glUniform1f", mUniform1f, missing);
    LoadOne(inContext, "glUniform3f", mUniform3f, missing);
    LoadOne(inContext, "glDispatchCompute", mDispatchCompute, missing);
    LoadOne(inContext, "glMemoryBarrier", mMemoryBarrier, missing);
    LoadOne(inContext, "glGenBuffers", mGenBuffers, missing);
    LoadOne(inContext, "glDeleteBuffers", mDeleteBuffers, missing);
    LoadOne(inContext, "glBindBuffer", mBindBuffer, missing);
    LoadOne(inContext, "glBindBufferBase", mBindBufferBase, missing);
    LoadOne(inContext, "glBufferData", mBufferData, missing);
    LoadOne(inContext, "glBufferSubData", mBufferSubData, missing);
    LoadOne(inContext, "glGetBufferSubData", mGetBufferSubData, missing);
    LoadOne(inContext, "glCopyBufferSubData", mCopyBufferSubData, missing);
    return missing;
}

} // namespace crumple::gpu
