#!/usr/bin/env python3
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

"""Tables (markdown) of the runs of benchmarks/mpi/run.sh; exits 1 if a tolerance fails.

  check.py pour REF DIR...      piles poured by in.pour, each compared with REF (1 rank)
  check.py continue DIR...      the same settled pile continued by in.continue

Each DIR is a run folder (log.lammps, grains.txt, contacts.*.txt); its name after the last
'.' in "pour.NAME" is the row label. Plain python3, no numpy.
"""
import argparse
import glob
import math
import os
import re
import sys

# Tolerances of a pile against the 1-rank pile (doc/mpi.md says why):
V_REST = 1e-3        # at rest: mean speed over the window below V_REST (units of sqrt(g d), d ~ 1)
MOVING_TOL = 0.03    # grains not at rest, fraction of the pile: in 1-rank pours at tolerance
                     # 1e-4, 0 to 1 grain of 80 still creeps near its friction limit
FLOOR_TOL = 1e-3     # |floor/weight - 1| of the window mean: 10 x the solver tolerance (a
                     # per-step force is right to about that; the mean is closer still:
                     # at rest it is fixed by momentum balance)
# relative, from the scatter of 1-rank pours with other initial velocities (set by run.sh)
HEIGHT_TOL = float(os.environ.get("HEIGHT_TOL", 0.05))
FORCE_TOL = float(os.environ.get("FORCE_TOL", 0.15))


