#!/usr/bin/env python3
"""Where the standing wave's energy goes: the water's mechanical energy and its kinetic energy
split into the part the grid carries and the part it cannot see, at the mode's extremes.

For each output at an extreme of the mode (where the mode's own kinetic energy is nil), per metre
of width, with each point's mass taken as rho_w V_q (the water's compression changes it by
p / K_w ~ 1e-4):
  - E - E0: kinetic plus potential energy, sum m (|v|^2 / 2 + g y), against the release's;
    a scheme without dissipation keeps it;
  - mode: the mode's energy rho_w g A^2 L / 4 (A the modal amplitude of modal_amplitude.py);
  - KE: the points' kinetic energy, split as the solver's transfer splits it: "grid", the
    energy of the field sum_I N_I v_I interpolated back to the points from the nodal velocities
    v_I = sum_q N_I m_q v_q / sum_q N_I m_q (the mesh of CASE/geometry.vtu, linear cells),
    and "unseen", that of v_q minus it (the two need not add up to KE): the FLIP null space, velocity the grid does not see
    and the PIC share of the transfer dissipates.

usage: wave_energy.py [--length L] CASE_FOLDER [CASE_FOLDER ...]
  --length: the tank's length (0.5 m unless given).
"""
import os
import sys

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk

from modal_amplitude import liquid_frames, record

RHO, G = 1000.0, 9.81


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    v = vtk_to_numpy(grid.GetPointData().GetArray("velocity"))[:, :2]
    volume = vtk_to_numpy(grid.GetPointData().GetArray("volume"))
    return x, v, volume


def mesh_of(case):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(case, "geometry.vtu"))
    reader.Update()
    mesh = reader.GetOutput()
    locator = vtk.vtkCellLocator()
    locator.SetDataSet(mesh)
    locator.BuildLocator()
    return mesh, locator


def shape_values(mesh, locator, x):
    """Node ids and linear shape values of each point's cell (triangles)."""
    ids = np.zeros((len(x), 3), dtype=np.int64)
    values = np.zeros((len(x), 3))
    cell, pcoords, weights = vtk.vtkGenericCell(), [0.0] * 3, [0.0] * 8
    for q, point in enumerate(x):
        c = locator.FindCell([point[0], point[1], 0.0], 1e-9, cell, pcoords, weights)
        nodes = mesh.GetCell(c).GetPointIds()
        for k in range(3):
            ids[q, k], values[q, k] = nodes.GetId(k), weights[k]
    return ids, values


def energies(x, v, volume, mesh, locator):
    m = RHO * volume
    kinetic = 0.5 * np.sum(m * np.sum(v * v, axis=1))
    potential = np.sum(m * G * x[:, 1])
    ids, values = shape_values(mesh, locator, x)
    nodes = mesh.GetNumberOfPoints()
    mass, momentum = np.zeros(nodes), np.zeros((nodes, 2))
    for k in range(3):
        np.add.at(mass, ids[:, k], values[:, k] * m)
        np.add.at(momentum, ids[:, k], (values[:, k] * m)[:, None] * v)
    nodal = momentum / np.maximum(mass, 1e-30)[:, None]
    seen = sum(values[:, k][:, None] * nodal[ids[:, k]] for k in range(3))
    unseen = v - seen
    grid = 0.5 * np.sum(m * np.sum(seen * seen, axis=1))
    return kinetic, potential, grid, 0.5 * np.sum(m * np.sum(unseen * unseen, axis=1))


def main():
    args = sys.argv[1:]
    length = 0.5
    if args and args[0] == "--length":
        length = float(args[1])
        args = args[2:]
    if not args or args[0].startswith("--"):
        sys.exit(__doc__)
    for case in args:
        mesh, locator = mesh_of(case)
        # The mode's amplitude of every output first (modal_amplitude.py's record); the
        # energies only at its extremes.
        _, amplitude, _ = record(case, length)
        a = np.abs(amplitude)
        print(f"{case} (J/m)")
        print("  t (s)   E - E0    mode     KE       grid      unseen")
        e0 = None
        for i, (t, f) in enumerate(liquid_frames(case)):
            if not (i == 0 or (0 < i < len(a) - 1 and a[i] >= a[i - 1] and a[i] >= a[i + 1])):
                continue
            kinetic, potential, grid, unseen = energies(*read(f), mesh, locator)
            if e0 is None:
                e0 = kinetic + potential
            mode = RHO * G * amplitude[i]**2 * length / 4
            print(f"  {t:5.2f}  {kinetic + potential - e0:8.5f} {mode:8.5f} {kinetic:8.5f} "
                  f"{grid:8.5f}  {unseen:8.5f}")


if __name__ == "__main__":
    main()
