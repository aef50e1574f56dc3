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

"""The papers' Fig. 2 style pictures with ParaView, headless:

    xvfb-run -a pvbatch tools/nscd_render.py --grains grains.5000.vtk --wire wire.5000.vtp \
        --network network.5000.vtp --out fig2/step5000

writes OUT_column.png (grains in grey, the wire as tubes coloured by its normalised strain
energy), OUT_network_side.png and OUT_network_top.png (the force network between grain
centres as tubes whose radius and colour grow with the normalised normal force). Inputs:
grains from `dump grains/vtk`, the wire and the network from `tools/nscd-analysis vtk-wire`
and `vtk-network` (doc/analysis.md). A view whose inputs are not given is skipped.

Normalisation: force by --fmax (default: the file's largest), energy by --emax (default:
the file's largest); give the same values for a series of loads to compare them. The colour
bar's title gives the value that maps to 1.

The floor (--floor Z, default: the lowest grain) and the plate (--plate Z, or `top`: on the
highest grain) are drawn as thin grey slabs in the side views. --axis X Y and --R R frame the
views on the column (|x - X|, |y - Y| <= 1.15 R; --zmax Z cuts the frame's top), so grains
that rolled away on the floor do not shrink the column in the picture."""

import argparse
import os
import sys


def arguments(argv):
    p = argparse.ArgumentParser(prog="nscd_render.py", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--grains", help="legacy VTK file of dump grains/vtk")
    p.add_argument("--wire", help=".vtp of nscd-analysis vtk-wire")
    p.add_argument("--network", help=".vtp of nscd-analysis vtk-network")
    p.add_argument("--out", required=True, help="prefix of the PNG files")
    p.add_argument("--size", type=int, nargs=2, default=(800, 800), metavar=("W", "H"),
                   help="picture size in pixels; H = 0: from the frame's shape (side views)")
    p.add_argument("--fmax", type=float, help="force that maps to 1 (default: largest in the file)")
    p.add_argument("--emax", type=float, help="wire energy that maps to 1 (default: largest in the file)")
    p.add_argument("--min-force", type=float, default=0.0,
                   help="hide pairs with normalised force below this (default 0: all)")
    p.add_argument("--tube", type=float, default=0.0,
                   help="largest network tube radius (default: 1/150 of the scene's size)")
    p.add_argument("--wire-radius", type=float, default=0.0,
                   help="wire tube radius (default: 1/250 of the scene's size)")
    p.add_argument("--grain-opacity", type=float, default=1.0)
    p.add_argument("--floor", type=float, help="floor height (default: the lowest grain's bottom)")
    p.add_argument("--plate", help="plate height, or 'top' (on the highest grain); default: no plate")
    p.add_argument("--axis", type=float, nargs=2, default=None, metavar=("X", "Y"),
                   help="column axis for the framing (default: the centre of the scene)")
    p.add_argument("--R", type=float, help="column radius: frame the views on |r| <= 1.15 R")
    p.add_argument("--zmax", type=float, help="top of the frame (default: the scene's top)")
    return p.parse_args(argv)


def main(argv):
    args = arguments(argv)
    try:
        import paraview.simple as pv
    except ImportError:
        sys.exit("nscd_render.py: needs ParaView's Python (run it with pvbatch: "
                 "apt-get install paraview python3-paraview xvfb; xvfb-run -a pvbatch nscd_render.py ...)")
    for name in ("grains", "wire", "network"):
        path = getattr(args, name)
        if path and not os.path.exists(path):
            sys.exit(f"nscd_render.py: --{name} {path}: no such file")
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    renderer = Renderer(pv, args)
    written = []
    if args.grains or args.wire:
        written.append(renderer.column())
    if args.network:
        written.append(renderer.network("side"))
        written.append(renderer.network("top"))
    if not written:
        sys.exit("nscd_render.py: nothing to draw: give --grains, --wire and/or --network")
    for path in written:
        print(path)


class Renderer:
    def __init__(self, pv, args):
        self.pv, self.args = pv, args
        self.readers = {name: pv.OpenDataFile(getattr(args, name)) for name in ("grains", "wire", "network")
                        if getattr(args, name)}
        for reader in self.readers.values():
            reader.UpdatePipeline()
        self.bounds = self._scene_bounds()
        self.size = self._scene_size()
        self.frame = self._frame()

    def _scene_size(self):
        bounds = self.bounds
        extent = max(bounds[2 * k + 1] - bounds[2 * k] for k in range(3))
        return extent if extent > 0 and extent != float("inf") else 1.0

    def _frame(self):
        """Bounds the camera is fitted to: the scene, or the column (--R) with floor and plate."""
        b = list(self.bounds)
        if self.args.R:
            cx = self.args.axis[0] if self.args.axis else 0.5 * (b[0] + b[1])
            cy = self.args.axis[1] if self.args.axis else 0.5 * (b[2] + b[3])
            half = 1.15 * self.args.R
            b[0:4] = [cx - half, cx + half, cy - half, cy + half]
        if self.args.zmax is not None:
            b[5] = min(b[5], self.args.zmax)
        return b

    def _scene_bounds(self):
        bounds = [float("inf"), float("-inf")] * 3
        for reader in self.readers.values():
            b = reader.GetDataInformation().GetBounds()
            for k in range(3):
                bounds[2 * k] = min(bounds[2 * k], b[2 * k])
                bounds[2 * k + 1] = max(bounds[2 * k + 1], b[2 * k + 1])
        return bounds

    def _slabs(self, view, outline=False):
        """Floor and plate as thin grey boxes across the frame (side views); outline: only their
        edges (the column view looks down on them: a face would veil the grains)."""
        b, thick = self.frame, self.size / 100.0
        heights = [("floor", self.args.floor if self.args.floor is not None else self.bounds[4], -1)]
        if self.args.plate:
            top = self.bounds[5] if self.args.plate == "top" else float(self.args.plate)
            heights.append(("plate", top, 1))
        for name, z, side in heights:
            box = self.pv.Box(XLength=b[1] - b[0], YLength=b[3] - b[2], ZLength=thick,
                              Center=[0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), z + 0.5 * side * thick])
            display = self.pv.Show(box, view)
            display.ColorArrayName = ["POINTS", ""]    # plain colour (the box has normals)
            display.AmbientColor = display.DiffuseColor = [0.45, 0.45, 0.5]
            display.Opacity = 0.35 if name == "floor" else 0.2    # the grains under the plate show
            if outline:
                display.SetRepresentationType("Outline")
                display.AmbientColor = display.DiffuseColor = [0.2, 0.2, 0.25]
                display.Opacity = 1.0
                display.LineWidth = 2.0

    def _pixels(self, side):
        """--size, or with H = 0 the frame's height/width ratio (between 0.5 and 2; top view square)."""
        width, height = self.args.size
        if height > 0:
            return [width, height]
        if side == "top":
            return [width, width]
        half_w, half_h = self._half_extent(side)
        return [width, int(width * min(max(half_h / max(half_w, 1e-300), 0.5), 2.0))]

    def _half_extent(self, side):
        """Half width and half height of the frame as the camera of SIDE sees it."""
        b = self.frame
        dx, dy, dz = b[1] - b[0], b[3] - b[2], b[5] - b[4]
        if side == "top":
            return 0.5 * dx, 0.5 * dy
        return 0.5 * max(dx, dy), 0.5 * (dz + (0.35 * dy if side == "column" else 0.0))

    def _view(self, side):
        pv = self.pv
        view = pv.CreateView("RenderView")
        view.ViewSize = self._pixels(side)
        view.OrientationAxesVisibility = 0
        if hasattr(view, "UseColorPaletteForBackground"):
            view.UseColorPaletteForBackground = 0
        view.Background = [1.0, 1.0, 1.0]
        return view

    def _largest(self, reader, association, name, given):
        if given:
            return given
        info = (reader.CellData if association == "CELLS" else reader.PointData)[name]
        top = info.GetRange()[1]
        return top if top > 0 else 1.0

    def _colour(self, display, view, association, name, title):
        """Jet over [0, 1] with a colour bar titled TITLE (which names the normalisation)."""
        pv = self.pv
        pv.ColorBy(display, (association, name))
        lut = pv.GetColorTransferFunction(name)
        lut.ApplyPreset("Jet", True)
        lut.RescaleTransferFunction(0.0, 1.0)
        lut.AutomaticRescaleRangeMode = "Never"
        display.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(lut, view)
        bar.Title = title
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
        bar.RangeLabelFormat = bar.LabelFormat = "%.1f"

    def _camera(self, view, side):
        pv = self.pv
        pv.Render(view)    # the first render resets the camera: done before it is placed
        camera = view.GetActiveCamera()
        if side == "top":
            camera.SetPosition(0.0, 0.0, 1.0)
            camera.SetFocalPoint(0.0, 0.0, 0.0)
            camera.SetViewUp(0.0, 1.0, 0.0)
        else:    # from the side, a little from above (the column view 20 degrees more)
            lift = 0.36 if side == "column" else 0.0
            camera.SetPosition(0.0, -1.0, lift)
            camera.SetFocalPoint(0.0, 0.0, 0.0)
            camera.SetViewUp(0.0, 0.0, 1.0)
        view.ResetCamera(*self.frame)
        # parallel projection scaled to the frame's box (ResetCamera fits its bounding sphere,
        # which leaves wide margins around a squat or slender column)
        view.CameraParallelProjection = 1
        width, height = view.ViewSize
        half_w, half_h = self._half_extent(side)
        view.CameraParallelScale = 1.1 * max(half_h, half_w * height / width)
        pv.Render(view)

    def _save(self, view, suffix):
        path = f"{self.args.out}_{suffix}.png"
        self.pv.SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))
        self.pv.Delete(view)
        return path

    def column(self):
        """Grains in grey and the wire coloured by its normalised strain energy (Fig. 2a)."""
        pv, view = self.pv, self._view("column")
        if "grains" in self.readers:
            grains = pv.Show(self.readers["grains"], view)
            pv.ColorBy(grains, None)
            grains.AmbientColor = grains.DiffuseColor = [0.72, 0.72, 0.70]
            grains.Opacity = self.args.grain_opacity
        if "wire" in self.readers:
            wire = self.readers["wire"]
            emax = self._largest(wire, "CELLS", "energy", self.args.emax)
            scaled = pv.Calculator(Input=wire, AttributeType="Cell Data", ResultArrayName="wire_energy",
                                   Function=f"energy/{emax!r}")
            tube = pv.Tube(Input=scaled)    # the tubes keep each element's cell data
            tube.Radius = self.args.wire_radius or self.size / 250.0
            tube.NumberofSides = 12
            display = pv.Show(tube, view)
            self._colour(display, view, "CELLS", "wire_energy", f"wire energy / {emax:.3g}")
        self._slabs(view, outline=True)
        self._camera(view, "column")
        return self._save(view, "column")

    def network(self, side):
        """The force network, radius and colour by normal force / fmax (Fig. 2b, c)."""
        pv, view = self.pv, self._view(side)
        network = self.readers["network"]
        fmax = self._largest(network, "POINTS", "fn", self.args.fmax)
        largest = self.args.tube or self.size / 150.0
        scaled = pv.Calculator(Input=network, AttributeType="Point Data", ResultArrayName="force",
                               Function=f"fn/{fmax!r}")
        source = scaled
        if self.args.min_force > 0:
            kept = pv.Threshold(Input=scaled, Scalars=["POINTS", "force"])
            _threshold_range(kept, self.args.min_force, 1e300)
            source = pv.ExtractSurface(Input=kept)    # Threshold gives cells, Tube wants lines
        radius = pv.Calculator(Input=source, AttributeType="Point Data", ResultArrayName="radius",
                               Function=f"{0.1 * largest!r}+{0.9 * largest!r}*min(force,1)")
        tube = pv.Tube(Input=radius)
        tube.Scalars = ["POINTS", "radius"]
        tube.VaryRadius = "By Absolute Scalar"
        tube.NumberofSides = 10
        display = pv.Show(tube, view)
        self._colour(display, view, "POINTS", "force", f"normal force / {fmax:.3g}")
        if side != "top":
            self._slabs(view)
        self._camera(view, side)
        return self._save(view, f"network_{side}")


def _threshold_range(threshold, low, high):
    """ParaView 5.10 and newer: LowerThreshold/UpperThreshold; older: ThresholdRange."""
    if hasattr(threshold, "LowerThreshold"):
        threshold.LowerThreshold, threshold.UpperThreshold = low, high
    else:
        threshold.ThresholdRange = [low, high]


if __name__ == "__main__":
    main(sys.argv[1:])
