#!/usr/bin/python3
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

"""Tabulates benchmarks/column/accuracy.sh: per setting, the mean and the scatter (sample
standard deviation) over the seeds of the column's outcome, and the cost.

    /usr/bin/python3 accuracy.py --work DIR --settings today new --seeds 1 2 3 [--csv out.csv]

Outcome, from the deck's "phase N done" lines and its thermo: height and retained fraction
kept through the walls (phase 3 over the state before them) and through the relaxation after
them (phase 4), the wire's stretch energy at rest after phase 4, the plate's sink (from the
seated height) at loads 50 and 100. Cost: steps, wall and user CPU seconds."""

import argparse
import math
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from nscd_analysis import logs  # noqa: E402

NUMBER = r"([-+0-9.eE]+)"
PHASE2 = re.compile(r"^phase 2 done: .*height " + NUMBER + r", retained fraction " + NUMBER)
PHASE3 = re.compile(r"^phase 3 done: height " + NUMBER + r" \(before " + NUMBER + r"\), retained fraction "
                    + NUMBER + r" \(before " + NUMBER + r"\)")
PHASE4 = re.compile(r"^phase 4 done: height " + NUMBER + r", retained fraction " + NUMBER
                    + r", wire stretch energy " + NUMBER)
LOOP = re.compile(r"^Loop time of \S+ on \d+ procs for (\d+) steps")
TIME = re.compile(r"^" + NUMBER + r" s wall, " + NUMBER + r" s user")
LOADS = (50.0, 100.0)
QUANTITIES = ["height kept (walls)", "height kept (walls + relax)", "retained kept (walls)",
              "retained kept (walls + relax)", "stretch energy at rest"] + \
             [f"plate sink at load {load:g}" for load in LOADS] + ["steps", "wall s", "user s"]


def sink_at(path, load):
    """The plate's displacement (downward positive) at the first thermo row of the loading
    with v_plate_load >= load; NaN if the loading did not get there."""
    for columns, data in logs.read_thermo(path):
        if "v_plate_load" not in columns or not len(data):
            continue
        phase, loads = data[:, columns.index("v_phase")], data[:, columns.index("v_plate_load")]
        for row, (p, value) in enumerate(zip(phase, loads)):
            if p == 5 and value >= load - 1e-9:
                return -data[row, columns.index("v_plate_disp")]
    return math.nan


def outcome(path, time_path):
    values = {}
    steps = 0
    with open(path) as f:
        for line in f:
            for pattern, key in ((PHASE3, 3), (PHASE4, 4)):
                m = pattern.match(line)
                if m:
                    values[key] = [float(x) for x in m.groups()]
            m = LOOP.match(line)
            if m:
                steps += int(m.group(1))
    if 3 not in values or 4 not in values:
        return None
    h3, h2, f3, f2 = values[3]
    h4, f4, stretch = values[4]
    result = {"height kept (walls)": h3 / h2, "height kept (walls + relax)": h4 / h2,
              "retained kept (walls)": f3 / f2, "retained kept (walls + relax)": f4 / f2,
              "stretch energy at rest": stretch, "steps": steps}
    for load in LOADS:
        result[f"plate sink at load {load:g}"] = sink_at(path, load)
    result["wall s"] = result["user s"] = math.nan
    if os.path.exists(time_path):
        with open(time_path) as f:
            for line in f:
                m = TIME.match(line.strip())
                if m:
                    result["wall s"], result["user s"] = float(m.group(1)), float(m.group(2))
    return result


def summary(values):
    finite = [v for v in values if not math.isnan(v)]
    if not finite:
        return "—"
    mean = statistics.mean(finite)
    scatter = statistics.stdev(finite) if len(finite) > 1 else 0.0
    digits = ".3g" if abs(mean) < 10 else ".0f"
    return f"{mean:{digits}} ± {scatter:{digits}} ({len(finite)})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--work", required=True)
    parser.add_argument("--settings", nargs="+", required=True)
    parser.add_argument("--seeds", nargs="+", required=True)
    parser.add_argument("--csv")
    args = parser.parse_args()
    table, rows = {}, ["setting,seed," + ",".join(QUANTITIES)]
    for setting in args.settings:
        for seed in args.seeds:
            base = os.path.join(args.work, f"{setting}.{seed}")
            result = outcome(base + ".log", base + ".time") if os.path.exists(base + ".log") else None
            if result is None:
                print(f"{setting} seed {seed}: no complete run (phases 3 and 4)", file=sys.stderr)
                continue
            table.setdefault(setting, []).append(result)
            rows.append(f"{setting},{seed}," + ",".join(f"{result[q]:.6g}" for q in QUANTITIES))
    print("| quantity | " + " | ".join(table) + " |")
    print("|---|" + "---|" * len(table))
    for q in QUANTITIES:
        print(f"| {q} | " + " | ".join(summary([r[q] for r in table[s]]) for s in table) + " |")
    print("(mean ± sample standard deviation over the seeds (number of seeds))")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
