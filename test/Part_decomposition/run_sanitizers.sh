#!/usr/bin/env bash
# The whole test suite (and hitops, which the robustness battery runs) built with AddressSanitizer
# and UndefinedBehaviorSanitizer, then run by ctest; any report fails the run.
#
#   test/Part_decomposition/run_sanitizers.sh [BUILD_DIR]     (default: build-asan)
#
# CXX selects the compiler (default c++, i.e. g++ on Debian; clang++ also works). JOBS (default 2)
# is the parallelism of the build and of ctest.
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build-asan}"
jobs="${JOBS:-2}"
# float-cast-overflow is not part of gcc's "undefined"; a double cast to an index is what the
# fuzzer found in the file parsers
flags="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer -g1"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="${CXX:-c++}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined,float-cast-overflow" \
  -DPART_DECOMPOSITION_BUILD_BENCHMARKS=OFF
cmake --build "$build" -j"$jobs"

# halt_on_error: the first report fails the test; the downstream test builds its own
# unsanitized project and is left to the normal run.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
ctest --test-dir "$build" --output-on-failure -j"$jobs" -E downstream_find_package
