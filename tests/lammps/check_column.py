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

"""Checks of the 2-layer column smoke test (tests/lammps/run_example_check.sh column):
the logs of examples/column/in.column with the wire (WIRE_LOG) and without (BARE_LOG).

    check_column.py WIRE_LOG BARE_LOG [RING_LOG [PRESTRAIN_LOG PRESTRAIN]]

Fails (exit 1, naming the check) unless, in every run:
  * every phase ran (the deck's "phase N done" lines, N = 1..5);
  * no grain was ever deeper than r_w / 2 in another grain or a wall (thermo f_nscd[3]):
    new layers are created clear of the deposit and the solver keeps them apart;
  * the seated plate, at rest on the column under its own weight M g, feels M g from the
    column to 5 % (its equation of motion with zero acceleration; the deck seats it until
    slower than 1e-3 and within 1 %, so this fails when it never comes to rest);
  * under load the plate force is load + M g: the median relative error over the thermo
    rows under load below 2 % (one row may be off while the column settles under a new
    load and the plate accelerates: force = load + M g + M a); a column that gives way
    under the load is not quasi-static, and then the deck must have seen the plate sink
    more than its fail_sink within its fail_window steps, or deeper than its fail_strain (the 26-grain ring column of
    the smoke test has done so at load 20-30 since 26 Nov 2026, when the relaxations became
    stricter and the wire substep the accurate one);
and with the wire:
  * the wire carries tension after the walls are gone (stretch energy > 0);
  * the column keeps at least 90 % of its grains within the loop radius and of its height
    through the wall removal.
and with closed rings (RING_LOG, `-var loop ring`):
  * every loop is a closed ring whose elements are exactly the rest length of the bond type
    (create_wire's element length against the bond_coeff the deck gave, to 1e-9): laid
    unstrained;
and with rings laid in tension (PRESTRAIN_LOG: the ring run's settings and seed, `-var
prestrain PRESTRAIN -var last 1`):
  * every ring is laid at the chord (its elements at the length the bond type had while
    create_wire ran, to 1e-9), and the rest length is then chord / (1 + PRESTRAIN) (1e-9);
  * the runs use that rest length: at the end of the deposit the wire's stretch energy
    exceeds the unstrained rings' (RING_LOG, the same trajectory until the first ring) by
    more than 2 % of what the rings held when laid, n 1/2 k_elo r0 PRESTRAIN^2 over their n
    elements. The rings slide inward over the grains and give up most of it (they kept 15 % on
    27 Nov 2026); rest lengths not applied would leave the unstrained rings' 0.004 %.
Two layers are too low to collapse without wire (both keep all their grains): the
collapse of the control is shown at 5 layers in examples/column/README.md, not here.
"""

import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from nscd_analysis import logs  # noqa: E402

PLATE_MASS, GRAVITY, R_W = 10.0, 1.0, 0.05
FAIL_SINK, FAIL_STRAIN = 0.05, 0.15    # the deck's failure criterion (its defaults)
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


def numbers_after(text, label):
    """The number following 'label' in text."""
    m = re.search(re.escape(label) + r"\s*([-+0-9.eE]+)", text)
    return float(m.group(1)) if m else float("nan")


def phase_lines(path):
    with open(path) as f:
        text = f.read()
    done = {int(m.group(1)): m.group(0) for m in re.finditer(r"^phase (\d) done:.*$", text, re.M)}
    seated = re.search(r"^phase 5: plate seated.*$", text, re.M)
    return done, seated.group(0) if seated else ""


