#!/usr/bin/env bash
# Quick start, step 1: install what is missing, build, and run the main example (Case A of
# the reference paper, 2D) from its gmsh geometry to plots.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
out=cases/case_a_2d
if [ -e "$out" ]; then
  echo "quickstart: $out exists from an earlier run; re-running with --force"
  force=--force
else
  force=
fi
./build/cli/lituya run examples/case_a_2d/scene.toml -o "$out" $force
echo
echo "VTU series (open in ParaView): $out/output/release_points.pvd and $out/output/release_grid.pvd"
echo "Plots and CSV:                 $out/post/ (runout.png, wall_height.png, profiles.png)"
