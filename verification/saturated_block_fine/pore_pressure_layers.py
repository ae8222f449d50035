#!/usr/bin/python3
"""Where the sliding block's pore pressure goes: its excess over hydrostatic, and whether its
pore water stays with its grains.

Reads a run of this case (CASE/output/slide_points_NNNN.vtu and slide_liquid_NNNN.vtu; the
verification runner keeps them under REPORT/saturated_block_fine/{slides,free}/output) and
prints, for every k-th output:
  - the distance the block has slid (the along-slope shift of its upslope end);
  - the mean excess pore pressure p - rho_w g (-y) of the liquid points over the block's
    length, in its bottom layer (0 <= t < LAYER) and in the layer 0.02-0.04 m above the bed,
    and that bottom excess times the block's 0.8 m length: the force it adds to the
    effective normal force on the bed (a suction is negative and presses the block down);
  - with --layers, the water and grain volume per unit area in 0.01 m layers across the block
    (away from its ends), relative to the first output: where the pore water stays with its
    grains, both rows keep the pattern of the start.

The still water line is y = 0 and the slope 25 degrees (../saturated_block/incline.geo).
Usage: /usr/bin/python3 pore_pressure_layers.py CASE/output [EVERY] [LAYER] [--layers]
Needs Debian's python3-vtk9 and python3-numpy (the system Python, not a virtual one).
"""
import glob
import math
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

RHO_W, G, RHO_S = 1000.0, 9.81, 2650.0  # kg/m3, m/s2, kg/m3 (the scenes' materials)
SLOPE = math.radians(25.0)
ALONG = np.array([math.cos(SLOPE), -math.sin(SLOPE)])  # downslope
NORMAL = np.array([math.sin(SLOPE), math.cos(SLOPE)])  # out of the bed
BLOCK_LENGTH = 0.8  # m


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    time = vtk_to_numpy(grid.GetFieldData().GetArray("stage_time"))[0]
    return time, vtk_to_numpy(grid.GetPoints().GetData())[:, :2], arrays


def layer_volumes(s, t, volume, start, end, edges):
    inside = (s > start) & (s < end)
    return np.histogram(t[inside], edges, weights=volume[inside])[0] / ((end - start) *
                                                                        (edges[1] - edges[0]))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not args:
        sys.exit(__doc__)
    folder = args[0]
    every = int(args[1]) if len(args) > 1 else 5
    layer = float(args[2]) if len(args) > 2 else 0.01
    show_layers = "--layers" in sys.argv
    outputs = len(glob.glob(f"{folder}/slide_points_*.vtu"))
    if outputs == 0:
        sys.exit(f"{folder}: no slide_points_NNNN.vtu files")
    edges = np.arange(0.0, 0.1001, 0.01)
    first_s = None
    print("| time (s) | slid (m) | bottom excess (Pa) | x 0.8 m (N/m) | 0.02-0.04 m excess (Pa) |")
    print("|---|---|---|---|---|")
    layer_rows = []
    for k in range(0, outputs, every):
        time, solid_x, solid = read(f"{folder}/slide_points_{k:04d}.vtu")
        _, liquid_x, liquid = read(f"{folder}/slide_liquid_{k:04d}.vtu")
        s_solid, t_solid = solid_x @ ALONG, solid_x @ NORMAL
        s_liquid, t_liquid = liquid_x @ ALONG, liquid_x @ NORMAL
        excess = liquid["pressure"] - RHO_W * G * (-liquid_x[:, 1])
        rear, front = s_solid.min(), s_solid.max()
        if first_s is None:
            first_s = rear
        over = (s_liquid > rear) & (s_liquid < front)
        bottom = excess[over & (t_liquid < layer)].mean()
        middle = excess[over & (t_liquid >= 0.02) & (t_liquid < 0.04)].mean()
        print(f"| {time:.3f} | {rear - first_s:.4f} | {bottom:.1f} | "
              f"{BLOCK_LENGTH * bottom:.1f} | {middle:.1f} |")
        if show_layers:
            start, end = rear + 0.1, front - 0.1
            grains = layer_volumes(s_solid, t_solid, solid["mass"] / RHO_S, start, end, edges)
            water = layer_volumes(s_liquid, t_liquid, liquid["volume"], start, end, edges)
            layer_rows.append((time, grains, water))
    if show_layers:
        print("\nvolume per unit area in 0.01 m layers from the bed (grains / water):")
        for time, grains, water in layer_rows:
            print(f"t = {time:.3f} s  grains " + " ".join(f"{v:.3f}" for v in grains[:7]))
            print("             water  " + " ".join(f"{v:.3f}" for v in water[:7]))


if __name__ == "__main__":
    main()
