#!/usr/bin/python3
"""How much of the water's pressure lies in a crossed mesh's force-free pressure mode.

A quadrangle cut into four triangles at its diagonals' crossing (`[mesh] crossed = true`)
has one dependent volume constraint: a vector lam with sum_k lam_k B_k = 0, B_k the row of
the integrated divergence over triangle k (int_Tk div u = B_k . u). A cell-wise pressure
p_k = a lam_k then gives no nodal force (the force is sum_k p_k B_k). Were the water's
points to store pressure in that pattern and release it as they cross cells, it could make
the jets that crossed meshes throw at the slope's toe (README.md, "Crossed meshes").

This script finds every such vertex of a case's mesh (a node of four triangles whose
divergence rows are rank-deficient), reads the liquid output at every tenth frame, sums each
triangle's point pressure weighted by volume (P_k), splits each quadrangle's P into its
area-weighted mean, the mode (a lam) and the rest, and prints, per kind of quadrangle (free
water: all four triangles filled above 0.8 by water volume; pores: all below 0.6; mixed),
the mode's share of the pressure's deviation from the quadrangle mean (an A-weighted norm).
Were the deviations random among the three non-mean patterns, that share would be about a
third; well below it, the mode is not being fed.

    /usr/bin/python3 crossed_pressure_mode.py CASE_FOLDER [STAGE] [EVERY]

CASE_FOLDER is what `lituya run` or `lituya pre` wrote (geometry.vtu, output/); the liquid
output needs `pressure` and `volume` in `[output] liquid_fields`. Needs Debian's python3-vtk9
and python3-numpy (the system Python, not a virtual one).
"""
import glob
import re
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def triangles(mesh):
    """The mesh's triangles (VTK type 5) as node triples, and for every VTK cell of the mesh
    its triangle's index (-1 for the boundary lines geometry.vtu also holds)."""
    ids = [c for c in range(mesh.GetNumberOfCells()) if mesh.GetCellType(c) == 5]
    index = -np.ones(mesh.GetNumberOfCells() + 1, dtype=int)  # the last entry: not found
    index[ids] = np.arange(len(ids))
    return np.array([[mesh.GetCell(c).GetPointId(i) for i in range(3)] for c in ids]), index


def divergence_row(corners):
    """Row of int_T div u over one triangle, in its corners' dofs (x0, y0, x1, ...), and T's area."""
    row = np.zeros(6)
    twice_area = np.cross(corners[1] - corners[0], corners[2] - corners[0])
    for i in range(3):
        j, k = (i + 1) % 3, (i + 2) % 3
        # A grad N_i = (y_j - y_k, x_k - x_j) / 2 for counter-clockwise corners.
        g = 0.5 * np.array([corners[j][1] - corners[k][1], corners[k][0] - corners[j][0]])
        row[2 * i:2 * i + 2] = g if twice_area > 0 else -g
    return row, abs(twice_area) / 2


def crossed_quadrangles(xy, cells):
    """(triangles, lam, areas) for every node whose four triangles have a dependent row."""
    around = {}
    for c, tri in enumerate(cells):
        for n in tri:
            around.setdefault(n, []).append(c)
    found = []
    for centre, ring in around.items():
        if len(ring) != 4:
            continue
        nodes = sorted(set(cells[ring].ravel()))
        if len(nodes) != 5:
            continue
        index = {n: i for i, n in enumerate(nodes)}
        rows, areas = np.zeros((4, 10)), np.zeros(4)
        for k, c in enumerate(ring):
            local, areas[k] = divergence_row(xy[cells[c]])
            for i, n in enumerate(cells[c]):
                rows[k, 2 * index[n]:2 * index[n] + 2] = local[2 * i:2 * i + 2]
        u, s, _ = np.linalg.svd(rows)
        if s[-1] > 1e-9 * s[0]:
            continue
        lam = u[:, -1] / np.max(np.abs(u[:, -1]))
        found.append((np.array(ring), lam, areas))
    return found


def main():
    case = sys.argv[1]
    stage = sys.argv[2] if len(sys.argv) > 2 else "release"
    every = int(sys.argv[3]) if len(sys.argv) > 3 else 10
    mesh = read_vtu(f"{case}/geometry.vtu")
    xy = vtk_to_numpy(mesh.GetPoints().GetData())[:, :2]
    cells, triangle_of_cell = triangles(mesh)
    quads = crossed_quadrangles(xy, cells)
    print(f"{len(quads)} crossed quadrangles ({4 * len(quads)} of {len(cells)} triangles)")
    locator = vtk.vtkCellLocator()
    locator.SetDataSet(mesh)
    locator.BuildLocator()
    frames = sorted(glob.glob(f"{case}/output/{stage}_liquid_*.vtu"),
                    key=lambda f: int(re.findall(r"_(\d+)\.vtu$", f)[0]))
    print("frame | kind: quadrangles, mode share of the deviation from the quadrangle mean")
    for path in frames[::every]:
        liquid = read_vtu(path)
        x = vtk_to_numpy(liquid.GetPoints().GetData())
        p = vtk_to_numpy(liquid.GetPointData().GetArray("pressure"))
        v = vtk_to_numpy(liquid.GetPointData().GetArray("volume"))
        cell = triangle_of_cell[[locator.FindCell(x[q]) for q in range(len(x))]]
        inside = cell >= 0
        pv = np.bincount(cell[inside], weights=(p * v)[inside], minlength=len(cells))
        volume = np.bincount(cell[inside], weights=v[inside], minlength=len(cells))
        pressure = pv / np.maximum(volume, 1e-300)
        sums = {}
        for ring, lam, areas in quads:
            fill = volume[ring] / areas
            if np.any(fill < 0.05):
                continue
            kind = "free" if np.all(fill > 0.8) else "pores" if np.all(fill < 0.6) else "mixed"
            pk = pressure[ring]
            mean = np.sum(areas * pk) / np.sum(areas)
            amplitude = np.sum(areas * lam * pk) / np.sum(areas * lam * lam)
            s = sums.setdefault(kind, [0, 0.0, 0.0])
            s[0] += 1
            s[1] += amplitude**2 * np.sum(areas * lam * lam)
            s[2] += np.sum(areas * (pk - mean) ** 2)
        frame = re.findall(r"_(\d+)\.vtu$", path)[0]
        print(frame, " | ".join(f"{k}: {s[0]}, {s[1] / max(s[2], 1e-300):.3f}"
                                for k, s in sorted(sums.items())))


if __name__ == "__main__":
    main()
