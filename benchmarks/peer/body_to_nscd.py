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

"""The last snapshot of a BODY run (dump of in.body) as a data file of atom_style
spheropolyhedron, so that in.overlap measures its overlaps with our contact geometry.

    body_to_nscd.py PEER_DATA BODY_DUMP OUT_DATA [SHAPES BODY_VERTICES]

PEER_DATA: our data file of the initial state (in.setup), for shape ids, masses and the
initial orientations q0. BODY_DUMP: in.body's dump (id x y z qw qi qj qk) of the first and
the last step. BODY turns each grain into its own principal frame, so its quaternion qb
differs from ours by a constant body-frame rotation: our orientation at the end is
qb_end * conj(qb_0) * q0.

With SHAPES (our shape library) and BODY_VERTICES (dump local of compute body/local id 1 2 3
at the last step), checks that our grains, so placed, have their vertices where BODY has
them, and prints the largest distance.
"""
import argparse
import sys

import numpy as np


def qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                     w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                     w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def conj(q):
    return np.array([q[0], -q[1], -q[2], -q[3]])


def read_snapshots(path):
    """{timestep: {id: (x(3), q(4))}} from a dump custom file."""
    snaps, lines = {}, open(path).read().split('\n')
    i = 0
    while i < len(lines):
        if lines[i].startswith('ITEM: TIMESTEP'):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            rows = {}
            for line in lines[i + 9:i + 9 + n]:
                v = dict(zip(cols, line.split()))
                rows[int(v['id'])] = (np.array([float(v[c]) for c in ('x', 'y', 'z')]),
                                      np.array([float(v['c_q[%d]' % k]) for k in (1, 2, 3, 4)]))
            snaps[step] = rows
            i += 9 + n
        else:
            i += 1
    return snaps


def read_shapes(path):
    """[body-frame vertex array] by shape id (1-based; index 0 unused) from a shape library."""
    shapes, words = [None], open(path).read().split('\n')
    k = 0
    while k < len(words):
        line = words[k].split('#')[0].split()
        if line and line[0] == 'vertices':
            n = int(line[1])
            shapes.append(np.array([[float(c) for c in words[k + 1 + i].split()[:3]] for i in range(n)]))
            k += n
        k += 1
    return shapes


def rotation(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def last_vertices(path):
    """{atom id: vertex array} of the last snapshot of a dump local of compute body/local."""
    lines = open(path).read().split('\n')
    start = max(i for i, line in enumerate(lines) if line.startswith('ITEM: TIMESTEP'))
    n = int(lines[start + 3])
    by_atom = {}
    for line in lines[start + 9:start + 9 + n]:
        v = line.split()
        by_atom.setdefault(int(float(v[1])), []).append([float(c) for c in v[2:5]])
    return {k: np.array(v) for k, v in by_atom.items()}


def vertex_mismatch(placed, shapes_path, vertices_path):
    """Largest distance from a vertex of our placed grain to the nearest of BODY's."""
    shapes, body = read_shapes(shapes_path), last_vertices(vertices_path)
    worst = 0.0
    for atom_id, (shape, x, q) in placed.items():
        ours = x + shapes[shape] @ rotation(q).T
        theirs = body[atom_id]
        if len(theirs) != len(ours):
            sys.exit(f'atom {atom_id}: BODY has {len(theirs)} vertices, our shape {shape} {len(ours)}')
        d = np.linalg.norm(ours[:, None, :] - theirs[None, :, :], axis=2)
        worst = max(worst, d.min(axis=1).max(), d.min(axis=0).max())
    return worst


def main(peer_data, dump, out_data, shapes=None, vertices=None):
    snaps = read_snapshots(dump)
    steps = sorted(snaps)
    if len(steps) < 2:
        sys.exit(f'{dump}: needs the first and the last step, found steps {steps}')
    first, last = snaps[steps[0]], snaps[steps[-1]]
    text = open(peer_data).read().split('\n')
    out, section, placed = [], None, {}
    for line in text:
        words = line.split()
        if words and words[0] in ('Atoms', 'Velocities'):
            section = words[0]
            if section == 'Velocities':
                break
            out.append(line)
            continue
        if section == 'Atoms' and len(words) >= 11:
            atom_id = int(words[0])
            q0 = np.array([float(w) for w in words[7:11]])
            x_end, qb_end = last[atom_id]
            q = qmul(qmul(qb_end, conj(first[atom_id][1])), q0)
            q /= np.linalg.norm(q)
            words[4:7] = ['%.17g' % c for c in x_end]
            words[7:11] = ['%.17g' % c for c in q]
            words[11:] = []
            placed[atom_id] = (int(words[2]), x_end, q)
            line = ' '.join(words)
        out.append(line)
    with open(out_data, 'w') as f:
        f.write('\n'.join(out).rstrip() + '\n')
    print(f'{out_data}: step {steps[-1]} of {dump}, {len(last)} grains')
    if vertices:
        print(f'largest distance between our and BODY\'s vertices: {vertex_mismatch(placed, shapes, vertices):.3g}')


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('peer_data', help='our data file of the initial state (in.setup)')
    parser.add_argument('body_dump', help="in.body's dump (id x y z qw qi qj qk), first and last step")
    parser.add_argument('out_data', help='the data file written')
    parser.add_argument('shapes', nargs='?', help='our shape library (with BODY_VERTICES: check the vertices)')
    parser.add_argument('body_vertices', nargs='?', help='dump local of compute body/local id 1 2 3, last step')
    args = parser.parse_args()
    if (args.shapes is None) != (args.body_vertices is None):
        parser.error('SHAPES and BODY_VERTICES go together')
    main(args.peer_data, args.body_dump, args.out_data, args.shapes, args.body_vertices)
