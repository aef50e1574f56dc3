#!/usr/bin/env bash
# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

# The papers' figures of a wire column (and of a silo to compare with) from any deck's output
# folders, in one command (doc/analysis.md, "The column against the silo in one command"):
#
#   tools/column_figures.sh [OPTIONS] --column DIR [--silo DIR] OUT_DIR
#   tools/column_figures.sh COLUMN_DIR SILO_DIR OUT_DIR [REST_STEP LOADED_STEP]   (the examples)
#
# Reads in DIR the files PREFIX.fabric.<step>.dump (dump custom id x y z c_fab[*]),
# PREFIX.pairs.<step>.dump (compute nscd/contacts pairs active), PREFIX.wire.<step>.dump +
# PREFIX.nodes.<step>.dump (compute wire/local, node positions), PREFIX.grains.<step>.vtk,
# PREFIX.wcontacts.<step>.dump (compute wire/contacts) and the log(s).
# Options (defaults for examples/column and examples/silo):
#   --column DIR, --silo DIR      output folders (the silo is optional)
#   --column-prefix P, --silo-prefix P   file prefix in each (default column, silo)
#   --column-log F, --silo-log F  a log; repeat for a run split by restarts, in order
#                                 (default DIR/log.PREFIX)
#   --axis X Y                    vertical axis (default: the grains' centre of mass)
#   --R R                         column radius: r drawn in units of R, R marked
#   --rmax R  --zmin Z  --zmax Z  only grains/contacts inside (Fig. 3, 4, 5): leave out debris
#   --floor Z                     height of the floor drawn in Fig. 2 (default: the lowest grain)
#   --rest STEP --loaded STEP     snapshots at rest and under load (default: the last dump
#                                 before the load phase starts, and the last dump)
#   --phase-column C (v_phase)  --load-phase N (5)  --load-column C (v_plate_load)
#   --series X:Y[,Y2]             time-series panels (repeat; default: the column preset)
#   --crush-value V --crush-threshold X   crush_column: the fraction of grains with column V
#                                 of compute nscd/crush/atom (index, sigma, fmax) >= X (default index 1)
# Writes OUT_DIR/fig2_*.png (ParaView), fig3_column.png, fig3_silo.png, fig4.png,
# fig5_column.png, fig5_silo.png, fig6.png, series_column.png, series_silo.png and, from
# PREFIX.stress.<step>.dump (c_sig[*] c_crush[*]), stress_field_column.png (stress and fabric
# side by side, under load), stress_angle.png, stress_profile_column.png and
# crush_column.png, each with its CSV. A figure whose inputs are missing (a dump set, a
# thermo column, pvbatch) is skipped with a warning naming what is missing; the others are
# still made. Ends with the lists of figures made and skipped; exits 1 only when none was made.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
usage() { sed -n '2,/^set -uo/p' "${BASH_SOURCE[0]}" | sed '$d'; exit 2; }

col="" silo="" col_prefix=column silo_prefix=silo col_logs=() silo_logs=() range=() r_opts=()
crush_value=index crush_threshold=1
rest="" loaded="" phase_column=v_phase load_phase=5 load_column=v_plate_load series=() axis=() R="" floor=()
positional=()
while [ $# -gt 0 ]; do
  case $1 in
    --column) col=$2; shift 2 ;;
    --silo) silo=$2; shift 2 ;;
    --column-prefix) col_prefix=$2; shift 2 ;;
    --silo-prefix) silo_prefix=$2; shift 2 ;;
    --column-log) col_logs+=("$2"); shift 2 ;;
    --silo-log) silo_logs+=("$2"); shift 2 ;;
    --axis) axis=(--axis "$2" "$3"); shift 3 ;;
    --floor) floor=(--floor "$2"); shift 2 ;;
    --R) R=$2; r_opts+=(--R "$2"); shift 2 ;;
    --rmax|--zmin|--zmax) range+=("$1" "$2"); shift 2 ;;
    --rest) rest=$2; shift 2 ;;
    --loaded) loaded=$2; shift 2 ;;
    --phase-column) phase_column=$2; shift 2 ;;
    --load-phase) load_phase=$2; shift 2 ;;
    --load-column) load_column=$2; shift 2 ;;
    --series) series+=(--plot "$2"); shift 2 ;;
    --crush-value) crush_value=$2; shift 2 ;;
    --crush-threshold) crush_threshold=$2; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "column_figures: unknown option $1" >&2; usage ;;
    *) positional+=("$1"); shift ;;
  esac
