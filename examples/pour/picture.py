"""Draws the last frame of a run's collection: the spheres coloured by material beside the
force chains (each contact a tube from centre to centre, or to the wall, its width and colour
by the force it carries). Runs in ParaView's batch interpreter, off screen:

    pvbatch examples/pour/picture.py DIR/pour.pvd picture.png

(Debian: the paraview package; where pvbatch wants a display, run it under xvfb-run.) It works
on any collection the scene's `Frames` writes; the material names are the pour's.
"""

import sys

from paraview.simple import (
    CellDatatoPointData,
    ColorBy,
    CreateLayout,
    CreateView,
    ExtractBlock,
    ExtractSurface,
    GetAnimationScene,
    GetColorTransferFunction,
    GetScalarBar,
    Glyph,
    MergeBlocks,
    PVDReader,
    SaveScreenshot,
    Show,
    Tube,
)

MATERIALS = ["glass", "steel", "polymer"]
COLOURS = [0.55, 0.8, 0.9, 0.45, 0.45, 0.5, 0.85, 0.45, 0.2]


def view(layout, cell):
    """A white render view in `cell` of `layout`, looking at the box from the front, above."""
    render = CreateView("RenderView")
    render.OrientationAxesVisibility = 0
    render.Background = [1, 1, 1]
    render.UseColorPaletteForBackground = 0
    layout.AssignView(cell, render)
    return render


def place_camera(render, bounds):
    (x0, x1, y0, y1, z0, z1) = bounds
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    size = max(x1 - x0, y1 - y0, z1 - z0)
    render.CameraFocalPoint = centre
    render.CameraPosition = [centre[0] + 1.2 * size, centre[1] - 2.2 * size, centre[2] + 1.4 * size]
    render.CameraViewUp = [0, 0, 1]
    render.CameraParallelProjection = 0
    render.ResetCamera(False)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: pvbatch picture.py DIR/pour.pvd picture.png")
    collection, image = sys.argv[1], sys.argv[2]
    reader = PVDReader(FileName=collection)
    reader.UpdatePipelineInformation()
    last = reader.TimestepValues[-1] if reader.TimestepValues else 0.0
    # Every view and filter at the last frame's time.
    animation = GetAnimationScene()
    animation.UpdateAnimationUsingDataTimeSteps()
    animation.AnimationTime = last
    # The collection's parts: 0 the spheres, 1 the contacts.
    spheres = MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=["/Root/Block0"]))
    contacts = ExtractSurface(
        Input=MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=["/Root/Block1"]))
    )

    layout = CreateLayout("pour")
    layout.SplitHorizontal(0, 0.5)
    left, right = view(layout, 1), view(layout, 2)

    balls = Glyph(Input=spheres, GlyphType="Sphere")
    balls.ScaleArray = ["POINTS", "radius"]
    balls.ScaleFactor = 2.0
    balls.GlyphMode = "All Points"
    balls.GlyphType.ThetaResolution = 24
    balls.GlyphType.PhiResolution = 24
    shown = Show(balls, left)
    ColorBy(shown, ("POINTS", "material"))
    table = GetColorTransferFunction("material")
    table.InterpretValuesAsCategories = 1
    table.Annotations = sum(([str(k), name] for k, name in enumerate(MATERIALS)), [])
    table.IndexedColors = COLOURS
    shown.SetScalarBarVisibility(left, True)
    bar = GetScalarBar(table, left)
    bar.Title = "material"
    bar.WindowLocation = "Upper Right Corner"
    bar.TitleColor = bar.LabelColor = [0, 0, 0]

    points = CellDatatoPointData(Input=contacts)
    chains = Tube(Input=points)
    chains.Scalars = ["POINTS", "force_magnitude"]
    chains.VaryRadius = "By Scalar"
    chains.Radius = 0.04e-3
    chains.RadiusFactor = 12.0
    chains.NumberofSides = 12
    drawn = Show(chains, right)
    ColorBy(drawn, ("POINTS", "force_magnitude"))
    force = GetColorTransferFunction("force_magnitude")
    force.ApplyPreset("Inferno (matplotlib)", True)
    force.InvertTransferFunction()
    drawn.SetScalarBarVisibility(right, True)
    bar = GetScalarBar(force, right)
    bar.Title = "contact force (N)"
    bar.WindowLocation = "Upper Right Corner"
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    faint = Show(balls, right)
    faint.Opacity = 0.08
    faint.ColorArrayName = ["POINTS", ""]
    faint.AmbientColor = faint.DiffuseColor = [0.6, 0.6, 0.6]

    bounds = spheres.GetDataInformation().GetBounds()
    for render in (left, right):
        place_camera(render, bounds)
    drawn.RescaleTransferFunctionToDataRange(False, True)
    SaveScreenshot(image, layout, ImageResolution=[1200, 600])


main()
