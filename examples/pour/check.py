"""Reads a pour's frames back with VTK's own XML reader and checks them as a user would.

    python3 examples/pour/check.py DIR/pour.pvd SPHERES

Checked, on the last frame: every sphere is there with its radius (0.5-2 mm), mass, velocity,
angular velocity, contact force and one of the three materials; every contact line has finite
forces, a unit normal, a tangential force within Coulomb's limit of the largest friction, and
ends that touch (their distance is the radii less the overlap); the walls carry the bed's weight
(to 1 %, the bed at rest), and the spheres' contact forces sum to what the walls put on them.
Every frame the collection lists exists, in increasing time. Needs VTK's Python bindings
(Debian: python3-vtk9).
"""

import math
import os
import sys
import xml.etree.ElementTree as ElementTree

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy

GRAVITY = 9.81
RADII = (0.5e-3, 2.0e-3)
# The largest friction coefficient of the pour's materials (the polymer's).
LARGEST_FRICTION = 0.45


def fail(message):
    print(f"check.py: {message}", file=sys.stderr)
    sys.exit(1)


def read(path):
    if not os.path.exists(path):
        fail(f"{path} is missing")
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if reader.GetErrorCode() != 0:
        fail(f"VTK could not read {path}")
    return data


def array(attributes, name, components, path):
    found = attributes.GetArray(name)
    if found is None:
        fail(f"{path}: no array {name}")
    if found.GetNumberOfComponents() != components:
        fail(f"{path}: {name} has {found.GetNumberOfComponents()} components, not {components}")
    values = vtk_to_numpy(found)
    if values.dtype.kind == "f" and not (values == values).all():
        fail(f"{path}: {name} holds NaN")
    if values.dtype.kind == "f" and not abs(values).max(initial=0.0) < math.inf:
        fail(f"{path}: {name} holds an infinity")
    return values


def main():
    if len(sys.argv) != 3:
        fail("usage: check.py DIR/pour.pvd SPHERES")
    collection, expected = sys.argv[1], int(sys.argv[2])
    directory = os.path.dirname(collection)
    frames = {}
    for entry in ElementTree.parse(collection).getroot().iter("DataSet"):
        time = float(entry.get("timestep"))
        frames.setdefault(time, {})[int(entry.get("part"))] = entry.get("file")
    times = sorted(frames)
    if not times:
        fail("the collection lists no frame")
    for time in times:
        if sorted(frames[time]) != [0, 1]:
            fail(f"the frame at {time} s is not a spheres and a contacts part")
        for file in frames[time].values():
            if not os.path.exists(os.path.join(directory, file)):
                fail(f"{file}, listed in the collection, is missing")

    last = frames[times[-1]]
    spheres_path = os.path.join(directory, last[0])
    spheres = read(spheres_path)
    if spheres.GetNumberOfPoints() != expected or spheres.GetNumberOfVerts() != expected:
        fail(f"{spheres.GetNumberOfPoints()} spheres, not {expected}")
    points = spheres.GetPointData()
    position = vtk_to_numpy(spheres.GetPoints().GetData())
    radius = array(points, "radius", 1, spheres_path)
    mass = array(points, "mass", 1, spheres_path)
    array(points, "velocity", 3, spheres_path)
    array(points, "angular_velocity", 3, spheres_path)
    contact_force = array(points, "contact_force", 3, spheres_path)
    material = array(points, "material", 1, spheres_path)
    if not ((radius >= RADII[0]) & (radius <= RADII[1])).all():
        fail("a radius outside 0.5-2 mm")
    if not (mass > 0).all():
        fail("a mass not positive")
    if sorted(set(material.tolist())) != [0, 1, 2]:
        fail(f"materials {sorted(set(material.tolist()))}, not the three")

    contacts_path = os.path.join(directory, last[1])
    contacts = read(contacts_path)
    lines = contacts.GetNumberOfLines()
    if lines == 0 or contacts.GetNumberOfPoints() != 2 * lines:
        fail(f"{lines} contact lines over {contacts.GetNumberOfPoints()} points")
    cells = contacts.GetCellData()
    ends = vtk_to_numpy(contacts.GetPoints().GetData()).reshape(lines, 2, 3)
    bodies = array(cells, "spheres", 2, contacts_path)
    wall = array(cells, "wall", 1, contacts_path)
    normal = array(cells, "normal", 3, contacts_path)
    overlap = array(cells, "overlap", 1, contacts_path)
    normal_force = array(cells, "normal_force", 1, contacts_path)
    tangential = array(cells, "tangential_force", 3, contacts_path)
    force = array(cells, "force", 3, contacts_path)
    array(cells, "force_magnitude", 1, contacts_path)
    array(cells, "sliding", 1, contacts_path)

    if abs((normal**2).sum(axis=1) - 1).max() > 1e-12:
        fail("a contact normal is not a unit vector")
    i, j = bodies[:, 0], bodies[:, 1]
    pairs = wall < 0
    # The overlap against the contact's radius scale: 2 R* for a pair, the radius at a wall.
    scale = radius[i].copy()
    scale[pairs] = (radius[i[pairs]] * radius[j[pairs]]) / (radius[i[pairs]] + radius[j[pairs]]) * 2
    if not (overlap > 0).all() or (overlap / scale).max() > 0.05:
        fail(f"overlaps up to {(overlap / scale).max():.3e} of a radius at rest")
    slack = 1e-9 * abs(normal_force).max()
    if ((tangential**2).sum(axis=1) ** 0.5 > LARGEST_FRICTION * abs(normal_force) + slack).any():
        fail("a tangential force past Coulomb's limit")
    if not ((bodies[:, 1] >= 0) == pairs).all():
        fail("a contact is both a pair's and a wall's")
    # Each line starts at sphere i's centre and reaches j's (or the wall) at the radii less
    # the overlap.
    if abs(ends[:, 0] - position[i]).max() > 0:
        fail("a contact line does not start at its sphere's centre")
    reach = radius[i] + (pairs * radius[j]) - overlap
    length = ((ends[:, 1] - ends[:, 0]) ** 2).sum(axis=1) ** 0.5
    if abs(length - reach).max() > 1e-9:
        fail("a contact line's length is not its bodies' distance")
    gap = ((position[j[pairs]] - position[i[pairs]]) ** 2).sum(axis=1) ** 0.5
    if abs(gap - reach[pairs]).max() > 1e-9:
        fail("a pair's line does not end at its other sphere's centre")

    weight = (mass * GRAVITY).sum()
    # force is the force on body j: the wall. The walls put its opposite on the spheres.
    carried = -force[~pairs, 2].sum()
    print(f"{expected} spheres, {lines} contacts ({(~pairs).sum()} on walls) at {times[-1]:.4f} s")
    print(f"the walls carry {carried:.6e} N of the weight {weight:.6e} N ({carried / weight - 1:+.2e})")
    if abs(carried / weight - 1) > 0.01:
        fail("the walls do not carry the bed's weight")
    # Pairs cancel in the spheres' sum: what is left is the walls' push.
    total = contact_force.sum(axis=0)
    from_walls = -force[~pairs].sum(axis=0)
    if abs(total - from_walls).max() > 1e-9 * weight:
        fail(f"the spheres' contact forces sum to {total}, the walls' to {from_walls}")
    print("check.py: the frames read back and hold the pour")


main()
