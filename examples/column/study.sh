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

# Parameter study of the wire column (the papers' Ref. [12] question: what keeps it up?):
# one parameter at a time around the deck's defaults, a small column each, through all
# phases of in.column. Writes study/study.csv and study/study.md (height and retained
# fraction before the wall removal and after it and the relaxation, wire stretch energy at
# rest, plate force at failure).
#
#   examples/column/study.sh                       # from anywhere; LMP=path/to/lmp to choose
#   SIZE="-var layers 5 -var R 2 -var cells 2" examples/column/study.sh    # another size
#   MU_PW="0.2 0.8" K_ELO="1000 10000" MU_PP="0.3 0.8" K_ROT="0.1 10" examples/column/study.sh
#   SIZE_MIN="0.6 0.95" SUBSTEPS="stable 400" examples/column/study.sh   # grain sizes, wire substeps
#   SEEDS="2026 7 11" examples/column/study.sh     # every point once per seed (deposits differ)
#   LAUNCH="mpiexec -np 2" examples/column/study.sh
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lmp=${LMP:-$here/../../build/lmp}
read -r -a launch <<< "${LAUNCH:-}"
read -r -a size <<< "${SIZE:--var layers 3 -var R 2.5 -var window cylinder -var cells 2 -var element 0.3 -var layer_steps 400 -var wire_steps 100 -var relax_chunk 250 -var relax_max 2 -var wall_speed 0.3 -var wall_travel 0.6 -var seat_steps 100 -var load_chunk 100 -var load_max 20 -var load_rate 20 -var dump_every 100000}"
mu_pw=(${MU_PW:-0.2 0.8}); k_elo=(${K_ELO:-1000 10000}); mu_pp=(${MU_PP:-0.3 0.8})    # around 0.5, 5000, 0.5
k_rot=(${K_ROT:-}); seeds=(${SEEDS:-2026})                                              # k_rot: none by default
size_min=(${SIZE_MIN:-}); substeps=(${SUBSTEPS:-})                                      # none by default (0.8, auto)
out=${OUT:-$PWD/study}
mkdir -p "$out"
cd "$out"

runs=("base:")
for v in "${mu_pw[@]}"; do runs+=("mu_pw:$v"); done
for v in "${k_elo[@]}"; do runs+=("k_elo:$v"); done
for v in "${mu_pp[@]}"; do runs+=("mu_pp:$v"); done
for v in "${k_rot[@]}"; do runs+=("k_rot:$v"); done
for v in "${size_min[@]}"; do runs+=("size_min:$v"); done
for v in "${substeps[@]}"; do runs+=("substeps:$v"); done

field() {    # FILE REGEX: the first group of REGEX in FILE
  sed -nE "s/$2/\1/p" "$1" | head -n 1
}
echo "parameter,value,seed,height_before,height_after,retained_before,retained_after,stretch_energy_at_rest,failure_load,peak_plate_force,wall_s" > study.csv
for seed in "${seeds[@]}"; do
for run in "${runs[@]}"; do
  param=${run%%:*} value=${run#*:}
  name=$param${value:+_$value}_seed$seed
  extra=(-var seed "$seed")
  [ -n "$value" ] && extra+=(-var "$param" "$value")
  t0=$SECONDS
  "${launch[@]}" "$lmp" -in "$here/in.column" -log "log.$name" -var name "$name" "${size[@]}" "${extra[@]}" > "screen.$name.txt"
  log=log.$name
  h_after=$(field "$log" '^phase 4 done: height ([^,]+),.*')        # after the walls and the relaxation
  h_before=$(field "$log" '^phase 3 done: height [^ ]+ \(before ([^)]+)\).*')
  f_after=$(field "$log" '^phase 4 done:.*retained fraction ([^,]+),.*')
  f_before=$(field "$log" '^phase 3 done:.*retained fraction [^ ]+ \(before ([^)]+)\).*')
  stretch=$(field "$log" '^phase 4 done:.*wire stretch energy ([^,]+),.*')
  load=$(field "$log" '^phase 5 done: load ([^,]+),.*')
  grep -q "^phase 5: no failure" "$log" && load=">$load (no failure)"
  peak=$(field "$log" '^phase 5 done:.*\(peak ([^ ]+) at.*')
  [ -n "$value" ] || { param=defaults; value=-; }
  echo "$param,$value,$seed,$h_before,$h_after,$f_before,$f_after,$stretch,$load,$peak,$(( SECONDS - t0 ))" >> study.csv
  echo "study: $name done in $(( SECONDS - t0 )) s"
done
done

/usr/bin/python3 - study.csv > study.md <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
def g(x, fmt="{:.3f}"):
    try:
        return fmt.format(float(x))
    except ValueError:
        return x or "-"    # e.g. ">200 (no failure)"
print("| parameter | value | seed | height before walls -> after walls and relaxation | retained before -> after | kept (after/before) | stretch energy at rest | load at failure | peak plate force | wall s |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    try:
        kept = "{:.2f}".format(float(r["retained_after"]) / float(r["retained_before"]))
    except (ValueError, ZeroDivisionError):
        kept = "-"
    print(f"| {r['parameter']} | {r['value']} | {r['seed']} | {g(r['height_before'])} -> {g(r['height_after'])} | "
          f"{g(r['retained_before'])} -> {g(r['retained_after'])} | {kept} | {g(r['stretch_energy_at_rest'], '{:.3g}')} | "
          f"{g(r['failure_load'], '{:.1f}')} | {g(r['peak_plate_force'], '{:.1f}')} | {r['wall_s']} |")
# with several seeds: each point's mean and standard deviation over the seeds, and Welch's t
# of the difference from the defaults (|t| > 3: separated from the seeds' scatter)
import math
points = {}
for r in rows:
    try:
        h = float(r["height_after"]) / float(r["height_before"])
        f = float(r["retained_after"]) / float(r["retained_before"])
        e = float(r["stretch_energy_at_rest"])
    except (ValueError, ZeroDivisionError):
        continue
    points.setdefault((r["parameter"], r["value"]), []).append((h, f, e))
def mean_sd(x):
    m = sum(x) / len(x)
    return m, math.sqrt(sum((v - m) ** 2 for v in x) / (len(x) - 1)) if len(x) > 1 else 0.0
def welch(a, b):
    (ma, sa), (mb, sb) = mean_sd(a), mean_sd(b)
    se = math.sqrt(sa * sa / len(a) + sb * sb / len(b)) if len(a) > 1 and len(b) > 1 else 0.0
    return f"{(ma - mb) / se:+.1f}" if se > 0 else "-"
if any(len(v) > 1 for v in points.values()):
    base = points.get(("defaults", "-"), [])
    print()
    print("| parameter | value | seeds | height kept | grains kept | stretch energy at rest | t: height, grains, energy |")
    print("|---|---|---|---|---|---|---|")
    for (param, value), v in points.items():
        cols = [[x[k] for x in v] for k in range(3)]
        cells = [("{:.3f} ± {:.3f}" if k < 2 else "{:.3g} ± {:.2g}").format(*mean_sd(cols[k])) for k in range(3)]
        ts = ", ".join(welch(cols[k], [x[k] for x in base]) for k in range(3)) if base and param != "defaults" else ""
        print(f"| {param} | {value} | {len(v)} | {cells[0]} | {cells[1]} | {cells[2]} | {ts} |")
EOF
cat study.md
echo "study: tables in $out/study.csv and $out/study.md"
