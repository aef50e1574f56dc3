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

"""Reads the logs of benchmarks/hard/run.sh and writes the hard-case table into
doc/BENCHMARKS.md (between the markers <!-- hard:begin --> and <!-- hard:end -->, the rest
of the file is kept) and the speed-against-error plot.

    /usr/bin/python3 report.py WORK_DIR BENCHMARKS.md PLOT.png
"""
import argparse
import glob
import os
import platform
import re
import statistics
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from nscd_analysis import logs  # noqa: E402

SCENES = ["tower20", "pyramid10", "column20", "column40", "pile"]
METHODS = ["method gs", "method nesterov", "method nesterov coarse yes"]


def read_log(path):
    """Per-step thermo rows (step, sweeps, residual, overlap, floor fz, weight, contacts) of
    the measured run (the log's last), the loop time and step count, the command line, the
    grain count."""
    loop, command, grains = None, "", 0
    with open(path) as f:
        for line in f:
            if line.startswith("Loop time of"):
                m = re.match(r"Loop time of ([\d.eE+-]+) on \d+ procs for (\d+) steps with (\d+)", line)
                loop, grains = (float(m.group(1)), int(m.group(2))), int(m.group(3))
            elif line.startswith("# command:"):
                command = line[len("# command:"):].strip()
    try:
        rows = logs.read_thermo(path)[-1][1].tolist()
    except logs.LogError:
        rows = []
    return rows, loop, command, grains


def setting(command, key, default):
    """The last value given to `key` in a run's command line (as -var key V or as a fix
    nscd keyword inside the solver string), else default."""
    values = re.findall(rf"(?:-var )?\b{key} ([\d.eE+-]+)", command)
    return float(values[-1]) if values else default


def summarise(path):
    rows, loop, command, grains = read_log(path)
    steps = rows[1:]    # the first row is the setup's, before any solve
    if not steps or loop is None:
        return None
    sweeps = [r[1] for r in steps]
    floor_error = [abs(r[4] + r[5]) / r[5] for r in steps]
    dt = setting(command, "dt", 0.005)
    max_sweeps = setting(command, "max_sweeps", float("inf"))
    return {
        "grains": grains,
        "median": statistics.median(sweeps),
        "mean": statistics.mean(sweeps),
        "max": max(sweeps),
        "unconverged": sum(1 for r in steps if r[2] > 0 and r[1] >= max_sweeps),
        "ms": 1e3 * loop[0] / loop[1],
        "per_time": loop[0] / (loop[1] * dt),    # wall seconds per simulated time unit
        "dt": dt,
        "residual": statistics.mean(r[2] for r in steps),
        "floor": statistics.median(floor_error),
        "overlap_start": steps[0][3],
        "overlap_end": steps[-1][3],
        "overlap_max": max(r[3] for r in steps),
        "command": command,
    }


def label_of(log_tag):
    """'method_nesterov_theta_0.5+dt0.0025' -> 'method nesterov theta 0.5, dt 0.0025'."""
    solver, _, dt = log_tag.partition("+dt")
    return solver.replace("_", " ") + (f", dt {dt}" if dt else "")


