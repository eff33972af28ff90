#!/usr/bin/env bash
# Builds PolycubeHex and runs the benchmark; writes BENCHMARKS.md at the top of the repository.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${POLYCUBEHEX_BUILD:-$source_dir/build}"
POLYCUBEHEX_BUILD="$build_dir" "$source_dir/Testing/Scripts/build.sh" > /dev/null
python_dir="$(find "$build_dir/lib" -type d -name polycubehex -path '*-packages/*' | head -n 1)"
PYTHONPATH="$(dirname "$python_dir")${PYTHONPATH:+:$PYTHONPATH}" \
  /usr/bin/python3.11 "$source_dir/Testing/Benchmark/benchmark.py" \
  --output "$source_dir/BENCHMARKS.md" "$@"
