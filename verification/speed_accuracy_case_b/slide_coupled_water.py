#!/usr/bin/env python3
"""How much water the grid couples to the beads of examples/case_b_2d, against the pores they
offer, from a finished run.

    python3 slide_coupled_water.py CASE [CASE ...]   (CASE: a run's case folder)

The water and the grains meet at the nodes: a liquid point at whose cell's nodes grains sit
sees a porosity below 1 (the nodal porosity interpolated; scientific manual 10.1), and the
drag of eq. (23) and the common normal velocity at the soil's surface (10.3) act on the
water of those nodes. At a slide's surface those cells are only partly covered by beads, so
the water in their uncovered part is reached too: a fringe of the order of a cell. For each
release output at 0.10, 0.16, 0.20, 0.24 and 0.28 s it prints, per metre of flume width:
  coupled_m2      the volume of the liquid points that see a porosity below 0.99 (porosity
                  field of release_liquid_*.vtu; 1 in free water, float32 rounding below 1)
  beads_pores_m2  the pore volume of the beads below the still water line y = 0.15 m: each
                  point's volume less its grain volume, mass / rho_s (rho_s = 2470 kg/m3)
  fringe_m2       the difference. Early in the entry, when the beads under water are few and
                  wetted, it is the water reached beyond their pores; later the beads' dry
                  inner part makes it smaller, even negative, so read it at 0.10 s
  P_coupled       the along-slope momentum of that water (N s/m), s = (1, -1)/sqrt(2)
  P_beads         the beads' along-slope momentum (N s/m)
Needs the solid points' mass, volume and velocity in the output (the example writes them).

Needs VTK's Python module (Debian: python3-vtk9 or python3-paraview) and numpy.
"""
import glob
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

DOWN_SLOPE = np.array([1.0, -1.0]) / math.sqrt(2.0)
STILL_WATER_LEVEL = 0.15  # m, case_b.geo's h0
GRAIN_DENSITY = 2470.0  # kg/m3, the beads' rho_s in scene.toml
TIMES = (0.10, 0.16, 0.20, 0.24, 0.28)


def read(name):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(name)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    arrays["position"] = vtk_to_numpy(grid.GetPoints().GetData())
    return arrays


def along_slope_momentum(points, selected):
    return float((points["mass"][selected, None] * points["velocity"][selected, :2]).sum(0)
                 @ DOWN_SLOPE)


def report(case):
    output = os.path.join(case, "output")
    times = {os.path.basename(ds.get("file")): float(ds.get("timestep"))
             for ds in ET.parse(os.path.join(output, "release_liquid.pvd")).getroot().iter(
                 "DataSet")}
    print(f"# {case}")
    print("t_s,coupled_m2,beads_pores_m2,fringe_m2,P_coupled_Ns_per_m,P_beads_Ns_per_m")
    for name in sorted(glob.glob(os.path.join(output, "release_liquid_0*.vtu"))):
        t = times.get(os.path.basename(name))
        if t is None or not any(abs(t - wanted) < 1e-4 for wanted in TIMES):
            continue
        liquid = read(name)
        beads = read(name.replace("release_liquid_", "release_points_"))
        coupled = liquid["porosity"] < 0.99
        coupled_water = float(liquid["volume"][coupled].sum())
        under = beads["position"][:, 1] < STILL_WATER_LEVEL
        pores = float((beads["volume"][under] - beads["mass"][under] / GRAIN_DENSITY).sum())
        print(f"{t:.2f},{coupled_water:.5f},{pores:.5f},{coupled_water - pores:.5f},"
              f"{along_slope_momentum(liquid, coupled):.3f},"
              f"{along_slope_momentum(beads, np.ones(len(beads['mass']), bool)):.3f}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in sys.argv[1:]:
        report(folder)
