#include "framefix/core/error.h"

namespace framefix {

Error::Error(std::string stage, const std::string& message)
    : std::runtime_error(stage + ": " + message), stage_(std::move(stage)), message_(message) {}

void assert_failed(const char* expr, const char* file, int line) {
    throw InternalError(std::string("internal error: ") + expr + " failed at " + file + ":" +
                        std::to_string(line));
}

}  // namespace framefix
