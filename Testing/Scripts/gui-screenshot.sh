#!/usr/bin/env bash
# Opens the ParaView GUI under Xvfb with the plugin loaded and a model open, and saves a
# screenshot of the whole screen: what a user sees. Usage: gui-screenshot.sh <model> <out.png>
# With POLYCUBEHEX_GUI_PIPELINE=1 the GUI loads the Python state
# Wrapping/Python/examples/pipeline_state.py instead: the whole pipeline on <model>.
# With POLYCUBEHEX_GUI_PIPELINE=pvsm it does what the README tells a user: from the repository's
# top, PV_PLUGIN_PATH=<plugin dir> \
#   paraview --state=Wrapping/Python/examples/polycubehex_pipeline.pvsm
# (the XML state, on Data/torus.obj; <model> is ignored).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${POLYCUBEHEX_BUILD:-$source_dir/build}"
model="$(realpath "${1:-$source_dir/Data/rockerarm.mesh}")"
output="$(realpath -m "${2:-$build_dir/gui-screenshot.png}")"
plugin="$build_dir/lib/paraview-5.11/plugins/PolycubeHex/PolycubeHex.so"
work="$(mktemp -d)"

cat > "$work/load.py" <<PY
from paraview.simple import *
LoadPlugin("$plugin", remote=False, ns=globals())
source = OpenDataFile("$model")
display = Show(source)
display.SetRepresentationType("Surface With Edges")
ResetCamera()
Render()
PY
if [ "${POLYCUBEHEX_GUI_PIPELINE:-0}" = 1 ]; then
  cat > "$work/load.py" <<PY
import os
os.environ["POLYCUBEHEX_PLUGIN"] = "$plugin"
os.environ["POLYCUBEHEX_MODEL"] = "$model"
exec(open("$source_dir/Wrapping/Python/examples/pipeline_state.py").read(),
     {"__file__": "$source_dir/Wrapping/Python/examples/pipeline_state.py"})
from paraview.simple import Render
Render()
PY
fi
start="--script=$work/load.py"
if [ "${POLYCUBEHEX_GUI_PIPELINE:-0}" = pvsm ]; then
  # The state names Data/torus.obj relative to the repository's top, and needs the plugin loaded
  # before it: PV_PLUGIN_PATH loads it at start-up.
  cd "$source_dir"
  export PV_PLUGIN_PATH="$(dirname "$plugin")"
  start="--state=Wrapping/Python/examples/polycubehex_pipeline.pvsm"
fi
# A settings directory of its own, without the welcome dialog: under Xvfb (no window manager)
# that modal dialog hides behind the main window and stalls loading a .pvsm until it is closed.
mkdir -p "$work/home/.config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=false\n' \
  > "$work/home/.config/ParaView/ParaView5.11.0.ini"
export HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config"
cat > "$work/run.sh" <<SH
paraview "$start" > "$work/paraview.log" 2>&1 &
sleep "\${POLYCUBEHEX_GUI_WAIT:-20}"
xwd -root -silent > "$work/screen.xwd"
convert "$work/screen.xwd" "$output"
kill %1 || true
SH
xvfb-run -a -s "-screen 0 1400x900x24" bash "$work/run.sh"
echo "wrote $output (ParaView's messages: $work/paraview.log)"
