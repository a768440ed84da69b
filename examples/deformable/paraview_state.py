"""ParaView state of a deformable run (examples/deformable): the block seen from the side,
coloured by sigma_zz, with the tool and the plate, and the bonded face seen from below,
coloured by the interface pressure (paper fig. 9), at one time.

    pvpython paraview_state.py OUTDIR [TIME] [PNG]

OUTDIR holds results.pvd of `plyform run`. TIME (default: the middle of the slide, 0.08 s)
picks the state shown; with PNG the two views are saved there (pvbatch works too), otherwise
the script leaves ParaView's views as set up (run it from ParaView's Python shell to explore:
the animation controls step through the states). The VTU points are the current positions, so
no warp is needed. Arrays: point data contact_pressure, beta, gap, contact_state on the bonded
face's nodes (NaN elsewhere, drawn grey), displacement, velocity; cell data stress (xx, yy, zz,
xy, yz, zx), part.
"""

import os
import sys

from paraview.simple import (ColorBy, CreateView, GetAnimationScene, GetColorTransferFunction,
                             GetLayout, PVDReader, Render, SaveScreenshot, Show, Threshold)

run = sys.argv[1] if len(sys.argv) > 1 else "deformable_out"
time = float(sys.argv[2]) if len(sys.argv) > 2 else 0.08
png = sys.argv[3] if len(sys.argv) > 3 else None

reader = PVDReader(FileName=os.path.join(run, "results.pvd"))
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = time


def part(pid):
    """The cells of one part (1 block, 2 plate, 3 tool)."""
    t = Threshold(Input=reader)
    t.Scalars = ["CELLS", "part"]
    try:  # ParaView 5.10 and later
        t.LowerThreshold, t.UpperThreshold = pid - 0.5, pid + 0.5
    except AttributeError:  # earlier versions
        t.ThresholdRange = [pid - 0.5, pid + 0.5]
    return t


block, plate, tool = part(1), part(2), part(3)

# Side view: sigma_zz in the block, the tool and the plate in grey.
side = CreateView("RenderView")
side.OrientationAxesVisibility = 1
d = Show(block, side)
ColorBy(d, ("CELLS", "stress", "Z"))
lut = GetColorTransferFunction("stress")
lut.VectorMode = "Component"
lut.VectorComponent = 2
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(-1.5, 1.5)
d.SetScalarBarVisibility(side, True)
d.Representation = "Surface With Edges"
for other in (plate, tool):
    o = Show(other, side)
    ColorBy(o, None)
    o.DiffuseColor = [0.7, 0.7, 0.7]
side.CameraPosition = [24.0, -80.0, 8.0]
side.CameraFocalPoint = [24.0, 5.0, 6.0]
side.CameraViewUp = [0.0, 0.0, 1.0]

# The bonded face from below: the interface pressure (compression > 0, tension < 0, the peel
# front; NaN, grey, away from the interface).
below = CreateView("RenderView")
b = Show(block, below)
ColorBy(b, ("POINTS", "contact_pressure"))
plut = GetColorTransferFunction("contact_pressure")
plut.ApplyPreset("Cool to Warm", True)
plut.RescaleTransferFunction(-0.3, 1.0)
plut.NanColor = [0.6, 0.6, 0.6]
b.SetScalarBarVisibility(below, True)
below.CameraPosition = [24.0, 5.0, -80.0]
below.CameraFocalPoint = [24.0, 5.0, 0.0]
below.CameraViewUp = [0.0, 1.0, 0.0]

layout = GetLayout(side)
if layout is not None:
    layout.AssignView(2, below)
Render(side)
Render(below)
if png:
    SaveScreenshot(png, layout if layout is not None else side, ImageResolution=[1600, 600])
    print(f"paraview_state.py: {png}")
