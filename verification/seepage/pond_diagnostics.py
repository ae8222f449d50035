#!/usr/bin/python3
"""Seepage column: how still the pond is and whether its points agree with its volume.

Reads a run's liquid VTU files (CASE/output/seepage_liquid_NNNN.vtu, outputs every 0.05 s)
and prints one Markdown row, the columns of the README's ninth-session table:
  - flux / Ergun from the pond's water volume (the verification case's own measure),
  - pond depth at 1 s (its volume over the width),
  - flux / Ergun from the water that reached the chamber below the plate,
  - the pond surface above the sand, from the points (mean of the 20 highest),
  - water volume over the space it spans, 1 to 5 cm above the sand,
  - RMS horizontal speed of the pond's points at 1 s.
The Ergun flux over 0.3-1.0 s is the case's reference (runner/src/seepage.cpp).

Usage: /usr/bin/python3 pond_diagnostics.py LABEL CASE/output
Needs Debian's python3-vtk9 and python3-numpy (the system Python, not a virtual one).
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

SAND_TOP, WIDTH = 0.5, 0.1  # m (seepage.geo)
# m/s, 0.3-1.0 s: the reference with the column's storage (seepage_column.cpp, since stop 35;
# the steady reading's (0.09627188827023193 - 0.08768603813547902) / 0.7 is 0.08 % more).
ERGUN_FLUX = (0.09669646836943 - 0.08811787213928) / 0.7


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    y = vtk_to_numpy(grid.GetPoints().GetData())[:, 1]
    return y, vtk_to_numpy(data.GetArray("volume")), vtk_to_numpy(data.GetArray("velocity"))


def main(label, output):
    frames = {i: read(f"{output}/seepage_liquid_{i:04d}.vtu") for i in (6, 20)}  # 0.3 s, 1 s
    pond = {i: v[y > SAND_TOP].sum() / WIDTH for i, (y, v, _) in frames.items()}
    chamber = {i: v[y < 0.2].sum() / WIDTH for i, (y, v, _) in frames.items()}
    y, volume, velocity = frames[20]
    in_pond = (y >= SAND_TOP) & (y < SAND_TOP + 0.1)
    band = (y >= SAND_TOP + 0.01) & (y < SAND_TOP + 0.05)
    surface = np.sort(y)[-20:].mean() - SAND_TOP
    print(f"| {label} | {(pond[6] - pond[20]) / 0.7 / ERGUN_FLUX:.3f} | {pond[20]:.4f} m "
          f"| {(chamber[20] - chamber[6]) / 0.7 / ERGUN_FLUX:.3f} | {surface:.4f} m "
          f"| {volume[band].sum() / (WIDTH * 0.04):.2f} "
          f"| {np.sqrt((velocity[in_pond, 0] ** 2).mean()):.3f} m/s |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
