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

"""VTK XML PolyData (.vtp) files for ParaView: the force network as line segments between
grain centres, the wire as connected line segments between its nodes.

Network: each grain-grain pair is a line cell with two points of its own (x_i and the image
of x_j nearest to it), so a Tube filter can vary the radius by point data. Cell and point
data: fn (total normal force), fn_norm (fn / largest fn of the file, or of a given
reference), force (vector on i), id_i, id_j.

Wire: one point per node, one line cell per element; cell data strain, tension, energy,
energy_norm (energy / largest of the file or a given reference); point data id and
node_energy (mean of the node's elements' energies, for smooth colouring)."""

from xml.sax.saxutils import quoteattr

import numpy as np

from .layouts import CONTACT_PAIRS, WIRE_ELEMENTS


def _data_array(name, values):
    values = np.asarray(values, dtype=float)
    components = 1 if values.ndim == 1 else values.shape[1]
    text = " ".join(f"{v:.9g}" for v in values.ravel())
    return (f'<DataArray type="Float64" Name={quoteattr(name)} NumberOfComponents="{components}" '
            f'format="ascii">{text}</DataArray>')


def write_polydata(path, points, lines, point_data=None, cell_data=None):
    """points: n x 3; lines: m x 2 point indices; *_data: dict name -> array (n or m rows)."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    lines = np.asarray(lines, dtype=np.int64).reshape(-1, 2)
    parts = ['<?xml version="1.0"?>',
             '<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">', "<PolyData>",
             f'<Piece NumberOfPoints="{len(points)}" NumberOfVerts="0" NumberOfLines="{len(lines)}" '
             f'NumberOfStrips="0" NumberOfPolys="0">',
             "<Points>", _data_array("Points", points), "</Points>"]
    for tag, data in (("PointData", point_data), ("CellData", cell_data)):
        parts.append(f"<{tag}>")
        for name, values in (data or {}).items():
            parts.append(_data_array(name, values))
        parts.append(f"</{tag}>")
    connectivity = " ".join(str(i) for i in lines.ravel())
    offsets = " ".join(str(2 * (k + 1)) for k in range(len(lines)))
    parts += ["<Lines>", f'<DataArray type="Int64" Name="connectivity" format="ascii">{connectivity}</DataArray>',
              f'<DataArray type="Int64" Name="offsets" format="ascii">{offsets}</DataArray>', "</Lines>",
              "</Piece>", "</PolyData>", "</VTKFile>"]
    with open(path, "w") as f:
        f.write("\n".join(parts) + "\n")


def _normalised(values, reference):
    top = reference if reference else (float(np.max(values)) if len(values) else 0.0)
    return values / top if top > 0 else np.zeros_like(values)


def network(snapshot, with_boundaries=False, reference_force=None):
    """Points, lines, point data and cell data of the force network of one pairs snapshot
    (rows with a positive normal force)."""
    layout = CONTACT_PAIRS
    id_j = snapshot.column("id_j", layout)
    fn = snapshot.column("fn", layout)
    keep = (fn > 0) & ((id_j > 0) | with_boundaries)
    xi = snapshot.vectors(("xi", "yi", "zi"), layout)[keep]
    xj = snapshot.vectors(("xj", "yj", "zj"), layout)[keep]
    fn = fn[keep]
    n = len(fn)
    points = np.empty((2 * n, 3))
    points[0::2], points[1::2] = xi, xj
    lines = np.arange(2 * n).reshape(n, 2)
    cells = {"fn": fn, "fn_norm": _normalised(fn, reference_force),
             "force": snapshot.vectors(("fx", "fy", "fz"), layout)[keep],
             "id_i": snapshot.column("id_i", layout)[keep], "id_j": id_j[keep]}
    point_data = {name: np.repeat(values, 2, axis=0) for name, values in cells.items()}
    return points, lines, point_data, cells


def wire(elements, nodes, reference_energy=None):
    """Points, lines, point data and cell data of the wire from a wire/local snapshot and a
    dump custom snapshot of the nodes (id and x y z, or xu yu zu: unwrapped positions keep an
    element that crosses a periodic boundary whole)."""
    layout = WIRE_ELEMENTS
    id1 = elements.column("id1", layout).astype(np.int64)
    id2 = elements.column("id2", layout).astype(np.int64)
    used = np.unique(np.concatenate([id1, id2]))
    index = {tag: k for k, tag in enumerate(used)}
    points = nodes.positions_of(used, "wire node")
    lines = np.array([[index[a], index[b]] for a, b in zip(id1, id2)], dtype=np.int64).reshape(-1, 2)
    energy = elements.column("energy", layout)
    cells = {"strain": elements.column("strain", layout), "tension": elements.column("tension", layout),
             "energy": energy, "energy_norm": _normalised(energy, reference_energy)}
    node_energy = np.zeros(len(used))
    touching = np.zeros(len(used))
    for k in range(2):
        np.add.at(node_energy, lines[:, k], energy)
        np.add.at(touching, lines[:, k], 1.0)
    point_data = {"id": used.astype(float), "node_energy": node_energy / np.maximum(touching, 1.0)}
    return points, lines, point_data, cells
