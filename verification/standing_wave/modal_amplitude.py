#!/usr/bin/env python3
"""The standing wave's modal amplitude, period and decay from a case folder's liquid output.

A(t) = (2 / L) sum_q V_q cos(k x_q), k = pi / L: the cosine moment of the water's volume. Over a
flat bed between walls at 0 and L, sum_q V_q cos(k x_q) approximates the integral of cos(k x) over
the water, int_0^L cos(k x) (h + eta(x)) dx = int_0^L cos(k x) eta dx (the still depth drops
out), that is L / 2 times the amplitude of the mode cos(k x) in the surface eta. No surface has
to be read off the points. The runner (verification/runner/src/standing_wave.cpp) computes the
same; this script serves studies over cases run by `lituya run` or `lituya sweep`.

usage: modal_amplitude.py [--length L] CASE_FOLDER [CASE_FOLDER ...]   (prints the amplitude at
the release, the period against linear theory, the height lost per period, the largest fall of
the water's volume centroid sum V y / sum V and the extremes;
--length: the tank's length, 0.5 m unless given, for copies of tank.geo with another L)
"""
import glob
import math
import os
import re
import sys

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk

L, H, G = 0.5, 0.15, 9.81


def liquid_frames(case):
    """(time, file) of each liquid output of the release stage."""
    pvd = os.path.join(case, "output", "release_liquid.pvd")
    for m in re.finditer(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(pvd).read()):
        yield float(m.group(1)), os.path.join(case, "output", m.group(2))


def record(case, length=None):
    """Times, modal amplitudes and volume-centroid heights of a case's liquid outputs."""
    length = L if length is None else length
    reader = vtk.vtkXMLUnstructuredGridReader()
    times, amplitude, centroid = [], [], []
    for t, f in liquid_frames(case):
        reader.SetFileName(f)
        reader.Update()
        grid = reader.GetOutput()
        x = vtk_to_numpy(grid.GetPoints().GetData())[:, 0]
        v = vtk_to_numpy(grid.GetPointData().GetArray("volume"))
        times.append(t)
        amplitude.append(2 / length * np.sum(v * np.cos(math.pi / length * x)))
        y = vtk_to_numpy(grid.GetPoints().GetData())[:, 1]
        centroid.append(np.sum(v * y) / np.sum(v))
    return np.array(times), np.array(amplitude), np.array(centroid)


def analyse(t, a):
    # zero crossings (linear interpolation) -> period from the first to the last
    crossings = [t[i] - a[i] * (t[i + 1] - t[i]) / (a[i + 1] - a[i])
                 for i in range(len(a) - 1) if a[i] * a[i + 1] < 0]
    period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    # extremes of |a| between crossings, refined by a parabola through the sample and neighbours
    extremes = []
    edges = [0] + [i + 1 for i in range(len(a) - 1) if a[i] * a[i + 1] < 0] + [len(a)]
    for s, e in zip(edges[:-1], edges[1:]):
        j = s + int(np.argmax(np.abs(a[s:e])))
        if j == 0:
            extremes.append((t[0], abs(a[0])))
            continue
        if j + 1 >= len(a) or j == e - 1:
            continue  # the half cycle runs past the record
        y0, y1, y2 = abs(a[j - 1]), abs(a[j]), abs(a[j + 1])
        d = y0 - 2 * y1 + y2
        shift = 0.5 * (y0 - y2) / d if d != 0 else 0
        extremes.append((t[j] + shift * (t[1] - t[0]), y1 - 0.25 * (y0 - y2) * shift))
    te = np.array([e[0] for e in extremes])
    ae = np.array([e[1] for e in extremes])
    slope = np.polyfit(te, np.log(ae), 1)[0]  # 1/s
    decay_per_period = 1 - math.exp(slope * period)
    return period, decay_per_period, te, ae


def main():
    global L
    args = sys.argv[1:]
    if args and args[0] == "--length":
        L = float(args[1])
        args = args[2:]
    k = math.pi / L
    T_LINEAR = 2 * math.pi / math.sqrt(G * k * math.tanh(k * H))
    for case in args:
        t, a, c = record(case)
        period, decay, te, ae = analyse(t, a)
        fall = 1000 * np.max(c[0] - c)
        print(f"{case}: A0 {a[0]*1000:.3f} mm, period {period:.4f} s = {period / T_LINEAR:.4f} T_linear "
              f"({T_LINEAR:.4f} s), decay per period {100 * decay:.2f} %, "
              f"largest fall of the volume centroid {fall:.2f} mm, extremes "
              + " ".join(f"{x*1000:.2f}" for x in ae))


if __name__ == "__main__":
    main()
