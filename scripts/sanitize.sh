#!/usr/bin/env bash
# The C++ unit tests and the CLI tests under AddressSanitizer + UndefinedBehaviorSanitizer, in
# asan-build/ (not build*: the workbench would find it as a backend). Run by hand, once per
# session, not in CI: a full instrumented build plus the tests take about half an hour on 2 cores.
# Extra arguments go to ctest (e.g. -R Isolation).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
[ -f asan-build/CMakeCache.txt ] || cmake -S . -B asan-build -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DFRAMEFIX_SANITIZE=ON -DFRAMEFIX_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build asan-build -j"$(nproc)"
# Leaks are not checked: OCCT keeps its handle caches until exit. Any UB report fails the test.
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd asan-build
ctest -L "backend|cli" -LE "workbench|gui" --output-on-failure -j"$(nproc)" "$@"
