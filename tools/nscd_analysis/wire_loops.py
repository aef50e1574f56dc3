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

from .cylinder import Cylindrical
from .layouts import WIRE_CONTACTS, WIRE_GRAIN, WIRE_WIRE

# How the grains press each chain (wire-loops --contacts): the loop's friction, which keeps
# its ends from sliding apart, can only be as large as what clamps it.
PRESS_FIELDS = ("grain_points", "press_down", "press_up", "press_out", "press_in", "wire_wire_fn")


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


def pressing(chain_paths, contacts, axis=(0.0, 0.0)):
    """How the grains press each chain (a list of node-ID paths), from one snapshot of
    compute wire/contacts (layouts.WIRE_CONTACTS): per chain a dict of PRESS_FIELDS.
    grain_points: its wire-grain contact points; press_down, press_up: the sums of their
    normal forces f_n times the part of the normal (from grain to wire) pointing down or up
    (grains above pressing the wire down, grains below pressing it up: down + up is the clamp
    between layers); press_out, press_in: the same along the outward radial direction about
    the vertical axis through axis = (X, Y) at the contact point (grains pushing the loop
    outward, as a column held in by it does, or inward); wire_wire_fn: the normal forces of
    the wire-wire points where the chain touches itself or another chain. A point belongs to
    the chain of its element's first node (for wire-wire, also to the other element's)."""
    chain_of = {node: k for k, path in enumerate(chain_paths) for node in path}
    out = [dict.fromkeys(PRESS_FIELDS, 0.0) for _ in chain_paths]
    kind = contacts.column("kind", WIRE_CONTACTS)
    id1 = contacts.column("id1", WIRE_CONTACTS).astype(np.int64)
    other = contacts.column("other", WIRE_CONTACTS).astype(np.int64)
    fn = contacts.column("fn", WIRE_CONTACTS)
    n = contacts.vectors(("nx", "ny", "nz"), WIRE_CONTACTS)
    n_r = np.einsum("ij,ij->i", n, Cylindrical(contacts.vectors(("px", "py", "pz"), WIRE_CONTACTS), axis).e_r)
    for k in range(len(kind)):
        mine = chain_of.get(int(id1[k]))
        if kind[k] == WIRE_GRAIN and mine is not None:
            m = out[mine]
            m["grain_points"] += 1
            m["press_down"] += fn[k] * max(0.0, -n[k, 2])
            m["press_up"] += fn[k] * max(0.0, n[k, 2])
            m["press_out"] += fn[k] * max(0.0, n_r[k])
            m["press_in"] += fn[k] * max(0.0, -n_r[k])
        elif kind[k] == WIRE_WIRE:
            for chain in {mine, chain_of.get(int(other[k]))} - {None}:
                out[chain]["wire_wire_fn"] += fn[k]
    return out
