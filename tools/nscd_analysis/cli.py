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

"""Command line: one subcommand per figure (doc/analysis.md). Each writes PREFIX.png and
PREFIX.csv (the numbers behind the picture) unless said otherwise. A command reads its
input, has the analysis modules compute the numbers, writes them as CSV, and hands them
to plots.py for the picture."""

import argparse
import csv
import os
import sys

import numpy as np

from . import (cylinder, fabric, fields, forces, load_curves, logs, phases, plots, stress, vtk, wire_breaks,
               wire_contacts, wire_loops)
from .dumps import DumpError, expand, read_dumps
from .layouts import FABRIC, WIRE_ELEMENTS, WIRE_GRAIN


def _write_csv(prefix, header, rows, comments=()):
    with open(prefix + ".csv", "w", newline="") as f:
        for line in comments:
            f.write(f"# {line}\n")
        w = csv.writer(f)
        w.writerow(header)
        for row in rows:
            w.writerow([_fmt(v) for v in row])
    return prefix + ".csv"


def _fmt(v):
    if isinstance(v, (float, np.floating)):
        return "nan" if np.isnan(v) else f"{v:.6g}"
    return v


def _zrange(args):
    if args.zmin is None and args.zmax is None:
        return None
    return (-np.inf if args.zmin is None else args.zmin, np.inf if args.zmax is None else args.zmax)


def _grain_axis(args, snapshot):
    """The axis given, or the centre of mass of the snapshot's grains (x y z columns)."""
    if args.axis is not None:
        return np.array(args.axis)
    pos = np.column_stack([snapshot.first_column(n) for n in (("xu", "x"), ("yu", "y"), ("zu", "z"))])
    masses = snapshot.column("mass") if snapshot.has("mass") else None
    return cylinder.axis_from_centre_of_mass(pos, masses)


def _radius(args):
    """The column's radius given with --R, or None."""
    return getattr(args, "R", None)


def _r_scale(args):
    """Divide r by this on 1-D profiles: R with --R, else 1."""
    return args.R if getattr(args, "R", None) else 1.0


def _r_edges(args, r_values):
    return cylinder.edges(r_values, count=args.rbins, width=args.rwidth, high=args.rmax)


def _z_edges(args, z_values):
    """--zbins bins from --zmin (default: lowest z) to --zmax (default: highest z)."""
    low = args.zmin if args.zmin is not None else (float(np.min(z_values)) if len(z_values) else 0.0)
    return cylinder.edges(z_values, count=args.zbins, low=low, high=args.zmax)


# --- cylavg: any per-atom column averaged in (r, z) bins --------------------------------

def cmd_cylavg(args):
    snaps = read_dumps(args.dump, args.steps, args.last)
    r_all, z_all, v_all = [], [], []
    for s in snaps:
        axis = _grain_axis(args, s)
        pos = np.column_stack([s.first_column(n) for n in (("xu", "x"), ("yu", "y"), ("zu", "z"))])
        cyl = cylinder.Cylindrical(pos, axis)
        r_all.append(cyl.r)
        z_all.append(cyl.z)
        v_all.append(s.column(args.value, FABRIC))
    r, z, v = map(np.concatenate, (r_all, z_all, v_all))
    r_edges = _r_edges(args, r)
    z_edges = _z_edges(args, z)
    count, mean = cylinder.binned_mean_2d(v, r, z, r_edges, z_edges)
    fig = plots.cylavg_map(r_edges, z_edges, mean, args.value, len(snaps), _radius(args))
    rows = [(r_edges[i], r_edges[i + 1], z_edges[j], z_edges[j + 1], count[i, j], mean[i, j])
            for i in range(len(r_edges) - 1) for j in range(len(z_edges) - 1)]
    print(plots.save(fig, args.out), _write_csv(args.out, ["r_lo", "r_hi", "z_lo", "z_hi", "count", "mean"], rows))


# --- fabric-field: the papers' Fig. 3 ---------------------------------------------------

def _fabric_per_grain(args):
    return lambda s: fabric.per_grain(s, _grain_axis(args, s), _zrange(args))


def _pooled_fabric(args, patterns, steps, last):
    return fields.pooled(_fabric_per_grain(args), read_dumps(patterns, steps, last))


FIELD_HEADER = ["r", "z", "grains", "F_rr", "F_rz", "F_zz", "lambda_max", "vmax_r", "vmax_z", "lambda_min",
                "vmin_r", "vmin_z", "angle_rad"]


def cmd_fabric_field(args):
    r, z, blocks, _, nsnap = _pooled_fabric(args, args.dump, args.steps, args.last)
    r_edges = _r_edges(args, r)
    z_edges = _z_edges(args, z)
    rows, segments = fields.principal_field(r, z, blocks, r_edges, z_edges)
    title = f"fabric in the r-z plane ({len(r)} grains, {nsnap} snapshot(s))"
    fig = plots.principal_fields([("fabric", title, segments)], r_edges, z_edges, _radius(args))
    print(plots.save(fig, args.out), _write_csv(args.out, FIELD_HEADER, rows, [
        "mean r-z block of the grains' fabric tensors in their cylindrical frame per (r, z) bin;",
        "angle: of the largest principal direction with z, positive = leaning outward going up (inward going down)"]))


# --- fabric-angle: the papers' Fig. 4 ---------------------------------------------------

def _parse_runs(runs):
    out = []
    for run in runs:
        label, sep, pattern = run.rpartition("=")    # labels may hold "=" (Fz=800)
        if not sep or not label or not pattern:
            raise SystemExit(f"nscd-analysis: --run '{run}' must be LABEL=FILES (e.g. column='col/fabric.*.dump')")
        out.append((label, pattern.split(",")))
    return out


def _seed_files(args, patterns):
    """--spread seeds: each file of a run is one seed, its snapshots (--last: its last one)
    pooled into one sample."""
    if args.steps is not None:
        raise SystemExit("nscd-analysis: --spread seeds takes each seed's files, not --steps "
                         "(name the snapshot files, or use --last)")
    files = expand(patterns)
    if len(files) < 2:
        raise SystemExit(f"nscd-analysis: --spread seeds needs two or more files per run (one per seed), "
                         f"got {len(files)}: {', '.join(files)}")
    return [read_dumps([f], None, args.last) for f in files]


