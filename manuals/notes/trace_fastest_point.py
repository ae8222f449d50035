#!/usr/bin/env python3
"""Trace the fastest solid point of a stage back through its outputs (thin-front-rebound.md).

    python3 trace_fastest_point.py CASE_FOLDER [--stage release] [--before 0.01] [--after 0.003]

CASE_FOLDER is a solved case (the folder with points.vtu and output/). The stage's history
(output/<stage>_history.csv) gives the time of the largest `max_speed_solid`; the point output
nearest that time gives the point (by id). For every output from `before` seconds earlier to
`after` seconds later, one line: the point's position, the velocity it carries (FLIP), the
speed it moves with (its displacement since the previous output over the interval), its volume
over its starting volume, its stress, and its three nearest points with theirs. Write the
outputs often (a stage's output_interval of 0.5-1 ms) or the lines say little.

The point fields needed: velocity, stress, volume (and the point ids, always written).
Needs Python's vtk (Debian: python3-vtk9).
"""
import argparse
import csv
import re
from pathlib import Path

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_points(file):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(file))
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    fields = {data.GetArrayName(k): vtk_to_numpy(data.GetArray(k))
              for k in range(data.GetNumberOfArrays())}
    fields["x"] = vtk_to_numpy(grid.GetPoints().GetData())
    ids = fields.get("id", np.arange(len(fields["x"])))
    order = np.argsort(ids)  # rows by point id
    return {name: values[order] for name, values in fields.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case")
    parser.add_argument("--stage", default="release")
    parser.add_argument("--before", type=float, default=0.01)
    parser.add_argument("--after", type=float, default=0.003)
    args = parser.parse_args()
    case = Path(args.case)
    output = case / "output"

    with open(output / f"{args.stage}_history.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["max_speed_solid"]]
    peak = max(rows, key=lambda r: float(r["max_speed_solid"]))
    t_peak = float(peak["stage_time"])
    print(f"largest carried speed {float(peak['max_speed_solid']):.3f} m/s at stage time {t_peak:.4f} s")

    pvd = (output / f"{args.stage}_points.pvd").read_text()
    frames = [(float(t), output / f) for t, f in
              re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)]
    start_volume = read_points(case / "points.vtu")["volume"]
    nearest = min(range(len(frames)), key=lambda k: abs(frames[k][0] - t_peak))
    at_peak = read_points(frames[nearest][1])
    point = int(np.argmax(np.linalg.norm(at_peak["velocity"], axis=1)))
    print(f"point {point} (fastest in the output at {frames[nearest][0]:.4f} s)")

    previous = None
    for t, file in frames:
        if t < t_peak - args.before or t > t_peak + args.after:
            continue
        p = read_points(file)
        x = p["x"]
        moving = (np.linalg.norm(x[point] - previous[1][point]) / (t - previous[0])
                  if previous else float("nan"))
        previous = (t, x)
        distance = np.linalg.norm(x - x[point], axis=1)
        near = [n for n in np.argsort(distance)[:4] if n != point][:3]

        def describe(n):
            v = p["velocity"][n]
            return (f"v=({v[0]:.2f},{v[1]:.2f}) V/V0={p['volume'][n] / start_volume[n]:.2f} "
                    f"s_yy={p['stress'][n][1] / 1e3:.1f} kPa")

        print(f"{t:.4f} x=({x[point][0]:.4f},{x[point][1]:.4f}) {describe(point)} "
              f"moves at {moving:.2f} m/s | near: " +
              "  ".join(f"[{n} d={distance[n]:.3f} {describe(n)}]" for n in near))


if __name__ == "__main__":
    main()
