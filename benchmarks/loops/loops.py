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

"""Columns of grains and elastic loops: stock LAMMPS (in.peer) against this package (in.nscd).

  loops.py run  --code nscd --spacing 1.3 --mu 0.3 --seed 1 [--grains 200] [--dir D]
  loops.py grid --spacings 0.7 0.9 1.2 1.5 1.9 --mus 0.1 0.3 0.5 --seeds 1 2 [--codes nscd peer peer-noroll]
  loops.py plot [--table results.csv]

`run` writes the scene's files into a run directory (the grains' start positions, the loops
at the spacing, the sphere shape), runs one deck with `lmp` and appends a row to the table:
code, spacing (grain diameters), mu, seed, heights after settling, after the hold and at the
end, the retained height (end / hold), stable or collapsed, wall and CPU time of the run.
`grid` runs the grid one run at a time (at the niceness of this process: start it with
`nice -n 15`), skipping rows already in the table; per friction, seed and code it goes up
the spacings and stops at the first collapse (--all: every spacing). `plot` draws the critical spacing
(the largest spacing at which every seed stood) against friction for each code.
"""
import argparse
import csv
import math
import os
import resource
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
D = 0.013            # grain diameter (m)
R_IN = 0.0385        # the cylinder the grains settle in
R_OUT = 0.04         # the second cylinder, outside the loops
R_LOOP = 0.03925     # loop radius (centre line): R_out - h/2
N_BEADS = 180        # beads (nodes) per loop, theirs
# peer: in.peer as theirs; peer-noroll: without rolling/twisting resistance; peer-locked: that,
# and the loops' beads integrated without rotation (fix nve), like this package's wire nodes
CODES = ["nscd", "peer", "peer-noroll", "peer-locked"]
CODE_COLOURS = {"nscd": "C0", "peer": "C3", "peer-noroll": "C2", "peer-locked": "C4"}
STABLE_RETAINED = 0.9   # a column that keeps this fraction of its held height stands
FIELDS = ["code", "spacing", "mu", "seed", "grains", "loops", "h_settled", "h_held", "h_end",
          "retained", "outcome", "wall_s", "cpu_s", "dt"]


def start_positions(n, seed):
    """n grain centres inside R_IN - d/2 (with a small margin), no two closer than 1.02 d,
    from the floor up: random sequential addition at 0.35 solid fraction."""
    rng = np.random.default_rng(seed)
    r_max = R_IN - 0.5 * D - 0.0005
    height = n * (math.pi / 6 * D**3) / (math.pi * r_max**2 * 0.35)
    pts = np.empty((0, 3))
    tries = 0
    while len(pts) < n:
        tries += 1
        if tries > 200000:
            raise RuntimeError("could not place the grains")
        r = r_max * math.sqrt(rng.random())
        a = 2 * math.pi * rng.random()
        p = np.array([r * math.cos(a), r * math.sin(a), 0.5 * D + 0.0005 + height * rng.random()])
        if len(pts) and np.min(np.sum((pts - p) ** 2, axis=1)) < (1.02 * D) ** 2:
            continue
        pts = np.vstack([pts, p])
    return pts


def loop_heights(spacing_d, n_grains):
    """Theirs: loops at s, 2s, ... below the nominal column height (0.16 m for 375 grains,
    scaled with the number of grains)."""
    s = spacing_d * D
    top = 0.16 * n_grains / 375.0
    return [k * s for k in range(1, int(top / s + 1e-9) + 1) if k * s < top]


def write_scene(rundir, n_grains, seed, spacing_d):
    os.makedirs(rundir, exist_ok=True)
    pts = start_positions(n_grains, seed)
    with open(os.path.join(rundir, "grains.txt"), "w") as f:
        for p in pts:
            f.write("create_atoms 1 single %.9g %.9g %.9g units box\n" % tuple(p))
    with open(os.path.join(rundir, "sphere.shapes"), "w") as f:
        f.write("# a sphere of the grains' diameter: one vertex dilated by d/2\n"
                "shape grain\nradius %.9g\nvertices 1\n0 0 0\nend\n" % (0.5 * D))
    zs = loop_heights(spacing_d, n_grains)
    # this package: one closed ring per height (180 equal chords = the rest length)
    with open(os.path.join(rundir, "loops_nscd.txt"), "w") as f:
        for z in zs:
            f.write("create_wire 2 loop 0 0 %.9g %.9g bond 1 angle 1 mass ${m_node}\n" % (z, R_LOOP))
    # the peer: beads, bonds and angles as their add_loop lays them (bead 0 on +x)
    with open(os.path.join(rundir, "loops_peer.txt"), "w") as f:
        first = n_grains + 1
        lines_b, lines_a = [], []
        for k, z in enumerate(zs):
            base = first + k * N_BEADS
            for i in range(N_BEADS):
                a = 2 * math.pi * i / N_BEADS
                f.write("create_atoms 2 single %.12g %.12g %.9g units box\n"
                        % (R_LOOP * math.cos(a), R_LOOP * math.sin(a), z))
            for i in range(N_BEADS):
                lines_b.append((base + i, base + (i + 1) % N_BEADS))
                lines_a.append((base + (i - 1) % N_BEADS, base + i, base + (i + 1) % N_BEADS))
        for j, (a, b) in enumerate(lines_b):
            f.write("create_bonds single/bond 1 %d %d special no\n" % (a, b))
        for j, (a, b, c) in enumerate(lines_a):
            last = j == len(lines_a) - 1
            f.write("create_bonds single/angle 1 %d %d %d%s\n" % (a, b, c, "" if last else " special no"))
    return zs


