// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Result.h>

namespace crumple
{

const char* ToString(EError inError)
{
    switch (inError)
    {
    case EError::InvalidArgument:
        return "invalid argument";
    case EError::NonFinite:
        return "non-finite value";
    case EError::OutOfRange:
        return "out of range";
    case EError::DegenerateGeometry:
        return "degenerate geometry";
    case EError::CorruptData:
        return "corrupt data";
    case EError::VersionMismatch:
        return "version mismatch";
    case EError::StateMismatch:
        return "state mismatch";
    case EError::IoError:
        return "i/o error";
    }
    return "unknown error";
}

} // namespace crumple
