// run_isolated and run_program: the worker's result comes back; its errors, crashes and hangs
// become Errors here, and this process goes on.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <new>
#include <thread>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/core/isolation.h"

namespace framefix {
namespace {

const IsolatedTask kTask{"mesh", "the test worker", "try something else"};

std::string message_of(const std::function<std::string()>& work, IsolatedTask task = kTask) {
    try {
        run_isolated(task, work);
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), task.stage);
        return e.message();
    }
    ADD_FAILURE() << "no Error";
    return "";
}

TEST(Isolation, ReturnsTheWorkersBytes) {
    const std::string big(5'000'000, 'x');  // more than a pipe holds: the parent reads while it writes
    EXPECT_EQ(run_isolated(kTask, [&] { return std::string("a\0b", 3) + big; }), std::string("a\0b", 3) + big);
}

TEST(Isolation, TheWorkerCannotChangeThisProcess) {
    int value = 1;
    run_isolated(kTask, [&] {
        value = 2;
        return std::string();
    });
    EXPECT_EQ(value, 1);
}

TEST(Isolation, AnErrorInTheWorkerIsRethrownWithItsStage) {
    try {
        run_isolated(kTask, []() -> std::string { throw Error("load", "bad file; re-export it"); });
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), "load");
        EXPECT_EQ(e.message(), "bad file; re-export it");
    }
}

TEST(Isolation, OutOfMemoryInTheWorkerIsBadAlloc) {
    EXPECT_THROW(run_isolated(kTask, []() -> std::string { throw std::bad_alloc(); }), std::bad_alloc);
}

TEST(Isolation, ACrashBecomesAnErrorNamingTheSignalAndTheHint) {
    const std::string m = message_of([]() -> std::string {
        std::raise(SIGSEGV);
        return "";
    });
    EXPECT_EQ(m, "the test worker crashed (Segmentation fault); try something else");
    EXPECT_NE(message_of([]() -> std::string { std::abort(); }).find("crashed (Aborted)"), std::string::npos);
}

TEST(Isolation, AnExitInTheWorkerIsReported) {
    EXPECT_NE(message_of([]() -> std::string { std::exit(7); }).find("stopped unexpectedly (exit code 7)"),
              std::string::npos);
}

TEST(Isolation, AHangIsStoppedAfterTheTimeout) {
    IsolatedTask task = kTask;
    task.timeout_s = 0.3;
    const auto t0 = std::chrono::steady_clock::now();
    const std::string m = message_of(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return std::string();
        },
        task);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
    EXPECT_EQ(m, "the test worker did not finish within 0.3 s; try something else");
}

std::string program_message(const std::string& program, const std::vector<std::string>& args) {
    try {
        run_program(kTask, program, args);
    } catch (const Error& e) {
        EXPECT_EQ(e.stage(), kTask.stage);
        return e.message();
    }
    ADD_FAILURE() << "no Error";
    return "";
}

TEST(Program, ReturnsWhatItWrote) {
    EXPECT_EQ(run_program(kTask, "/bin/sh", {"-c", "printf 'a\\0b'"}), std::string("a\0b", 3));
}

TEST(Program, ACrashAnExitAndAMissingProgramAreErrors) {
    EXPECT_EQ(program_message("/bin/sh", {"-c", "kill -SEGV $$"}), "the test worker crashed (Segmentation fault); try something else");
    EXPECT_NE(program_message("/bin/sh", {"-c", "exit 3"}).find("stopped unexpectedly (exit code 3)"), std::string::npos);
    EXPECT_EQ(program_message("/nonexistent/framefix-hxt", {}), "cannot run /nonexistent/framefix-hxt; try something else");
}

TEST(Program, AHangIsStoppedAfterTheTimeout) {
    IsolatedTask task = kTask;
    task.timeout_s = 0.3;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        run_program(task, "/bin/sleep", {"30"});
        ADD_FAILURE() << "no Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.message(), "the test worker did not finish within 0.3 s; try something else");
    }
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
}

TEST(Isolation, CanBeTurnedOffToDebug) {
    setenv("FRAMEFIX_ISOLATION", "0", 1);
    int value = 1;
    run_isolated(kTask, [&] {
        value = 2;
        return std::string();
    });
    unsetenv("FRAMEFIX_ISOLATION");
    EXPECT_EQ(value, 2);  // ran here
}

TEST(Error, MessagesStayOnePrintableUtf8Line) {
    const Error e("load", std::string("found '0.86\x97\x01' in Teil_\xc3\xbc.step\n"));
    EXPECT_EQ(e.message(), "found '0.86?" "?' in Teil_\xc3\xbc.step?");
    EXPECT_EQ(std::string(e.what()), "load: " + e.message());
}

}  // namespace
}  // namespace framefix
