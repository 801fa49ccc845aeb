#!/usr/bin/env bash
# The fitter's work over a dataset: the seeds and least-squares solves that hitops --verbose prints,
# summed over every .off file of DIR (2 threads; extra hitops options are passed on).
#
#   fitter_work.sh HITOPS DIR [HITOPS_OPTIONS...]
h=$1; d=$2; shift 2
seeds=0; solves=0
for f in $d/*.off; do
  line=$($h $f --threads 2 --verbose "$@" 2>&1 >/dev/null | grep "seeds,.*solves" | tail -1)
  s=$(echo "$line" | sed -E 's/.* ([0-9]+) seeds, ([0-9]+) solves.*/\1 \2/')
  seeds=$((seeds + ${s% *})); solves=$((solves + ${s#* }))
done
echo "seeds $seeds solves $solves"
