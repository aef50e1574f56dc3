#!/usr/bin/python3
"""Per-phase summary of a log of examples/column/in.column (or examples/silo/in.silo):
steps, wall time (sum of the runs' "Loop time"), wall time per step, mean solver sweeps per
step, fraction of unconverged steps, then the deck's "phase N done" lines. A run still going
(no "Loop time" yet) is left out, with a note.

    /usr/bin/python3 summary.py log.column [--csv out.csv]

Needs the thermo columns the deck prints (v_phase, f_solver[1], f_solver[2])."""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from nscd_analysis import logs  # noqa: E402

LOOP = re.compile(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps")
NAMES = {1: "deposit", 2: "relax", 3: "walls", 4: "relax", 5: "load"}


def loop_times(path):
    with open(path) as f:
        return [(float(m.group(1)), int(m.group(3))) for m in map(LOOP.match, f) if m]


def summarise(path):
    blocks = logs.read_thermo(path)
    loops = loop_times(path)
    if len(blocks) == len(loops) + 1:
        # a run still going (or stopped): the finished runs are summarised, the last left out
        print(f"{path}: the last run has no 'Loop time' yet (still running or stopped); its "
              f"{len(blocks[-1][1])} thermo rows are left out", file=sys.stderr)
        blocks = blocks[:-1]
    if len(blocks) != len(loops):
        raise SystemExit(f"{path}: {len(blocks)} thermo blocks but {len(loops)} 'Loop time' lines "
                         "(a run without thermo output)")
    phases = {}
    for (columns, data), (seconds, steps) in zip(blocks, loops):
        if "v_phase" not in columns or not len(data):
            continue
        phase = int(data[-1, columns.index("v_phase")])
        p = phases.setdefault(phase, {"steps": 0, "seconds": 0.0, "sweeps": [], "unconverged": []})
        p["steps"] += steps
        p["seconds"] += seconds
        if steps and "f_solver[1]" in columns:
            rows = data[1:]    # the first row repeats the state before the run
            p["sweeps"] += list(rows[:, columns.index("f_solver[1]")])
            p["unconverged"] += list(rows[:, columns.index("f_solver[2]")])
    return phases


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log")
    parser.add_argument("--csv")
    args = parser.parse_args()
    phases = summarise(args.log)
    header = "phase,name,steps,wall_s,ms_per_step,mean_sweeps,unconverged_fraction"
    rows = []
    for phase in sorted(phases):
        p = phases[phase]
        if not p["steps"]:
            continue    # only a 'run 0' (e.g. the run left out above had the phase's steps)
        per_step = 1000 * p["seconds"] / p["steps"]
        rows.append(f"{phase},{NAMES.get(phase, '?')},{p['steps']},{p['seconds']:.1f},{per_step:.1f},"
                    f"{mean(p['sweeps']):.1f},{mean(p['unconverged']):.3f}")
    total_steps = sum(p["steps"] for p in phases.values())
    total_s = sum(p["seconds"] for p in phases.values())
    rows.append(f"all,,{total_steps},{total_s:.1f},{1000 * total_s / max(total_steps, 1):.1f},,")
    print(header)
    print("\n".join(rows))
    with open(args.log) as f:
        for line in f:
            if re.match(r"^phase \d", line):
                print(line.rstrip())
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(header + "\n" + "\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