def log_of(run):
    text = open(os.path.join(run, "log.lammps")).read()
    results = [dict(zip(m.split()[1::2], m.split()[2::2]))
               for m in re.findall(r"^result .*$", text, re.M)]
    # fix nscd warns at most every 1000 steps: the worst residual it named
    worst = max([float(r) for r in re.findall(r"ended unconverged: residual (\S+)", text)] or [0.0])
    for r in results:
        r["worst_warned"] = worst
    loops = [(float(t), int(p), int(s)) for t, p, s in
             re.findall(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps", text, re.M)]
    return results, loops


def grains(name):
    lines = open(name).read().splitlines()
    start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    return {int(float(line.split()[0])): dict(zip(cols, map(float, line.split())))
            for line in lines[start + 1:]}


def grains_at_rest(run, window_time):
    """Grains whose farthest surface point moved less than V_REST * window_time over the
    window (translation + rotation angle x bounding radius), i.e. a mean speed below
    V_REST. Not the speed at one instant: a grain rocking on a rounded edge (rolling
    without slip, no impact: NSCD does not damp it) keeps |w| R ~ 1e-2 but goes nowhere."""
    names = sorted(glob.glob(os.path.join(run, "grains.*.txt")),
                   key=lambda n: int(n.rsplit(".", 2)[-2]))
    first, last = grains(names[0]), grains(names[-1])
    rest = 0
    for tag, g in last.items():
        g0 = first[tag]
        shift = math.dist([g["x"], g["y"], g["z"]], [g0["x"], g0["y"], g0["z"]])
        dot = abs(sum(g[f"c_q[{k}]"] * g0[f"c_q[{k}]"] for k in range(1, 5)))
        angle = 2 * math.acos(min(1.0, dot))
        rest += shift + angle * g["radius"] < V_REST * window_time
    return rest


def mean_contact_force(run):
    """Mean normal force per force-carrying grain-grain contact, over the snapshots. The
    points of one grain pair are summed: how a face contact's force splits among its
    points is not unique for rigid grains (it follows the Gauss-Seidel order, which the
    decomposition changes); the pair's total is far less so."""
    means = []
    for name in sorted(glob.glob(os.path.join(run, "contacts.*.txt"))):
        lines = open(name).read().splitlines()
        start = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ENTRIES"))
        pairs = {}
        for line in lines[start + 1:]:
            i, j, fn = line.split()
            i, j = int(float(i)), int(float(j))
            if j > 0:    # walls have j < 0
                key = (min(i, j), max(i, j))
                pairs[key] = pairs.get(key, 0.0) + float(fn)
        carrying = [f for f in pairs.values() if f > 0]
        means.append(sum(carrying) / len(carrying))
    return sum(means) / len(means), len(means)


def label(run):
    return os.path.basename(run.rstrip("/")).split(".", 1)[-1]


def pile(run):
    """The statistics of one pour, or None if it did not finish."""
    try:
        results, loops = log_of(run)
        r = results[0]
        force, _ = mean_contact_force(run)
        rest = grains_at_rest(run, loops[-1][2] * float(r["dt"]))
    except (OSError, IndexError, StopIteration, ZeroDivisionError):
        return None
    weight, height, side = float(r["weight"]), float(r["height"]), float(r["side"])
    return dict(ranks=loops[-1][1], atoms=int(r["atoms"]), rest=rest,
                floor=float(r["floor_mean"]) / weight - 1, height=height,
                fraction=weight / (side * side * height),    # density 1, g = 1: weight = volume
                force=force, sweeps=float(r["sweeps_mean"]),
                step=loops[-1][0] / loops[-1][2],
                to_rest=sum(s for _, _, s in loops[:-1]), pour=sum(t for t, _, _ in loops[:-1]),
                unconverged=float(r["unconverged_before"]), worst=r["worst_warned"])


def pour(ref, runs):
    """Each pile against the mean of the 1-rank piles (REF and any other 1-rank runs): pours
    differing only in their initial velocities scatter, so one 1-rank pile is no better a
    reference than another."""
    rows = {run: pile(run) for run in [ref] + runs}
    singles = [row for row in rows.values() if row is not None and row["ranks"] == 1]
    print(f"Piles at rest (statistics over a window at rest; a grain is at rest if its "
          f"farthest point moved less than {V_REST} x the window's duration). "
          f"Tolerances: same atoms as the 1-rank pile, at most {MOVING_TOL:.0%} of the grains not "
          f"at rest, "
          f"|floor/weight - 1| < {FLOOR_TOL}, height within {HEIGHT_TOL:.0%}, "
          f"mean contact force within {FORCE_TOL:.0%} of the mean of the {len(singles)} "
          f"1-rank pile(s) (the percentages).\n")
    print("| run | ranks | atoms | at rest | floor/weight - 1 | height H = 2 z_com | "
          "solid fraction | mean contact force | steps to rest | unconverged steps (worst residual) | pour+settle s | "
          "window sweeps/step | window s/step | check |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    failed = False
    base = None
    if rows[ref] is not None and singles:
        base = dict(atoms=rows[ref]["atoms"],
                    height=sum(r["height"] for r in singles) / len(singles),
                    force=sum(r["force"] for r in singles) / len(singles))
    for run, row in rows.items():
        if row is None or base is None:
            print(f"| {label(run)} | | | | | | | | | | | | | FAILED: no result, see {run}/log.lammps |")
            failed = True
            continue
        dh, df = row["height"] / base["height"] - 1, row["force"] / base["force"] - 1
        bad = [name for name, broken in [
            ("atoms", row["atoms"] != base["atoms"]), ("at rest", row["atoms"] - row["rest"] > MOVING_TOL * row["atoms"]),
            ("floor", abs(row["floor"]) > FLOOR_TOL), ("height", abs(dh) > HEIGHT_TOL),
            ("force", abs(df) > FORCE_TOL)] if broken]
        failed |= bool(bad)
        print(f"| {label(run)} | {row['ranks']} | {row['atoms']} | {row['rest']} | "
              f"{row['floor']:+.1e} | {row['height']:.4f} ({dh:+.1%}) | {row['fraction']:.3f} | "
              f"{row['force']:.4f} ({df:+.1%}) | {row['to_rest']} | "
              f"{row['unconverged']:.1%} ({row['worst']:.2g}) | {row['pour']:.0f} | "
              f"{row['sweeps']:.1f} | {row['step']:.4f} | "
              f"{'FAILED: ' + ', '.join(bad) if bad else 'ok'} |")
    return failed


def continued(runs):
    print("\nThe same settled pile (the 1-rank pile's restart) continued on each rank count: "
          "at rest, then with gravity tilted by 34 degrees (the pile slides; contacts open, "
          "close and change rank). Means over each phase; (x) = ratio to the 1-rank run. "
          "yield = Open MPI's mpi_yield_when_idle.\n")
    print("| run | ranks | rest: sweeps/step | rest: residual | rest: s/step | "
          "tilt: sweeps/step | tilt: residual | tilt: converged steps | tilt: s/step | atoms |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    base = None
    for run in runs:
        results, loops = log_of(run)
        if not results or len(loops) < len(results):
            print(f"| {label(run)} | | | | | | | | | did not finish, see {run}/log.lammps |")
            continue
        phases = [(float(r["sweeps_mean"]), r["residual_mean"], t / s, r["converged_fraction"])
                  for r, (t, _, s) in zip(results, loops)]
        base = base or phases
        cells = []
        for (sweeps, residual, step, _), (b_sweeps, _, b_step, _) in zip(phases, base):
            cells += [f"{sweeps:.2f} ({sweeps / b_sweeps:.2f}x)", residual,
                      f"{step:.4f} ({step / b_step:.2f}x)"]
        if len(phases) > 1:
            cells.insert(5, phases[1][3])
        cells += ["(not run)"] * (7 - len(cells))
        print(f"| {label(run)} | {loops[0][1]} | " + " | ".join(cells) + f" | {results[-1]['atoms']} |")
    return False


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    modes = parser.add_subparsers(dest="mode", required=True)
    p = modes.add_parser("pour", help="piles poured by in.pour, each compared with REF (1 rank)")
    p.add_argument("ref", help="run folder of the 1-rank pour")
    p.add_argument("dirs", nargs="+", metavar="DIR", help="run folders compared with REF")
    p = modes.add_parser("continue", help="the same settled pile continued by in.continue")
    p.add_argument("dirs", nargs="+", metavar="DIR", help="run folders (the first: 1 rank)")
    args = parser.parse_args()
    failed = pour(args.ref, args.dirs) if args.mode == "pour" else continued(args.dirs)
    if failed:
        print("\nFAILED: a run differs from the 1-rank run by more than a tolerance")
    sys.exit(1 if failed else 0)
