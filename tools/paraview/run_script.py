# pvpython puts /lib/python3/dist-packages, where YADE's python3-vtk9 keeps its vtkmodules, before
# ParaView's own; importing paraview.simple with those crashes. Move it behind, then run the script.
import runpy
import sys

sys.path = [p for p in sys.path if not (p.endswith("lib/python3/dist-packages") and not p.startswith("/opt"))]
sys.path.append("/usr/lib/python3/dist-packages")
script = sys.argv[1]
sys.argv = sys.argv[1:]
runpy.run_path(script, run_name="__main__")
