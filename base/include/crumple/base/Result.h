// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <string>
#include <utility>
#include <variant>

namespace crumple
{

/// What kind of failure an API call reports. Each value says what the caller should fix.
enum class EError
{
    InvalidArgument,    ///< A parameter is out of its documented range (negative mass, < 4 controls): fix the call.
    NonFinite,          ///< A NaN or Inf was passed: the caller's simulation has already diverged.
    OutOfRange,         ///< An index or handle does not name an existing object.
    DegenerateGeometry, ///< A volume, mesh or frame has (near) zero size or is not a rotation.
    CorruptData,        ///< A file or buffer failed its checksum or is truncated.
    VersionMismatch,    ///< A file was written by an incompatible format version.
    StateMismatch,      ///< Saved data does not fit the objects it is loaded into.
    IoError,            ///< The operating system refused a read or write.
};

/// Short name of an EError, for messages.
CRUMPLE_API const char* ToString(EError inError);

/// An error: its kind and a message that names the offending field and value.
struct CRUMPLE_API Error
{
    EError mCode = EError::InvalidArgument; ///< What went wrong
    std::string mMessage;                   ///< Human-readable detail, e.g. "BodySettings.mMass = -1 kg must be >= 0"
};

/// A value or an error (Jolt's Result<T>). Functions that can fail on user input return this; nothing
/// throws across the API. [[nodiscard]] so a refused input cannot be ignored silently.
template <class T>
class [[nodiscard]] Result
{
public:
    /// Success
    Result(T inValue) : mData(std::in_place_index<0>, std::move(inValue)) {}
    /// Failure
    Result(Error inError) : mData(std::in_place_index<1>, std::move(inError)) {}

    /// True when a value is held
    bool IsValid() const { return mData.index() == 0; }
    /// True when an error is held
    bool HasError() const { return mData.index() == 1; }
    explicit operator bool() const { return IsValid(); }

    /// The value; only when IsValid()
    T& Get() & { return std::get<0>(mData); }
    const T& Get() const& { return std::get<0>(mData); }
    T&& Get() && { return std::get<0>(std::move(mData)); }
    /// The error; only when HasError()
    const Error& GetError() const { return std::get<1>(mData); }

private:
    std::variant<T, Error> mData;
};

/// Result of an operation that produces no value.
class [[nodiscard]] CRUMPLE_API Status
{
public:
    /// Success
    Status() = default;
    /// Failure
    Status(Error inError) : mError(std::move(inError)), mFailed(true) {}
    /// Success as a named value, for readability at return sites
    static Status Ok() { return {}; }

    bool IsValid() const { return !mFailed; }
    bool HasError() const { return mFailed; }
    explicit operator bool() const { return IsValid(); }
    /// The error; only when HasError()
    const Error& GetError() const { return mError; }

private:
    Error mError;
    bool mFailed = false;
};

/// Builds an Error; a shorthand at return sites.
inline Error MakeError(EError inCode, std::string inMessage)
{
    return Error{inCode, std::move(inMessage)};
}

} // namespace crumple
