#!/usr/bin/env python3
"""Highest liquid point in 2 cm bins along the tank, in mm above the still water (0.15 m),
at chosen release outputs of a Case B run: the shape of the wave between X1 and X2, spray
included (a gauge reads a surface estimate, user manual 6.1, not this maximum).

Usage: surface_profile.py CASE/output FRAME [FRAME ...]   (frames: release_liquid_NNNN.vtu;
outputs every 0.01 s, so frame 68 is t = 0.68 s). Needs python3-vtk9 and python3-numpy.
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

STILL_WATER = 0.15
BINS = np.arange(0.44, 0.76, 0.02)


def liquid_positions(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPoints().GetData())


def main():
    output, frames = sys.argv[1], [int(f) for f in sys.argv[2:]]
    print("x (m)", " ".join(f"{b + 0.01:5.2f}" for b in BINS))
    for frame in frames:
        x = liquid_positions(f"{output}/release_liquid_{frame:04d}.vtu")
        top = []
        for left in BINS:
            inside = (x[:, 0] >= left) & (x[:, 0] < left + 0.02)
            top.append(1000 * (x[inside, 1].max() - STILL_WATER) if inside.any() else float("nan"))
        print(f"{frame / 100:5.2f}", " ".join(f"{v:5.0f}" for v in top))


if __name__ == "__main__":
    main()