def check_run(path, label):
    done, seated = phase_lines(path)
    check(sorted(done) == [1, 2, 3, 4, 5], f"{label}: phases done {sorted(done)}, expected 1..5")
    table = logs.thermo_columns(path, ["Step", "v_phase", "f_nscd[3]"])
    deepest = table[:, 2].max()
    check(deepest < R_W / 2, f"{label}: largest interpenetration {deepest:.3g} >= r_w/2 = {R_W / 2}")
    weight = PLATE_MASS * GRAVITY
    if "failed under the weight of the plate alone" in open(path).read():
        # failure at load 0: the plate sank past fail_strain x the height while seating
        line = re.search(r"^phase 5: the column failed.*$", open(path).read(), re.M).group(0)
        strain = numbers_after(line, "the plate sank") / numbers_after(line, "of the height")
        check(strain > FAIL_STRAIN, f"{label}: failure while seating reported, but the plate sank only {strain:.3g} "
                                    f"of the height (fail_strain {FAIL_STRAIN})")
        print(f"{label}: largest interpenetration {deepest:.3g}; failed while seating under the plate's weight "
              f"(sank {strain:.3g} of the height)")
        return done
    seated_force = numbers_after(seated, "force")
    check(abs(seated_force / weight - 1) < 0.05,
          f"{label}: seated plate feels {seated_force:.4g}, its weight is {weight} (5 % allowed)")
    load = logs.thermo_columns(path, ["v_phase", "v_plate_force", "v_plate_load"])
    load = load[(load[:, 0] == 5) & (load[:, 2] > 0)]
    check(len(load) > 0, f"{label}: no thermo row under load")
    failed = "phase 5: no failure" not in open(path).read()
    if len(load) and failed:
        # A column that gives way is not quasi-static: then the deck must have seen the plate
        # sink more than fail_sink within its window (a slump), or by more than fail_strain.
        speed = numbers_after(done.get(5, ""), "speed")
        sink = numbers_after(done.get(5, ""), "sink over the window")
        strain = -numbers_after(done.get(5, ""), "), displacement") / numbers_after(seated, "top of the column")
        check(sink > FAIL_SINK or strain > FAIL_STRAIN,
              f"{label}: the deck reports a failure, but the plate sank {sink:.3g} over its window (fail_sink "
              f"{FAIL_SINK}) and by {strain:.3g} of the height (fail_strain {FAIL_STRAIN})")
        print(f"{label}: largest interpenetration {deepest:.3g}, seated plate force {seated_force:.4g} "
              f"(weight {weight}); failed under load {load[-1, 2]:.4g}: plate sinking at {-speed:.3g}")
    elif len(load):
        # Newton on the plate: force = load + weight + m a. A column that settles under a new
        # load lets the plate accelerate for a moment (a row can be 8 % off), so the test is on
        # the median over the rows under load, which a quasi-static column meets closely.
        errors = np.abs(load[:, 1] / (load[:, 2] + weight) - 1)
        error = float(np.median(errors))
        check(error < 0.02, f"{label}: plate force against load + weight under load: median relative "
                            f"error {error:.3g} over {len(load)} rows (2 % allowed)")
        print(f"{label}: largest interpenetration {deepest:.3g}, seated plate force {seated_force:.4g} "
              f"(weight {weight}), under load up to {load[-1, 2]:.4g}: plate force = load + weight to a "
              f"median {error:.2g} over {len(load)} rows (largest {errors.max():.2g})")
    return done


def walls(done):
    """(height before, after; retained fraction before, after) from 'phase 3 done'."""
    line = done.get(3, "")
    h = re.search(r"height (\S+) \(before (\S+)\)", line)
    f = re.search(r"retained fraction (\S+) \(before (\S+)\)", line)
    if not (h and f):
        return None
    return float(h.group(2)), float(h.group(1)), float(f.group(2)), float(f.group(1))


def check_rings(path):
    """Every create_wire made a closed ring, its elements at the bond type's rest length."""
    with open(path) as f:
        text = f.read()
    rests = re.findall(r"^bond_coeff 1 \S+ ([-+0-9.eE]+)\s*$", text, re.M)
    made = re.findall(r"^create_wire: loop \(([^)]*)\): .* elements of length ([-+0-9.eE]+)", text, re.M)
    check(len(rests) > 0 and len(made) > 0, f"ring: no bond_coeff ({len(rests)}) or create_wire ({len(made)}) line")
    if rests and made:
        rest = float(rests[-1])
        kinds = sorted({kind for kind, _ in made})
        worst = max(abs(float(length) / rest - 1) for _, length in made)
        check(kinds == ["closed ring"], f"ring: create_wire made {kinds}, expected closed rings only")
        check(worst < 1e-9, f"ring: elements differ from the rest length {rest} by up to {worst:.3g} (relative)")
        print(f"rings: {len(made)} closed rings, elements at the rest length {rest:.10g} to {worst:.2g}")