def _angle_plot(args, per_grain, ylabel, what):
    """Mean signed angle vs r of each run's principal direction (fabric-angle, stress-angle);
    per_grain(snapshot) gives (r, z, blocks, angle); `what` names the direction in the
    summary lines. --spread seeds: the mean and standard deviation over the run's files."""
    if args.spread == "seeds":
        return _angle_plot_over_seeds(args, per_grain, ylabel, what)
    runs = [(label, fields.pooled(per_grain, read_dumps(patterns, args.steps, args.last)))
            for label, patterns in _parse_runs(args.run)]
    r_edges = _r_edges(args, np.concatenate([data[0] for _, data in runs]))
    rc = cylinder.centres(r_edges)
    rows, summary, curves = [], [], []
    for label, (r, _, blocks, angle, nsnap) in runs:
        count, mean, sem, tensor_angle = fields.angle_profile(r, blocks, angle, r_edges)
        value = tensor_angle if args.method == "tensor" else mean
        curves.append((label, rc / _r_scale(args), value, None if args.method == "tensor" else sem))
        for b in range(len(rc)):
            rows.append((label, r_edges[b], r_edges[b + 1], rc[b], count[b], mean[b], sem[b], tensor_angle[b]))
        summary.append(f"{label}: mean angle {what}over all grains {np.nanmean(angle):+.4f} rad "
                       f"({int(np.sum(~np.isnan(angle)))} grains, {nsnap} snapshot(s))")
    fig = plots.profiles(curves, _radius(args), ylabel, zero_line=True,
                         title="mean over grains" if args.method == "grains" else "angle of the mean tensor")
    print(plots.save(fig, args.out), _write_csv(args.out, ["run", "r_lo", "r_hi", "r", "grains", "mean_angle_rad",
                                                            "sem_rad", "tensor_angle_rad"], rows, summary))
    for line in summary:
        print(line)


def _angle_plot_over_seeds(args, per_grain, ylabel, what):
    """_angle_plot with one sample per file: each seed's profile (rows 'LABEL #k'), then per
    r bin their mean and sample standard deviation (rows 'LABEL'), which the figure draws."""
    runs = [(label, [fields.pooled(per_grain, snaps) for snaps in _seed_files(args, patterns)])
            for label, patterns in _parse_runs(args.run)]
    r_edges = _r_edges(args, np.concatenate([seed[0] for _, seeds in runs for seed in seeds]))
    rc = cylinder.centres(r_edges)
    rows, summary, curves = [], [], []
    for label, seeds in runs:
        profiles = [fields.angle_profile(r, blocks, angle, r_edges) for r, _, blocks, angle, _ in seeds]
        for k, (count, mean, _, tensor_angle) in enumerate(profiles):
            rows += [(f"{label} #{k + 1}", r_edges[b], r_edges[b + 1], rc[b], count[b], 1, mean[b], "",
                      tensor_angle[b]) for b in range(len(rc))]
        column = 3 if args.method == "tensor" else 1
        n, mean, sd = cylinder.over_samples([p[column] for p in profiles])
        _, tensor_mean, _ = cylinder.over_samples([p[3] for p in profiles])
        grains = np.sum([p[0] for p in profiles], axis=0)
        rows += [(label, r_edges[b], r_edges[b + 1], rc[b], grains[b], n[b], mean[b], sd[b], tensor_mean[b])
                 for b in range(len(rc))]
        curves.append((f"{label} ({len(seeds)} seeds)", rc / _r_scale(args), mean, sd))
        per_seed = [np.nanmean(angle) for _, _, _, angle, _ in seeds]
        summary.append(f"{label}: mean angle {what}over all grains per seed "
                       f"{', '.join(f'{a:+.4f}' for a in per_seed)} rad: {np.mean(per_seed):+.4f} "
                       f"+- {np.std(per_seed, ddof=1):.4f} (sd over {len(seeds)} seeds)")
    title = ("mean over grains" if args.method == "grains" else "angle of the mean tensor") + \
        ", per seed; bars: sd over the seeds"
    fig = plots.profiles(curves, _radius(args), ylabel, zero_line=True, title=title)
    print(plots.save(fig, args.out), _write_csv(args.out, ["run", "r_lo", "r_hi", "r", "grains", "seeds",
                                                            "mean_angle_rad", "sd_over_seeds_rad",
                                                            "tensor_angle_rad"], rows,
                                                [f"--spread seeds, --method {args.method}: rows 'RUN #k' one seed "
                                                 "(mean_angle_rad its mean over grains), rows 'RUN' the mean and "
                                                 "sample sd of the seeds' values per bin"] + summary))
    for line in summary:
        print(line)


def cmd_fabric_angle(args):
    _angle_plot(args, _fabric_per_grain(args), "signed angle of the largest fabric direction (rad)", "")


# --- stress fields: stress-field, stress-angle, stress-profile, crush-profile ------------

def _stress_per_grain(args):
    return lambda s: stress.per_grain(s, _grain_axis(args, s), _zrange(args), args.stress_id)


def _pooled_stress(args, patterns, steps, last):
    return fields.pooled(_stress_per_grain(args), read_dumps(patterns, steps, last))


def cmd_stress_field(args):
    r, z, blocks, _, nsnap = _pooled_stress(args, args.dump, args.steps, args.last)
    panels = [("stress", r, z, blocks, nsnap)]
    if args.fabric:
        fr, fz, fblocks, _, fsnap = _pooled_fabric(args, args.fabric, args.steps, args.last)
        panels.append(("fabric", fr, fz, fblocks, fsnap))
    r_edges = _r_edges(args, np.concatenate([p[1] for p in panels]))
    z_edges = _z_edges(args, np.concatenate([p[2] for p in panels]))
    rows, drawn = [], []
    for what, pr, pz, pblocks, psnap in panels:
        field_rows, segments = fields.principal_field(pr, pz, pblocks, r_edges, z_edges)
        rows += [(what,) + row for row in field_rows]
        drawn.append((what, f"{what} in the r-z plane ({len(pr)} grains, {psnap} snapshot(s))", segments))
    fig = plots.principal_fields(drawn, r_edges, z_edges, _radius(args), lambda what: (
        "major (most compressive) stress" if what == "stress" else "largest fabric direction"))
    print(plots.save(fig, args.out), _write_csv(args.out, ["field"] + FIELD_HEADER, rows, [
        "per (r, z) bin the mean r-z block in the grains' cylindrical frames: stress rows hold -sigma "
        "(compression positive, compute nscd/stress/atom), fabric rows the fabric tensor;",
        "angle: of the largest principal direction (stress: the most compressive) with z, positive = "
        "leaning outward going up"]))


