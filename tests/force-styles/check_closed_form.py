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

"""Checks the reference values of a force-style YAML file (bond-wire.yaml, angle-wire.yaml)
against the closed-form law, computed here independently of LAMMPS and of lib/wire:

  bond_style wire   f = k_elo (L - r0) / r0 along the bond, E = k_elo (L - r0)^2 / (2 r0);
                    zero for L < r0 with 'string yes'           (doc/bond_style_wire.rst)
  angle_style wire  E = k_rot (pi - theta)^2 / 2, forces = -grad E  (doc/angle_style_wire.rst)

on the testers' molecule (data.fourmol): init_energy, init_forces (every atom) and
init_stress (the virial, xx yy zz xy xz yz) must agree to 1e-10 relative. LAMMPS' tester in
turn checks its own result against the same YAML values, so LAMMPS agrees with the closed form.

  check_closed_form.py <bond-wire.yaml|angle-wire.yaml> <data.fourmol>
"""
import math
import sys

import numpy as np
import yaml

TOLERANCE = 1e-10    # relative to the largest value of each kind: round-off, not physics


def data_sections(path):
    """The rows of each section of a LAMMPS data file, keyed by the section's first word."""
    sections, name = {}, None
    for line in open(path):
        words = line.split("#")[0].split()
        if not words:
            continue
        if words[0][0].isalpha() and len(words) == 1 or words[0] in ("Atoms", "Pair", "Bond",
                                                                     "Angle", "Dihedral", "Improper"):
            name = words[0]
            sections[name] = []
        elif name:
            sections[name].append(words)
    return sections


def coefficients(block):
    """{type: [words after the type]} from a bond_coeff/angle_coeff block."""
    rows = [line.split() for line in block.strip().splitlines()]
    return {int(r[0]): r[1:] for r in rows}


def bond_terms(x, bonds, coeff):
    for row in bonds:
        btype, i, j = int(row[1]), int(row[2]), int(row[3])
        k, r0 = float(coeff[btype][0]), float(coeff[btype][1])
        string = len(coeff[btype]) == 4 and coeff[btype][3] == "yes"
        d = x[i] - x[j]
        length = np.linalg.norm(d)
        stretch = length - r0
        if string and stretch < 0.0:
            continue
        on_i = -k * stretch / r0 * d / length    # tension pulls i towards j
        yield k * stretch**2 / (2.0 * r0), {i: on_i, j: -on_i}, np.outer(d, on_i)


def angle_terms(x, angles, coeff):
    for row in angles:
        atype, i, j, l = (int(w) for w in row[1:5])
        k = float(coeff[atype][0])
        u, v = x[i] - x[j], x[l] - x[j]
        nu, nv = np.linalg.norm(u), np.linalg.norm(v)
        c = u @ v / (nu * nv)
        theta = math.acos(c)
        # dtheta/dx = -(dc/dx) / sin(theta); dE/dtheta = -k (pi - theta)
        dc_du = (v / nv - c * u / nu) / nu
        dc_dv = (u / nu - c * v / nv) / nv
        scale = -k * (math.pi - theta) / math.sin(theta)    # F = -dE/dtheta dtheta/dx
        on_i, on_l = scale * dc_du, scale * dc_dv
        forces = {i: on_i, l: on_l, j: -(on_i + on_l)}
        yield k * (math.pi - theta)**2 / 2.0, forces, np.outer(u, on_i) + np.outer(v, on_l)


def closed_form(case, data):
    sections = data_sections(data)
    x = {int(r[0]): np.array([float(w) for w in r[4:7]]) for r in sections["Atoms"]}
    if "bond_style" in case:
        assert case["bond_style"] == "wire", case["bond_style"]
        terms = bond_terms(x, sections["Bonds"], coefficients(case["bond_coeff"]))
    else:
        assert case["angle_style"] == "wire", case["angle_style"]
        terms = angle_terms(x, sections["Angles"], coefficients(case["angle_coeff"]))
    energy, forces, virial = 0.0, {tag: np.zeros(3) for tag in x}, np.zeros((3, 3))
    for e, f, w in terms:
        energy += e
        for tag, value in f.items():
            forces[tag] += value
        virial += w
    stress = np.array([virial[0, 0], virial[1, 1], virial[2, 2], virial[0, 1], virial[0, 2],
                       virial[1, 2]])
    return energy, forces, stress


def compare(name, expected, actual):
    scale = max(np.max(np.abs(expected)), 1e-300)
    error = np.max(np.abs(np.asarray(actual) - np.asarray(expected))) / scale
    print(f"{name}: largest difference {error:.2e} of the largest value {scale:.6g}")
    return error <= TOLERANCE


def main(yaml_file, data):
    case = yaml.safe_load(open(yaml_file))
    for key in ("init_energy", "init_forces", "init_stress"):
        if key not in case:
            sys.exit(f"{yaml_file} has no {key}: generate it with the tester's -g option")
    energy, forces, stress = closed_form(case, data)
    ref_forces = {int(r.split()[0]): np.array([float(w) for w in r.split()[1:4]])
                  for r in case["init_forces"].strip().splitlines()}
    if set(ref_forces) != set(forces):
        sys.exit(f"{yaml_file}: forces of atoms {sorted(ref_forces)}, the data file has {sorted(forces)}")
    tags = sorted(forces)
    ok = compare("energy", [energy], [case["init_energy"]])
    ok &= compare("forces", [forces[t] for t in tags], [ref_forces[t] for t in tags])
    ok &= compare("virial", stress, [float(w) for w in case["init_stress"].split()])
    if not ok:
        sys.exit(f"{yaml_file}: the reference values disagree with the closed form beyond {TOLERANCE}")
    print(f"{yaml_file}: energy, forces and virial agree with the closed form")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
