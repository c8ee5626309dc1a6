"""A run's particles in ParaView, from a script: loads DIR/particles.pvd (or a .pvtu series of a
multi-rank run), goes to the last snapshot (or --time T [s]), draws the particles as Point
Gaussian splats coloured by plastic strain (or --field NAME), clipped to the half y >= 0 so the
crater and the cylinder's inside show, and writes a PNG.

  pvpython campaigns/plot/paraview_snapshot.py DIR --out FIG.png [--field plastic_strain] [--time T]
  xvfb-run -a pvpython ...   (without a display)

Run by `./run.sh paraview` on the main job's output (README.md, docs/mpm.md#output). Every field is SI
(docs/mpm.md lists them); the colour bar says which and its unit.
"""
import argparse
import os
import sys

from paraview import simple as pv

UNITS = {"plastic_strain": "-", "temperature": "K", "damage": "-", "pressure": "Pa",
         "von_mises": "Pa", "velocity": "m/s", "stress": "Pa", "failed": "-"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--out", required=True)
    parser.add_argument("--field", default="plastic_strain")
    parser.add_argument("--time", type=float, default=None)
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 800])
    args = parser.parse_args()

    series = os.path.join(args.directory, "particles.pvd")
    if not os.path.exists(series):
        sys.exit(f"paraview_snapshot: {series} not found (a run with output.snapshots on)")
    reader = pv.PVDReader(FileName=series)
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    time = times[-1] if args.time is None else min(times, key=lambda t: abs(t - args.time))
    if args.field not in reader.PointData.keys():
        sys.exit(f"paraview_snapshot: no field '{args.field}' in {series}; it has "
                 + ", ".join(reader.PointData.keys()))

    # Half the model (y >= its centre), so a section through the impact axis shows.
    bounds = reader.GetDataInformation().GetBounds()
    clip = pv.Clip(Input=reader)
    clip.ClipType = "Plane"
    clip.ClipType.Origin = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                            0.5 * (bounds[4] + bounds[5])]
    clip.ClipType.Normal = [0.0, -1.0, 0.0]
    clip.Invert = 1

    view = pv.CreateView("RenderView")
    view.ViewSize = args.size
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    view.ViewTime = time
    display = pv.Show(clip, view)
    display.SetRepresentationType("Point Gaussian")
    # Splats about half a particle spacing wide: the particle count over the box's volume.
    extent = [b - a for a, b in zip(bounds[0::2], bounds[1::2])]
    count = max(reader.GetDataInformation().GetNumberOfPoints(), 1)
    spacing = (extent[0] * extent[1] * extent[2] / count) ** (1.0 / 3.0)
    display.GaussianRadius = 0.35 * spacing
    pv.ColorBy(display, ("POINTS", args.field))
    lut = pv.GetColorTransferFunction(args.field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    data_range = clip.PointData[args.field].GetRange()
    lut.RescaleTransferFunction(data_range[0], max(data_range[1], data_range[0] + 1e-12))
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = f"{args.field} [{UNITS.get(args.field, 'SI')}]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    text = pv.Text(Text=f"t = {time * 1e6:.1f} us")
    text_display = pv.Show(text, view)
    text_display.Color = [0.0, 0.0, 0.0]
    text_display.WindowLocation = "Upper Left Corner"

    # Looking at the cut face (from -y), the impact axis horizontal.
    view.CameraPosition = [clip.ClipType.Origin[0], bounds[2] - 3.0 * (bounds[3] - bounds[2]),
                           clip.ClipType.Origin[2]]
    view.CameraFocalPoint = clip.ClipType.Origin
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    pv.GetActiveCamera().Dolly(1.4)
    pv.Render(view)
    pv.SaveScreenshot(args.out, view, ImageResolution=args.size)
    print(f"wrote {args.out} ({args.field} at t = {time:.3e} s, {len(times)} snapshots)")


if __name__ == "__main__":
    main()