def cmd_stress_angle(args):
    _angle_plot(args, _stress_per_grain(args), "signed angle of the major principal stress (rad)",
                "of the major principal stress ")


def _labelled_snapshots(args):
    """The snapshots and their labels. Without --steps the files (patterns) keep the order
    given, each one's snapshots in timestep order (--last: the last of each), so that labels
    follow the files when several runs are compared; with --steps, those steps in that order."""
    if args.steps is None:
        snaps = [s for pattern in args.dump for s in read_dumps([pattern], None, args.last)]
    else:
        snaps = read_dumps(args.dump, args.steps, args.last)
    return snaps, _labels(args, snaps)


def _labels(args, snaps):
    """--labels, one per snapshot, or each snapshot's step."""
    labels = args.labels or [f"step {s.timestep}" for s in snaps]
    if len(labels) != len(snaps):
        raise SystemExit(f"nscd-analysis: {len(labels)} labels for {len(snaps)} snapshots")
    return labels


def cmd_stress_profile(args):
    snaps, labels = _labelled_snapshots(args)
    axes_of = [_grain_axis(args, s) for s in snaps]
    r_edges = _r_edges(args, np.concatenate([cylinder.Cylindrical(stress.positions(s), a).r
                                             for s, a in zip(snaps, axes_of)]))
    rc = cylinder.centres(r_edges)
    rows, curves = [], []
    for s, axis, label in zip(snaps, axes_of, labels):
        count, mean, sem = stress.szz_profile(s, axis, r_edges, _zrange(args), args.stress_id)
        curves.append((label, rc / _r_scale(args), -mean, sem))
        for b in range(len(rc)):
            rows.append((label, s.timestep, r_edges[b], r_edges[b + 1], rc[b], count[b], mean[b], sem[b]))
    fig = plots.profiles(curves, _radius(args), "-sigma_zz, mean over grains (compression > 0)")
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "step", "r_lo", "r_hi", "r", "grains",
                                                            "mean_szz", "sem_szz"], rows,
                                                ["sigma_zz of compute nscd/stress/atom (tension positive) over "
                                                 "grains with contacts"]))


def cmd_crush_profile(args):
    snaps, labels = _labelled_snapshots(args)
    data = []
    for s in snaps:
        pos, flags = stress.crushed(s, args.threshold, args.value, _zrange(args), args.crush_id)
        data.append((s, cylinder.Cylindrical(pos, _grain_axis(args, s)), flags))
    r_edges = _r_edges(args, np.concatenate([c.r for _, c, _ in data]))
    z_edges = _z_edges(args, np.concatenate([c.z for _, c, _ in data]))
    rows, summary, curves = [], [], {"r": [], "z": []}
    for (s, cyl, flags), label in zip(data, labels):
        for coord, values, edges in (("r", cyl.r, r_edges), ("z", cyl.z, z_edges)):
            count, fraction, error = stress.fraction_profile(flags, values, edges)
            centre = cylinder.centres(edges)
            curves[coord].append((label, centre / _r_scale(args) if coord == "r" else centre, fraction, error))
            for b in range(len(centre)):
                rows.append((label, s.timestep, coord, edges[b], edges[b + 1], centre[b], count[b], fraction[b], error[b]))
        summary.append(f"{label}: {int(flags.sum())} of {len(flags)} grains with {args.value} >= {args.threshold:g} "
                       f"({flags.mean() if len(flags) else np.nan:.4f})")
    fig = plots.r_and_z_profiles(curves["r"], curves["z"], _radius(args),
                                 f"fraction of grains with {args.value} >= {args.threshold:g}")
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "step", "along", "lo", "hi", "centre", "grains",
                                                            "fraction", "error"], rows,
                                                ["compute nscd/crush/atom: fraction of grains past the threshold per "
                                                 "r bin and per z bin; error: sqrt(f (1 - f) / n)"] + summary))
    for line in summary:
        print(line)


# --- wire-breaks: where fix wire's elements broke ---------------------------------------

def cmd_wire_breaks(args):
    runs = _parse_runs(args.run)
    rows, summary, groups = [], [], []
    for label, paths in runs:
        for path in paths:
            b = wire_breaks.read_breaks(path)
            r, z = wire_breaks.positions_rz(b, args.axis)
            groups.append((f"{label} ({len(b)})", r / _r_scale(args), z))
            rows += [(label, int(row[0]), int(row[1]), int(row[2]), row[3], ri, zi) for row, ri, zi in zip(b, r, z)]
            summary.append(f"{label}: {len(b)} breaks" + (f", z {np.min(z):.3g}..{np.max(z):.3g} (median {np.median(z):.3g}), "
                                                          f"r {np.min(r):.3g}..{np.max(r):.3g} (median {np.median(r):.3g}), "
                                                          f"steps {int(b[:, 0].min())}..{int(b[:, 0].max())}" if len(b) else ""))
    fig = plots.points_rz(groups, _radius(args), args.zmax, "where the wire broke (element midpoints)")
    print(plots.save(fig, args.out), _write_csv(args.out, ["run", "step", "id1", "id2", "tension", "r", "z"], rows,
                                                summary))
    for line in summary:
        print(line)


# --- force-profile: the papers' Fig. 5 --------------------------------------------------

