#pragma once
// OCCT reports failures as Standard_Failure, which is not a std::exception. Every call into
// OpenCASCADE that can throw goes through occt_call, so callers only ever see framefix::Error.
#include <string>
#include <utility>

#include <Standard_Failure.hxx>

#include "framefix/core/error.h"

namespace framefix {

inline std::string occt_message(const Standard_Failure& failure) {
    std::string text = failure.DynamicType()->Name();
    const char* detail = failure.GetMessageString();
    if (detail && *detail) text += std::string(" (") + detail + ")";
    return text;
}

// Runs f(); an OCCT failure becomes Error(stage, what + ": OpenCASCADE " + detail).
template <class F>
auto occt_call(const std::string& stage, const std::string& what, F&& f) -> decltype(f()) {
    try {
        return std::forward<F>(f)();
    } catch (const Standard_Failure& failure) {
        throw Error(stage, what + ": OpenCASCADE raised " + occt_message(failure));
    }
}

}  // namespace framefix
