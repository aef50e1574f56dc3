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

"""The figures of nscd-analysis (matplotlib, Agg): each function takes numbers the analysis
modules computed (cli.py gathers them) and returns a figure; save() writes it as PREFIX.png.
Nothing here reads a dump or computes a statistic."""

import os

import numpy as np

DPI = 100


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, prefix):
    os.makedirs(os.path.dirname(os.path.abspath(prefix)), exist_ok=True)
    fig.savefig(prefix + ".png", dpi=DPI)
    pyplot().close(fig)
    return prefix + ".png"


def mark_r_axis(ax, radius, scaled):
    """Label the r axis; with a column radius, mark it on the axis. scaled: the plotted r is
    already r / radius."""
    if radius is None:
        ax.set_xlabel("r")
        return
    ax.axvline(1.0 if scaled else radius, color="0.4", ls="--", lw=0.8)
    ax.annotate("R", xy=(1.0 if scaled else radius, 1.0), xycoords=("data", "axes fraction"),
                xytext=(2, -10), textcoords="offset points", color="0.3")
    ax.set_xlabel(f"r / R   (R = {radius:g})" if scaled else f"r   (R = {radius:g})")


def cylavg_map(r_edges, z_edges, mean, value, snapshots, radius):
    """A per-atom value averaged in (r, z) bins, as a colour map."""
    fig, ax = pyplot().subplots(figsize=(5.0, 5.0))
    mesh = ax.pcolormesh(r_edges, z_edges, np.ma.masked_invalid(mean.T), shading="flat", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=value)
    mark_r_axis(ax, radius, scaled=False)
    ax.set_ylabel("z")
    ax.set_title(f"{value} averaged around the axis ({snapshots} snapshot(s))")
    fig.tight_layout()
    return fig


def angle_limit(segments):
    """The largest |signed angle| of a field's bins (the colour scale of draw_field)."""
    return max([abs(s[6]) for s in segments] + [1e-3])


def draw_field(fig, ax, segments, r_edges, z_edges, title, radius, what="largest direction", limit=None):
    """Bars along the principal directions of each bin (fields.principal_field's segments;
    length: the principal value; the largest coloured by its signed angle, on -limit..limit:
    default the largest |angle|)."""
    from matplotlib.collections import LineCollection
    cell = min(np.diff(r_edges).min(), np.diff(z_edges).min())
    scale = 0.9 * cell / max([abs(s[2]) for s in segments] + [1e-300])
    if limit is None:
        limit = angle_limit(segments)

    def bars(length_of, direction_of):
        return [[(x - 0.5 * scale * length_of(s) * direction_of(s)[0], y - 0.5 * scale * length_of(s) * direction_of(s)[1]),
                 (x + 0.5 * scale * length_of(s) * direction_of(s)[0], y + 0.5 * scale * length_of(s) * direction_of(s)[1])]
                for s in segments for x, y in [s[:2]]]
    big = bars(lambda s: abs(s[2]), lambda s: s[3])
    small = bars(lambda s: abs(s[4]), lambda s: s[5])
    ax.add_collection(LineCollection(small, colors="0.35", linewidths=0.8))
    lc = LineCollection(big, array=np.array([s[6] for s in segments]), cmap="coolwarm", linewidths=3.0)
    lc.set_clim(-limit, limit)
    ax.add_collection(lc)
    fig.colorbar(lc, ax=ax, label=f"signed angle of the {what} with z (rad)")
    ax.set_xlim(r_edges[0], r_edges[-1])
    ax.set_ylim(z_edges[0], z_edges[-1])
    ax.set_aspect("equal")
    mark_r_axis(ax, radius, scaled=False)
    ax.set_ylabel("z")
    ax.set_title(title, fontsize=9)


def principal_fields(fields, r_edges, z_edges, radius, what_of=lambda name: "largest direction"):
    """One panel per field, side by side, on one colour scale: fields = [(name, title,
    segments)]; what_of(name) names the direction drawn in colour."""
    fig, axes = pyplot().subplots(1, len(fields), figsize=(5.0 * len(fields), 6.0), squeeze=False)
    limit = max(angle_limit(segments) for _, _, segments in fields)
    for (name, title, segments), ax in zip(fields, axes[0]):
        draw_field(fig, ax, segments, r_edges, z_edges, title, radius, what_of(name), limit)
    fig.tight_layout()
    return fig


def profiles(curves, radius, ylabel, title=None, zero_line=False):
    """Curves against r / R with error bars: curves = [(label, x, y, yerr or None)]."""
    fig, ax = pyplot().subplots(figsize=(6.0, 4.2))
    for label, x, y, yerr in curves:
        ax.errorbar(x, y, yerr=yerr, marker="o", ms=4, capsize=2, label=label)
    if zero_line:
        ax.axhline(0.0, color="0.6", lw=0.8)
    mark_r_axis(ax, radius, scaled=True)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=9)
    ax.legend()
    fig.tight_layout()
    return fig


