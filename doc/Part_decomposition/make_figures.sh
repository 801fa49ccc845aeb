#!/usr/bin/env bash
# Regenerates every figure of the Part_decomposition manual (doc/Part_decomposition/fig/*.png) from
# the current code: builds the hitops tool, the stage dumper figure_data and the software renderer
# render_mesh (doc/Part_decomposition/tools/), runs them on the shipped meshes and, when they are
# present, on the development meshes, and renders the PNG files.
#
# usage: doc/Part_decomposition/make_figures.sh
# environment:
#   BUILD_DIR   the build directory of the tools (default: <repo>/build-figures)
#   DEV_DATA    the Princeton development meshes (default: <repo>/../shared/data/princeton_segbench);
#               without them the figures that need them (teaser, gallery) are left unchanged
#   JOBS        parallel compile jobs (default 2)
#   THREADS     threads of the pipeline runs (default: all cores; results do not depend on it)
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
DOC=$ROOT/doc/Part_decomposition
FIG=$DOC/fig
BUILD=${BUILD_DIR:-$ROOT/build-figures}
DATA=$ROOT/examples/Part_decomposition/data
DEV=${DEV_DATA:-$ROOT/../shared/data/princeton_segbench}
JOBS=${JOBS:-2}
THREADS_OPT=()
[ -n "${THREADS:-}" ] && THREADS_OPT=(--threads "$THREADS")

mkdir -p "$BUILD"
cmake -S "$DOC/tools" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release > "$BUILD/figures_cmake.log" 2>&1 ||
  { cat "$BUILD/figures_cmake.log"; exit 1; }
cmake --build "$BUILD" --target hitops figure_data render_mesh sdf_segmentation -j "$JOBS"
HITOPS=$BUILD/part_decomposition/bin/hitops
FIGURE_DATA=$BUILD/bin/figure_data
RENDER=$BUILD/bin/render_mesh
SDF=$BUILD/bin/sdf_segmentation
WORK=$BUILD/figure_work
mkdir -p "$WORK" "$FIG"

# stage <name> <mesh> [figure_data options]: the outputs of every stage in $WORK/<name>
stage() {
  local name=$1 mesh=$2
  shift 2
  mkdir -p "$WORK/$name"
  "$FIGURE_DATA" "$mesh" "$WORK/$name" "$@"
}

# parts <name> <mesh>: hitops labels and primitive mesh in $WORK/<name>.{seg,off}
parts() {
  "$HITOPS" "$2" --labels "$WORK/$1.seg" --primitive-mesh "$WORK/$1_primitives.off" "${THREADS_OPT[@]}"
}

# ---------------------------------------------------------------------------------------------
# The pipeline, stage by stage, on the shipped four-legged animal (z up).
ANIMAL=$DATA/animal.off
A=$WORK/animal
stage animal "$ANIMAL" --slice y
VIEW=(--up z --view 35,22)

"$RENDER" -o "$FIG/pipeline.png" "${VIEW[@]}" --panel 260x230 \
  "$ANIMAL" "$A/prior_fused.off" "$A/zones_slice.ppm" "$A/primitives.off@components" \
  "$ANIMAL@labels=$A/parts.seg"
"$RENDER" -o "$FIG/stage_prior.png" "${VIEW[@]}" --panel 250x220 \
  "$A/prior_16.off" "$A/prior_32.off" "$A/prior_64.off" "$A/prior_fused.off"
"$RENDER" -o "$FIG/stage_tsdf.png" --panel 300x300 "$A/tsdf_slice.ppm" "$A/zones_slice.ppm"
"$RENDER" -o "$FIG/stage_fitting.png" "${VIEW[@]}" --panel 280x240 \
  "$A/claimed.off" "$A/primitives.off@components" "$A/primitives.off@components+$ANIMAL@color=8a8a8a,alpha=0.3"
"$RENDER" -o "$FIG/stage_assignment.png" "${VIEW[@]}" --panel 280x240 \
  "$ANIMAL@labels=$A/patches.seg" "$ANIMAL@labels=$A/parts.seg" "$A/part_primitives.off@components"

# ---------------------------------------------------------------------------------------------
# Effect of the parameters on the same shape: the fused prior (top) and the parts (bottom).
for alpha in 0.05 0.15 0.25; do
  stage "animal_alpha_$alpha" "$ANIMAL" --freeze-ratio "$alpha" --slice y
