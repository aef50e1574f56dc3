"""Reads the logs of benchmarks/hard/run.sh and writes the hard-case table into
doc/BENCHMARKS.md (between the markers <!-- hard:begin --> and <!-- hard:end -->, the rest
of the file is kept) and the speed-against-error plot.

    /usr/bin/python3 report.py WORK_DIR BENCHMARKS.md PLOT.png
"""
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

SCENES = ["tower20", "pyramid10", "column20", "column40", "pile"]
METHODS = ["method gs", "method nesterov", "method nesterov coarse yes"]


def read_log(path):
    """Per-step thermo rows (step, sweeps, residual, overlap, floor fz, weight, contacts),
    the loop time, the step count and the command line of one run."""
    rows, loop, command, grains = [], None, "", 0
    in_thermo = False
    with open(path) as f:
        for line in f:
            if line.strip().startswith("Step"):
                in_thermo = True
                continue
            if line.startswith("Loop time of"):
                m = re.match(r"Loop time of ([\d.eE+-]+) on \d+ procs for (\d+) steps with (\d+)", line)
                loop, grains = (float(m.group(1)), int(m.group(2))), int(m.group(3))
                in_thermo = False
            elif line.startswith("# command:"):
                command = line[len("# command:"):].strip()
            elif in_thermo:
                fields = line.split()
                try:
                    rows.append([float(x) for x in fields])
                except ValueError:
                    in_thermo = False
    return rows, loop, command, grains


def summarise(path):
    rows, loop, command, grains = read_log(path)
    steps = rows[1:]    # the first row is the setup's, before any solve
    if not steps or loop is None:
        return None
    sweeps = [r[1] for r in steps]
    floor_error = [abs(r[4] + r[5]) / r[5] for r in steps]
    return {
        "grains": grains,
        "median": statistics.median(sweeps),
        "mean": statistics.mean(sweeps),
        "max": max(sweeps),
        "unconverged": sum(1 for r in steps if r[2] > 0 and r[1] >= MAX_SWEEPS[path]),
        "ms": 1e3 * loop[0] / loop[1],
        "floor": statistics.median(floor_error),
        "overlap_start": steps[0][3],
        "overlap_end": steps[-1][3],
        "command": command,
    }


MAX_SWEEPS = {}


def main(work, markdown, plot):
    results = {}
    for path in glob.glob(os.path.join(work, "*.log")):
        name = os.path.basename(path)
        m = re.match(r"([a-z0-9]+)\.(.+)\.(1e-\d+)\.log$", name)
        if not m or m.group(1) not in SCENES:
            continue
        text = open(path).read()
        mm = re.search(r"-var max_sweeps (\d+)", text)
        MAX_SWEEPS[path] = int(mm.group(1)) if mm else 10**9
        s = summarise(path)
        if s:
            results[(m.group(1), m.group(2).replace("_", " "), m.group(3))] = s

    lines = ["<!-- hard:begin -->", "## Hard cases: solver methods (`benchmarks/hard`)", ""]
    cpu = subprocess.run(["sh", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                         capture_output=True, text=True).stdout.strip()
    lines += [
        f"Written by `benchmarks/hard/run.sh` (report.py) on {platform.node()}: {cpu}, "
        f"{os.cpu_count()} cores shared with other jobs (load average "
        f"{os.getloadavg()[0]:.1f} at the end), so wall times are noisy (±30 % or worse); "
        "sweeps, floor errors and overlaps are exact for the deck. Every run: dt = 0.005, "
        "g = 9.81, the steps after the restart (or from rest), thermo every step.",
        "",
        "Columns: sweeps per step median / mean / max; ms/step = `Loop time` / steps (wall); "
        "floor error = median over steps of |F_floor + W| / W (W = weight of grains and plate: "
        "the closed-form reaction of a scene at rest); overlap = max predicted overlap "
        "(f_nscd[3]) at the first / last step.",
        "",
        "| scene | grains | method | tolerance | sweeps median / mean / max | unconverged steps | ms/step | floor error | overlap first / last |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for scene in SCENES:
        for tol in sorted({k[2] for k in results}, key=float, reverse=True):
            for method in METHODS:
                s = results.get((scene, method, tol))
                if not s:
                    continue
                lines.append(
                    f"| {scene} | {s['grains']} | `{method}` | {tol} | {s['median']:.0f} / "
                    f"{s['mean']:.1f} / {s['max']:.0f} | {s['unconverged']} | {s['ms']:.2f} | "
                    f"{s['floor']:.2e} | {s['overlap_start']:.4f} / {s['overlap_end']:.4f} |")
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

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), dpi=80)
    markers = {"method gs": "o", "method nesterov": "s", "method nesterov coarse yes": "^"}
    colours = dict(zip(SCENES, ["C0", "C1", "C2", "C3", "C4"]))
    for (scene, method, tol), s in results.items():
        for ax, x in zip(axes, (s["mean"], s["ms"])):
            ax.scatter(x, max(s["floor"], 1e-12), marker=markers[method], color=colours[scene], s=25)
    for ax, label in zip(axes, ("sweeps per step (mean)", "wall ms per step")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("floor error |F+W|/W (median)")
        ax.grid(True, which="both", alpha=0.3)
    handles = [plt.Line2D([], [], color=c, marker="o", ls="") for c in colours.values()]
    handles += [plt.Line2D([], [], color="k", marker=m, ls="") for m in markers.values()]
    axes[1].legend(handles, list(colours) + [m.replace("method ", "") for m in markers],
                   fontsize=7, loc="best")
    fig.tight_layout()
    os.makedirs(os.path.dirname(plot), exist_ok=True)
    fig.savefig(plot)
    print(f"wrote {markdown} and {plot} ({len(results)} runs)")


if __name__ == "__main__":
    main(*sys.argv[1:4])
