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
seated height) at loads 50 and 100, the load at failure (0: failed while seating under the
plate's weight; no failure: the last load, the deck's limit) with its median and, for each
setting after the first, the two-sided Mann-Whitney p against the first. Cost: steps, wall
and user CPU seconds. A log with phase 5 alone (accuracy.sh's CROSS runs) gives the loading's
quantities only."""

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
PHASE5 = re.compile(r"^phase 5 done: load " + NUMBER)
NO_FAILURE = re.compile(r"^phase 5: no failure within")
LOOP = re.compile(r"^Loop time of \S+ on \d+ procs for (\d+) steps")
TIME = re.compile(r"^" + NUMBER + r" s wall, " + NUMBER + r" s user")
LOADS = (50.0, 100.0)
QUANTITIES = ["height kept (walls)", "height kept (walls + relax)", "retained kept (walls)",
              "retained kept (walls + relax)", "stretch energy at rest"] + \
             [f"plate sink at load {load:g}" for load in LOADS] + ["load at failure", "steps", "wall s", "user s"]
FAILURE = "load at failure"


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
    """The quantities of one run; None unless it got through phase 4 or phase 5."""
    values = {}
    steps = 0
    failed = True
    with open(path) as f:
        for line in f:
            for pattern, key in ((PHASE3, 3), (PHASE4, 4), (PHASE5, 5)):
                m = pattern.match(line)
                if m:
                    values[key] = [float(x) for x in m.groups()]
            failed = failed and not NO_FAILURE.match(line)
            m = LOOP.match(line)
            if m:
                steps += int(m.group(1))
    if (3 not in values or 4 not in values) and 5 not in values:
        return None
    result = {q: math.nan for q in QUANTITIES}
    if 3 in values and 4 in values:
        h3, h2, f3, f2 = values[3]
        h4, f4, stretch = values[4]
        result.update({"height kept (walls)": h3 / h2, "height kept (walls + relax)": h4 / h2,
                       "retained kept (walls)": f3 / f2, "retained kept (walls + relax)": f4 / f2,
                       "stretch energy at rest": stretch})
    result["steps"] = steps
    result["failed"] = failed
    if 5 in values:
        result[FAILURE] = values[5][0]
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


def failure_summary(results):
    """Failure loads are draws spread over a decade or more: the median, the values, and
    how many failed while seating (load 0) or not at all (+)."""
    runs = [r for r in results if not math.isnan(r[FAILURE])]
    if not runs:
        return "—"
    values = " ".join(f"{r[FAILURE]:.3g}" + ("" if r["failed"] else "+") for r in runs)
    seating = sum(1 for r in runs if r["failed"] and r[FAILURE] == 0)
    return (f"median {statistics.median(r[FAILURE] for r in runs):.3g} ({len(runs)}; {values}; "
            f"{seating} while seating)")


def mann_whitney_p(a, b):
    """Two-sided Mann-Whitney p of two samples (NaN when either is empty)."""
    a = [v for v in a if not math.isnan(v)]
    b = [v for v in b if not math.isnan(v)]
    if not a or not b:
        return math.nan
    from scipy.stats import mannwhitneyu
    return mannwhitneyu(a, b, alternative="two-sided").pvalue


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
                print(f"{setting} seed {seed}: no complete run (phases 3 and 4, or 5)", file=sys.stderr)
                continue
            table.setdefault(setting, []).append(result)
            rows.append(f"{setting},{seed}," + ",".join(f"{result[q]:.6g}" for q in QUANTITIES))
    print("| quantity | " + " | ".join(table) + " |")
    print("|---|" + "---|" * len(table))
    for q in QUANTITIES:
        cells = (failure_summary(table[s]) if q == FAILURE else summary([r[q] for r in table[s]]) for s in table)
        print(f"| {q} | " + " | ".join(cells) + " |")
    print("(mean ± sample standard deviation over the seeds (number of seeds); load at failure: + = no failure)")
    names = list(table)
    for other in names[1:]:
        p = mann_whitney_p([r[FAILURE] for r in table[names[0]]], [r[FAILURE] for r in table[other]])
        print(f"load at failure, {other} against {names[0]}: Mann-Whitney p = {p:.3g}")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