done
"$RENDER" -o "$FIG/freeze_ratio.png" "${VIEW[@]}" --panel 250x210 --columns 3 \
  "$WORK/animal_alpha_0.05/prior_fused.off" "$WORK/animal_alpha_0.15/prior_fused.off" \
  "$WORK/animal_alpha_0.25/prior_fused.off" \
  "$ANIMAL@labels=$WORK/animal_alpha_0.05/parts.seg" "$ANIMAL@labels=$WORK/animal_alpha_0.15/parts.seg" \
  "$ANIMAL@labels=$WORK/animal_alpha_0.25/parts.seg"

stage animal_r32 "$ANIMAL" --resolutions 32 --slice y
stage animal_r32_128 "$ANIMAL" --resolutions 32,64,128 --slice y
"$RENDER" -o "$FIG/resolutions.png" "${VIEW[@]}" --panel 250x210 --columns 3 \
  "$A/prior_fused.off" "$WORK/animal_r32/prior_fused.off" "$WORK/animal_r32_128/prior_fused.off" \
  "$ANIMAL@labels=$A/parts.seg" "$ANIMAL@labels=$WORK/animal_r32/parts.seg" \
  "$ANIMAL@labels=$WORK/animal_r32_128/parts.seg"

# The three shipped meshes and their parts (the figures of the examples).
for shape in table dumbbell; do parts "$shape" "$DATA/$shape.off"; done
parts animal "$ANIMAL"
"$RENDER" -o "$FIG/shipped_shapes.png" --up z --view 35,25 --panel 230x200 --columns 3 --frame own \
  "$DATA/table.off@labels=$WORK/table.seg" "$ANIMAL@labels=$WORK/animal.seg" \
  "$DATA/dumbbell.off@labels=$WORK/dumbbell.seg" \
  "$WORK/table_primitives.off@components" "$WORK/animal_primitives.off@components" \
  "$WORK/dumbbell_primitives.off@components"

# ---------------------------------------------------------------------------------------------
# Development meshes (Princeton segmentation benchmark), when present.
if [ -d "$DEV" ]; then
  # teaser: input, parts, superquadrics
  for shape in human_2 chair_108 fourleg_385; do parts "$shape" "$DEV/$shape.off"; done
  "$RENDER" -o "$FIG/teaser.png" --view 30,15 --panel 220x220 --columns 3 --frame own \
    "$DEV/human_2.off" "$DEV/human_2.off@labels=$WORK/human_2.seg" "$WORK/human_2_primitives.off@components" \
    "$DEV/fourleg_385.off" "$DEV/fourleg_385.off@labels=$WORK/fourleg_385.seg" \
    "$WORK/fourleg_385_primitives.off@components"

  # comparison with CGAL's SDF segmentation: a human segmentation, SDF, Hi-TOPS
  COMPARE=(chair_108 octopus_123 hand_187)
  PANELS=()
  for shape in "${COMPARE[@]}"; do
    [ -f "$WORK/$shape.seg" ] || parts "$shape" "$DEV/$shape.off"
    "$SDF" "$DEV/$shape.off" "$WORK/${shape}_sdf.seg"
    case $shape in hand_187) view="+view=0,80" ;; *) view="" ;; esac
    PANELS+=("$DEV/$shape.off@labels=$DEV/${shape}_0.seg$view" "$DEV/$shape.off@labels=$WORK/${shape}_sdf.seg$view"
             "$DEV/$shape.off@labels=$WORK/$shape.seg$view")
  done
  "$RENDER" -o "$FIG/comparison_sdf.png" --view 30,15 --panel 190x190 --columns 3 --frame own "${PANELS[@]}"

  # gallery: one shape of each of 12 categories, with its own view
  GALLERY=(airplane_71 ant_90 armadillo_281 bird_245 chair_108 cup_21 fish_222 glasses_53
           hand_187 octopus_123 plier_207 table_152)
  PANELS=()
  for shape in "${GALLERY[@]}"; do
    parts "$shape" "$DEV/$shape.off"
    case $shape in
      airplane_71) view="up=-z+view=210,35" ;;
      ant_90) view="up=z+view=30,40" ;;
      armadillo_281) view="view=180,10" ;;
      glasses_53) view="up=z+view=30,20" ;;
      hand_187|plier_207) view="view=0,80" ;;
      bird_245) view="view=30,60" ;;
      cup_21) view="view=30,35" ;;
      fish_222) view="view=0,10" ;;
      *) view="view=30,15" ;;
    esac
    PANELS+=("$DEV/$shape.off@labels=$WORK/$shape.seg+$view")
  done
  "$RENDER" -o "$FIG/gallery.png" --panel 170x170 --columns 6 --frame own "${PANELS[@]}"
else
  echo "no development meshes in $DEV: teaser.png, comparison_sdf.png and gallery.png left unchanged"
fi

ls -l "$FIG"/*.png
