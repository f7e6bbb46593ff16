#pragma once
// Errors have one home each: bad input is a framefix::Error naming the stage, the number that
// shows it and what to do; our own bugs are InternalError thrown by FF_ASSERT (always on).
#include <stdexcept>
#include <string>

namespace framefix {

class Error : public std::runtime_error {
public:
    Error(std::string stage, const std::string& message);
    const std::string& stage() const { return stage_; }
    const std::string& message() const { return message_; }

private:
    std::string stage_;
    std::string message_;
};

class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

[[noreturn]] void assert_failed(const char* expr, const char* file, int line);

}  // namespace framefix

#define FF_ASSERT(cond) \
    ((cond) ? (void)0 : ::framefix::assert_failed(#cond, __FILE__, __LINE__))
