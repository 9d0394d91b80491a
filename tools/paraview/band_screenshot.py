"""The README's ParaView picture of a run (docs/paraview_band.png): left, the grains at the last
snapshot coloured by their displacement along x since the start of shear; right, the coarse-grained
|dV_x/dz| over x-z. Needs a display: xvfb-run -a tools/paraview/pvpython (with IWB_PVPYTHON_FLAGS=""):
  IWB_PVPYTHON_FLAGS="" xvfb-run -a -s "-screen 0 1600x1000x24" tools/paraview/pvpython \
      tools/paraview/band_screenshot.py RUN_DIR docs/paraview_band.png"""
import sys

from paraview.simple import (AssignViewToLayout, Calculator, ColorBy, CreateLayout, CreateView, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, Glyph, OpenDataFile, SaveScreenshot, Show,
                             UpdatePipeline)

run, out = sys.argv[1], sys.argv[2]
particles = OpenDataFile(run + "/vtk/particles.pvd")
fields = OpenDataFile(run + "/fields/fields.pvd")
last = particles.TimestepValues[-1]

layout = CreateLayout("band")
grains_view, field_view = CreateView("RenderView"), CreateView("RenderView")
AssignViewToLayout(view=grains_view, layout=layout, hint=0)
AssignViewToLayout(view=field_view, layout=layout, hint=2)

spheres = Glyph(Input=particles, GlyphType="Sphere")
spheres.ScaleArray = ["POINTS", "radius_m"]
spheres.ScaleFactor = 2.0  # the unit sphere's diameter is 1: radius x 2
spheres.GlyphMode = "All Points"
shown = Show(spheres, grains_view)
ColorBy(shown, ("POINTS", "displacement_m", "X"))
shown.SetScalarBarVisibility(grains_view, True)

rate = Calculator(Input=fields)
rate.ResultArrayName = "shear_rate_magnitude_1_s"
rate.Function = "abs(shear_rate_dvx_dz_1_s)"
image = Show(rate, field_view)
ColorBy(image, ("POINTS", "shear_rate_magnitude_1_s"))
image.SetScalarBarVisibility(field_view, True)
GetColorTransferFunction("shear_rate_magnitude_1_s").ApplyPreset("Inferno (matplotlib)", True)

scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = last
UpdatePipeline(time=last, proxy=spheres)
UpdatePipeline(time=last, proxy=rate)
for view, name, title in ((grains_view, "displacement_m", "u_x (m)"), (field_view, "shear_rate_magnitude_1_s", "|dV_x/dz| (1/s)")):
    bar = GetScalarBar(GetColorTransferFunction(name), view)
    bar.Title, bar.ComponentTitle = title, ""
    bar.TitleFontSize, bar.LabelFontSize, bar.ScalarBarLength = 10, 9, 0.4
    bar.RangeLabelFormat = "%-#6.2g"
    bar.WindowLocation = "Any Location"
    bar.Position = [0.72, 0.3]
for view in (grains_view, field_view):
    view.ViewTime = last
    view.OrientationAxesVisibility = 1
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [0, -1, 0], [0, 0, 0], [0, 0, 1]
    view.ResetCamera()
image.RescaleTransferFunctionToDataRange(False, True)
shown.RescaleTransferFunctionToDataRange(False, True)
SaveScreenshot(out, layout, ImageResolution=[1600, 900])
print("wrote " + out)