def _over_seeds(args):
    """force-profile, wire-contacts: True for --run groups of seeds, False for snapshot files
    (not both)."""
    if bool(args.dump) == bool(args.run):
        raise SystemExit(f"nscd-analysis {args.command}: give dump files, or --run LABEL=FILES (one file per "
                         "seed), not both")
    if args.run and args.labels:
        raise SystemExit(f"nscd-analysis {args.command}: --labels names snapshots; with --run the runs' LABELs do")
    return bool(args.run)


def _snapshots_and_labels(args):
    """The dump files' snapshots in timestep order (--steps, --last) and their labels."""
    snaps = read_dumps(args.dump, args.steps, args.last)
    return snaps, _labels(args, snaps)


def _force_profiles(args, snaps):
    """Each snapshot's normal-force profile per r bin: [(snapshot, axis, contacts' r)]."""
    profiles = []
    for s in snaps:
        positions, _, centres = forces.grain_contacts(s, args.points)
        axis = np.array(args.axis) if args.axis is not None else cylinder.axis_from_centre_of_mass(centres)
        profiles.append((s, axis, cylinder.Cylindrical(positions, axis).r if len(positions) else np.zeros(0)))
    return profiles


def cmd_force_profile(args):
    if _over_seeds(args):
        return _force_profile_over_seeds(args)
    snaps, labels = _snapshots_and_labels(args)
    profiles = _force_profiles(args, snaps)
    r_edges = _r_edges(args, np.concatenate([p[2] for p in profiles]))
    rc = cylinder.centres(r_edges)
    rows, curves = [], []
    for (s, axis, _), label in zip(profiles, labels):
        count, mean, sem, _ = forces.radial_profile(s, r_edges, axis, _zrange(args), args.points)
        curves.append((label, rc / _r_scale(args), mean, sem))
        for b in range(len(rc)):
            rows.append((label, s.timestep, r_edges[b], r_edges[b + 1], rc[b], count[b], mean[b], sem[b]))
    fig = plots.profiles(curves, _radius(args), "mean normal force between grains")
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "step", "r_lo", "r_hi", "r", "contacts",
                                                            "mean_fn", "sem_fn"], rows))


def _force_profile_over_seeds(args):
    """force-profile --run: per run, each seed's profile (its files' snapshots pooled: rows
    'LABEL #k'), then per r bin the mean and sample standard deviation of the seeds' means."""
    axis = None if args.axis is None else np.array(args.axis)
    runs = [(label, [[(s.timestep,) + forces.radii_and_forces(s, axis, _zrange(args), args.points)[:2]
                      for s in snaps] for snaps in _seed_files(args, patterns)])
            for label, patterns in _parse_runs(args.run)]
    r_edges = _r_edges(args, np.concatenate([r for _, seeds in runs for seed in seeds for _, r, _ in seed]))
    rc = cylinder.centres(r_edges)
    rows, curves = [], []
    for label, seeds in runs:
        means, contacts = [], np.zeros(len(rc), dtype=int)
        for k, seed in enumerate(seeds):
            count, mean, _ = cylinder.binned_mean(np.concatenate([fn for _, _, fn in seed]),
                                                  np.concatenate([r for _, r, _ in seed]), r_edges)
            means.append(mean)
            contacts += count
            steps = "+".join(str(step) for step, _, _ in seed)
            rows += [(f"{label} #{k + 1}", steps, r_edges[b], r_edges[b + 1], rc[b], count[b], 1, mean[b], "")
                     for b in range(len(rc))]
        n, mean, sd = cylinder.over_samples(means)
        rows += [(label, "", r_edges[b], r_edges[b + 1], rc[b], contacts[b], n[b], mean[b], sd[b])
                 for b in range(len(rc))]
        curves.append((f"{label} ({len(seeds)} seeds)", rc / _r_scale(args), mean, sd))
    fig = plots.profiles(curves, _radius(args), "mean normal force between grains",
                         title="mean over contacts, per seed; bars: sd over the seeds")
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "steps", "r_lo", "r_hi", "r", "contacts", "seeds",
                                                            "mean_fn", "sd_over_seeds_fn"], rows,
                                                ["--run: rows 'LABEL #k' one seed (its snapshots' contacts pooled), "
                                                 "rows 'LABEL' the mean and sample sd of the seeds' means per bin"]))


# --- wire-contacts: the papers' Fig. 6 --------------------------------------------------

def cmd_wire_contacts(args):
    if _over_seeds(args):
        return _wire_contacts_over_seeds(args)
    snaps, labels = _snapshots_and_labels(args)
    rows, summary, histograms = [], [], []
    for s, label in zip(snaps, labels):
        alpha, magnitude = _wire_orientations(args, s)
        edges, fraction, mean, normalised = wire_contacts.polar_histogram(alpha, magnitude, args.bins)
        near = wire_contacts.fraction_near_vertical(alpha, args.vertical_within)
        summary.append(f"{label}: {len(alpha)} contacts, fraction within {args.vertical_within:g} deg of the "
                       f"vertical {near:.3f}, mean in-plane force {np.mean(magnitude) if len(magnitude) else np.nan:.4g}")
        histograms.append((label, edges, fraction, normalised))
        for b in range(args.bins):
            rows.append((label, s.timestep, np.degrees(edges[b]), np.degrees(edges[b + 1]), fraction[b], mean[b],
                         normalised[b]))
        rows.append((label, s.timestep, "within", args.vertical_within, near, "", ""))
    fig = plots.polar_histograms(histograms)
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "step", "alpha_lo_deg", "alpha_hi_deg", "fraction",
                                                            "mean_force", "mean_force_normalised"], rows,
                                                ["alpha: angle of (f_r, f_z) from the radial direction, 90 = vertical;",
                                                 "rows 'within': fraction of contacts within that many degrees of 90"]
                                                + summary))
    for line in summary:
        print(line)


def _wire_orientations(args, snapshot):
    """alpha and in-plane magnitude of the snapshot's wire contacts of --kind (wire-contacts)."""
    points, f = wire_contacts.forces_on_wire(snapshot, args.kind)
    axis = np.array(args.axis) if args.axis is not None else (
        cylinder.axis_from_centre_of_mass(points) if len(points) else np.zeros(2))
    return wire_contacts.orientation_rz(points, f, axis)


