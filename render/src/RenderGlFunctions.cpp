// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RenderGlFunctions.h"

#include <crumple/gpu/LoadGlFunction.h>

namespace crumple::render
{

namespace
{

// One entry point through the context (see LoadGlFunction).
template <class Function>
void LoadOne(const gpu::EglContext& inContext, const char* inName, Function& ioFunction, std::string& ioMissing)
{
    gpu::LoadGlFunction([&inContext](const char* inProc) { return inContext.GetProcAddress(inProc); }, inName, ioFunction,
                        ioMissing);
}

} // namespace

std::string RenderGlFunctions::Load(const gpu::EglContext& inContext)
{
    std::string missing;
    LoadOne(inContext, "glAttachShader", mAttachShader, missing);
    LoadOne(inContext, "glBindBuffer", mBindBuffer, missing);
    LoadOne(inContext, "glBindFramebuffer", mBindFramebuffer, missing);
    LoadOne(inContext, "glBindRenderbuffer", mBindRenderbuffer, missing);
    LoadOne(inContext, "glBindVertexArray", mBindVertexArray, missing);
    LoadOne(inContext, "glBlitFramebuffer", mBlitFramebuffer, missing);
    LoadOne(inContext, "glBufferData", mBufferData, missing);
    LoadOne(inContext, "glCheckFramebufferStatus", mCheckFramebufferStatus, missing);
    LoadOne(inContext, "glClear", mClear, missing);
    LoadOne(inContext, "glClearColor", mClearColor, missing);
    LoadOne(inContext, "glClearDepth", mClearDepth, missing);
    LoadOne(inContext, "glCompileShader", mCompileShader, missing);
    LoadOne(inContext, "glCreateProgram", mCreateProgram, missing);
    LoadOne(inContext, "glCreateShader", mCreateShader, missing);
    LoadOne(inContext, "glDeleteBuffers", mDeleteBuffers, missing);
    LoadOne(inContext, "glDeleteFramebuffers", mDeleteFramebuffers, missing);
    LoadOne(inContext, "glDeleteProgram", mDeleteProgram, missing);
    LoadOne(inContext, "glDeleteRenderbuffers", mDeleteRenderbuffers, missing);
    LoadOne(inContext, "glDeleteShader", mDeleteShader, missing);
    LoadOne(inContext, "glDeleteVertexArrays", mDeleteVertexArrays, missing);
    LoadOne(inContext, "glDepthFunc", mDepthFunc, missing);
    LoadOne(inContext, "glDisable", mDisable, missing);
    LoadOne(inContext, "glDisableVertexAttribArray", mDisableVertexAttribArray, missing);
    LoadOne(inContext, "glDrawElements", mDrawElements, missing);
    LoadOne(inContext, "glEnable", mEnable, missing);
    LoadOne(inContext, "glEnableVertexAttribArray", mEnableVertexAttribArray, missing);
    LoadOne(inContext, "glFinish", mFinish, missing);
    LoadOne(inContext, "glFramebufferRenderbuffer", mFramebufferRenderbuffer, missing);
    LoadOne(inContext, "glGenBuffers", mGenBuffers, missing);
    LoadOne(inContext, "glGenFramebuffers", mGenFramebuffers, missing);
    LoadOne(inContext, "glGenRenderbuffers", mGenRenderbuffers, missing);
    LoadOne(inContext, "glGenVertexArrays", mGenVertexArrays, missing);
    LoadOne(inContext, "glGetError", mGetError, missing);
    LoadOne(inContext, "glGetIntegerv", mGetIntegerv, missing);
    LoadOne(inContext, "glGetProgramInfoLog", mGetProgramInfoLog, missing);
    LoadOne(inContext, "glGetProgramiv", mGetProgramiv, missing);
    LoadOne(inContext, "glGetShaderInfoLog", mGetShaderInfoLog, missing);
    LoadOne(inContext, "glGetShaderiv", mGetShaderiv, missing);
    LoadOne(inContext, "glGetUniformLocation", mGetUniformLocation, missing);
    LoadOne(inContext, "glLinkProgram", mLinkProgram, missing);
    LoadOne(inContext, "glPixelStorei", mPixelStorei, missing);
    LoadOne(inContext, "glReadBuffer", mReadBuffer, missing);
    LoadOne(inContext, "glReadPixels", mReadPixels, missing);
    LoadOne(inContext, "glRenderbufferStorageMultisample", mRenderbufferStorageMultisample, missing);
    LoadOne(inContext, "glShaderSource", mShaderSource, missing);
    LoadOne(inContext, "glUniform1f", mUniform1f, missing);
    LoadOne(inContext, "glUniform1i", mUniform1i, missing);
    LoadOne(inContext, "glUniform3f", mUniform3f, missing);
    LoadOne(inContext, "glUniform3fv", mUniform3fv, missing);
    LoadOne(inContext, "glUniformMatrix4fv", mUniformMatrix4fv, missing);
    LoadOne(inContext, "glUseProgram", mUseProgram, missing);
    LoadOne(inContext, "glVertexAttrib1f", mVertexAttrib1f, missing);
    LoadOne(inContext, "glVertexAttribPointer", mVertexAttribPointer, missing);
    LoadOne(inContext, "glViewport", mViewport, missing);
    return missing;
}

} // namespace crumple::render
