#pragma once
// Third-party code that can crash instead of failing (OCCT's readers on damaged files, TetGen's
// boundary recovery) runs in a forked child process. A signal there becomes a framefix::Error in
// the caller, whose process (the CLI, a Python interpreter) lives on. fork() is used rather than
// OCCT's signal-to-exception handlers because those cannot make a corrupted heap usable again,
// and TetGen has none; the child's copy-on-write memory makes the start cheap.
#include <functional>
#include <string>
#include <vector>

namespace framefix {

struct IsolatedTask {
    std::string stage;  // the Error's stage
    std::string what;   // "OpenCASCADE's STEP reader on part.step": names the crashing code
    std::string hint;   // what the user can try, ends the crash message
    double timeout_s = 0;  // the child is stopped after this long (a reader looping on a damaged
                           // file); 0 = no limit
};

// Runs work() in a child process and returns the bytes it returned. framefix::Error and
// std::bad_alloc thrown in the child are rethrown here; a signal or an unexpected exit becomes
// Error(task.stage, task.what + " crashed (<signal>); " + task.hint), without "; " for an empty
// hint; so does a child that runs past task.timeout_s, which is killed.
// With isolation off (see isolation_enabled) work() runs in this process.
std::string run_isolated(const IsolatedTask& task, const std::function<std::string()>& work);

// Runs `program` with `args` in a new process and returns what it wrote to its standard output.
// For libraries that cannot run in a forked copy of this process: gmsh's OpenMP hangs in a child
// forked after this process used OpenMP (libgomp's thread pool does not survive fork()). A
// signal, a timeout (task.timeout_s) or an exit code other than 0 become Error as above; a
// program that cannot be started too.
std::string run_program(const IsolatedTask& task, const std::string& program, const std::vector<std::string>& args);

// False when the environment sets FRAMEFIX_ISOLATION=0 (to debug the third-party call in gdb,
// or to measure what the isolation costs).
bool isolation_enabled();

}  // namespace framefix
