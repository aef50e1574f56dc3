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

"""Reads growth.sh's logs and prints, per method, the sweeps per step of the 20- and
40-layer columns of every seed and their ratio (issue 14: 40 over 20 layers <= 1.5), as a
markdown table.

    /usr/bin/python3 growth.py WORK_DIR RAMP
"""
import argparse
import glob
import os
import re
import statistics

from report import read_log, setting


def sweeps_of(path):
    """Sweeps of every solved step (the first thermo row is the setup's), the median
    floor error |F_floor + W| / W, and the number of steps that ended above the tolerance."""
    rows, _, command, _ = read_log(path)
    steps = rows[1:]
    floor = statistics.median(abs(r[4] + r[5]) / r[5] for r in steps) if steps else float("nan")
    tolerance = setting(command, "tolerance", 1e-4)
    return [r[1] for r in steps], floor, sum(1 for r in steps if r[2] > tolerance)


def cell(sweeps, unconverged):
    text = f"{statistics.median(sweeps):.0f} / {statistics.mean(sweeps):.1f} / {max(sweeps):.0f}"
    return text + (f" ({unconverged} unconverged)" if unconverged else "")


def main(work, ramp):
    runs = {}    # (method, seed) -> {layers: (sweeps, floor error)}
    for path in glob.glob(os.path.join(work, f"column*_s*.*.ramp{ramp}.log")):
        m = re.match(r"column(\d+)_s(\d+)\.(.+)\.ramp", os.path.basename(path))
        sweeps, floor, unconverged = sweeps_of(path)
        if sweeps:
            runs.setdefault((m.group(3).replace("_", " "), m.group(2)), {})[int(m.group(1))] = \
                (sweeps, floor, unconverged)
    print(f"ramp {ramp}: sweeps per step (median / mean / max) and floor error, "
          "20 and 40 layers; growth = mean 40 / mean 20\n")
    print("| method | seed | 20 layers | 40 layers | growth of the mean | floor error 20 / 40 |")
    print("|---|---|---|---|---|---|")
    for method in sorted({k[0] for k in runs}):
        totals, failed = {20: [], 40: []}, {20: 0, 40: 0}
        for seed in sorted({k[1] for k in runs if k[0] == method}, key=int):
            both = runs[(method, seed)]
            if 20 not in both or 40 not in both:
                continue
            cells = []
            for layers in (20, 40):
                sweeps, _, unconverged = both[layers]
                totals[layers] += sweeps
                failed[layers] += unconverged
                cells.append(cell(sweeps, unconverged))
            growth = statistics.mean(both[40][0]) / max(statistics.mean(both[20][0]), 1e-9)
            print(f"| `{method}` | {seed} | {cells[0]} | {cells[1]} | x{growth:.2f} | "
                  f"{both[20][1]:.1e} / {both[40][1]:.1e} |")
        if totals[20] and totals[40]:
            growth = statistics.mean(totals[40]) / max(statistics.mean(totals[20]), 1e-9)
            print(f"| `{method}` | all | {cell(totals[20], failed[20])} | {cell(totals[40], failed[40])} | "
                  f"**x{growth:.2f}** ({'met' if growth <= 1.5 else 'NOT met'}) | |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("work", help="folder of growth.sh's logs")
    parser.add_argument("ramp", nargs="?", default="0", help="the RAMP of the runs, as in their log names (default 0)")
    args = parser.parse_args()
    main(args.work, args.ramp)
