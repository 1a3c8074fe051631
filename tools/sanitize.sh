#!/usr/bin/env bash
# Builds the host-free libraries and their unit tests with AddressSanitizer and
# UndefinedBehaviorSanitizer in build-asan/, and runs them with CTest: any memory error, leak or
# undefined behaviour fails the test that triggers it. The MeshLab plugins are not built.
#
#   tools/sanitize.sh               configure, build and run every unit test
#   tools/sanitize.sh -R hostile    extra arguments go to ctest
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${VOXELFAIR_ASAN_BUILD_DIR:-$here/build-asan}
jobs=$(nproc 2>/dev/null || echo 2)

# The project's packages (idempotent: installs only what is missing).
bash "$here/voxelfair.sh" setup

# RelWithDebInfo: optimised enough for the larger tests, with line numbers in reports.
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DVOXELFAIR_SANITIZE=address,undefined \
  -DVOXELFAIR_BUILD_PLUGINS=OFF -DVOXELFAIR_BUILD_BENCHMARKS=OFF -DVOXELFAIR_BUILD_TESTS=ON >/dev/null
cmake --build "$build" -j"$jobs"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Every test takes seconds even under the sanitizers; one that runs for minutes hangs.
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 300 "$@"
