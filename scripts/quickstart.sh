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
echo "                               runout.png, profiles.png, snapshots/)"
echo
echo "Pictures to open first:"
# A snapshot after the release (the second profile time of [post], else the first).
snapshot() {
  find "$out/post/snapshots" -maxdepth 1 -name "t*_$1.png" 2>/dev/null | sort | head -n 2 | tail -n 1
}
for picture in "$out/post/gauges.png" "$(snapshot material)" "$(snapshot speed)" \
               "$out/post/leading_wave.png" "$out/post/runout.png"; do
  if [ -n "$picture" ] && [ -f "$picture" ]; then echo "  $picture"; fi
done
if [ -f "$out/post/errors.csv" ]; then
  echo "Errors against the reference data (RMS, peak, arrival time): $out/post/errors.csv"
fi
echo "All snapshots (points by material and by speed at each profile time): $out/post/snapshots/"
