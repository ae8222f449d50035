#!/usr/bin/env bash
# Quick start, step 1: install what is missing, build, and run the main example (Case B of
# the reference paper, 2D: a slide raising a wave) from its gmsh geometry to plots.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
out=cases/case_b_2d
if [ -e "$out" ]; then
  echo "quickstart: $out exists from an earlier run; re-running with --force"
  force=--force
else
  force=
fi
./build/cli/lituya run examples/case_b_2d/scene.toml -o "$out" $force
echo
echo "VTU series (open in ParaView): $out/output/release_points.pvd (the slide),"
echo "                               $out/output/release_liquid.pvd (the water), release_grid.pvd"
echo "Plots and CSV:                 $out/post/ (gauges.png, leading_wave.png, surface_profiles.png,"
echo "                               runout.png, profiles.png)"
