"""tools/paraview/force_chains.py draws each 3D particle at its true size:
an ellipsoid of semi-axes 3, 2 and 1 m, turned 30 degrees about z, and a
sphere of radius 0.5 m 10 m away (the bounds ParaView would scale glyphs
by). Measures the drawn ellipsoid's extent along each axis against the
semi-axes (the sphere glyph is a polygon: within 1 %), and a 2D disc's.
Runs under pvpython (scripts/pvpython.sh; ParaView's programmable filter
puts VTK's array algorithms - sum, max, min - into __main__, so the
builtins are named in full):
    pvpython force_chains_shapes.py REPOSITORY WORK_DIR
"""

import builtins
import math
import pathlib
import sys

from paraview import servermanager
from paraview import simple as pv
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

repository, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
sys.path.insert(0, str(repository / "tools" / "paraview"))
import force_chains  # noqa: E402

work.mkdir(parents=True, exist_ok=True)
ANGLE = math.radians(30.0)


def particles_file(name, centres, semi_axes, axes):
    """A particles.vtp as io/vtk_files.h writes it: shape_tensor's column j
    is body axis j scaled by semi-axis j (components 3j..3j+2)."""
    points = vtkPoints()
    tensors = vtkDoubleArray()
    tensors.SetName("shape_tensor")
    tensors.SetNumberOfComponents(9)
    radii = vtkDoubleArray()
    radii.SetName("semi_axes")
    radii.SetNumberOfComponents(3)
    exponents = vtkDoubleArray()
    exponents.SetName("exponent")
    orientations = vtkDoubleArray()
    orientations.SetName("orientation")
    orientations.SetNumberOfComponents(4)
    for centre, semi, body in zip(centres, semi_axes, axes):
        points.InsertNextPoint(*centre)
        tensors.InsertNextTuple([body[j][i] * semi[j] for j in range(3) for i in range(3)])
        radii.InsertNextTuple(semi)
        exponents.InsertNextValue(2.0)
        half = 0.5 * math.atan2(body[0][1], body[0][0])
        orientations.InsertNextTuple([math.cos(half), 0.0, 0.0, math.sin(half)])
    data = vtkPolyData()
    data.SetPoints(points)
    for array in (tensors, radii, exponents, orientations):
        data.GetPointData().AddArray(array)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(str(work / name))
    writer.SetInputData(data)
    writer.Write()
    return pv.XMLPolyDataReader(FileName=[str(work / name)])


def extent(polydata, axis, centre, reach):
    """Half the extent along `axis` (a unit vector) of the points within
    `reach` of `centre`: one particle's drawn semi-axis in that direction."""
    along = []
    for i in range(polydata.GetNumberOfPoints()):
        p = polydata.GetPoint(i)
        d = [p[k] - centre[k] for k in range(3)]
        if math.sqrt(builtins.sum(x * x for x in d)) <= reach:
            along.append(builtins.sum(d[k] * axis[k] for k in range(3)))
    return 0.5 * (builtins.max(along) - builtins.min(along))


failures = []


def check(what, drawn, true):
    error = abs(drawn - true) / true
    print(f"{what}: drawn semi-axis {drawn:.4f} m, true {true:.4f} m ({100 * error:.2f} %)")
    if error > 0.01:
        failures.append(what)


# 3D: the ellipsoid's body axes turned by ANGLE about z.
c, s = math.cos(ANGLE), math.sin(ANGLE)
body = [(c, s, 0.0), (-s, c, 0.0), (0.0, 0.0, 1.0)]
identity = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
reader = particles_file("particles3.vtp", [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0)], [(3.0, 2.0, 1.0), (0.5, 0.5, 0.5)],
                        [body, identity])
shapes = force_chains.particle_shapes(reader, flat=False)
pv.UpdatePipeline(proxy=shapes)
drawn = servermanager.Fetch(shapes)
for j, semi in enumerate((3.0, 2.0, 1.0)):
    check(f"3D ellipsoid, body axis {j + 1}", extent(drawn, body[j], (0.0, 0.0, 0.0), 3.5), semi)
check("3D sphere", extent(drawn, (1.0, 0.0, 0.0), (10.0, 0.0, 0.0), 1.0), 0.5)

# 2D: discs, outlines in the plane z = 0.
reader = particles_file("particles2.vtp", [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0)], [(1.5, 1.5, 0.0), (0.5, 0.5, 0.0)],
                        [identity, identity])
shapes = force_chains.particle_shapes(reader, flat=True)
pv.UpdatePipeline(proxy=shapes)
drawn = servermanager.Fetch(shapes)
check("2D disc", extent(drawn, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0), 2.0), 1.5)

if failures:
    sys.exit("drawn at the wrong size: " + ", ".join(failures))
print("every particle drawn at its true size")
