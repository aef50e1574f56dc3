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

"""Reading LAMMPS text dumps (dump custom: ITEM: ATOMS; dump local: ITEM: ENTRIES), plain or
gzip-compressed, one Snapshot per timestep, and finding columns by name.

A column is found by its name in the header ("x", "id", or a name given with
`dump_modify colname`) or, for the output of one of our computes, by its place in that
compute's layout (layouts.py): the header entry c_ID[k] is column k of compute ID."""

import glob
import gzip
import re

import numpy as np

_INDEXED = re.compile(r"^[cf]_([^\[\]]+)\[(\d+)\]$")


def indexed_entry(header_name):
    """(ID, k) of a header entry c_ID[k] or f_ID[k]; None for any other name."""
    m = _INDEXED.match(header_name)
    return (m.group(1), int(m.group(2))) if m else None


class DumpError(ValueError):
    """A dump that cannot be read, or a column it does not have."""


class Snapshot:
    """One timestep of a dump: its box bounds (3 x 2, tilt factors dropped), column names and
    data (rows x columns, float)."""

    def __init__(self, timestep, box, columns, data, source=""):
        self.timestep = timestep
        self.box = box
        self.columns = columns
        self.data = data
        self.source = source

    def __len__(self):
        return self.data.shape[0]

    def has(self, name, layout=None):
        try:
            self.column_index(name, layout)
            return True
        except DumpError:
            return False

    def column_index(self, name, layout=None):
        """Index of column `name`: by header name first, then by `layout` (a dict canonical
        name -> 1-based column of the compute) matched against c_ID[k] headers."""
        if name in self.columns:
            return self.columns.index(name)
        if layout is not None and name in layout:
            k = layout[name]
            found = [i for i, c in enumerate(self.columns) if indexed_entry(c) and indexed_entry(c)[1] == k]
            if len(found) == 1:
                return found[0]
            if len(found) > 1:
                raise DumpError(f"{self.source}: column '{name}' (entry {k} of the compute) is ambiguous: "
                                f"{', '.join(self.columns[i] for i in found)}; name it with "
                                f"'dump_modify ID colname N {name}'")
        raise DumpError(f"{self.source}: no column '{name}' in ITEM line ({' '.join(self.columns)}); "
                        f"dump it, or name it with 'dump_modify ID colname N {name}'")

    def column(self, name, layout=None):
        return self.data[:, self.column_index(name, layout)]

    def first_column(self, names, layout=None):
        """The first of `names` that the snapshot has (e.g. ('xu', 'x'))."""
        for name in names:
            if self.has(name, layout):
                return self.column(name, layout)
        raise DumpError(f"{self.source}: none of the columns {', '.join(names)} in ITEM line "
                        f"({' '.join(self.columns)})")

    def positions_of(self, ids, what="atom"):
        """Positions (rows x 3) of the atoms with these IDs, in their order: unwrapped xu yu zu
        if dumped (an element across a periodic boundary stays whole), else x y z. A missing ID
        is named."""
        row_of = {int(t): k for k, t in enumerate(self.column("id").astype(np.int64))}
        missing = sorted({int(t) for t in ids if int(t) not in row_of})
        if missing:
            raise DumpError(f"{self.source} step {self.timestep}: no position for {what} IDs "
                            f"{missing[:10]}{' ...' if len(missing) > 10 else ''} (dump the wire's group)")
        positions = np.column_stack([self.first_column(n) for n in (("xu", "x"), ("yu", "y"), ("zu", "z"))])
        return positions[[row_of[int(t)] for t in ids]]

    def vectors(self, names, layout=None):
        """Columns side by side: vectors(('x', 'y', 'z')) -> rows x 3."""
        return np.column_stack([self.column(n, layout) for n in names]) if len(self) else np.zeros((0, len(names)))


def _open_text(path):
    if str(path).endswith(".gz"):
        return gzip.open(path, "rt")
    return open(path, "r")


def read_dump(path):
    """All snapshots of one dump file, in file order."""
    snapshots = []
    with _open_text(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if not lines[k].startswith("ITEM: TIMESTEP"):
            if lines[k].strip():
                raise DumpError(f"{path}: line {k + 1}: expected 'ITEM: TIMESTEP', found '{lines[k][:60]}'")
            k += 1
            continue
        try:
            timestep = int(lines[k + 1])
            if not lines[k + 2].startswith("ITEM: NUMBER OF"):
                raise DumpError(f"{path}: line {k + 3}: expected 'ITEM: NUMBER OF ...'")
            rows = int(lines[k + 3])
            box = np.array([[float(v) for v in lines[k + 5 + d].split()[:2]] for d in range(3)])
            header = lines[k + 8]
        except (IndexError, ValueError) as e:
            raise DumpError(f"{path}: snapshot header at line {k + 1} is cut or malformed ({e})") from None
        if not (header.startswith("ITEM: ATOMS") or header.startswith("ITEM: ENTRIES")):
            raise DumpError(f"{path}: line {k + 9}: expected 'ITEM: ATOMS' or 'ITEM: ENTRIES', found "
                            f"'{header[:60]}' (only text dumps of custom/local style are read)")
        columns = header.split()[2:]
        body = lines[k + 9:k + 9 + rows]
        if len(body) < rows:
            raise DumpError(f"{path}: step {timestep} announces {rows} rows, the file ends after {len(body)}")
        values = " ".join(body).split()
        if len(values) != rows * len(columns):
            raise DumpError(f"{path}: step {timestep}: {len(values)} values for {rows} rows of "
                            f"{len(columns)} columns")
        data = np.array(values, dtype=float).reshape(rows, len(columns))
        snapshots.append(Snapshot(timestep, box, columns, data, str(path)))
        k += 9 + rows
    return snapshots


def expand(patterns):
    """File names from names and glob patterns, each pattern's matches in natural order
    (dump.2.txt before dump.10.txt)."""
    files = []
    for p in patterns:
        matches = glob.glob(p) if any(ch in p for ch in "*?[") else [p]
        if not matches:
            raise DumpError(f"no file matches '{p}'")
        files += sorted(matches, key=lambda s: [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", s)])
    return files


def read_dumps(patterns, steps=None, last=False):
    """Snapshots of several files (names or glob patterns) in timestep order; `steps` keeps
    only those timesteps (all must be found); `last` keeps only the last snapshot."""
    snaps = []
    for path in expand(patterns):
        snaps += read_dump(path)
    snaps.sort(key=lambda s: s.timestep)
    if steps is not None:
        have = {s.timestep: s for s in snaps}
        missing = [t for t in steps if t not in have]
        if missing:
            raise DumpError(f"timesteps {missing} not in {', '.join(patterns)} "
                            f"(it has {sorted(have)[:10]}{' ...' if len(have) > 10 else ''})")
        snaps = [have[t] for t in steps]
    if last and snaps:
        snaps = snaps[-1:]
    if not snaps:
        raise DumpError(f"no snapshot in {', '.join(patterns)}")
    return snaps