def _wire_contacts_over_seeds(args):
    """wire-contacts --run: per run, each seed's histogram (its files' snapshots pooled: rows
    'LABEL #k'), then per bin the mean and sample standard deviation over the seeds."""
    rows, summary, histograms = [], [], []
    for label, patterns in _parse_runs(args.run):
        fractions, normalised, near, magnitude_means = [], [], [], []
        for k, snaps in enumerate(_seed_files(args, patterns)):
            parts = [_wire_orientations(args, s) for s in snaps]
            alpha, magnitude = np.concatenate([a for a, _ in parts]), np.concatenate([m for _, m in parts])
            edges, fraction, mean, norm = wire_contacts.polar_histogram(alpha, magnitude, args.bins)
            fractions.append(fraction)
            normalised.append(norm)
            near.append(wire_contacts.fraction_near_vertical(alpha, args.vertical_within))
            magnitude_means.append(np.mean(magnitude) if len(magnitude) else np.nan)
            steps = "+".join(str(s.timestep) for s in snaps)
            rows += [(f"{label} #{k + 1}", steps, np.degrees(edges[b]), np.degrees(edges[b + 1]), 1, fraction[b], "",
                      mean[b], norm[b], "") for b in range(args.bins)]
            rows.append((f"{label} #{k + 1}", steps, "within", args.vertical_within, 1, near[-1], "", "", "", ""))
        n, fraction, fraction_sd = cylinder.over_samples(fractions)
        _, norm, norm_sd = cylinder.over_samples(normalised)
        rows += [(label, "", np.degrees(edges[b]), np.degrees(edges[b + 1]), n[b], fraction[b], fraction_sd[b], "",
                  norm[b], norm_sd[b]) for b in range(args.bins)]
        rows.append((label, "", "within", args.vertical_within, len(near), np.mean(near), np.std(near, ddof=1),
                     "", "", ""))
        histograms.append((f"{label} ({len(near)} seeds)", edges, fraction, norm, fraction_sd, norm_sd))
        summary.append(f"{label}: fraction within {args.vertical_within:g} deg of the vertical per seed "
                       f"{', '.join(f'{v:.3f}' for v in near)}: {np.mean(near):.3f} +- {np.std(near, ddof=1):.3f}; "
                       f"mean in-plane force {np.mean(magnitude_means):.4g} +- {np.std(magnitude_means, ddof=1):.2g} "
                       f"(sd over {len(near)} seeds)")
    fig = plots.polar_histograms(histograms)
    print(plots.save(fig, args.out), _write_csv(args.out, ["label", "steps", "alpha_lo_deg", "alpha_hi_deg", "seeds",
                                                            "fraction", "sd_fraction", "mean_force",
                                                            "mean_force_normalised", "sd_normalised"], rows,
                                                ["alpha: angle of (f_r, f_z) from the radial direction, 90 = vertical;",
                                                 "--run: rows 'LABEL #k' one seed, rows 'LABEL' the mean and sample sd "
                                                 "over the seeds per bin; rows 'within': the fraction within that many "
                                                 "degrees of 90"] + summary))
    for line in summary:
        print(line)


# --- load-curves: load against the plate's sink, over seeds ------------------------------

def cmd_load_curves(args):
    rows, summary, lines = [], [], []
    for label, patterns in _parse_runs(args.run):
        at_loads = []
        for path in expand(patterns):
            curve = load_curves.read_load_curve(path)
            last_load, last_sink, peak, peak_sink = load_curves.summary(curve)
            sinks = load_curves.sink_at_loads(curve, args.at or [])
            at_loads.append(sinks)
            lines.append((label, load_curves.sink(curve), curve[:, 1]))
            rows.append((label, path, len(curve), int(curve[-1, 0]), last_load, last_sink, peak, peak_sink,
                         *sinks))
        if args.at:
            n, mean, sd = cylinder.over_samples(at_loads)
            rows.append((label, "mean", "", "", "", "", "", "", *mean))
            rows.append((label, "sd", "", "", "", "", "", "", *sd))
            summary += [f"{label}: sink at load {load:g}: {m:.4g} +- {d:.2g} ({k} of {len(at_loads)} curves reach it)"
                        for load, m, d, k in zip(args.at, mean, sd, n)]
    fig = plots.load_curves(lines)
    header = ["run", "file", "rows", "last_step", "last_load", "last_sink", "peak_force", "sink_at_peak"] + \
        [f"sink_at_{load:g}" for load in (args.at or [])]
    print(plots.save(fig, args.out), _write_csv(args.out, header, rows, [
        "sink: how far the plate sank since the loading started; load: the applied force (the plate's weight "
        "not included); peak_force: the largest force the column exerted on the plate"] + summary))
    for line in summary:
        print(line)


# --- timeseries -------------------------------------------------------------------------

# The thermo columns of examples/column/in.column (and examples/silo), for --preset column.
COLUMN_PRESET = ["Step:v_height", "Step:v_retained", "Step:v_e_stretch,v_e_bend,v_e_contact",
                 "v_plate_disp:v_plate_force"]


def _panels_in_logs(paths, panels):
    """The panels whose X and at least one Y the log(s) print; the others are left out with
    a warning naming the missing columns. Ys a log lacks are dropped from their panel."""
    kept = []
    for x, ys in panels:
        missing = logs.has_columns(paths, [x] + ys)
        present = [y for y in ys if y not in missing]
        if x in missing or not present:
            print(f"nscd-analysis timeseries: WARNING: panel {x}:{','.join(ys)} skipped: the log has no "
                  f"{', '.join(missing)}", file=sys.stderr)
            continue
        if missing:
            print(f"nscd-analysis timeseries: WARNING: panel {x}:{','.join(ys)} drawn without "
                  f"{', '.join(missing)} (not in the log)", file=sys.stderr)
        kept.append((x, present))
    if not kept:
        raise logs.LogError("no panel can be drawn: the log(s) print none of the columns asked for")
    return kept