def r_and_z_profiles(curves_r, curves_z, radius, ylabel):
    """Two panels: curves against r / R (left) and against z (right), as in profiles()."""
    fig, (left, right) = pyplot().subplots(1, 2, figsize=(9.0, 4.0))
    for ax, curves in ((left, curves_r), (right, curves_z)):
        for label, x, y, yerr in curves:
            ax.errorbar(x, y, yerr=yerr, marker="o", ms=4, capsize=2, label=label)
    mark_r_axis(left, radius, scaled=True)
    right.set_xlabel("z")
    for ax in (left, right):
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def points_rz(groups, radius, zmax, title):
    """Points in the (r / R, z) plane: groups = [(label, r, z)]."""
    fig, ax = pyplot().subplots(figsize=(5.0, 5.0))
    for label, r, z in groups:
        ax.scatter(r, z, s=14, label=label)
    mark_r_axis(ax, radius, scaled=True)
    ax.set_ylabel("z")
    if zmax is not None:
        ax.set_ylim(0.0, zmax)
    ax.set_xlim(0.0, None)
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def polar_histograms(rows):
    """One row of two half-disc histograms per snapshot: rows = [(label, edges, fraction,
    normalised mean force[, sd of fraction, sd of normalised])] (wire_contacts.polar_histogram;
    the sds, over seeds, drawn as radial bars)."""
    from matplotlib.ticker import MaxNLocator
    fig, axes = pyplot().subplots(len(rows), 2, figsize=(6.4, 2.4 * len(rows)), subplot_kw={"projection": "polar"},
                                  squeeze=False)
    for (label, edges, fraction, normalised, *sds), (left, right) in zip(rows, axes):
        width = np.diff(edges)
        left.bar(edges[:-1], fraction, width=width, align="edge", color="tab:blue", edgecolor="k", lw=0.4)
        right.bar(edges[:-1], np.nan_to_num(normalised), width=width, align="edge", color="tab:orange",
                  edgecolor="k", lw=0.4)
        for ax, values, sd in zip((left, right), (fraction, normalised), sds):
            ax.errorbar(edges[:-1] + 0.5 * width, values, yerr=sd, fmt="none", ecolor="k", elinewidth=0.8, capsize=1.5)
        for ax, title in ((left, f"{label}: fraction of contacts"), (right, f"{label}: mean |f| / max")):
            ax.set_thetamin(0)
            ax.set_thetamax(180)
            ax.set_title(title, fontsize=9)
            ax.yaxis.set_major_locator(MaxNLocator(3))
            ax.tick_params(labelsize=7)
    fig.tight_layout()
    return fig


def load_curves(lines):
    """Load against the plate's sink: lines = [(run label, sink, load)], one colour per run."""
    fig, ax = pyplot().subplots(figsize=(6.0, 4.2))
    colours = {}
    for label, down, load in lines:
        first = label not in colours
        colours.setdefault(label, f"C{len(colours) % 10}")
        ax.plot(down, load, color=colours[label], lw=1.2, label=label if first else None)
        ax.plot(down[-1:], load[-1:], "x", color=colours[label], ms=6)
    ax.set_xlabel("sink of the plate since the loading started")
    ax.set_ylabel("load on the plate")
    ax.set_title("one line per seed; x: the last row (failure, or the run's end)", fontsize=9)
    ax.legend()
    fig.tight_layout()
    return fig


def series_panels(panels):
    """One panel per X: panels = [(x_name, y_names, data)], data's first column X, then the Ys."""
    fig, axes = pyplot().subplots(len(panels), 1, figsize=(6.0, 2.4 * len(panels)), squeeze=False)
    for (x, ys, data), (ax,) in zip(panels, axes):
        for k, y in enumerate(ys):
            ax.plot(data[:, 0], data[:, k + 1], label=y)
        ax.set_xlabel(x)
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def wire_loops(series):
    """Slack, median radius and centre offset of each loop against its height: series =
    [(step, slack, radius, offset, height)], one curve per step."""
    fig, (left, middle, right) = pyplot().subplots(1, 3, figsize=(12, 4), sharey=True)
    for step, slack, radius, offset, height in series:
        left.plot(slack, height, "o-", label=f"step {step}")
        middle.plot(radius, height, "o-", label=f"step {step}")
        right.plot(offset, height, "o-", label=f"step {step}")
    left.set_xlabel("slack (length / circle - 1)")
    left.set_ylabel("mean height of the loop")
    middle.set_xlabel("median radius of the loop")
    right.set_xlabel("offset of the loop's centre from the axis")
    left.legend(fontsize=8)
    fig.tight_layout()
    return fig
