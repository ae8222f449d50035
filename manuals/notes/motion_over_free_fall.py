#!/usr/bin/env python3
"""Per time window, the solid point that moves fastest for its height (thin-front-rebound.md, 11).

    python3 motion_over_free_fall.py CASE_FOLDER [--stage release] [--window 0.05]

For every pair of consecutive point outputs of the stage, each point's motion speed is its
displacement over the interval (not the velocity it carries); it is divided by the free-fall
speed sqrt(2 g (y_top - y)) from the top of the solid at the stage's first output (at least
0.01 m of fall, so points at the top do not divide by zero). One line per window: the worst
ratio, its time, the point (row in id order), its motion speed, its height, its carried speed
and the largest carried speed of that output. Write the outputs often (0.5-1 ms).
Needs Python's vtk (Debian: python3-vtk9).
"""
import argparse
import re
from pathlib import Path

import numpy as np

from trace_fastest_point import read_points

GRAVITY = 9.81


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case_folder", type=Path)
    parser.add_argument("--stage", default="release")
    parser.add_argument("--window", type=float, default=0.05)
    args = parser.parse_args()
    output = args.case_folder / "output"
    series = (output / f"{args.stage}_points.pvd").read_text()
    entries = [(float(t), f) for t, f in
               re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', series)]
    top = read_points(output / entries[0][1])["x"][:, 1].max()
    worst = {}
    previous = None
    for time, file in entries:
        points = read_points(output / file)
        x, carried = points["x"], np.linalg.norm(points["velocity"], axis=1)
        if previous is not None:
            motion = np.linalg.norm(x - previous[1], axis=1) / (time - previous[0])
            free_fall = np.sqrt(2 * GRAVITY * np.maximum(top - x[:, 1], 0.01))
            ratio = motion / free_fall
            p = int(np.argmax(ratio))
            window = int(time / args.window)
            if ratio[p] > worst.get(window, (0,))[0]:
                worst[window] = (ratio[p], time, p, motion[p], x[p, 1], carried[p], carried.max())
        previous = (time, x)
    print("window (s): worst motion / free fall, time, point, motion (m/s), y (m), "
          "its carried speed, largest carried speed")
    for window in sorted(worst):
        r, t, p, v, y, c, cmax = worst[window]
        print(f"{window * args.window:.2f}-{(window + 1) * args.window:.2f}: {r:.2f} "
              f"t={t:.4f} point {p} {v:.2f} m/s y={y:.3f} carried {c:.2f} max carried {cmax:.2f}")


if __name__ == "__main__":
    main()
