#!/usr/bin/python3
"""The papers' Fig. 2 style pictures with ParaView, headless:

    xvfb-run -a pvbatch tools/nscd_render.py --grains grains.5000.vtk --wire wire.5000.vtp \
        --network network.5000.vtp --out fig2/step5000

writes OUT_column.png (grains in grey, the wire as tubes coloured by its normalised strain
energy), OUT_network_side.png and OUT_network_top.png (the force network between grain
centres as tubes whose radius and colour grow with the normalised normal force). Inputs:
grains from `dump grains/vtk`, the wire and the network from `tools/nscd-analysis vtk-wire`
and `vtk-network` (doc/analysis.md). A view whose inputs are not given is skipped.

Normalisation: force by --fmax (default: the file's largest), energy by --emax (default:
the file's largest); give the same values for a series of loads to compare them."""

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
    p.add_argument("--size", type=int, nargs=2, default=(800, 800), metavar=("W", "H"))
    p.add_argument("--fmax", type=float, help="force that maps to 1 (default: largest in the file)")
    p.add_argument("--emax", type=float, help="wire energy that maps to 1 (default: largest in the file)")
    p.add_argument("--min-force", type=float, default=0.0,
                   help="hide pairs with normalised force below this (default 0: all)")
    p.add_argument("--tube", type=float, default=0.0,
                   help="largest network tube radius (default: 1/150 of the scene's size)")
    p.add_argument("--wire-radius", type=float, default=0.0,
                   help="wire tube radius (default: 1/250 of the scene's size)")
    p.add_argument("--grain-opacity", type=float, default=1.0)
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
        self.size = self._scene_size()

    def _scene_size(self):
        bounds = [float("inf"), float("-inf")] * 3
        for reader in self.readers.values():
            b = reader.GetDataInformation().GetBounds()
            for k in range(3):
                bounds[2 * k] = min(bounds[2 * k], b[2 * k])
                bounds[2 * k + 1] = max(bounds[2 * k + 1], b[2 * k + 1])
        extent = max(bounds[2 * k + 1] - bounds[2 * k] for k in range(3))
        return extent if extent > 0 and extent != float("inf") else 1.0

    def _view(self):
        pv = self.pv
        view = pv.CreateView("RenderView")
        view.ViewSize = list(self.args.size)
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
        view.ResetCamera()
        pv.Render(view)

    def _save(self, view, suffix):
        path = f"{self.args.out}_{suffix}.png"
        self.pv.SaveScreenshot(path, view, ImageResolution=list(self.args.size))
        self.pv.Delete(view)
        return path

    def column(self):
        """Grains in grey and the wire coloured by its normalised strain energy (Fig. 2a)."""
        pv, view = self.pv, self._view()
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
            self._colour(display, view, "CELLS", "wire_energy", "wire energy / max")
        self._camera(view, "column")
        return self._save(view, "column")

    def network(self, side):
        """The force network, radius and colour by normal force / fmax (Fig. 2b, c)."""
        pv, view = self.pv, self._view()
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
        self._colour(display, view, "POINTS", "force", "normal force / max")
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
