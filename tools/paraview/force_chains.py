"""Draws a run's force chains with ParaView: the particles at the last step
of a ParaView series (dem_run --vtk-interval, dem_server --vtk-interval or
dem_vtk), the contacts as tubes whose width and colour grow with the normal
force, and the walls. Runs under ParaView's pvpython; headless, as
scripts/pvpython.sh runs it (in Xvfb; docs/PARAVIEW.md):

    bash scripts/pvpython.sh tools/paraview/force_chains.py OUT_DIR PNG [--title TEXT] [--width PX] [--height PX]

OUT_DIR holds particles.pvd, contacts.pvd and walls.pvd. 2D runs are seen
from +z; 3D runs from the side (-y), with z up.
"""

import argparse
import builtins
import pathlib
import sys

from paraview import simple as pv

# (ParaView's programmable filter puts VTK's array algorithms, max and min
# among them, into __main__: the builtins are named in full below.)

# A ProgrammableFilter's script (it runs inside ParaView, with `inputs` and
# `output`): each 2D particle as a filled polygon on its boundary
# (Miyata et al. 2002, eq. 35: x = a sgn(cos t)|cos t|^(2/n), y likewise with b).
OUTLINES_2D = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
source = inputs[0]
centres = source.Points
axes = source.PointData["semi_axes"]
exponent = source.PointData["exponent"]
q = source.PointData["orientation"]
t = np.linspace(0.0, 2.0 * np.pi, 97)[:-1]
c, s = np.cos(t), np.sin(t)
points = vtkPoints()
polygons = vtkCellArray()
for i in range(source.GetNumberOfPoints()):
    e = 2.0 / exponent[i]
    x = axes[i][0] * np.sign(c) * np.abs(c) ** e
    y = axes[i][1] * np.sign(s) * np.abs(s) ** e
    angle = 2.0 * np.arctan2(q[i][3], q[i][0])
    ca, sa = np.cos(angle), np.sin(angle)
    polygons.InsertNextCell(len(t))
    for xk, yk in zip(x, y):
        polygons.InsertCellPoint(points.InsertNextPoint(centres[i][0] + ca * xk - sa * yk,
                                                        centres[i][1] + sa * xk + ca * yk, 0.0))
