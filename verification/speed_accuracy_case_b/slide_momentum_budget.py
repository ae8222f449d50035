#!/usr/bin/env python3
"""The beads' momentum budget along the slope of examples/case_b_2d, from a finished run.

    python3 slide_momentum_budget.py CASE [CASE ...]   (CASE: a run's case folder)

For each output time t of the release stage it prints, per metre of flume width:
  P      the beads' momentum along the slope, sum m v . s (N s/m), s = (1, -1)/sqrt(2)
         pointing down the 45 degree slope (release_points_*.vtu: mass, velocity);
  dP/dt  its rate, a central difference over the neighbouring outputs (N/m);
  wall   the force the beads put on the slope wall along s (release_history.csv,
         wall_slope_force_x/_y, the mean over the output interval that ends at t): their
         basal friction, positive down the slope;
  water  what the momentum balance leaves for the water, dP/dt - M g sin 45 + wall: its
         buoyancy, drag and pressure together (negative: it holds the slide back).
The balance assumes every bead is on the slope, true until the front reaches the tank's
floor (about 0.3 s after the release at 0.01 m cells); later the floor carries part of the
weight and `water` is no longer the water's force alone.

Needs VTK's Python module (Debian: python3-vtk9 or python3-paraview).
"""
import csv
import glob
import math
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

DOWN_SLOPE = np.array([1.0, -1.0]) / math.sqrt(2.0)
G_ALONG_SLOPE = 9.81 * math.sin(math.pi / 4.0)


def momentum_series(output):
    """(time, momentum along the slope, mass) at each release output."""
    series = []
    pvd_times = {}
    pvd = os.path.join(output, "release_points.pvd")
    if os.path.exists(pvd):
        import xml.etree.ElementTree as ET
        for ds in ET.parse(pvd).getroot().iter("DataSet"):
            pvd_times[os.path.basename(ds.get("file"))] = float(ds.get("timestep"))
    for name in sorted(glob.glob(os.path.join(output, "release_points_0*.vtu"))):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(name)
        reader.Update()
        data = reader.GetOutput().GetPointData()
        mass = vtk_to_numpy(data.GetArray("mass"))
        velocity = vtk_to_numpy(data.GetArray("velocity"))[:, :2]
        time = pvd_times.get(os.path.basename(name))
        series.append((time, float((mass[:, None] * velocity).sum(0) @ DOWN_SLOPE),
                       float(mass.sum())))
    return series


def budget(case):
    output = os.path.join(case, "output")
    rows = list(csv.DictReader(open(os.path.join(output, "release_history.csv"))))
    series = momentum_series(output)
    print(f"# {case}")
    print("t_s,P_Ns_per_m,dPdt_N_per_m,gravity_N_per_m,wall_N_per_m,water_N_per_m")
    for k in range(1, len(series) - 1):
        t, p, mass = series[k]
        if t is None:
            continue
        rate = (series[k + 1][1] - series[k - 1][1]) / (series[k + 1][0] - series[k - 1][0])
        row = min(rows, key=lambda r: abs(float(r["stage_time"]) - t))
        wall = np.array([float(row["wall_slope_force_x"]), float(row["wall_slope_force_y"])])
        wall_along = float(wall @ DOWN_SLOPE)
        gravity = mass * G_ALONG_SLOPE
        print(f"{t:.3f},{p:.4f},{rate:.2f},{gravity:.2f},{wall_along:.2f},"
              f"{rate - gravity + wall_along:.2f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in sys.argv[1:]:
        budget(folder)