def read_dump(path):
    with open(path) as f:
        lines = f.readlines()
    i = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return np.array([[float(v) for v in l.split()] for l in lines[i + 1:] if l.strip()])


def column_height(xyz):
    """The column's top: mean of the 5 highest grain tops (one perched grain does not count
    alone) among the grains within the loop radius + d of the axis (a grain rolled away is
    not the column)."""
    r = np.hypot(xyz[:, 1], xyz[:, 2])
    z = np.sort(xyz[r < R_LOOP + D, 3])[::-1]
    if len(z) == 0:
        return 0.0
    return float(np.mean(z[:5]) + 0.5 * D)


def run_one(args, code, spacing, mu, seed, table):
    lmp = os.path.abspath(args.lmp)
    rundir = os.path.join(args.dir, "%s_s%.2f_mu%.2f_seed%d" % (code, spacing, mu, seed))
    zs = write_scene(rundir, args.grains, seed, spacing)
    deck = os.path.join(HERE, "in.nscd" if code == "nscd" else "in.peer")
    dt = args.dt_nscd if code == "nscd" else args.dt_peer
    cmd = [lmp, "-in", deck, "-log", os.path.join(rundir, "log.lammps"), "-screen", "none",
           "-var", "dir", rundir, "-var", "mu", str(mu), "-var", "dt", str(dt),
           "-var", "inertia", str(args.inertia), "-var", "t_settle", str(args.t_settle),
           "-var", "t_hold", str(args.t_hold), "-var", "t_free", str(args.t_free)]
    if code != "nscd":
        cmd += ["-var", "rolling", "yes" if code == "peer" else "no",
                "-var", "bead_spin", "no" if code == "peer-locked" else "yes"]
    cmd += sum((["-var"] + v.split("=", 1) for v in args.var), [])
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    proc = subprocess.run(cmd, cwd=rundir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if proc.returncode != 0:
        tail = proc.stdout.strip().splitlines()[-5:]
        log = os.path.join(rundir, "log.lammps")
        if os.path.exists(log):
            tail = open(log).read().strip().splitlines()[-5:]
        print("FAILED %s: %s" % (rundir, " | ".join(tail)), file=sys.stderr)
        row = dict(code=code, spacing=spacing, mu=mu, seed=seed, grains=args.grains, loops=len(zs),
                   h_settled="", h_held="", h_end="", retained="", outcome="failed",
                   wall_s="%.1f" % wall, cpu_s="%.1f" % cpu, dt=dt)
    else:
        prefix = "nscd" if code == "nscd" else "peer"
        h = [column_height(read_dump(os.path.join(rundir, "%s.%s.dump" % (prefix, stage))))
             for stage in ("settled", "held", "end")]
        retained = h[2] / h[1]
        row = dict(code=code, spacing=spacing, mu=mu, seed=seed, grains=args.grains, loops=len(zs),
                   h_settled="%.5f" % h[0], h_held="%.5f" % h[1], h_end="%.5f" % h[2],
                   retained="%.3f" % retained,
                   outcome="stable" if retained >= STABLE_RETAINED else "collapsed",
                   wall_s="%.1f" % wall, cpu_s="%.1f" % cpu, dt=dt)
    new = not os.path.exists(table)
    with open(table, "a", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        if new:
            w.writeheader()
        w.writerow(row)
    print(" ".join("%s=%s" % (k, row[k]) for k in FIELDS), flush=True)
    return row


def done_rows(table):
    """The rows of the table so far, by (code, spacing, mu, seed)."""
    if not os.path.exists(table):
        return {}
    with open(table) as f:
        return {(r["code"], float(r["spacing"]), float(r["mu"]), int(r["seed"])): r for r in csv.DictReader(f)}


def critical_spacings(rows, code):
    """Per friction: the largest spacing at which every seed stood, with no collapse at a
    smaller spacing (else the smallest spacing's value and a flag)."""
    out = {}
    for mu in sorted({float(r["mu"]) for r in rows if r["code"] == code}):
        by_s = {}
        for r in rows:
            if r["code"] == code and float(r["mu"]) == mu and r["outcome"] != "failed":
                by_s.setdefault(float(r["spacing"]), []).append(r["outcome"] == "stable")
        crit = None
        for s in sorted(by_s):
            if all(by_s[s]):
                crit = s
            else:
                break
        out[mu] = (crit, by_s)
    return out


def plot(args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(args.table) as f:
        rows = list(csv.DictReader(f))
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    retained_panel(ax2, rows)
    for code, mark, label in (("nscd", "o-", "this package (NSCD + wire)"),
                              ("peer", "s--", "stock LAMMPS GRANULAR, theirs (rolling)"),
                              ("peer-noroll", "^:", "stock LAMMPS GRANULAR, no rolling"),
                              ("peer-locked", "d-.", "stock LAMMPS GRANULAR, no rolling, beads locked")):
        crit = critical_spacings(rows, code)
        # no stable spacing: drawn below the smallest tried (a downward triangle on the line)
        floor = min(float(r["spacing"]) for r in rows) - 0.2
        mus = sorted(crit)
        if mus:
            ys = [crit[m][0] if crit[m][0] is not None else floor for m in mus]
            line, = ax.plot(mus, ys, mark, label=label, color=CODE_COLOURS[code])
            for m, y in zip(mus, ys):
                if crit[m][0] is None:
                    ax.plot(m, y, "v", color=line.get_color(), ms=9)
        # every run: stable filled, collapsed open, slightly offset per code
        off = {"nscd": -0.009, "peer": -0.003, "peer-noroll": 0.003, "peer-locked": 0.009}[code]
        for r in rows:
            if r["code"] != code or r["outcome"] == "failed":
                continue
            ax.plot(float(r["mu"]) + off, float(r["spacing"]), mark[0], color=CODE_COLOURS[code],
                    mfc=CODE_COLOURS[code] if r["outcome"] == "stable" else "none", ms=4, alpha=0.6)
    ax.set_xlabel("friction coefficient $\\mu$")
    ax.set_ylabel("largest stable loop spacing / grain diameter")
    ax.axhline(min(float(r["spacing"]) for r in rows) - 0.1, color="gray", lw=0.5, ls=":")
    ax.plot([], [], "v", color="gray", ms=8, label="no spacing tried stood")
    ax.plot([], [], "o", color="gray", ms=4, label="a run that stood (open: collapsed)")
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title("columns of grains and elastic loops", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print("wrote", args.out)
    print_tables(rows)


def retained_panel(ax, rows):
    """Retained height against spacing, the mean over seeds, one colour per friction, one
    line style per code: the graded measure behind the stood/collapsed threshold."""
    styles = {"nscd": "o-", "peer": "s--", "peer-noroll": "^:", "peer-locked": "d-."}
    mus = sorted({float(r["mu"]) for r in rows})
    colours = dict(zip(mus, ["C0", "C1", "C2", "C3", "C4"]))
    for code in CODES:
        for mu in mus:
            pts = {}
            for r in rows:
                if r["code"] == code and float(r["mu"]) == mu and r["outcome"] != "failed":
                    pts.setdefault(float(r["spacing"]), []).append(float(r["retained"]))
            if pts:
                xs = sorted(pts)
                ax.plot(xs, [np.mean(pts[x]) for x in xs], styles[code], color=colours[mu], ms=4,
                        label="%s, $\\mu$ = %.1f" % (code, mu))
    ax.axhline(STABLE_RETAINED, color="gray", lw=0.8, ls=":")
    ax.set_xlabel("loop spacing / grain diameter")
    ax.set_ylabel("retained height (end / held), mean over seeds")
    ax.legend(fontsize=6, ncol=3)


def print_tables(rows):
    """The README's tables (markdown): the critical spacings, every run, the cost."""
    print("\n| friction | " + " | ".join(CODES) + " |")
    print("|---|" + "---|" * len(CODES))
    crit = {code: critical_spacings(rows, code) for code in CODES}
    for mu in sorted({float(r["mu"]) for r in rows}):
        cells = []
        for code in CODES:
            if mu not in crit[code]:
                cells.append("")
                continue
            c, by_s = crit[code][mu]
            tried = ", ".join("%.1f: %d/%d" % (s, sum(v), len(v)) for s, v in sorted(by_s.items()))
            cells.append("%s (stood: %s)" % ("< %.1f" % min(by_s) if c is None else "%.1f" % c, tried))
        print("| %.1f | %s |" % (mu, " | ".join(cells)))
    print("\n| code | mu | seed | spacing / d | loops | h held (m) | h end (m) | retained | outcome | wall (s) | CPU (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (r["code"], float(r["mu"]), int(r["seed"]), float(r["spacing"]))):
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % tuple(
            r[k] for k in ("code", "mu", "seed", "spacing", "loops", "h_held", "h_end", "retained",
                           "outcome", "wall_s", "cpu_s")))
    # cost: this package against each peer variant on the runs (friction, seed, spacing) both did
    keys = {code: {(r["mu"], r["seed"], r["spacing"]): r for r in rows if r["code"] == code and r["outcome"] != "failed"}
            for code in CODES}
    print()
    for code in CODES[1:]:
        common = set(keys["nscd"]) & set(keys[code])
        if not common:
            continue
        tot = {c: {f: sum(float(keys[c][k][f]) for k in common) for f in ("wall_s", "cpu_s")} for c in ("nscd", code)}
        print("nscd against %s on the %d runs both did: wall %.0f / %.0f s, CPU %.0f / %.0f s (per run CPU %.1f / %.1f s); "
              "ratio nscd / %s: wall %.2f, CPU %.2f"
              % (code, len(common), tot["nscd"]["wall_s"], tot[code]["wall_s"], tot["nscd"]["cpu_s"], tot[code]["cpu_s"],
                 tot["nscd"]["cpu_s"] / len(common), tot[code]["cpu_s"] / len(common), code,
                 tot["nscd"]["wall_s"] / tot[code]["wall_s"], tot["nscd"]["cpu_s"] / tot[code]["cpu_s"]))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("what", choices=["run", "grid", "plot"])
    p.add_argument("--lmp", default=os.path.join(HERE, "..", "..", "build", "lmp"),
                   help="lmp with GRANULAR for the peer (build with -DNSCD_WITH_GRANULAR=ON)")
    p.add_argument("--dir", default="/tmp/loops", help="run directories")
    p.add_argument("--table", default=None, help="results table (default DIR/results.csv)")
    p.add_argument("--out", default=os.path.join(HERE, "critical_spacing.png"))
    p.add_argument("--code", default="nscd", choices=CODES)
    p.add_argument("--codes", nargs="+", default=CODES, choices=CODES)
    p.add_argument("--spacing", type=float, default=1.3)
    p.add_argument("--spacings", type=float, nargs="+", default=[0.7, 0.9, 1.2, 1.5, 1.9])
    p.add_argument("--mu", type=float, default=0.3)
    p.add_argument("--mus", type=float, nargs="+", default=[0.1, 0.3, 0.5])
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2])
    p.add_argument("--grains", type=int, default=200)
    p.add_argument("--inertia", type=float, default=100)
    p.add_argument("--dt-nscd", type=float, default=1e-4)
    p.add_argument("--dt-peer", type=float, default=5e-6)
    p.add_argument("--t-settle", type=float, default=0.3)
    p.add_argument("--t-hold", type=float, default=0.05)
    p.add_argument("--t-free", type=float, default=0.3)
    p.add_argument("--all", action="store_true", help="grid: every spacing, not only up to the first collapse")
    p.add_argument("--var", action="append", default=[], help="NAME=VALUE passed to the deck")
    args = p.parse_args()
    args.dir = os.path.abspath(args.dir)
    os.makedirs(args.dir, exist_ok=True)
    table = args.table or os.path.join(args.dir, "results.csv")
    args.table = table
    if args.what == "run":
        run_one(args, args.code, args.spacing, args.mu, args.seed, table)
    elif args.what == "grid":
        # per friction, seed and code: spacings from the smallest up, until the first
        # collapse (a wider spacing is assumed to collapse too; --all runs every one)
        done = done_rows(table)
        for mu in args.mus:
            for seed in args.seeds:
                for code in args.codes:
                    for s in sorted(args.spacings):
                        row = done.get((code, s, mu, seed)) or run_one(args, code, s, mu, seed, table)
                        if row["outcome"] == "collapsed" and not args.all:
                            break
    else:
        plot(args)


if __name__ == "__main__":
    main()