def last_deposit_stretch(path):
    """The wire's stretch energy in the last thermo row of phase 1."""
    table = logs.thermo_columns(path, ["v_phase", "v_e_stretch"])
    table = table[table[:, 0] == 1]
    return table[-1, 1] if len(table) else float("nan")


def check_prestrain(path, ring_path, prestrain):
    """Rings laid at the chord, then the rest length chord / (1 + prestrain), used by the runs."""
    with open(path) as f:
        text = f.read()
    # per ring: the bond_coeff before create_wire (the chord), the elements made, the one after
    laid = re.findall(r"^bond_coeff 1 (\S+) ([-+0-9.eE]+)\s*\n(?:.*\n)*?create_wire: loop \(([^)]*)\): (\d+) nodes.*"
                      r"elements of length ([-+0-9.eE]+).*\n(?:.*\n)*?bond_coeff 1 \S+ ([-+0-9.eE]+)\s*$", text, re.M)
    check(len(laid) > 0, "prestrain: no bond_coeff / create_wire / bond_coeff sequence in the log")
    held = 0.0
    for k_elo, chord, kind, nodes, length, rest in laid:
        k_elo, chord, length, rest = float(k_elo), float(chord), float(length), float(rest)
        check(kind == "closed ring", f"prestrain: create_wire made a {kind}, expected a closed ring")
        check(abs(length / chord - 1) < 1e-9, f"prestrain: elements of {length}, laid while the rest length was {chord}")
        check(abs(rest * (1 + prestrain) / chord - 1) < 1e-9,
              f"prestrain: rest length {rest} after laying at {chord}, expected chord / (1 + {prestrain})")
        held += int(nodes) * 0.5 * k_elo * rest * prestrain ** 2    # a closed ring: as many elements as nodes
    strained, unstrained = last_deposit_stretch(path), last_deposit_stretch(ring_path)
    check(strained - unstrained > 0.02 * held,
          f"prestrain: stretch energy at the end of the deposit {strained:.4g}, unstrained rings {unstrained:.4g}: "
          f"the runs did not keep the rings in tension (laid with {held:.4g})")
    print(f"prestrain {prestrain}: {len(laid)} rings laid at the chord, rest length chord / {1 + prestrain}; "
          f"stretch energy at the end of the deposit {strained:.4g} against {unstrained:.4g} unstrained "
          f"(laid with {held:.4g})")


def main():
    if len(sys.argv) not in (3, 4, 6):
        sys.exit(__doc__)
    if len(sys.argv) >= 4:
        check_run(sys.argv[3], "ring")
        check_rings(sys.argv[3])
    if len(sys.argv) == 6:
        check_prestrain(sys.argv[4], sys.argv[3], float(sys.argv[5]))
    wire_done = check_run(sys.argv[1], "wire")
    bare_done = check_run(sys.argv[2], "no wire")
    wire, bare = walls(wire_done), walls(bare_done)
    if wire and bare:
        print(f"wall removal, wire: height {wire[0]:.3f} -> {wire[1]:.3f}, retained {wire[2]:.3f} -> {wire[3]:.3f}")
        print(f"wall removal, no wire: height {bare[0]:.3f} -> {bare[1]:.3f}, retained {bare[2]:.3f} -> {bare[3]:.3f}")
        check(wire[3] >= 0.9 * wire[2], f"wire: retained fraction {wire[2]:.3f} -> {wire[3]:.3f} (< 90 % kept)")
        check(wire[1] >= 0.9 * wire[0], f"wire: height {wire[0]:.3f} -> {wire[1]:.3f} (< 90 % kept)")
    else:
        failures.append("no 'phase 3 done' line with heights and retained fractions")
    stretch = numbers_after(wire_done.get(4, ""), "wire stretch energy")
    check(stretch > 0, f"wire: stretch energy after the walls {stretch} (expected > 0)")
    if failures:
        print("check column: FAILED\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("check column: passed")


if __name__ == "__main__":
    main()
