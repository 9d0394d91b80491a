"""Opens a run directory's .pvd collections in ParaView (as a user would, OpenDataFile) and checks
what each must hold at every time step. Usage: tools/paraview/pvpython tools/paraview/check_run.py
RUN_DIR. Prints one line per collection; exit 1 naming the first thing missing."""
import os
import sys

from paraview.simple import OpenDataFile, UpdatePipeline

EXPECTED = {
    "vtk/particles.pvd": ("point", ["id", "radius_m", "mass_kg", "velocity_m_s", "angular_velocity_rad_s", "displacement_m"]),
    "vtk/contacts.pvd": ("cell", ["force_N", "boundary"]),
    "vtk/walls.pvd": ("cell", []),
    "fields/fields.pvd": ("point", ["solid_fraction", "velocity_x_m_s", "shear_rate_dvx_dz_1_s", "vorticity_y_1_s",
                                    "cosserat_rotation_y_rad_s", "stress_xz_Pa", "stress_zz_Pa"]),
}


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def check(run, name, where, arrays):
    path = os.path.join(run, name)
    if not os.path.exists(path):
        fail(path + ": missing")
    reader = OpenDataFile(path)
    if reader is None:
        fail(path + ": ParaView has no reader for it")
    times = list(reader.TimestepValues) or [0.0]
    data = reader.PointData if where == "point" else reader.CellData
    largest_displacement = 0.0
    for t in times:
        UpdatePipeline(time=t, proxy=reader)
        info = reader.GetDataInformation()
        if info.GetNumberOfPoints() == 0:
            fail("%s at t = %g: no points" % (path, t))
        for a in arrays:
            if a not in data.keys():
                fail("%s at t = %g: no %s array %s (has %s)" % (path, t, where, a, list(data.keys())))
        if "displacement_m" in arrays:
            lo, hi = data["displacement_m"].GetRange(0)
            if t == times[0] and (lo != 0.0 or hi != 0.0):
                fail("%s: displacement at the first snapshot is not zero (%g, %g)" % (path, lo, hi))
            largest_displacement = max(largest_displacement, hi - lo)
        if "solid_fraction" in arrays:
            lo, hi = data["solid_fraction"].GetRange()
            if not (lo >= 0.0 and 0.3 < hi < 1.0):
                fail("%s at t = %g: solid fraction in [%g, %g]" % (path, t, lo, hi))
    if "displacement_m" in arrays and len(times) > 1 and largest_displacement <= 0.0:
        fail(path + ": the grains never moved along x")
    print("%s: %d time steps, %d points, %s arrays %s" % (name, len(times), info.GetNumberOfPoints(), where, ", ".join(arrays)))


run = sys.argv[1]
for name, (where, arrays) in EXPECTED.items():
    check(run, name, where, arrays)
print("ParaView opened every collection of " + run)
