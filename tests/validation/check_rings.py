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

"""Checks of tests/validation/column_rings.sh: the papers' contrast (a wired column stands,
its control without wire slumps) on a 3-layer column of thick layers with closed rings.

    check_rings.py log.ring1 log.bare1 [log.ring2 log.bare2 ...]

Each pair is one seed: the ring column and its control. "Kept" is after / before the wall
removal: the height at the end of phase 4 (walls gone, short relaxation) over the height
before the walls moved, and likewise the retained fraction (grains within R of the axis).
Over the pairs given, fails (exit 1, naming the check) unless
  * every run reached phase 4 and the rings carry tension after the walls (stretch > 0);
  * the control slumps: its mean kept height is below CONTROL_HEIGHT_MAX;
  * the rings keep more: the mean over the seeds of (ring - control) is at least
    MIN_HEIGHT_GAIN in kept height and MIN_GRAIN_GAIN in kept grains.

Where the thresholds come from (27 Nov 2026, main c6c9075 + this deck's `last`, seeds
1-10 of column_rings.sh's scene, doc/validation.md): kept height ring 0.768 +- 0.064
(0.683-0.889), control 0.575 +- 0.034 (0.505-0.615); kept grains ring 0.734 +- 0.077,
control 0.497 +- 0.043. The ring kept more than its control on every seed, by 0.068-0.384 in
height (mean 0.193, sd 0.091) and 0.112-0.415 in grains (mean 0.237, sd 0.100). The
thresholds are half the smallest gain of any seed: the mean of two seeds falls below them
~2.5 standard deviations from the measured mean; a wire that does not hold (gain ~0) fails.
The control's ceiling: its largest kept height over the 10 seeds was 0.615.

What the scene is not: at rest. To run in a minute, each layer gets at most 400 steps and the
relaxations 2 x 250: phase 2 ends at its cap with a kinetic energy of 0.46-1.21 (rings) and
1.18-2.70 (control), and the top ring, laid above grains still falling, hangs on the grains in
the box's corners (outside R) at its laying height until the walls take them away. The test
asserts the contrast of this scene over seeds; doc/validation.md gives the settled 10-layer
columns. A ring 1000 times softer (k_elo 5, seeds 1-2) kept as much (0.647 and 0.834 of the
height): this checks that rings confine, not how stiff they are.
"""
import re
import sys

CONTROL_HEIGHT_MAX = 0.70
MIN_HEIGHT_GAIN = 0.034
MIN_GRAIN_GAIN = 0.056

PHASE3 = re.compile(r"^phase 3 done: height \S+ \(before (\S+)\), retained fraction \S+ \(before (\S+)\)", re.M)
PHASE4 = re.compile(r"^phase 4 done: height (\S+), retained fraction ([-+0-9.eE]+), "
                    r"wire stretch energy ([-+0-9.eE]+)", re.M)


def kept(path):
    """(kept height, kept retained fraction, stretch energy) of one run's log."""
    text = open(path).read()
    before, after = PHASE3.search(text), PHASE4.search(text)
    if not (before and after):
        sys.exit(f"{path}: phases 3 and 4 not both done")
    h0, f0 = float(before.group(1)), float(before.group(2))
    h1, f1, stretch = (float(after.group(k)) for k in (1, 2, 3))
    return h1 / h0, f1 / f0, stretch


def main(logs):
    if len(logs) < 2 or len(logs) % 2:
        sys.exit("usage: check_rings.py log.ring1 log.bare1 [log.ring2 log.bare2 ...]")
    failures, gains_h, gains_f, bare_h = [], [], [], []
    for ring_log, bare_log in zip(logs[0::2], logs[1::2]):
        rh, rf, stretch = kept(ring_log)
        bh, bf, _ = kept(bare_log)
        print(f"{ring_log}: kept height {rh:.3f}, grains {rf:.3f}, stretch energy {stretch:.3g}; "
              f"{bare_log}: kept height {bh:.3f}, grains {bf:.3f}")
        if not stretch > 0:
            failures.append(f"{ring_log}: the rings carry no tension after the walls (stretch {stretch})")
        gains_h.append(rh - bh)
        gains_f.append(rf - bf)
        bare_h.append(bh)
    mean = lambda xs: sum(xs) / len(xs)
    gh, gf, bh = mean(gains_h), mean(gains_f), mean(bare_h)
    print(f"mean over {len(gains_h)} seed(s): rings keep {gh:+.3f} of the height and {gf:+.3f} of the "
          f"grains more than the control (at least {MIN_HEIGHT_GAIN}, {MIN_GRAIN_GAIN}); the control keeps "
          f"{bh:.3f} of its height (at most {CONTROL_HEIGHT_MAX})")
    if bh >= CONTROL_HEIGHT_MAX:
        failures.append(f"the control does not slump: it keeps {bh:.3f} of its height (at most {CONTROL_HEIGHT_MAX})")
    if gh < MIN_HEIGHT_GAIN:
        failures.append(f"the rings keep only {gh:+.3f} more of the height than the control (at least {MIN_HEIGHT_GAIN})")
    if gf < MIN_GRAIN_GAIN:
        failures.append(f"the rings keep only {gf:+.3f} more of the grains than the control (at least {MIN_GRAIN_GAIN})")
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