done
case ${#positional[@]} in
  1) out=${positional[0]} ;;
  3|5) col=${positional[0]} silo=${positional[1]} out=${positional[2]}
       [ ${#positional[@]} = 5 ] && rest=${positional[3]} loaded=${positional[4]} ;;
  *) usage ;;
esac
[ -n "$col" ] || { echo "column_figures: give --column DIR" >&2; usage; }
[ ${#col_logs[@]} -gt 0 ] || col_logs=("$col/log.$col_prefix")
[ -n "$silo" ] && [ ${#silo_logs[@]} -eq 0 ] && silo_logs=("$silo/log.$silo_prefix")
mkdir -p "$out"
analysis() { /usr/bin/python3 "$here/nscd-analysis" "$@"; }

made=() skipped=()
skip() {    # FIGURE REASON
  echo "column_figures: WARNING: $1 skipped: $2" >&2
  skipped+=("$1 ($2)")
}
figure() {    # FIGURE COMMAND...: run it; on failure the figure is skipped with the tool's message
  local name=$1 log
  shift
  log=$(mktemp)
  if "$@" > "$log" 2>&1; then
    cat "$log"; made+=("$name")
  else
    cat "$log" >&2
    skip "$name" "$(grep -v '^ *$' "$log" | tail -1)"
  fi
  rm -f "$log"
}
existing_logs() {    # LOG...: the ones that exist (a missing one is warned about)
  for f in "$@"; do
    if [ -f "$f" ]; then echo "$f"; else echo "column_figures: WARNING: no log $f" >&2; fi
  done
}
steps_of() {    # DIR PREFIX.KIND: timesteps of PREFIX.KIND.<step>.dump in DIR, ascending
  ls "$1"/"$2".*.dump 2>/dev/null | sed -E 's/.*\.([0-9]+)\.dump$/\1/' | sort -n
}
dumps() {    # DIR PREFIX.KIND STEPS...: the dump files of those steps
  local dir=$1 kind=$2; shift 2
  for s in "$@"; do echo "$dir/$kind.$s.dump"; done
}
last_before_loading() {    # LOGS... -- STEPS...: the last of STEPS at or before the load phase's first step
  local logs=() start
  while [ "$1" != "--" ]; do logs+=("$1"); shift; done
  shift
  start=""
  [ ${#logs[@]} -gt 0 ] && start=$(analysis first-step "${logs[@]}" --column "$phase_column" --value "$load_phase" 2>/dev/null)
  local best=$1
  for s in "$@"; do [ -z "$start" ] || [ "$s" -le "$start" ] && best=$s; done
  echo "$best"
}
load_labels() {    # LOGS... -- STEPS...: "load L (step S)" per step, "step S" where the log lacks the load
  local logs=()
  while [ "$1" != "--" ]; do logs+=("$1"); shift; done
  shift
  local values=()
  [ ${#logs[@]} -gt 0 ] &&
    mapfile -t values < <(analysis thermo-at "${logs[@]}" --column "$load_column" --steps "$@" 2>/dev/null | awk '{print $2}')
  if ! printf '%s\n' "${values[@]}" | grep -qv '^nan$'; then
    echo "column_figures: WARNING: no thermo column $load_column (--load-column) in the log at these steps: labelled by step" >&2
  fi
  local k=0
  for s in "$@"; do
    local v=${values[$k]:-nan}
    if [ "$v" = nan ]; then echo "step $s"; else printf 'load %.4g (step %s)\n' "$v" "$s"; fi
    k=$((k + 1))
  done
}

# --- the column's snapshots ------------------------------------------------------------
mapfile -t col_logs < <(existing_logs "${col_logs[@]}")
mapfile -t col_steps < <(steps_of "$col" "$col_prefix.fabric")
mapfile -t pair_steps < <(steps_of "$col" "$col_prefix.pairs")
all_steps=("${col_steps[@]}")
[ ${#all_steps[@]} -ge 1 ] || all_steps=("${pair_steps[@]}")
if [ ${#all_steps[@]} -ge 1 ]; then
  [ -n "$rest" ] || rest=$(last_before_loading "${col_logs[@]}" -- "${all_steps[@]}")
  [ -n "$loaded" ] || loaded=${all_steps[$(( ${#all_steps[@]} - 1 ))]}
  echo "column_figures: column at rest: step $rest, under load: step $loaded"
fi
silo_steps=() silo_last=""
if [ -n "$silo" ]; then
  mapfile -t silo_logs < <(existing_logs "${silo_logs[@]}")
  mapfile -t silo_steps < <(steps_of "$silo" "$silo_prefix.fabric")
  [ ${#silo_steps[@]} -ge 1 ] && silo_last=$(last_before_loading "${silo_logs[@]}" -- "${silo_steps[@]}") &&
    echo "column_figures: silo at rest: step $silo_last"
fi
opts=("${axis[@]}" "${r_opts[@]}" "${range[@]}")

# --- Fig. 3 and 4: fabric field of each, the mean angle vs r of both on one plot --------
if [ ${#col_steps[@]} -ge 1 ]; then
  figure fig3_column analysis fabric-field "$col/$col_prefix.fabric.$rest.dump" "${opts[@]}" -o "$out/fig3_column"
else
  skip fig3_column "no $col_prefix.fabric.*.dump in $col (dump custom ... c_fab[*])"
fi
if [ -z "$silo" ]; then
  skip fig3_silo "no --silo folder given"
elif [ -n "$silo_last" ]; then
  figure fig3_silo analysis fabric-field "$silo/$silo_prefix.fabric.$silo_last.dump" "${opts[@]}" -o "$out/fig3_silo"
else
  skip fig3_silo "no $silo_prefix.fabric.*.dump in $silo"
fi
runs=()
[ ${#col_steps[@]} -ge 1 ] && runs+=(--run "column=$col/$col_prefix.fabric.$rest.dump")
[ ${#col_steps[@]} -ge 1 ] && [ "$loaded" != "$rest" ] && [ -f "$col/$col_prefix.fabric.$loaded.dump" ] &&
  runs+=(--run "column loaded=$col/$col_prefix.fabric.$loaded.dump")
[ -n "$silo_last" ] && runs+=(--run "silo=$silo/$silo_prefix.fabric.$silo_last.dump")
if [ ${#runs[@]} -gt 0 ]; then
  figure fig4 analysis fabric-angle "${runs[@]}" "${opts[@]}" -o "$out/fig4"
else
  skip fig4 "no fabric dumps (PREFIX.fabric.*.dump)"
fi

# --- Fig. 5: Fn(r) from the rest step on, panels labelled by the plate's load ------------
force_profile() {    # NAME DIR PREFIX LOGS... -- FROM_STEP
  local name=$1 dir=$2 prefix=$3; shift 3
  local logs=()
  while [ "$1" != "--" ]; do logs+=("$1"); shift; done
  local from=$2 steps=() s
  mapfile -t steps < <(for s in $(steps_of "$dir" "$prefix.pairs"); do [ "$s" -ge "$from" ] && echo "$s"; done)
  if [ ${#steps[@]} -eq 0 ]; then
    skip "$name" "no $prefix.pairs.*.dump from step $from on in $dir (compute nscd/contacts pairs)"
    return
  fi
  local labels=()
  mapfile -t labels < <(load_labels "${logs[@]}" -- "${steps[@]}")
  mapfile -t files < <(dumps "$dir" "$prefix.pairs" "${steps[@]}")
  figure "$name" analysis force-profile "${files[@]}" --labels "${labels[@]}" "${opts[@]}" -o "$out/$name"
}
if [ -n "$rest" ]; then force_profile fig5_column "$col" "$col_prefix" "${col_logs[@]}" -- "$rest"
else skip fig5_column "no $col_prefix.fabric.*.dump or $col_prefix.pairs.*.dump in $col"; fi
if [ -z "$silo" ]; then skip fig5_silo "no --silo folder given"
elif [ -n "$silo_last" ]; then force_profile fig5_silo "$silo" "$silo_prefix" "${silo_logs[@]}" -- "$silo_last"
else skip fig5_silo "no $silo_prefix.fabric.*.dump in $silo"; fi

# --- Fig. 6: wire-grain force orientations at rest and under load, labelled by load ------
if [ -z "$rest" ]; then
  skip fig6 "no snapshots of the column"
elif [ -f "$col/$col_prefix.wcontacts.$rest.dump" ] && [ -f "$col/$col_prefix.wcontacts.$loaded.dump" ]; then
  mapfile -t labels < <(load_labels "${col_logs[@]}" -- "$rest" "$loaded")
  labels[0]="${labels[0]}, rest"
  figure fig6 analysis wire-contacts "$col/$col_prefix.wcontacts.$rest.dump" "$col/$col_prefix.wcontacts.$loaded.dump" \
    "${axis[@]}" --labels "${labels[@]}" -o "$out/fig6"
else
  skip fig6 "no $col_prefix.wcontacts.$rest.dump and $col_prefix.wcontacts.$loaded.dump in $col (compute wire/contacts)"
fi

# --- stress and crushing (PREFIX.stress.<step>.dump: in.column -var fields yes) ----------
mapfile -t stress_steps < <(steps_of "$col" "$col_prefix.stress")
stress_at() { [ -f "$col/$col_prefix.stress.$1.dump" ]; }
if [ ${#stress_steps[@]} -eq 0 ] || [ -z "$rest" ]; then
  skip "stress_*, crush_column" "no $col_prefix.stress.*.dump in $col (dump custom ... c_sig[*] c_crush[*]: in.column -var fields yes)"
else
  s_rest=$rest s_loaded=$loaded
  stress_at "$s_rest" || s_rest=${stress_steps[0]}
  stress_at "$s_loaded" || s_loaded=${stress_steps[$(( ${#stress_steps[@]} - 1 ))]}
  fabric_beside=()
  [ -f "$col/$col_prefix.fabric.$s_loaded.dump" ] && fabric_beside=(--fabric "$col/$col_prefix.fabric.$s_loaded.dump")
  figure stress_field_column analysis stress-field "$col/$col_prefix.stress.$s_loaded.dump" "${fabric_beside[@]}" \
    "${opts[@]}" -o "$out/stress_field_column"
  runs=(--run "column=$col/$col_prefix.stress.$s_rest.dump")
  [ "$s_loaded" != "$s_rest" ] && runs+=(--run "column loaded=$col/$col_prefix.stress.$s_loaded.dump")
  [ -n "$silo_last" ] && [ -f "$silo/$silo_prefix.stress.$silo_last.dump" ] &&
    runs+=(--run "silo=$silo/$silo_prefix.stress.$silo_last.dump")
  figure stress_angle analysis stress-angle "${runs[@]}" "${opts[@]}" -o "$out/stress_angle"
  mapfile -t labels < <(load_labels "${col_logs[@]}" -- "$s_rest" "$s_loaded")
  if [ "$s_loaded" != "$s_rest" ]; then
    figure stress_profile_column analysis stress-profile "$col/$col_prefix.stress.$s_rest.dump" \
      "$col/$col_prefix.stress.$s_loaded.dump" --labels "${labels[@]}" "${opts[@]}" -o "$out/stress_profile_column"
  else
    figure stress_profile_column analysis stress-profile "$col/$col_prefix.stress.$s_rest.dump" --labels "${labels[0]}" \
      "${opts[@]}" -o "$out/stress_profile_column"
  fi
  figure crush_column analysis crush-profile "$col/$col_prefix.stress.$s_loaded.dump" --labels "${labels[-1]}" \
    --value "$crush_value" --threshold "$crush_threshold" "${opts[@]}" -o "$out/crush_column"
fi

# --- time series: panels whose columns the log lacks are left out by the tool ------------
[ ${#series[@]} -gt 0 ] || series=(--preset column)
if [ ${#col_logs[@]} -gt 0 ]; then
  figure series_column analysis timeseries "${col_logs[@]}" "${series[@]}" -o "$out/series_column"
else
  skip series_column "no log of the column (--column-log)"
fi
if [ -z "$silo" ]; then skip series_silo "no --silo folder given"
elif [ ${#silo_logs[@]} -gt 0 ]; then
  figure series_silo analysis timeseries "${silo_logs[@]}" --plot Step:v_height --plot v_plate_disp:v_plate_force \
    -o "$out/series_silo"
else skip series_silo "no log of the silo (--silo-log)"; fi

# --- Fig. 2: ParaView ---------------------------------------------------------------------
render_step() {    # STEP: fig2_stepSTEP_*.png of the column
  local s=$1
  local grains="$col/$col_prefix.grains.$s.vtk" pairs="$col/$col_prefix.pairs.$s.dump"
  if [ ! -f "$grains" ] && [ ! -f "$pairs" ]; then
    skip "fig2_step$s" "no $col_prefix.grains.$s.vtk or $col_prefix.pairs.$s.dump in $col"
    return
  fi
  local in=()
  [ -f "$grains" ] && in+=(--grains "$grains")
  if [ -f "$pairs" ] && analysis vtk-network "$pairs" -o "$out/vtk/column_network" > /dev/null; then
    in+=(--network "$out/vtk/column_network.$s.vtp")
  else
    echo "column_figures: WARNING: fig2_step$s drawn without the force network (no or bad $pairs)" >&2
  fi
  if [ -f "$col/$col_prefix.wire.$s.dump" ] && [ -f "$col/$col_prefix.nodes.$s.dump" ] &&
     analysis vtk-wire --elements "$col/$col_prefix.wire.$s.dump" --nodes "$col/$col_prefix.nodes.$s.dump" \
       -o "$out/vtk/column_wire" > /dev/null; then
    in+=(--wire "$out/vtk/column_wire.$s.vtp")
  fi
  local frame=("${axis[@]}")
  [ -n "$R" ] && frame+=(--R "$R")
  local zmax_opt=() k
  for ((k = 0; k < ${#range[@]}; k += 2)); do
    [ "${range[$k]}" = --zmax ] && zmax_opt=(--zmax "${range[$((k + 1))]}")
  done
  local plate=()
  [ "$s" != "$rest" ] && plate=(--plate top)    # under load: the plate rests on the top grains
  figure "fig2_step$s" render xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch "$here/nscd_render.py" "${in[@]}" \
    "${frame[@]}" "${zmax_opt[@]}" "${floor[@]}" "${plate[@]}" --min-force 0.02 --size 800 0 --out "$out/fig2_step$s"
}
render() {    # pvbatch exits 0 after pipeline errors: they count as a failure
  local log rc try
  log=$(mktemp)
  # pvbatch has been seen to abort while opening its X window on a loaded machine: 3 tries
  for try in 1 2 3; do
    "$@" > "$log" 2>&1
    rc=$?
    grep -q "bad X server connection\|CreateAWindow" "$log" || break
    sleep $((2 * try))
  done
  grep -v "^$" "$log" | grep -v "WARN|" || true
  if grep -q " ERR| " "$log"; then rc=1; fi
  rm -f "$log"
  return $rc
}
if [ -z "$rest" ]; then
  skip fig2 "no snapshots of the column"
elif command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
  render_step "$rest"
  [ "$loaded" != "$rest" ] && render_step "$loaded"
else
  skip fig2 "pvbatch or xvfb-run missing (apt-get install paraview python3-paraview xvfb xauth)"
fi

echo "column_figures: made: ${made[*]:-none}"
if [ ${#skipped[@]} -gt 0 ]; then
  echo "column_figures: skipped:"
  printf '  %s\n' "${skipped[@]}"
fi
[ ${#made[@]} -gt 0 ]
