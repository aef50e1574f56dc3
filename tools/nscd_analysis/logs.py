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

"""Thermo output of a LAMMPS log file: the blocks between a header line starting with
'Step' (or any thermo_style custom header) and 'Loop time'."""

import gzip
import os

import numpy as np


class LogError(ValueError):
    pass


def read_thermo(path):
    """List of (columns, data) per run in the log; data is rows x columns (float)."""
    opener = gzip.open if str(path).endswith(".gz") else open
    with opener(path, "rt") as f:
        lines = f.read().splitlines()
    blocks, k = [], 0
    while k < len(lines):
        words = lines[k].split()
        if words and words[0] in ("Step", "Time", "Elapsed") and _numeric_row_follows(lines, k, len(words)):
            columns, rows = words, []
            k += 1
            while k < len(lines):
                if lines[k].startswith("WARNING"):    # LAMMPS warns between thermo rows
                    k += 1
                    continue
                values = lines[k].split()
                if len(values) != len(columns) or not _all_numbers(values):
                    break
                rows.append([float(v) for v in values])
                k += 1
            blocks.append((columns, np.array(rows)))
            continue
        k += 1
    if not blocks:
        raise LogError(f"{path}: no thermo output found (a header line starting with 'Step' "
                       f"followed by rows of numbers)")
    return blocks


def _all_numbers(values):
    try:
        for v in values:
            float(v)
        return True
    except ValueError:
        return False


def _numeric_row_follows(lines, k, n):
    return k + 1 < len(lines) and len(lines[k + 1].split()) == n and _all_numbers(lines[k + 1].split())


def read_thermo_logs(paths):
    """read_thermo of one log or of several (a run split by restarts: one log per part, in
    the order given), the blocks of all concatenated."""
    if isinstance(paths, (str, bytes, os.PathLike)):
        return read_thermo(paths)
    return [block for path in paths for block in read_thermo(path)]


def has_columns(paths, names):
    """The names that no run of the log(s) prints (empty: all are there)."""
    have = {c for cols, _ in read_thermo_logs(paths) for c in cols}
    return [n for n in names if n not in have]


def thermo_columns(path, names, require_all=True):
    """The named columns over the runs of the log (or of several logs, in the order given:
    a run split by restarts), concatenated in run order (a run that starts by repeating the
    previous run's last step drops that row; after reset_timestep Step starts again).
    require_all: only runs that print all of them; else every run that prints any, NaN for
    the others."""
    parts, last_step = [], None
    blocks = read_thermo_logs(path)
    for columns, data in blocks:
        present = [n in columns for n in names]
        if not len(data) or not (all(present) if require_all else any(present)):
            continue
        rows = np.ones(len(data), dtype=bool)
        if "Step" in columns:
            step = data[:, columns.index("Step")]
            if last_step is not None and step[0] == last_step:
                rows[0] = False
            last_step = step[-1]
        part = np.full((int(rows.sum()), len(names)), np.nan)
        for k, n in enumerate(names):
            if n in columns:
                part[:, k] = data[rows, columns.index(n)]
        parts.append(part)
    if not parts:
        have = sorted({c for cols, _ in blocks for c in cols})
        where = path if isinstance(path, (str, bytes, os.PathLike)) else " + ".join(map(str, path))
        raise LogError(f"{where}: no run prints {'all' if require_all else 'any'} of {', '.join(names)} "
                       f"(thermo columns: {', '.join(have)})")
    return np.vstack(parts)
