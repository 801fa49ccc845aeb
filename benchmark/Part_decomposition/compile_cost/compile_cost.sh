#!/usr/bin/env bash
# Compile cost of the package for a user: wall time and peak memory of compiling the decompose
# example (one translation unit including decompose.h and the reader) as a program linking the
# target CGAL::Part_decomposition compiles it (the pipeline and the reader in the library) and as
# one linking CGAL::Part_decomposition_headers compiles it (header-only), and, in the same run and
# with the same flags (CMake's Release flags and definitions of the examples), the reference
# program of CGAL's SDF segmentation. Run on an idle machine (each run prints the load average it started with):
#
#   benchmark/Part_decomposition/compile_cost/compile_cost.sh [RUNS]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../../.." && pwd)
runs=${1:-3}
flags="-std=gnu++17 -O3 -DNDEBUG -frounding-math -DBOOST_ALL_NO_LIB -DCGAL_EIGEN3_ENABLED -DCGAL_LINKED_WITH_TBB -DCGAL_USE_GMPXX=1 -DNOMINMAX -I$top/include -isystem /usr/include/eigen3"
flags="$flags -DPD_EXAMPLE_DATA_DIR=\"$top/examples/Part_decomposition/data\""
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
measure() { # name source [extra flags]
  for i in $(seq "$runs"); do
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -f "%e %U %M" -o "$work/t" c++ $flags ${3:-} -c "$2" -o "$work/o.o"
    read -r s user kb < "$work/t"
    # the CPU time is less sensitive than the wall time to other work on the machine
    echo "$1 run $i: $s s ($user s CPU), $((kb / 1024)) MB, load $load before"
  done
}
echo "$(c++ --version | head -1); flags: $flags"
measure "decompose_example.cpp, CGAL::Part_decomposition" "$top/examples/Part_decomposition/decompose_example.cpp" \
  -DCGAL_PART_DECOMPOSITION_COMPILED_LIBRARY
measure "decompose_example.cpp, CGAL::Part_decomposition_headers" "$top/examples/Part_decomposition/decompose_example.cpp"
measure "sdf_segmentation_reference.cpp" "$here/sdf_segmentation_reference.cpp"