output.SetPoints(points)
output.SetPolys(polygons)
"""


def particle_shapes(particles, flat):
    """The particles in their true shapes (io/vtk_files.h). In 2D an outline
    of |x/a|^n + |y/b|^n = 1 per particle, turned by its orientation (discs:
    a = b = R, n = 2); in 3D a unit sphere stretched and turned by each
    particle's shape_tensor, whose columns are its body axes scaled by its
    semi-axes (spheres and ellipsoids)."""
    if flat:
        glyphs = pv.ProgrammableFilter(Input=particles)
        glyphs.OutputDataSetType = "vtkPolyData"
        glyphs.Script = OUTLINES_2D
        return glyphs
    glyphs = pv.TensorGlyph(Input=particles, GlyphType="Sphere")
    glyphs.Tensors = ["POINTS", "shape_tensor"]
    glyphs.ExtractEigenvalues = 0
    glyphs.Symmetric = 0
    glyphs.ColorGlyphs = 0
    # The tensor is the size: ParaView's default scale factor is a share of
    # the data's bounds (0.53 of the true size for Miyata's 3D sample).
    glyphs.ScaleFactor = 1.0
    glyphs.GlyphType.Radius = 1.0
    glyphs.GlyphType.ThetaResolution = 32
    glyphs.GlyphType.PhiResolution = 16
    return glyphs


def main(argv):
    parser = argparse.ArgumentParser(prog="force_chains.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", type=pathlib.Path)
    parser.add_argument("png", type=pathlib.Path)
    parser.add_argument("--title", default="")
    parser.add_argument("--width", type=int, default=1600)
    parser.add_argument("--height", type=int, help="default: the sample's proportions, with room for the title and colour bar")
    args = parser.parse_args(argv)
    series = {kind: args.directory / f"{kind}.pvd" for kind in ("particles", "contacts", "walls")}
    missing = [str(path) for path in series.values() if not path.is_file()]
    if missing:
        sys.exit(f"force_chains.py: no ParaView series: {', '.join(missing)} missing "
                 "(run dem_run or dem_server with --vtk-interval N)")

    particles = pv.PVDReader(FileName=str(series["particles"]))
    contacts = pv.PVDReader(FileName=str(series["contacts"]))
    walls = pv.PVDReader(FileName=str(series["walls"]))
    # The last step (one step comes as a number, several as a list).
    try:
        times = list(particles.TimestepValues)
    except TypeError:
        times = [particles.TimestepValues]
    last = float(times[-1]) if times else 0.0

    view = pv.CreateView("RenderView")
    view.ViewTime = last
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0

    pv.UpdatePipeline(last, particles)
    bounds = particles.GetDataInformation().GetBounds()
    flat = abs(bounds[5] - bounds[4]) < 1e-12
    glyphs = particle_shapes(particles, flat)
    shown = pv.Show(glyphs, view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.DiffuseColor = [0.82, 0.82, 0.80]
    shown.AmbientColor = [0.82, 0.82, 0.80]
    shown.Opacity = 0.55

    # Contacts: tubes whose radius grows with the normal force (cell data
    # moved to the points; each line has its own two points).
    forces = pv.CellDatatoPointData(Input=contacts)
    forces.PassCellData = 1
    tubes = pv.Tube(Input=forces)
    tubes.Scalars = ["POINTS", "normal_force"]
    tubes.VaryRadius = "By Scalar"  # from Radius at the weakest to Radius x RadiusFactor at the strongest
    tubes.NumberofSides = 12
    for source in (contacts, walls):
        pv.UpdatePipeline(last, source)
    # Sized by the particles' second semi-axis (a disc's radius, a
    # superquadric's b), not by bounding radii, which elongated shapes inflate.
    size_range = particles.PointData["semi_axes"].GetRange(1)
    force_range = contacts.CellData["normal_force"].GetRange() if contacts.CellData.GetArray("normal_force") else (0, 1)
    mean_radius = 0.5 * (size_range[0] + size_range[1])
    tubes.Radius = 0.02 * mean_radius
    tubes.RadiusFactor = 20.0  # the strongest contact's tube: 0.4 of a mean radius
    chains = pv.Show(tubes, view)
    pv.ColorBy(chains, ("POINTS", "normal_force"))
    lut = pv.GetColorTransferFunction("normal_force")
    lut.ApplyPreset("Inferno (matplotlib)", True)
    lut.InvertTransferFunction()
    lut.RescaleTransferFunction(0.0, builtins.max(force_range[1], 1e-30))
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "contact normal force (N)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.Visibility = 1
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Lower Center"

    wall_lines = pv.Show(walls, view)
    wall_lines.ColorArrayName = ["CELLS", ""]
    wall_lines.DiffuseColor = wall_lines.AmbientColor = [0.15, 0.15, 0.15]
    wall_lines.LineWidth = 4.0

    if args.title:
        title = pv.Text(Text=args.title)
        shown_title = pv.Show(title, view)
        shown_title.Color = [0.1, 0.1, 0.1]
        shown_title.FontSize = 20
        shown_title.WindowLocation = "Upper Center"

    walls_bounds = walls.GetDataInformation().GetBounds()
    if walls_bounds[0] <= walls_bounds[1]:  # an empty data set reports inverted bounds
        bounds = [builtins.min(bounds[i], walls_bounds[i]) if i % 2 == 0 else builtins.max(bounds[i], walls_bounds[i]) for i in range(6)]
    # What the camera looks at: x and y from +z in 2D; x and z from -y in 3D.
    up_axis = 1 if flat else 2
    across = bounds[1] - bounds[0]
    up = bounds[2 * up_axis + 1] - bounds[2 * up_axis]
    if args.height is None:
        # The sample's proportions, with room for the title and the colour bar.
        args.height = int(builtins.min(builtins.max(args.width * 0.9 * up / builtins.max(across, 1e-30) + 220, 400), 2 * args.width))
    view.ViewSize = [args.width, args.height]
    # Half the view's height in world units: the sample 92% wide or 70% high.
    scale = builtins.max(0.5 * across / 0.92 * args.height / args.width, 0.5 * up / 0.7)
    view.CameraParallelProjection = 1
    view.CameraParallelScale = scale
    # Looking at a point a little below the sample's centre puts the sample
    # above the middle, clear of the colour bar.
    target = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    target[up_axis] -= 0.12 * scale
    distance = 10.0 * builtins.max(across, up)
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(*target)
    if flat:
        camera.SetPosition(target[0], target[1], target[2] + distance)
        camera.SetViewUp(0.0, 1.0, 0.0)
    else:
        camera.SetPosition(target[0], target[1] - distance, target[2])
        camera.SetViewUp(0.0, 0.0, 1.0)
    args.png.parent.mkdir(parents=True, exist_ok=True)
    pv.SaveScreenshot(str(args.png), view, ImageResolution=[args.width, args.height], TransparentBackground=0)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main(sys.argv[1:])
