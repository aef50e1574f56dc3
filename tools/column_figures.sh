#!/usr/bin/env bash
# The papers' figures of a wire column against a silo, from the output folders of
# examples/column (NAME = column) and examples/silo (NAME = silo), in one command:
#
#   tools/column_figures.sh COLUMN_DIR SILO_DIR OUT_DIR [REST_STEP LOADED_STEP]
#
# Reads in each folder NAME.fabric.<step>.dump (dump custom id x y z c_fab[*]),
# NAME.pairs.<step>.dump (dump local of compute nscd/contacts pairs active),
# NAME.wire.<step>.dump + NAME.nodes.<step>.dump (compute wire/local, node positions),
# NAME.grains.<step>.vtk, NAME.wcontacts.<step>.dump (compute wire/contacts, when it
# exists) and log.NAME (doc/analysis.md lists the deck lines). REST_STEP: the snapshot
# before loading (default: the last dump before the log's thermo shows v_phase = 5, the
# loading); LOADED_STEP: under load (default: the last dump). Writes OUT_DIR/fig2_*.png (ParaView, when pvbatch and xvfb-run are there),
# fig3_column.png, fig3_silo.png, fig4.png, fig5_column.png, fig5_silo.png, fig6.png (when the
# wire-contact dumps exist), series_column.png, series_silo.png, each with its CSV, and
# prints the numbers the papers compare (mean fabric angle of each, fraction of wire-grain
# forces within 30 degrees of the vertical). Each network picture is normalised by its own
# largest force (at rest the forces are far below the loaded ones).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[ $# -ge 3 ] || { sed -n 2,18p "${BASH_SOURCE[0]}"; exit 2; }
col=$1 silo=$2 out=$3
mkdir -p "$out"
analysis() { /usr/bin/python3 "$here/nscd-analysis" "$@"; }

steps_of() {    # timesteps of NAME.KIND.<step>.dump in DIR, ascending
  ls "$1"/"$2".*.dump 2>/dev/null | sed -E 's/.*\.([0-9]+)\.dump$/\1/' | sort -n
}
mapfile -t col_steps < <(steps_of "$col" column.fabric)
mapfile -t silo_steps < <(steps_of "$silo" silo.fabric)
[ ${#col_steps[@]} -ge 1 ] || { echo "column_figures: no column.fabric.*.dump in $col" >&2; exit 1; }
[ ${#silo_steps[@]} -ge 1 ] || { echo "column_figures: no silo.fabric.*.dump in $silo" >&2; exit 1; }
n=${#col_steps[@]}
last_before_loading() {    # DIR NAME STEPS...: the last of STEPS before phase 5 starts in log.NAME
  local dir=$1 name=$2; shift 2
  PYTHONPATH="$here" /usr/bin/python3 - "$dir/log.$name" "$@" <<'EOF'
import sys
from nscd_analysis import logs
steps = [int(s) for s in sys.argv[2:]]
try:
    table = logs.thermo_columns(sys.argv[1], ["Step", "v_phase"])
    loading = table[table[:, 1] >= 5, 0]
    start = loading.min() if len(loading) else float("inf")
except (OSError, ValueError):
    start = float("inf")
before = [s for s in steps if s <= start]
print(before[-1] if before else steps[0])
EOF
}
rest=${4:-$(last_before_loading "$col" column "${col_steps[@]}")}
loaded=${5:-${col_steps[$(( n - 1 ))]}}
silo_last=$(last_before_loading "$silo" silo "${silo_steps[@]}")    # the silo at rest
echo "column_figures: column at rest: step $rest, under load: step $loaded; silo at rest: step $silo_last"

# Fig. 3 and 4: fabric field of each, and the mean angle vs r of both on one plot
analysis fabric-field "$col/column.fabric.$rest.dump" -o "$out/fig3_column"
analysis fabric-field "$silo/silo.fabric.$silo_last.dump" -o "$out/fig3_silo"
analysis fabric-angle --run "column=$col/column.fabric.$rest.dump" \
  --run "column loaded=$col/column.fabric.$loaded.dump" --run "silo=$silo/silo.fabric.$silo_last.dump" \
  -o "$out/fig4"

# Fig. 5: Fn(r) of the column at every dumped step from REST_STEP on
mapfile -t load_steps < <(for s in "${col_steps[@]}"; do [ "$s" -ge "$rest" ] && echo "$s"; done)
analysis force-profile "$col"/column.pairs.*.dump --steps "${load_steps[@]}" -o "$out/fig5_column"
# and of the silo, at rest and under its plate
mapfile -t silo_load_steps < <(for s in "${silo_steps[@]}"; do [ "$s" -ge "$silo_last" ] && echo "$s"; done)
if ls "$silo"/silo.pairs.*.dump > /dev/null 2>&1; then
  analysis force-profile "$silo"/silo.pairs.*.dump --steps "${silo_load_steps[@]}" -o "$out/fig5_silo"
fi

# Fig. 6: wire-grain force orientations, before and under load
if ls "$col"/column.wcontacts.*.dump > /dev/null 2>&1; then
  analysis wire-contacts "$col"/column.wcontacts.*.dump --steps "$rest" "$loaded" \
    --labels "step $rest (rest)" "step $loaded (loaded)" -o "$out/fig6"
else
  echo "column_figures: no column.wcontacts.*.dump (compute wire/contacts): Fig. 6 skipped"
fi

# time series
[ -f "$col/log.column" ] && analysis timeseries "$col/log.column" --preset column -o "$out/series_column"
[ -f "$silo/log.silo" ] && analysis timeseries "$silo/log.silo" --plot Step:v_height --plot v_plate_disp:v_plate_force \
  -o "$out/series_silo"

# Fig. 2: ParaView
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
  for s in "$rest" "$loaded"; do
    analysis vtk-network "$col/column.pairs.$s.dump" -o "$out/vtk/column_network"
    if [ -f "$col/column.wire.$s.dump" ]; then
      analysis vtk-wire --elements "$col/column.wire.$s.dump" --nodes "$col/column.nodes.$s.dump" \
        -o "$out/vtk/column_wire"
    fi
  done
  for s in "$rest" "$loaded"; do
    wire_arg=()
    [ -f "$out/vtk/column_wire.$s.vtp" ] && wire_arg=(--wire "$out/vtk/column_wire.$s.vtp")
    xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch "$here/nscd_render.py" --grains "$col/column.grains.$s.vtk" "${wire_arg[@]}" \
      --network "$out/vtk/column_network.$s.vtp" --min-force 0.02 --size 600 800 \
      --out "$out/fig2_step$s" 2>&1 | grep -v "^$" | grep -v "ERR|\|WARN|" || true
  done
else
  echo "column_figures: pvbatch or xvfb-run missing: Fig. 2 skipped (apt-get install paraview python3-paraview xvfb xauth)"
fi
ls -la "$out"/*.png
