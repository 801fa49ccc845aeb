#!/usr/bin/env bash
# Checks that a change keeps every label: runs two hitops builds on the same meshes with 1 and 2
# threads (default parameters plus any extra hitops options) and compares the label files byte by
# byte. Prints one line per difference and a final count; exit status 1 if any label differs.
#
#   same_labels.sh OLD_HITOPS NEW_HITOPS MESH_OR_DIR... [-- HITOPS_OPTIONS...]
#
# A directory stands for every .off/.obj/.ply/.stl file in it.
set -u
old=$1; new=$2; shift 2
inputs=(); opts=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--" ]; then shift; opts=("$@"); break; fi
  inputs+=("$1"); shift
done
files=()
for i in "${inputs[@]}"; do
  if [ -d "$i" ]; then
    for f in "$i"/*.off "$i"/*.obj "$i"/*.ply "$i"/*.stl; do [ -f "$f" ] && files+=("$f"); done
  else files+=("$i"); fi
done
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
same=0; differ=0
for f in "${files[@]}"; do
  for t in 1 2; do
    "$old" "$f" --threads $t --labels "$work/old.seg" "${opts[@]}" > /dev/null 2> "$work/old.err"; ro=$?
    "$new" "$f" --threads $t --labels "$work/new.seg" "${opts[@]}" > /dev/null 2> "$work/new.err"; rn=$?
    if [ $ro -ne $rn ]; then echo "DIFFERS (exit $ro vs $rn): $f, $t threads"; differ=$((differ+1)); continue; fi
    if [ $ro -ne 0 ]; then
      if cmp -s "$work/old.err" "$work/new.err"; then same=$((same+1)); else echo "DIFFERS (error): $f, $t threads"; differ=$((differ+1)); fi
      continue
    fi
    if cmp -s "$work/old.seg" "$work/new.seg"; then same=$((same+1)); else echo "DIFFERS: $f, $t threads"; differ=$((differ+1)); fi
  done
done
echo "same labels: $same of $((same+differ)) runs (${#files[@]} meshes x 1 and 2 threads)"
[ $differ -eq 0 ]
