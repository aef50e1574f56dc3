"""Analysis of LAMMPS dumps and logs of the NSCD package: the papers' figures (fabric field,
principal fabric angle vs r, Fn(r), wire-grain force orientations, time series) and VTK
files for ParaView. Command line: tools/nscd-analysis (see doc/analysis.md).

Needs numpy, scipy and matplotlib (Debian's python3-numpy, python3-scipy,
python3-matplotlib; run with /usr/bin/python3)."""
