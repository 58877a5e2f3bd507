// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/IsolatedCall.h>

#include <cmath>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/resource.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

#include <cerrno>
#include <chrono>
#include <cstring>
#endif

namespace crumple
{

namespace
{

// The child's answer: u8 1 and the bytes, or u8 0, u8 error code and the message.
std::vector<std::byte> EncodeAnswer(const Result<std::vector<std::byte>>& inResult)
{
    ByteWriter writer;
    if (inResult.IsValid())
    {
        writer.WriteU8(1);
        writer.WriteU64(inResult.Get().size());
        writer.WriteBytes(inResult.Get());
    }
    else
    {
        writer.WriteU8(0);
        writer.WriteU8(static_cast<std::uint8_t>(inResult.GetError().mCode));
        const std::string& message = inResult.GetError().mMessage;
        writer.WriteU64(message.size());
        writer.WriteBytes(std::as_bytes(std::span(message.data(), message.size())));
    }
    return writer.GetBytes();
}

Result<std::vector<std::byte>> DecodeAnswer(std::span<const std::byte> inBytes, const std::string& inWhat)
{
    ByteReader reader(inBytes);
    const std::uint8_t ok = reader.ReadU8();
    if (ok == 1)
    {
        const std::uint64_t size = reader.ReadU64();
        if (reader.Failed() || size != reader.Remaining())
            return MakeError(EError::CorruptData, inWhat + ": the isolated reader's answer is truncated");
        return std::vector<std::byte>(inBytes.end() - static_cast<std::ptrdiff_t>(size), inBytes.end());
    }
    const std::uint8_t code = reader.ReadU8();
    const std::uint64_t size = reader.ReadU64();
    if (ok != 0 || reader.Failed() || size != reader.Remaining() || code > static_cast<std::uint8_t>(EError::IoError))
        return MakeError(EError::CorruptData, inWhat + ": the isolated reader's answer is malformed");
    const auto* text = reinterpret_cast<const char*>(inBytes.data() + (inBytes.size() - size));
    return MakeError(static_cast<EError>(code), std::string(text, size));
}

} // namespace

Result<std::vector<std::byte>> RunIsolated(const std::function<Result<std::vector<std::byte>>()>& inWork,
                                           double inTimeout, const std::string& inWhat)
{
    // intent: bounded so that the CPU limit's integer seconds hold it (1e20 s became a limit of 1 s)
    if (!(inTimeout > 0.0 && inTimeout <= cMaxIsolatedTimeout))
        return MakeError(EError::InvalidArgument, inWhat + ": the isolated reader's timeout must be in (0, 1e6] s");
#if defined(__unix__) || defined(__APPLE__)
    int channel[2];
    if (pipe(channel) != 0)
        return MakeError(EError::IoError, inWhat + ": cannot create a pipe: " + std::strerror(errno));
    const pid_t parent = getpid();
    const pid_t child = fork();
    if (child < 0)
    {
        close(channel[0]);
        close(channel[1]);
        return MakeError(EError::IoError, inWhat + ": cannot start the isolated reader: " + std::strerror(errno));
    }
    if (child == 0)
    {
        close(channel[0]);
        // A child must not outlive its work: killed when the caller dies (Linux), and by its own CPU limit
        // (a looping parser whose caller is gone would otherwise spin forever).
#if defined(__linux__)
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
            _exit(1); // the caller died before the line above
#endif
        const rlim_t seconds = static_cast<rlim_t>(std::ceil(inTimeout)) + 1;
        const rlimit cpu{seconds, seconds + 1};
        setrlimit(RLIMIT_CPU, &cpu);
        // The child is expendable: a fatal signal ends it (the caller reads the signal), whatever handlers
        // the caller installed (a crash reporter, a sanitizer, a fuzzer), and it prints nothing.
        for (int fatal : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGTRAP})
            signal(fatal, SIG_DFL);
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
        {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            close(null);
        }
        const std::vector<std::byte> answer = EncodeAnswer(inWork());
        std::size_t written = 0;
        while (written < answer.size())
        {
            const ssize_t n = write(channel[1], answer.data() + written, answer.size() - written);
            if (n <= 0 && errno != EINTR)
                _exit(1);
            written += n > 0 ? static_cast<std::size_t>(n) : 0;
        }
        _exit(0); // no destructors, no atexit handlers of the caller's copy
    }
    close(channel[1]);

    // Read until the child closes its end, or the deadline.
    std::vector<std::byte> answer;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(inTimeout);
    bool timed_out = false;
    for (;;)
    {
        const double left = std::chrono::duration<double, std::milli>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0.0)
        {
            timed_out = true;
            break;
        }
        pollfd readable{channel[0], POLLIN, 0};
        const int ready = poll(&readable, 1, static_cast<int>(std::min(left, 1000.0)) + 1);
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            continue;
        std::byte buffer[65536];
        const ssize_t n = read(channel[0], buffer, sizeof(buffer));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break; // end of file: the child closed the pipe (done or dead)
        answer.insert(answer.end(), buffer, buffer + n);
    }
    close(channel[0]);
    if (timed_out)
        kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR)
    {
    }
    if (timed_out)
        return MakeError(EError::CorruptData, inWhat + ": reading took longer than " + std::to_string(inTimeout) +
                                                  " s and was stopped (a malformed file can make the parser loop)");
    if (WIFSIGNALED(status))
        return MakeError(EError::CorruptData, inWhat + ": the parser crashed on it (signal " +
                                                  std::to_string(WTERMSIG(status)) + "): the file is malformed");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return MakeError(EError::CorruptData, inWhat + ": the isolated reader failed (exit " +
                                                  std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
    return DecodeAnswer(answer, inWhat);
#else
    (void)inTimeout;
    (void)inWhat;
    return inWork();
#endif
}

} // namespace crumple
