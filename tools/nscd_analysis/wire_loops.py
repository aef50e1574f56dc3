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

"""How taut the wire's loops are (nscd-analysis wire-loops): each chain of elements (a
loop of the column) walked from end to end, with its median distance from the column axis,
the turns it spans about the axis, its length, its slack: how much longer it is than the
circle of its median radius over the angle it spans, and its centre's offset from the axis.
A loop with slack s lets the column widen by about s before it pulls; loops whose centres
move off the axis together, more with height, are a column that leans. For a loop that has
moved off the axis the radius and slack about its own centre (own_r_median, own_slack) say
whether it is still taut where those about the axis no longer can."""

import numpy as np


def chains(id1, id2):
    """The node IDs of each connected chain of elements (id1[k], id2[k]), in path order from
    one free end (a closed chain starts at its smallest ID); chains sorted by first ID."""
    neighbours = {}
    for a, b in zip(id1, id2):
        a, b = int(a), int(b)
        neighbours.setdefault(a, []).append(b)
        neighbours.setdefault(b, []).append(a)
    branching = sorted(t for t, n in neighbours.items() if len(n) > 2)
    if branching:
        raise ValueError(f"wire nodes {branching[:10]} join more than two elements: not a chain")
    seen, result = set(), []
    ends = sorted(t for t, n in neighbours.items() if len(n) == 1)
    for start in ends + sorted(neighbours):    # open chains from an end, then closed rings
        if start in seen:
            continue
        path, previous, current = [start], None, start
        seen.add(start)
        while True:
            following = [t for t in neighbours[current] if t != previous and t not in seen]
            if not following:
                break
            previous, current = current, following[0]
            path.append(current)
            seen.add(current)
        closed = len(neighbours[start]) == 2 and start in neighbours[path[-1]] and len(path) > 2
        result.append((path, closed))
    return sorted(result, key=lambda c: c[0][0])


def loop_measures(points, closed, axis=(0.0, 0.0)):
    """Measures of one chain (points in path order, n x 3) about a vertical axis through
    axis = (X, Y): a dict of nodes, x_offset and y_offset (the mean node position less the
    axis: where the loop's centre has moved), offset (its distance from the axis), z_mean,
    z_span (highest node minus lowest: how far the chain has warped out of a horizontal
    plane, a helix's own rise included), r_median, turns
    (signed turns spanned about the axis), length (sum of the element lengths, the closing one
    of a ring included), horizontal_length, circle (r_median times the angle spanned: a closed
    chain's is a whole number of turns, so a ring that no longer encloses the axis spans none
    and its slack is nan), slack (length / circle - 1), and own_r_median and own_slack: the
    same two about the vertical axis through the chain's own centre (its mean node)."""
    m = _measures_about(points, closed, axis)
    own = _measures_about(points, closed, (axis[0] + m["x_offset"], axis[1] + m["y_offset"]))
    m["own_r_median"], m["own_slack"] = own["r_median"], own["slack"]
    return m


def _measures_about(points, closed, axis):
    """loop_measures' fields but the own_ ones, about the vertical axis through axis."""
    p = np.asarray(points, dtype=float)
    if closed:
        p = np.vstack([p, p[:1]])
    x, y, z = p[:, 0] - axis[0], p[:, 1] - axis[1], p[:, 2]
    r = np.hypot(x, y)
    step = np.diff(p, axis=0)
    length = float(np.sqrt((step ** 2).sum(axis=1)).sum())
    horizontal = float(np.hypot(step[:, 0], step[:, 1]).sum())
    angle = np.unwrap(np.arctan2(y, x))
    spanned = float(angle[-1] - angle[0])
    if closed:    # a closed chain winds a whole number of times (none: it has left the axis)
        spanned = 2.0 * np.pi * round(spanned / (2.0 * np.pi))
    nodes = len(points)
    r_median = float(np.median(r[:nodes]))
    circle = r_median * abs(spanned)
    x_offset, y_offset = float(x[:nodes].mean()), float(y[:nodes].mean())
    return {"nodes": nodes, "x_offset": x_offset, "y_offset": y_offset,
            "offset": float(np.hypot(x_offset, y_offset)),
            "z_mean": float(z[:nodes].mean()), "z_span": float(np.ptp(z[:nodes])), "r_median": r_median,
            "turns": spanned / (2.0 * np.pi), "length": length, "horizontal_length": horizontal,
            "circle": circle, "slack": length / circle - 1.0 if circle > 0.0 else float("nan")}
