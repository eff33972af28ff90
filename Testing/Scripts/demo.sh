#!/usr/bin/env bash
# The main job: installs the Debian packages, builds, and runs the pipeline on a bundled
# model. Today the pipeline is: read a surface, tetrahedralize it, report mesh statistics.
# Usage: demo.sh [surface file, default Data/fertility.off]
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${POLYCUBEHEX_BUILD:-$source_dir/build}"

"$source_dir/Testing/Scripts/install-dependencies.sh"
POLYCUBEHEX_BUILD="$build_dir" "$source_dir/Testing/Scripts/build.sh"
python_dir="$(find "$build_dir/lib" -type d -name polycubehex -path '*-packages/*' | head -n 1)"
PYTHONPATH="$(dirname "$python_dir")${PYTHONPATH:+:$PYTHONPATH}" \
  /usr/bin/python3.11 "$source_dir/Wrapping/Python/examples/tetrahedralize_and_report.py" \
  "${1:-$source_dir/Data/fertility.off}" --output-dir "$build_dir/demo"
