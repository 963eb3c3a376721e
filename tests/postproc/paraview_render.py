"""pvpython script of paraview_test.sh: opens a frix .pvd, goes to its last time step, warps the
mesh by the displacement (factor SCALE), colours it by the displacement's x component, saves
a PNG and prints the warped bounds and the colour range.
usage: pvpython paraview_render.py RESULT.pvd SCALE OUT.png"""
import sys
from paraview.simple import (PVDReader, WarpByVector, CreateView, Show, ColorBy, ResetCamera,
                             SaveScreenshot, GetColorTransferFunction)

result, scale, image = sys.argv[1], float(sys.argv[2]), sys.argv[3]
reader = PVDReader(FileName=result)
last = reader.TimestepValues[-1]
warp = WarpByVector(Input=reader)
warp.Vectors = ['POINTS', 'displacement']
warp.ScaleFactor = scale
warp.UpdatePipeline(last)
view = CreateView('RenderView')
view.ViewSize = [640, 480]
view.ViewTime = last
display = Show(warp, view)
ColorBy(display, ('POINTS', 'displacement', 'X'))
display.RescaleTransferFunctionToDataRange(True, False)
view.CameraPosition = [1.0, -6.0, 3.0]
view.CameraFocalPoint = [1.0, 0.5, 0.5]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
SaveScreenshot(image, view, ImageResolution=[640, 480])
lookup = GetColorTransferFunction('displacement')
points = lookup.RGBPoints
print("time %.6g" % last)
print("bounds " + " ".join("%.9g" % b for b in warp.GetDataInformation().GetBounds()))
print("colour_range %.9g %.9g" % (points[0], points[-4]))