def cmd_timeseries(args):
    panels = []
    specs = (COLUMN_PRESET if args.preset == "column" else []) + (args.plot or [])
    if not specs:
        raise SystemExit("nscd-analysis timeseries: give --plot X:Y (or --preset column)")
    for spec in specs:
        x, sep, ys = spec.partition(":")
        if not sep or not ys:
            raise SystemExit(f"nscd-analysis: --plot '{spec}' must be X:Y[,Y2...] (thermo column names)")
        panels.append((x, ys.split(",")))
    panels = _panels_in_logs(args.log, panels)
    names = []
    for x, ys in panels:
        for n in [x] + ys:
            if n not in names:
                names.append(n)
    fig = plots.series_panels([(x, ys, logs.thermo_columns(args.log, [x] + ys)) for x, ys in panels])
    table = logs.thermo_columns(args.log, names, require_all=False)
    print(plots.save(fig, args.out), _write_csv(args.out, names, table.tolist()))


def cmd_thermo_at(args):
    """One line per step: the step and the column's value at the last thermo row at or before
    it (nan before the first row or where the column is not printed)."""
    table = logs.thermo_columns(args.log, ["Step", args.column], require_all=False)
    for step in args.steps:
        rows = table[(table[:, 0] <= step) & ~np.isnan(table[:, 1])]
        print(step, _fmt(rows[-1, 1]) if len(rows) else "nan")


def cmd_first_step(args):
    """The first thermo step at which the column reaches the value (nothing if never)."""
    table = logs.thermo_columns(args.log, ["Step", args.column])
    reached = table[table[:, 1] >= args.value, 0]
    if len(reached):
        print(int(reached.min()))


# --- VTK for ParaView ---------------------------------------------------------------------

def cmd_vtk_network(args):
    for s in read_dumps(args.dump, args.steps, args.last):
        points, lines, point_data, cells = vtk.network(s, args.with_boundaries, args.reference_force)
        path = f"{args.out}.{s.timestep}.vtp"
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        vtk.write_polydata(path, points, lines, point_data, cells)
        print(path, f"{len(lines)} pairs")


def _wire_steps(args):
    """(elements, nodes) snapshots of the steps that both --elements and --nodes have."""
    nodes = {s.timestep: s for s in read_dumps(args.nodes)}
    for elements in read_dumps(args.elements, args.steps, args.last):
        if elements.timestep not in nodes:
            print(f"nscd-analysis: step {elements.timestep}: no node positions in {' '.join(args.nodes)}; skipped",
                  file=sys.stderr)
            continue
        yield elements, nodes[elements.timestep]


def cmd_vtk_wire(args):
    written = 0
    for elements, nodes in _wire_steps(args):
        points, lines, point_data, cells = vtk.wire(elements, nodes, args.reference_energy)
        path = f"{args.out}.{elements.timestep}.vtp"
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        vtk.write_polydata(path, points, lines, point_data, cells)
        print(path, f"{len(lines)} elements")
        written += 1
    if written == 0:
        raise SystemExit("nscd-analysis: no step with both element rows and node positions")


# --- wire-loops: how taut each loop is ---------------------------------------------------

LOOP_FIELDS = ("nodes", "x_offset", "y_offset", "offset", "z_mean", "z_span", "r_median", "turns", "length",
               "horizontal_length", "circle", "slack", "own_r_median", "own_slack")


def cmd_wire_loops(args):
    rows, series = [], []
    contacts = {s.timestep: s for s in read_dumps(args.contacts)} if args.contacts else {}
    fields = LOOP_FIELDS + (wire_loops.PRESS_FIELDS if args.contacts else ())
    for elements, nodes in _wire_steps(args):
        found = wire_loops.chains(elements.column("id1", WIRE_ELEMENTS), elements.column("id2", WIRE_ELEMENTS))
        if not found:
            print(f"step {elements.timestep}: no wire elements")
            continue
        measures = [wire_loops.loop_measures(nodes.positions_of(path, "wire node"), closed, args.axis)
                    for path, closed in found]
        if args.contacts:
            if elements.timestep in contacts:
                pressed = wire_loops.pressing([path for path, _ in found], contacts[elements.timestep], args.axis)
            else:
                print(f"nscd-analysis: step {elements.timestep}: no wire contacts in {' '.join(args.contacts)}; "
                      "its pressing columns are nan", file=sys.stderr)
                pressed = [dict.fromkeys(wire_loops.PRESS_FIELDS, float("nan")) for _ in found]
            for m, extra in zip(measures, pressed):
                m.update(extra)
        rows += [[elements.timestep, path[0], "closed" if closed else "open"] + [m[f] for f in fields]
                 for (path, closed), m in zip(found, measures)]
        series.append((elements.timestep, sorted(measures, key=lambda m: m["z_mean"])))    # drawn upwards
        slack = np.array([m["slack"] for m in measures])
        undefined = int(np.isnan(slack).sum())    # chains that span no angle about the axis
        slack_text = (f"slack median {np.nanmedian(slack):.3f} (min {np.nanmin(slack):.3f}, "
                      f"max {np.nanmax(slack):.3f})" if undefined < len(slack) else "slack undefined")
        if undefined:
            slack_text += f", {undefined} chains around no axis"
        print(f"step {elements.timestep}: {len(measures)} chains, {slack_text}, median radius "
              f"{np.median([m['r_median'] for m in measures]):.3f}, centre offset median "
              f"{np.median([m['offset'] for m in measures]):.3f} (max {max(m['offset'] for m in measures):.3f})")
    if not rows:
        raise SystemExit("nscd-analysis: no step with both element rows and node positions")
    notes = [f"wire chains about the vertical axis through {tuple(args.axis)}; slack = length / "
             "(r_median x angle spanned) - 1; offset = distance of the chain's mean node "
             "position from the axis; own_r_median, own_slack: the same about the chain's own centre"]
    if args.contacts:
        notes.append("press_down/up/out/in: the chain's wire-grain normal forces times the part of the normal "
                     "(grain to wire) pointing down/up/radially out/in; wire_wire_fn: its wire-wire normal forces")
    print(_write_csv(args.out, ["step", "first_id", "kind"] + list(fields), rows, notes))
    fig = plots.wire_loops([(step, [m["slack"] for m in measures], [m["r_median"] for m in measures],
                             [m["offset"] for m in measures], [m["z_mean"] for m in measures])
                            for step, measures in series])
    print(plots.save(fig, args.out))


