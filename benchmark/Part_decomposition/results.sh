#!/usr/bin/env bash
# Reruns the current table of RESULTS.md: every data set, this package and CGAL's SDF segmentation
# in the same run (told the human part count too where the set has one), then writes the table
# between its marks in RESULTS.md with results_table.py. Run from the top of the repository, after
# building benchmark_segmentation and generate_superquadric_unions, on an otherwise idle machine
# (about 15 minutes on 2 cores):
#
#   benchmark/Part_decomposition/results.sh [BUILD_DIR] [OUT_DIR]
#
# Data: ../shared/data/princeton_segbench; the CAD-style objects in bench/data/partnet_mobility (made
# by ../shared/data/partnet_mobility/build.sh, skipped if absent); the open and generated sets are
# made in bench/data/ when missing.
set -eu
build=${1:-build}
out=${2:-bench/results}
here=$(cd "$(dirname "$0")" && pwd)
princeton=../shared/data/princeton_segbench
bench=$build/bin/benchmark_segmentation
mkdir -p "$out" bench/data

# open versions of the closed shapes: 3 holes of 0.4% of the area ("open"), 6 of 0.8% ("hard")
for setting in "3 0.004 1" "3 0.004 2" "6 0.008 1" "6 0.008 2"; do
  set -- $setting
  dir=bench/data/princeton_open_h$1_s$3
  if [ ! -f "$dir/manifest.tsv" ]; then
    python3 ../shared/data/open_meshes/make_open.py "$princeton" "$dir" --holes "$1" --area "$2" --seed "$3"
    cut -f1,2 "$princeton/manifest.tsv" > "$dir/manifest.tsv"
  fi
done
[ -f bench/data/sq_unions/manifest.tsv ] || "$build/bin/generate_superquadric_unions" bench/data/sq_unions
# the CAD-style objects against their coarse parts: the same meshes, NAME.coarse.seg as NAME.seg
cad=bench/data/partnet_mobility
if [ -f "$cad/manifest.tsv" ] && [ ! -f bench/data/partnet_coarse/manifest.tsv ]; then
  mkdir -p bench/data/partnet_coarse
  ln -sf ../partnet_mobility/manifest.tsv bench/data/partnet_coarse/manifest.tsv
  for f in "$cad"/*.coarse.seg; do
    name=$(basename "$f" .coarse.seg)
    ln -sf "../partnet_mobility/$name.off" "bench/data/partnet_coarse/$name.off"
    ln -sf "../partnet_mobility/$name.coarse.seg" "bench/data/partnet_coarse/$name.seg"
  done
fi

run() { # DATASET METHODS NAME
  "$bench" "$1" --methods "$2" --threads 2 --out "$out/$3" > "$out/$3.log"
}
run "$princeton" sdf,ours,ours_k closed
for s in h3_s1 h3_s2 h6_s1 h6_s2; do run bench/data/princeton_open_$s sdf,ours open_$s; done
sets=("closed=$out/closed" "open=$out/open_h3_s1,$out/open_h3_s2" "hard=$out/open_h6_s1,$out/open_h6_s2")
if [ -f "$cad/manifest.tsv" ]; then
  run "$cad" sdf,ours cad_fine
  run bench/data/partnet_coarse sdf,ours,ours_k cad_coarse
  sets+=("CAD-style fine=$out/cad_fine" "CAD-style coarse=$out/cad_coarse")
else
  echo "no $cad: the CAD-style rows are left out (see ../shared/data/partnet_mobility/build.sh)" >&2
fi
run bench/data/sq_unions sdf,ours unions
sets+=("generated unions=$out/unions")
python3 "$here/results_table.py" "$here/RESULTS.md" "$(git rev-parse --short HEAD)" "${sets[@]}"