def main(work, markdown, plot):
    results = {}
    for path in glob.glob(os.path.join(work, "*.log")):
        name = os.path.basename(path)
        m = re.match(r"([a-z0-9]+)\.(.+)\.(1e-\d+)\.log$", name)
        if not m or m.group(1) not in SCENES:
            continue
        s = summarise(path)
        if s:
            results[(m.group(1), label_of(m.group(2)), m.group(3))] = s
    labels = METHODS + sorted({k[1] for k in results} - set(METHODS))

    lines = ["<!-- hard:begin -->", "## Hard cases: solver methods (`benchmarks/hard`)", ""]
    cpu = subprocess.run(["sh", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                         capture_output=True, text=True).stdout.strip()
    lines += [
        f"Written by `benchmarks/hard/run.sh` (report.py) on {platform.node()}: {cpu}, "
        f"{os.cpu_count()} cores shared with other jobs (load average "
        f"{os.getloadavg()[0]:.1f} at the end), so wall times are noisy (±30 % or worse); "
        "sweeps, floor errors and overlaps are exact for the deck. Every run: dt = 0.005 (unless the method column names another), "
        "g = 9.81, the steps after the restart (or from rest), thermo every step.",
        "",
        "Columns: sweeps per step median / mean / max; ms/step = `Loop time` / steps (wall); "
        "s per time unit = wall seconds per simulated time unit (runs at another dt cover the "
        "same simulated time); residual = mean over the steps of the residual reached "
        "(f_nscd[2]); floor error = median over steps of |F_floor + W| / W (W = weight of "
        "grains and plate: the closed-form reaction of a scene at rest); overlap = max "
        "predicted overlap (f_nscd[3]) at the first / last step, and its largest over the run. "
        "The rows after the three methods change one setting of the default method "
        "(`theta`, `max_sweeps`, dt, tolerance).",
        "",
        "| scene | grains | method | tolerance | sweeps median / mean / max | unconverged steps | ms/step | s per time unit | residual | floor error | overlap first / last / max |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for scene in SCENES:
        for label in labels:
            for tol in sorted({k[2] for k in results}, key=float, reverse=True):
                s = results.get((scene, label, tol))
                if not s:
                    continue
                lines.append(
                    f"| {scene} | {s['grains']} | `{label}` | {tol} | {s['median']:.0f} / "
                    f"{s['mean']:.1f} / {s['max']:.0f} | {s['unconverged']} | {s['ms']:.2f} | "
                    f"{s['per_time']:.2f} | {s['residual']:.1e} | {s['floor']:.2e} | "
                    f"{s['overlap_start']:.4f} / {s['overlap_end']:.4f} / {s['overlap_max']:.4f} |")
    lines += ["", "Targets of issue 14 at tolerance 1e-4 (mean sweeps per step):", ""]
    for method in METHODS:
        pile = results.get(("pile", method, "1e-4"))
        c20 = results.get(("column20", method, "1e-4"))
        c40 = results.get(("column40", method, "1e-4"))
        parts = []
        if pile:
            parts.append(f"settled {pile['grains']}-grain pile {pile['mean']:.1f} (<= 50: "
                         f"{'met' if pile['mean'] <= 50 else 'NOT met'})")
        if c40:
            parts.append(f"40-layer column under the plate {c40['mean']:.1f} (<= 200: "
                         f"{'met' if c40['mean'] <= 200 else 'NOT met'})")
        if c20 and c40:
            growth = c40["mean"] / max(c20["mean"], 1e-9)
            parts.append(f"20 -> 40 layers x{growth:.2f} (<= 1.5: "
                         f"{'met' if growth <= 1.5 else 'NOT met'})")
        if parts:
            lines.append(f"* `{method}`: " + "; ".join(parts))
    lines += ["", "Commands (WORK = the runner's scratch directory; the settled column and "
              "pile come from `in.column_settle` and `in.pile_settle` there):", ""]
    for key in sorted(results):
        lines.append(f"* {key[0]}, {key[1]}, {key[2]}: `{results[key]['command']}`")
    lines += ["", "![speed against error](img/hard_speed_error.png)", "", "<!-- hard:end -->"]
    block = "\n".join(lines) + "\n"

    if os.path.exists(markdown):
        old = open(markdown).read()
        if "<!-- hard:begin -->" in old:
            before = old.split("<!-- hard:begin -->")[0]
            after = old.split("<!-- hard:end -->")[1].lstrip("\n")
            text = before + block + ("\n" + after if after else "")
        else:
            text = old.rstrip("\n") + "\n\n" + block
    else:
        text = "# Benchmarks\n\n" + block
    open(markdown, "w").write(text)

    # Pareto plots: cost against error, one point per run (colour: scene, marker: method or
    # the setting changed)
    fig, axes = plt.subplots(1, 3, figsize=(15, 3.8), dpi=80)
    marker_list = ["o", "s", "^", "v", "D", "P", "X", "*"]
    markers = {label: marker_list[k % len(marker_list)] for k, label in enumerate(labels)}
    colours = dict(zip(SCENES, ["C0", "C1", "C2", "C3", "C4"]))
    panels = (("per_time", "overlap_max", "wall s per simulated time unit", "max predicted overlap"),
              ("ms", "residual", "wall ms per step", "residual reached (mean)"),
              ("mean", "floor", "sweeps per step (mean)", "floor error |F+W|/W (median)"))
    for (scene, label, tol), s in results.items():
        for ax, (x, y, _, _) in zip(axes, panels):
            ax.scatter(s[x], max(s[y], 1e-12), marker=markers[label], s=25,
                       edgecolors=colours[scene],
                       facecolors="none" if tol == "1e-3" else colours[scene])
    for ax, (_, _, xlabel, ylabel) in zip(axes, panels):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
    handles = [plt.Line2D([], [], color=c, marker="o", ls="") for c in colours.values()]
    handles += [plt.Line2D([], [], color="k", marker=m, ls="") for m in markers.values()]
    axes[2].legend(handles, list(colours) + [m.replace("method ", "") for m in markers],
                   fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))    # beside, not on the points
    axes[0].set_title("open markers: tolerance 1e-3", fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(plot), exist_ok=True)
    fig.savefig(plot)
    print(f"wrote {markdown} and {plot} ({len(results)} runs)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("work", help="folder of run.sh's logs")
    parser.add_argument("markdown", help="BENCHMARKS.md: the table goes between its hard:begin/end markers")
    parser.add_argument("plot", help="the speed-against-error plot (PNG) written")
    args = parser.parse_args()
    main(args.work, args.markdown, args.plot)
