#!/usr/bin/env bash
# What `hitops --batch --report` (a thumbnail per mesh and report.html) costs on top of the batch:
# RUNS interleaved runs of the same batch with and without --report, each into an empty folder, and
# the ratio of the medians. Run it when nothing else is compiling (pgrep -c cc1plus gives 0).
#
# usage: benchmark/Part_decomposition/report_cost.sh [MESH_DIR]
# environment: HITOPS (default build/bin/hitops), RUNS (default 3), THREADS (default 2),
#              WORK (default: a temporary folder, removed at the end)
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
MESHES=${1:-$ROOT/../shared/data/princeton_segbench}
HITOPS=${HITOPS:-$ROOT/build/bin/hitops}
RUNS=${RUNS:-3}
THREADS=${THREADS:-2}
WORK=${WORK:-$(mktemp -d)}
[ -n "${KEEP:-}" ] || trap 'rm -rf "$WORK"' EXIT

find "$MESHES" -maxdepth 1 -name '*.off' | sort > "$WORK/list.txt"
echo "$(wc -l < "$WORK/list.txt") meshes of $MESHES, $THREADS threads, $RUNS runs each"

# seconds of one batch into an empty folder
run() {
  rm -rf "$WORK/out"
  local start end
  start=$(date +%s.%N)
  "$HITOPS" --batch "$WORK/list.txt" --out "$WORK/out" --threads "$THREADS" --quiet "$@" > /dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

plain=() report=()
for ((i = 0; i < RUNS; ++i)); do
  plain+=("$(run)")
  report+=("$(run --report)")
  echo "run $((i + 1)): without --report ${plain[-1]} s, with --report ${report[-1]} s"
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
p=$(median "${plain[@]}")
r=$(median "${report[@]}")
echo "median: without --report $p s, with --report $r s, cost $(echo "scale=4; ($r / $p - 1) * 100" | bc) %"
