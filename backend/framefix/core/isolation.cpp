#include "framefix/core/isolation.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <optional>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "framefix/core/error.h"

namespace framefix {
namespace {

// First byte of the child's message: what follows it.
constexpr char kResult = 'R', kError = 'E', kNoMemory = 'M', kOther = 'X';

void write_all(int fd, const std::string& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;  // the parent is gone: nobody to tell
        done += size_t(n);
    }
}

using Clock = std::chrono::steady_clock;

// Reads until the child closes the pipe; false when `deadline` passed first.
bool read_all(int fd, std::string& bytes, std::optional<Clock::time_point> deadline) {
    char buffer[1 << 16];
    for (;;) {
        int wait_ms = -1;
        if (deadline) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - Clock::now()).count();
            if (left <= 0) return false;
            wait_ms = int(std::min<long long>(left, 1 << 30));
        }
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, wait_ms);
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) return false;
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;
        bytes.append(buffer, size_t(n));
    }
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g s", s);
    return text;
}

// The host's crash handlers (Python's faulthandler, FreeCAD's, which throws from the handler)
// must not run in the worker: a crash there is only the signal the parent reads.
void default_crash_signals() {
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
}

// In the child: run, send the outcome, leave without running the parent's exit handlers.
[[noreturn]] void child(int fd, const std::function<std::string()>& work) {
    default_crash_signals();
    std::string message;
    try {
        message = kResult + work();
    } catch (const Error& e) {
        message = kError + e.stage() + '\0' + e.message();
    } catch (const std::bad_alloc&) {
        message = std::string(1, kNoMemory);
    } catch (const std::exception& e) {
        message = kOther + std::string(e.what());
    } catch (...) {
        message = kOther + std::string("unknown exception");
    }
    write_all(fd, message);
    ::close(fd);
    ::_exit(0);
}

std::string hint(const IsolatedTask& task) { return task.hint.empty() ? "" : "; " + task.hint; }

// A signal, an exit code other than 0, or no answer at all, as an Error.
void check_exit(const IsolatedTask& task, int status, bool answered) {
    if (WIFSIGNALED(status))
        throw Error(task.stage, task.what + " crashed (" + strsignal(WTERMSIG(status)) + ")" + hint(task));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !answered)
        throw Error(task.stage, task.what + " stopped unexpectedly (exit code " +
                                    std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")" + hint(task));
}

std::string outcome(const IsolatedTask& task, const std::string& message, int status) {
    check_exit(task, status, !message.empty());
    switch (message[0]) {
        case kResult: return message.substr(1);
        case kError: {
            const size_t cut = message.find('\0', 1);
            throw Error(message.substr(1, cut - 1), message.substr(cut + 1));
        }
        case kNoMemory: throw std::bad_alloc();
        default: throw Error(task.stage, task.what + " failed: " + message.substr(1) + hint(task));
    }
}

// Reads the child's pipe until it closes, waits for the child, and kills it past the deadline.
// Returns the bytes and the wait status.
std::pair<std::string, int> collect(const IsolatedTask& task, pid_t pid, int fd) {
    std::string message;
    std::optional<Clock::time_point> deadline;
    if (task.timeout_s > 0)
        deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(task.timeout_s));
    const bool finished = read_all(fd, message, deadline);
    ::close(fd);
    if (!finished) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!finished)
        throw Error(task.stage, task.what + " did not finish within " + seconds(task.timeout_s) + hint(task));
    return {std::move(message), status};
}

// Exit code of a child whose exec failed (the shell's "command not found").
constexpr int kCannotExec = 127;

}  // namespace

bool isolation_enabled() {
    const char* v = std::getenv("FRAMEFIX_ISOLATION");
    return !(v && std::strcmp(v, "0") == 0);
}

std::string run_program(const IsolatedTask& task, const std::string& program, const std::vector<std::string>& args) {
    std::vector<std::string> all = {program};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    int fds[2];
    if (::pipe(fds) != 0) throw Error(task.stage, std::string("cannot create a pipe: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw Error(task.stage, std::string("cannot start ") + program + ": " + std::strerror(errno));
    }
    if (pid == 0) {
        ::dup2(fds[1], STDOUT_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        ::execv(program.c_str(), argv.data());
        ::_exit(kCannotExec);
    }
    ::close(fds[1]);
    const auto [output, status] = collect(task, pid, fds[0]);
    if (WIFEXITED(status) && WEXITSTATUS(status) == kCannotExec) throw Error(task.stage, "cannot run " + program + hint(task));
    check_exit(task, status, true);
    return output;
}

std::string run_isolated(const IsolatedTask& task, const std::function<std::string()>& work) {
    if (!isolation_enabled()) return work();
    // What this process has buffered must not be written twice: by the worker too, if a library
    // there flushes stdout.
    std::fflush(nullptr);
    int fds[2];
    if (::pipe(fds) != 0) throw Error(task.stage, std::string("cannot create a pipe: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw Error(task.stage, std::string("cannot start a worker process: ") + std::strerror(errno) +
                                    "; free some memory or set FRAMEFIX_ISOLATION=0");
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], work);
    }
    ::close(fds[1]);
    const auto [message, status] = collect(task, pid, fds[0]);
    return outcome(task, message, status);
}

}  // namespace framefix
