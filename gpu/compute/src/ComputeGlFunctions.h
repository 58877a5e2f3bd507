// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/gpu/EglContext.h>

#include <GL/glcorearb.h>

#include <string>

namespace crumple::gpu
{

/// The GL entry points the compute module uses, loaded through EglContext::GetProcAddress (no global
/// function pointers: each ComputeDevice owns its table).
struct ComputeGlFunctions
{
    PFNGLGETERRORPROC mGetError = nullptr;
    PFNGLFINISHPROC mFinish = nullptr;
    PFNGLCREATESHADERPROC mCreateShader = nullptr;
    PFNGLSHADERSOURCEPROC mShaderSource = nullptr;
    PFNGLCOMPILESHADERPROC mCompileShader = nullptr;
    PFNGLGETSHADERIVPROC mGetShaderiv = nullptr;
    PFNGLGETSHADERINFOLOGPROC mGetShaderInfoLog = nullptr;
    PFNGLDELETESHADERPROC mDeleteShader = nullptr;
    PFNGLCREATEPROGRAMPROC mCreateProgram = nullptr;
    PFNGLATTACHSHADERPROC mAttachShader = nullptr;
    PFNGLLINKPROGRAMPROC mLinkProgram = nullptr;
    PFNGLGETPROGRAMIVPROC mGetProgramiv = nullptr;
    PFNGLGETPROGRAMINFOLOGPROC mGetProgramInfoLog = nullptr;
    PFNGLDELETEPROGRAMPROC mDeleteProgram = nullptr;
    PFNGLUSEPROGRAMPROC mUseProgram = nullptr;
    PFNGLGETUNIFORMLOCATIONPROC mGetUniformLocation = nullptr;
    PFNGLUNIFORM1IPROC mUniform1i = nullptr;
    PFNGLUNIFORM1UIPROC mUniform1ui = nullptr;
    PFNGLUNIFORM1FPROC mUniform1f = nullptr;
    PFNGLUNIFORM3FPROC mUniform3f = nullptr;
    PFNGLDISPATCHCOMPUTEPROC mDispatchCompute = nullptr;
    PFNGLMEMORYBARRIERPROC mMemoryBarrier = nullptr;
    PFNGLGENBUFFERSPROC mGenBuffers = nullptr;
    PFNGLDELETEBUFFERSPROC mDeleteBuffers = nullptr;
    PFNGLBINDBUFFERPROC mBindBuffer = nullptr;
    PFNGLBINDBUFFERBASEPROC mBindBufferBase = nullptr;
    PFNGLBUFFERDATAPROC mBufferData = nullptr;
    PFNGLBUFFERSUBDATAPROC mBufferSubData = nullptr;
    PFNGLGETBUFFERSUBDATAPROC mGetBufferSubData = nullptr;
    PFNGLCOPYBUFFERSUBDATAPROC mCopyBufferSubData = nullptr;

    /// Loads every entry point from inContext (current). Returns the missing names, space separated; empty
    /// on success.
    std::string Load(const EglContext& inContext);
};

} // namespace crumple::gpu
