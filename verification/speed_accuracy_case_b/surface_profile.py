#!/usr/bin/env python3
"""Highest liquid point in 2 cm bins along the tank, in mm above the still water (0.15 m),
at chosen release outputs of a Case B run: the shape of the wave between X1 and X2, spray
included (a gauge reads a surface estimate, user manual 6.1, not this maximum). Then, per
frame, the 15 highest liquid points between x = 0.4 and 0.8 m: where they are and their
horizontal velocity u, to set beside the crest's own speed (kinematic breaking: u reaches
the crest's speed). The runs must write the `velocity` point field.

Usage: surface_profile.py CASE/output FRAME [FRAME ...]   (frames: release_liquid_NNNN.vtu;
outputs every 0.01 s, so frame 68 is t = 0.68 s). Needs python3-vtk9 and python3-numpy.
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

STILL_WATER = 0.15
BINS = np.arange(0.44, 0.76, 0.02)


def liquid_points(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    velocity = grid.GetPointData().GetArray("velocity")
    return (vtk_to_numpy(grid.GetPoints().GetData()),
            vtk_to_numpy(velocity) if velocity is not None else None)


def main():
    output, frames = sys.argv[1], [int(f) for f in sys.argv[2:]]
    print("x (m)", " ".join(f"{b + 0.01:5.2f}" for b in BINS))
    crests = []
    for frame in frames:
        x, v = liquid_points(f"{output}/release_liquid_{frame:04d}.vtu")
        top = []
        for left in BINS:
            inside = (x[:, 0] >= left) & (x[:, 0] < left + 0.02)
            top.append(1000 * (x[inside, 1].max() - STILL_WATER) if inside.any() else float("nan"))
        print(f"{frame / 100:5.2f}", " ".join(f"{t:5.0f}" for t in top))
        near = np.flatnonzero((x[:, 0] > 0.4) & (x[:, 0] < 0.8))
        highest = near[np.argsort(-x[near, 1])[:15]]
        crests.append((frame, x[highest], v[highest] if v is not None else None))
    print("crest: the 15 highest liquid points between x = 0.4 and 0.8 m")
    for frame, xs, vs in crests:
        line = (f"{frame / 100:5.2f} s: x {xs[:, 0].min():.3f}-{xs[:, 0].max():.3f} m (mean "
                f"{xs[:, 0].mean():.3f}), {1000 * (xs[:, 1].min() - STILL_WATER):.0f}-"
                f"{1000 * (xs[:, 1].max() - STILL_WATER):.0f} mm")
        if vs is not None:
            line += f", u {vs[:, 0].min():.2f}-{vs[:, 0].max():.2f} m/s"
        print(line)


if __name__ == "__main__":
    main()
