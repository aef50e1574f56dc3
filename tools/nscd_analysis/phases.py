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

"""Per-phase table of a log of examples/column/in.column (or examples/silo/in.silo, or any deck
that prints a phase number as a thermo column), `nscd-analysis phases` (doc/analysis.md):
steps, wall time (sum of the runs' "Loop time"), wall time per step, mean solver sweeps per
step, fraction of unconverged steps, largest interpenetration and median residual of the
thermo rows (thermo columns f_nscd[3] and f_nscd[2], where the log has them), then where the
time went (the time-per-part tables fix
nscd and fix wire print after each run, summed over the phase's runs: each part's average
over the ranks in % of the wall time, and the busy share of the slowest rank, i.e. the wall
time less the least time any rank spent in communication, waiting included), then the
deck's "phase N done" lines. A run still going (no "Loop time" yet) is left out, with a note.
A phase whose runs took no steps (only `run 0`, or its steps were in the run left out) is
shown with 0 steps and empty rates, not dropped. Columns the log lacks are left empty.

    tools/nscd-analysis phases log.column [log.column.2 ...] [--csv out.csv] [--parts parts.csv]

Reads the thermo columns --phase-column (v_phase), f_solver[1] and f_solver[2] (sweeps and
unconverged fraction), f_nscd[2] and f_nscd[3] (residual, interpenetration) where printed."""

import re
import sys

from . import logs

