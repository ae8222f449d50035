#!/usr/bin/env python3
"""The noise of a standing wave, read at its turning points (README.md, stops 55 and 56).

Every half period a standing wave's own velocity is zero everywhere, so what the liquid points
still move with then is noise. For each turning point k T / 2 (k = 1, 2, ...) this prints:

- `all`: the RMS speed of the liquid points (volume-weighted), mm/s;
- `grid`: the RMS of the part the grid sees, v_g(x_q) = sum_i N_i(x_q) v_i, where v_i is the
  volume-weighted nodal mean of the points' velocities (the water's density is even, so volume
  stands for mass), mm/s;
- `null`: the RMS of the rest, v_q - v_g(x_q): what the grid cannot see (FLIP keeps it), mm/s;
- `div`, `curl`: the area-weighted RMS divergence and curl of the nodal field over the wet
  cells, 1/s (a standing wave is irrotational: its curl is noise);
- `fill`: the 5th and 95th percentiles of the wet cells' point volume over their area.

Usage: turning_point_noise.py CASE [--period T] [--frames-per-second F]
CASE is the case folder (geometry.vtu, output/release_liquid_NNNN.vtu with `volume` and
`velocity` among the liquid fields); T the wave's period in s (0.584 s for the L = 0.25 m tank
at g = 9.81); F the outputs per second (100 for output_interval = 0.01).
"""
import argparse

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or grid.GetPoints() is None:
        raise SystemExit(f"turning_point_noise.py: cannot read {path}")
    return grid


def triangles(geometry):
    """The mesh's nodes (x, y) and its triangles (the boundary lines are left out)."""
    nodes = vtk_to_numpy(geometry.GetPoints().GetData())[:, :2]
    cells = geometry.GetCells()
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    tri = [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)
           if offsets[i + 1] - offsets[i] == 3]
    return nodes, np.array(tri, dtype=int)


class Mesh:
    def __init__(self, nodes, tri):
        self.nodes, self.tri = nodes, tri
        corner = nodes[tri]
        self.origin = corner[:, 0]
        edges = np.stack([corner[:, 1] - corner[:, 0], corner[:, 2] - corner[:, 0]], axis=2)
        self.inverse = np.linalg.inv(edges)
        self.area = 0.5 * np.abs(np.linalg.det(edges))
        # grad lambda_1, grad lambda_2 are the rows of the inverse; lambda_0 takes the rest.
        self.gradient = np.zeros((len(tri), 3, 2))
        self.gradient[:, 1] = self.inverse[:, 0]
        self.gradient[:, 2] = self.inverse[:, 1]
        self.gradient[:, 0] = -self.gradient[:, 1] - self.gradient[:, 2]

    def locate(self, points, block=256):
        """Each point's cell and barycentric coordinates (brute force over blocks of cells)."""
        cell = np.full(len(points), -1)
        shape = np.zeros((len(points), 3))
        for start in range(0, len(self.tri), block):
            stop = min(start + block, len(self.tri))
            d = points[:, None, :] - self.origin[None, start:stop]
            l12 = np.einsum("cij,pcj->pci", self.inverse[start:stop], d)
            l = np.concatenate([1 - l12.sum(2, keepdims=True), l12], axis=2)
            p, c = np.nonzero((l >= -1e-9).all(2))
            new = cell[p] < 0
            cell[p[new]] = c[new] + start
            shape[p[new]] = l[p[new], c[new]]
        if (cell < 0).any():
            raise SystemExit(f"turning_point_noise.py: {np.sum(cell < 0)} points outside the mesh")
        return cell, shape


def noise(mesh, position, velocity, volume):
    cell, shape = mesh.locate(position)
    corners = mesh.tri[cell]
    weight = np.zeros(len(mesh.nodes))
    momentum = np.zeros((len(mesh.nodes), 2))
    for a in range(3):
        np.add.at(weight, corners[:, a], shape[:, a] * volume)
        np.add.at(momentum, corners[:, a], (shape[:, a] * volume)[:, None] * velocity)
    nodal = np.where(weight[:, None] > 0, momentum / np.maximum(weight, 1e-300)[:, None], 0.0)
    seen = np.einsum("pa,paj->pj", shape, nodal[corners])

    def rms(v):
        return 1000 * np.sqrt((volume * (v ** 2).sum(1)).sum() / volume.sum())

    wet = np.unique(cell)
    v = nodal[mesh.tri[wet]]
    g = mesh.gradient[wet]
    area = mesh.area[wet]
    divergence = np.einsum("cij,cij->c", v, g)
    curl = np.einsum("ci,ci->c", v[:, :, 1], g[:, :, 0]) - np.einsum("ci,ci->c", v[:, :, 0], g[:, :, 1])
    fill = np.bincount(cell, weights=volume, minlength=len(mesh.tri))[wet] / area

    def field_rms(f):
        return np.sqrt((f ** 2 * area).sum() / area.sum())

    return (rms(velocity), rms(seen), rms(velocity - seen), field_rms(divergence), field_rms(curl),
            np.percentile(fill, 5), np.percentile(fill, 95))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case")
    parser.add_argument("--period", type=float, default=0.584)
    parser.add_argument("--frames-per-second", type=float, default=100.0)
    args = parser.parse_args()
    mesh = Mesh(*triangles(read(f"{args.case}/geometry.vtu")))
    print("t (s)   all  grid  null (mm/s)   div  curl (1/s)   fill p5 / p95")
    k = 1
    while True:
        frame = int(round(k * args.period / 2 * args.frames_per_second))
        path = f"{args.case}/output/release_liquid_{frame:04d}.vtu"
        try:
            with open(path, "rb"):
                pass
        except OSError:
            break
        points = read(path)
        data = points.GetPointData()
        position = vtk_to_numpy(points.GetPoints().GetData())[:, :2]
        velocity = vtk_to_numpy(data.GetArray("velocity"))[:, :2]
        volume = vtk_to_numpy(data.GetArray("volume"))
        a, s, n, d, c, f5, f95 = noise(mesh, position, velocity, volume)
        print(f"{frame / args.frames_per_second:5.2f} {a:6.1f} {s:5.1f} {n:5.1f}   {d:6.3f} {c:5.2f}"
              f"         {f5:.2f} / {f95:.2f}")
        k += 1


if __name__ == "__main__":
    main()
