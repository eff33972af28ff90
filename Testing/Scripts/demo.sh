#!/usr/bin/env bash
# The main job: installs the Debian packages, builds, and meshes a bundled model end to end
# (tets, cuts, frame field, polycube, hexes) in ParaView's pvbatch under Xvfb. Writes into
# build/demo/: the hex mesh (.vtu and MEDIT .mesh), report.md and report.html with the quality
# table, and a picture per stage (cuts, frame field, polycube, hexes by scaled Jacobian, a slice,
# the histogram).
# Usage: demo.sh [model, default Data/rockerarm.mesh] [target hexes, default 17594 = the
#        paper's closed-form count for rockerarm]
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${POLYCUBEHEX_BUILD:-$source_dir/build}"

"$source_dir/Testing/Scripts/install-dependencies.sh"
POLYCUBEHEX_BUILD="$build_dir" "$source_dir/Testing/Scripts/build.sh"
python_dir="$(find "$build_dir/lib" -type d -name polycubehex -path '*-packages/*' | head -n 1)"
PYTHONPATH="$(dirname "$python_dir")${PYTHONPATH:+:$PYTHONPATH}" \
  xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch \
  "$source_dir/Wrapping/Python/examples/demo_report.py" \
  "${1:-$source_dir/Data/rockerarm.mesh}" --hexes "${2:-17594}" --output-dir "$build_dir/demo" \
  --plugin "$build_dir/lib/paraview-5.11/plugins/PolycubeHex/PolycubeHex.so"
echo "Open $build_dir/demo/report.html in a browser, or report.md (the pictures are beside them)."