# --- argument parsing -------------------------------------------------------------------------

def _common(p, axis=True, bins=True):
    p.add_argument("--out", "-o", required=True, help="output prefix: PREFIX.png and PREFIX.csv")
    p.add_argument("--steps", type=int, nargs="+", help="only these timesteps")
    p.add_argument("--last", action="store_true", help="only the last snapshot")
    if axis:
        p.add_argument("--axis", type=float, nargs=2, metavar=("X", "Y"),
                       help="vertical column axis through (X, Y); default: the grains' centre of mass")
        p.add_argument("--zmin", type=float, help="only grains/contacts with z >= ZMIN")
        p.add_argument("--zmax", type=float, help="only grains/contacts with z <= ZMAX")
    if bins:
        p.add_argument("--rbins", type=int, default=8, help="number of r bins (default 8)")
        p.add_argument("--rwidth", type=float, help="r bin width (instead of --rbins)")
        p.add_argument("--rmax", type=float, help="outer r of the last bin (default: largest r)")
        p.add_argument("--R", type=float, help="the column's radius: r is drawn in units of R (profiles) "
                                               "and R is marked on the r axis")


def _stress_ids(p):
    p.add_argument("--stress-id", default="sig", help="ID of compute nscd/stress/atom in the dump's c_ID[k] "
                                                      "headers (default sig, as examples/column/in.column)")
    p.add_argument("--crush-id", default="crush", help="ID of compute nscd/crush/atom (default crush)")


def _spread(p):
    p.add_argument("--spread", choices=("grains", "seeds"), default="grains",
                   help="error bars: standard error over the pooled grains (default), or seeds: each file "
                        "of a run one seed, bars the standard deviation over them")


def _seed_runs(p):
    p.add_argument("--run", action="append", help="LABEL=FILES, one file per seed (comma-separated names or glob "
                                                   "patterns), repeat per run: the mean over the seeds, bars their sd")


