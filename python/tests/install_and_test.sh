#!/bin/sh
# Installs the package with pip into a fresh virtual environment, as README.md tells users to
# (offline: --no-build-isolation --no-index, Debian's numpy and pytest through the system site
# packages), then runs the pytest suite on the installed package from outside the source tree.
#   python/tests/install_and_test.sh [PYTHON]     (default /usr/bin/python3)
# PD_HITOPS, if set, is passed on to the tests (the comparisons with the hitops tool).
set -eu

source_dir=$(cd "$(dirname "$0")/../.." && pwd)
python=${1:-/usr/bin/python3}
if [ -n "${PD_HITOPS:-}" ]; then
  # absolute: the tests run from the scratch directory
  PD_HITOPS=$(cd "$(dirname "$PD_HITOPS")" && pwd)/$(basename "$PD_HITOPS")
  export PD_HITOPS
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

"$python" -m venv --system-site-packages "$scratch/venv"
start=$(date +%s)
"$scratch/venv/bin/pip" install --no-build-isolation --no-index --no-cache-dir --disable-pip-version-check "$source_dir"
echo "install_and_test.sh: pip install took $(( $(date +%s) - start )) s"

# from the scratch directory: the package imported is the one pip installed, not python/'s
cd "$scratch"
"$scratch/venv/bin/python" -c '
import sys, part_decomposition as pd
assert pd.__file__.startswith(sys.prefix), pd.__file__ + " is not in the virtual environment"
print("install_and_test.sh: testing", pd.__file__)'
PD_EXAMPLE_DATA_DIR="$source_dir/examples/Part_decomposition/data" \
  "$scratch/venv/bin/python" -m pytest -q -p no:cacheprovider "$source_dir/python/tests"
