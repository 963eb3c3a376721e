"""The tutorial's ParaView picture (docs/img/pipe_in_soil.png): the last increment of a run of
pipe_in_soil.dck, warped by 20 x the displacement and coloured by its x component (the pull's
direction), seen
along the pipe (the y axis), the soil clipped at y = 2 so that the section through the middle
of the pipe shows. ParaView's pvpython, headless:
    xvfb-run -a pvpython render_paraview.py RESULTS/pipe_in_soil.pvd OUT.png
(two xvfb-runs at once: give each its own authority file, xvfb-run -a -f FILE)"""
import sys
from paraview.simple import (PVDReader, WarpByVector, Clip, CreateView, Show, ColorBy, ResetCamera,
                             SaveScreenshot, GetColorTransferFunction)

reader = PVDReader(FileName=sys.argv[1])
last = reader.TimestepValues[-1]
warp = WarpByVector(Input=reader, Vectors=['POINTS', 'displacement'], ScaleFactor=20.0)
clip = Clip(Input=warp, ClipType='Plane')
clip.ClipType.Origin = [0.0, 2.0, 0.0]
clip.ClipType.Normal = [0.0, -1.0, 0.0]
view = CreateView('RenderView')
view.ViewSize = [900, 700]
view.ViewTime = last
view.OrientationAxesVisibility = 1
display = Show(clip, view)
ColorBy(display, ('POINTS', 'displacement', 'X'))
display.RescaleTransferFunctionToDataRange(True, False)
display.SetScalarBarVisibility(view, True)
GetColorTransferFunction('displacement').ApplyPreset('Viridis (matplotlib)', True)
view.CameraPosition = [3.0, -9.0, 2.5]
view.CameraFocalPoint = [0.0, 2.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[900, 700])