def parser():
    top = argparse.ArgumentParser(prog="nscd-analysis", description=__doc__)
    sub = top.add_subparsers(dest="command", required=True)

    p = sub.add_parser("cylavg", help="a per-atom column averaged in (r, z) bins")
    p.add_argument("dump", nargs="+", help="dump custom files (glob patterns allowed)")
    p.add_argument("--value", required=True, help="column name, e.g. c_fab[7] or nc")
    p.add_argument("--zbins", type=int, default=8)
    _common(p)
    p.set_defaults(func=cmd_cylavg)

    p = sub.add_parser("fabric-field", help="Fig. 3: principal fabric directions in the r-z plane")
    p.add_argument("dump", nargs="+", help="dump custom files with x y z and compute fabric/atom's columns")
    p.add_argument("--zbins", type=int, default=8)
    _common(p)
    p.set_defaults(func=cmd_fabric_field)

    p = sub.add_parser("fabric-angle", help="Fig. 4: mean signed angle of the largest fabric direction vs r")
    p.add_argument("--run", action="append", required=True,
                   help="LABEL=FILES (comma-separated names or glob patterns); repeat per run")
    p.add_argument("--method", choices=("grains", "tensor"), default="grains",
                   help="plot the mean of per-grain angles (default) or the angle of the mean tensor")
    _spread(p)
    _common(p)
    p.set_defaults(func=cmd_fabric_angle)

    p = sub.add_parser("stress-field", help="principal stress directions in the r-z plane (with --fabric: "
                                            "the fabric's beside them)")
    p.add_argument("dump", nargs="+", help="dump custom files with x y z and compute nscd/stress/atom's columns")
    p.add_argument("--fabric", nargs="+", help="dump custom files of compute fabric/atom: a second panel")
    p.add_argument("--zbins", type=int, default=8)
    _stress_ids(p)
    _common(p)
    p.set_defaults(func=cmd_stress_field)

    p = sub.add_parser("stress-angle", help="mean signed angle of the major principal stress vs r")
    p.add_argument("--run", action="append", required=True,
                   help="LABEL=FILES (comma-separated names or glob patterns); repeat per run")
    p.add_argument("--method", choices=("grains", "tensor"), default="grains",
                   help="plot the mean of per-grain angles (default) or the angle of the mean tensor")
    _spread(p)
    _stress_ids(p)
    _common(p)
    p.set_defaults(func=cmd_stress_angle)

    p = sub.add_parser("stress-profile", help="vertical stress sigma_zz vs r")
    p.add_argument("dump", nargs="+", help="dump custom files with x y z and compute nscd/stress/atom's columns")
    p.add_argument("--labels", nargs="+", help="one label per snapshot")
    _stress_ids(p)
    _common(p)
    p.set_defaults(func=cmd_stress_profile)

    p = sub.add_parser("crush-profile", help="fraction of grains past a crushing threshold vs r and vs z")
    p.add_argument("dump", nargs="+", help="dump custom files with x y z and compute nscd/crush/atom's columns")
    p.add_argument("--labels", nargs="+", help="one label per snapshot")
    p.add_argument("--value", choices=tuple(stress.CRUSH), default="index",
                   help="the column compared: index (default), sigma (F/d^2), fmax or d")
    p.add_argument("--threshold", type=float, default=1.0, help="a grain counts when value >= this (default 1)")
    p.add_argument("--zbins", type=int, default=8)
    _stress_ids(p)
    _common(p)
    p.set_defaults(func=cmd_crush_profile)

    p = sub.add_parser("wire-breaks", help="where the wire broke: fix wire's breaks files in (r, z)")
    p.add_argument("--run", action="append", required=True, help="LABEL=FILE[,FILE...] (breaks files); repeat per run")
    p.add_argument("--axis", type=float, nargs=2, default=(0.0, 0.0), metavar=("X", "Y"),
                   help="vertical column axis through (X, Y) (default 0 0)")
    p.add_argument("--R", type=float, help="the column's radius: r drawn in units of R")
    p.add_argument("--zmax", type=float, help="top of the z axis")
    p.add_argument("--out", "-o", required=True, help="output prefix: PREFIX.png and PREFIX.csv")
    p.set_defaults(func=cmd_wire_breaks)

    p = sub.add_parser("force-profile", help="Fig. 5: mean normal force between grains vs r")
    p.add_argument("dump", nargs="*", help="dump local files of compute nscd/contacts pairs")
    _seed_runs(p)
    p.add_argument("--labels", nargs="+", help="one label per snapshot (e.g. the plate loads)")
    p.add_argument("--points", action="store_true", help="the dump has one row per point (no 'pairs')")
    _common(p)
    p.set_defaults(func=cmd_force_profile)

    p = sub.add_parser("wire-contacts", help="Fig. 6: polar histograms of wire-grain force orientations")
    p.add_argument("dump", nargs="*", help="dump local files of compute wire/contacts")
    _seed_runs(p)
    p.add_argument("--labels", nargs="+", help="one label per snapshot (e.g. 'no load' 'Fz = 800')")
    p.add_argument("--bins", type=int, default=12, help="angular bins over 180 degrees (default 12)")
    p.add_argument("--kind", type=int, default=WIRE_GRAIN, help="contact kind: 1 wire-grain (default), 2, 3")
    p.add_argument("--vertical-within", type=float, default=30.0, help="degrees (default 30)")
    _common(p, bins=False)
    p.set_defaults(func=cmd_wire_contacts)

    p = sub.add_parser("load-curves", help="load against the plate's sink (NAME.load_curve.txt), one line per "
                                           "file, one colour per run")
    p.add_argument("--run", action="append", required=True,
                   help="LABEL=FILES (load-curve files, comma-separated names or glob patterns); repeat per run")
    p.add_argument("--at", type=float, nargs="+", help="also the sink at these loads, per file and as mean +- sd")
    p.add_argument("--out", "-o", required=True, help="output prefix: PREFIX.png and PREFIX.csv")
    p.set_defaults(func=cmd_load_curves)

    p = sub.add_parser("timeseries", help="thermo columns of a log against each other")
    p.add_argument("log", nargs="+", help="LAMMPS log file(s); several: one run split by restarts, in order")
    p.add_argument("--plot", action="append", help="X:Y[,Y2...], one panel each")
    p.add_argument("--preset", choices=("column",),
                   help="column: height, retained fraction, wire energies vs step and plate force vs "
                        "displacement, as examples/column/in.column prints them")
    p.add_argument("--out", "-o", required=True)
    p.set_defaults(func=cmd_timeseries)

    p = sub.add_parser("phases", help="per-phase table: steps, wall time, sweeps, unconverged steps, "
                                      "interpenetration, residual, time per part")
    p.add_argument("log", nargs="+", help="LAMMPS log file(s); several: one run split by restarts, in order")
    p.add_argument("--phase-column", default="v_phase", help="thermo column holding the phase number "
                                                             "(default v_phase)")
    p.add_argument("--csv", help="write the per-phase table here")
    p.add_argument("--parts", help="write the time-per-part table of the phases here (CSV)")
    p.set_defaults(func=phases.run)

    p = sub.add_parser("thermo-at", help="a thermo column's value at given steps (last row at or before each)")
    p.add_argument("log", nargs="+", help="LAMMPS log file(s), in order")
    p.add_argument("--column", required=True)
    p.add_argument("--steps", type=int, nargs="+", required=True)
    p.set_defaults(func=cmd_thermo_at)

    p = sub.add_parser("first-step", help="the first thermo step at which a column reaches a value")
    p.add_argument("log", nargs="+", help="LAMMPS log file(s), in order")
    p.add_argument("--column", required=True)
    p.add_argument("--value", type=float, required=True)
    p.set_defaults(func=cmd_first_step)

    p = sub.add_parser("vtk-network", help="force network as .vtp line segments (one file per step)")
    p.add_argument("dump", nargs="+", help="dump local files of compute nscd/contacts pairs")
    p.add_argument("--out", "-o", required=True, help="writes OUT.<step>.vtp")
    p.add_argument("--steps", type=int, nargs="+")
    p.add_argument("--last", action="store_true")
    p.add_argument("--with-boundaries", action="store_true", help="also grain-wall/plate pairs")
    p.add_argument("--reference-force", type=float, help="fn_norm = fn / this (default: the step's largest fn)")
    p.set_defaults(func=cmd_vtk_network)

    p = sub.add_parser("wire-loops",
                       help="how taut each wire loop is: radius, turns spanned, length, slack, centre offset")
    p.add_argument("--elements", nargs="+", required=True, help="dump local files of compute wire/local")
    p.add_argument("--nodes", nargs="+", required=True, help="dump custom files with id x y z of the wire nodes")
    p.add_argument("--axis", type=float, nargs=2, default=(0.0, 0.0), metavar=("X", "Y"),
                   help="vertical column axis through (X, Y) (default 0 0)")
    p.add_argument("--contacts", nargs="+", help="dump local files of compute wire/contacts: adds how the grains "
                                                  "press each loop (down, up, out, in) to the CSV")
    p.add_argument("--out", "-o", required=True, help="output prefix: PREFIX.png and PREFIX.csv")
    p.add_argument("--steps", type=int, nargs="+")
    p.add_argument("--last", action="store_true")
    p.set_defaults(func=cmd_wire_loops)

    p = sub.add_parser("vtk-wire", help="wire as .vtp line segments with per-element energy (one file per step)")
    p.add_argument("--elements", nargs="+", required=True, help="dump local files of compute wire/local")
    p.add_argument("--nodes", nargs="+", required=True, help="dump custom files with id x y z of the wire nodes")
    p.add_argument("--out", "-o", required=True, help="writes OUT.<step>.vtp")
    p.add_argument("--steps", type=int, nargs="+")
    p.add_argument("--last", action="store_true")
    p.add_argument("--reference-energy", type=float, help="energy_norm = energy / this (default: the step's largest)")
    p.set_defaults(func=cmd_vtk_wire)
    return top


def main(argv=None):
    args = parser().parse_args(argv)
    try:
        args.func(args)
    except (DumpError, logs.LogError, wire_breaks.BreaksError, ValueError, OSError) as e:
        print(f"nscd-analysis {args.command}: {e}", file=sys.stderr)
        return 1
    return 0
