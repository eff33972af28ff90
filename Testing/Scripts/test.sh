#!/usr/bin/env bash
# The test command: installs the Debian packages, builds, and runs the whole CTest suite
# under one X server (rendering tests need X; one server avoids display-number races). -noreset:
# Xvfb otherwise resets whenever its last client leaves, and a test connecting during that
# reset fails with "bad X server connection" (seen on TestPVPipeline under load).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${POLYCUBEHEX_BUILD:-$source_dir/build}"

"$source_dir/Testing/Scripts/install-dependencies.sh"
POLYCUBEHEX_BUILD="$build_dir" "$source_dir/Testing/Scripts/build.sh"
cd "$build_dir"
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure --timeout 900 "$@"