LOOP = re.compile(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps")
TABLE = re.compile(r"^fix (nscd|wire) \S+: time per part")
ROW = re.compile(r"^(.+?)\s*\|\s*(\S+)\s*\|\s*(\S+)\s*\|\s*(\S+)\s*\|")
NAMES = {1: "deposit", 2: "relax", 3: "walls", 4: "relax", 5: "load"}    # examples/column's v_phase
COMMUNICATION = ("nscd: sweep communication", "wire: communication")


def loop_times(path):
    with open(path) as f:
        return [(float(m.group(1)), int(m.group(3))) for m in map(LOOP.match, f) if m]


def summarise_logs(paths, phase_column="v_phase"):
    """summarise of each log (a run split by restarts), the phases of all merged."""
    phases = {}
    for path in paths:
        for phase, p in summarise(path, phase_column).items():
            merge(phases.setdefault(phase, new_phase()), p)
    return phases


def new_phase():
    return {"steps": 0, "seconds": 0.0, "sweeps": [], "unconverged": [], "residual": [], "overlap": [],
            "parts": {}, "least_communication": 0.0}


def merge(into, p):
    for key in ("steps", "seconds", "least_communication"):
        into[key] += p[key]
    for key in ("sweeps", "unconverged", "residual", "overlap"):
        into[key] += p[key]
    for name, seconds in p["parts"].items():
        into["parts"][name] = into["parts"].get(name, 0.0) + seconds


def part_times(path):
    """Per finished run (in the order of the 'Loop time' lines): {"nscd: sweeps": (min, avg,
    max), ...} from the time-per-part tables printed before the run's 'Loop time' line."""
    runs, pending, style = [], {}, None
    with open(path) as f:
        for line in f:
            table = TABLE.match(line)
            if table:
                style = table.group(1)
                continue
            if style:
                row = ROW.match(line)
                if line.startswith(("part ", "---")):
                    pass    # the table's header and rule
                elif row and row.group(1) != "total":
                    pending[f"{style}: {row.group(1)}"] = tuple(float(row.group(k)) for k in (2, 3, 4))
                elif row is None:
                    style = None
            if LOOP.match(line):
                runs.append(pending)
                pending, style = {}, None
    return runs


def summarise(path, phase_column="v_phase"):
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
    parts = part_times(path)
    phases = {}
    for (columns, data), (seconds, steps), times in zip(blocks, loops, parts):
        if phase_column not in columns or not len(data):
            continue
        phase = int(data[-1, columns.index(phase_column)])
        p = phases.setdefault(phase, new_phase())
        p["steps"] += steps
        p["seconds"] += seconds
        for name, (low, average, _) in times.items():
            p["parts"][name] = p["parts"].get(name, 0.0) + average
        p["least_communication"] += sum(times[name][0] for name in COMMUNICATION if name in times)
        if steps and "f_solver[1]" in columns:
            rows = data[1:]    # the first row repeats the state before the run
            p["sweeps"] += list(rows[:, columns.index("f_solver[1]")])
            p["unconverged"] += list(rows[:, columns.index("f_solver[2]")])
        for column, key in (("f_nscd[2]", "residual"), ("f_nscd[3]", "overlap")):
            if steps and column in columns:
                p[key] += list(data[1:, columns.index(column)])
    return phases


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def median(values):
    ordered = sorted(values)
    if not ordered:
        return float("nan")
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else 0.5 * (ordered[middle - 1] + ordered[middle])


def table_rows(phases, names=NAMES):
    """The per-phase CSV rows (header first) and the 'all' row; phases of 0 steps included."""
    header = ("phase,name,steps,wall_s,ms_per_step,mean_sweeps,unconverged_fraction,"
              "largest_interpenetration,median_residual")
    rows = []
    for phase in sorted(phases):
        p = phases[phase]
        if not p["steps"]:
            # only 'run 0' (or the phase's steps were in the run left out): shown, no rates
            rows.append(f"{phase},{names.get(phase, '')},0,{p['seconds']:.1f},,,,,")
            continue
        per_step = 1000 * p["seconds"] / p["steps"]
        rows.append(f"{phase},{names.get(phase, '')},{p['steps']},{p['seconds']:.1f},{per_step:.1f},"
                    f"{_or_empty(mean(p['sweeps']), '.1f')},{_or_empty(mean(p['unconverged']), '.3f')},"
                    f"{_or_empty(max(p['overlap'], default=float('nan')), '.2g')},"
                    f"{_or_empty(median(p['residual']), '.2g')}")
    total_steps = sum(p["steps"] for p in phases.values())
    total_s = sum(p["seconds"] for p in phases.values())
    rows.append(f"all,,{total_steps},{total_s:.1f},{1000 * total_s / max(total_steps, 1):.1f},,,,")
    return header, rows


def _or_empty(value, spec):
    return "" if value != value else format(value, spec)    # NaN: the log lacks the column


def run(args):
    """nscd-analysis phases: print the tables, write the CSV files asked for."""
    phases = summarise_logs(args.log, args.phase_column)
    if not phases:
        raise logs.LogError(f"{' + '.join(args.log)}: no run prints the phase column {args.phase_column} "
                            "(give --phase-column)")
    names = NAMES if args.phase_column == "v_phase" else {}    # another deck's phases: no names
    header, rows = table_rows(phases, names)
    print(header)
    print("\n".join(rows))
    part_rows = part_table(phases, names)
    if part_rows:
        print()
        print("\n".join(part_rows))
    for path in args.log:
        with open(path) as f:
            for line in f:
                if re.match(r"^phase \d", line):
                    print(line.rstrip())
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(header + "\n" + "\n".join(rows) + "\n")
    if args.parts and part_rows:
        with open(args.parts, "w") as f:
            f.write("\n".join(part_rows) + "\n")


def part_table(phases, phase_names=NAMES):
    """Where the time of each phase went: each part's average over the ranks in % of the
    phase's wall time, and the slowest rank's busy share (CSV rows, header first)."""
    names = sorted({name for p in phases.values() for name in p["parts"]})
    if not names:
        return []
    rows = ["phase,name,wall_s," + ",".join(f"{n} %" for n in names) + ",slowest rank busy %"]
    for phase in sorted(phases):
        p = phases[phase]
        if not p["steps"] or not p["seconds"]:
            continue
        shares = ",".join(f"{100 * p['parts'].get(n, 0.0) / p['seconds']:.1f}" for n in names)
        busy = 100 * (1 - p["least_communication"] / p["seconds"])
        rows.append(f"{phase},{phase_names.get(phase, '')},{p['seconds']:.1f},{shares},{busy:.1f}")
    return rows

