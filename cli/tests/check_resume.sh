#!/usr/bin/env bash
# Checkpoint and resume from end to end (issue 9, item 1), on a coarse Case B (a slide into
# water, two stages, grid output; about 3 s of solve on one core):
#   1. an uninterrupted run;
#   2. the same case killed with SIGKILL within its second stage, after a timed checkpoint,
#      then `solve --resume`: every VTU and PVD file must be byte for byte those of run 1;
#   3. `solve --from-stage release` on run 1's folder re-runs the release from the end of the
#      gravity stage: the same bytes again;
#   4. refusals, each with exit code 1 and a message that says why: case files edited since
#      the checkpoint, a damaged checkpoint, no checkpoint, a first or unknown stage.
# Usage: check_resume.sh LITUYA SOURCE_DIR WORK_DIR
set -u
lituya=$1
source_dir=$2
work=$3
export OMP_NUM_THREADS=1

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# expect CODE PATTERN COMMAND...: the command's exit code is CODE and its stderr matches
# PATTERN (grep -E; empty: anything).
expect() {
  local code=$1 pattern=$2
  shift 2
  "$@" >"$work/out.txt" 2>"$work/err.txt"
  local got=$?
  [[ $got == "$code" ]] || fail "$* gave exit code $got, expected $code; stderr: $(cat "$work/err.txt")"
  if [[ -n $pattern ]] && ! grep -Eq -- "$pattern" "$work/err.txt"; then
    fail "$*: stderr does not match '$pattern': $(cat "$work/err.txt")"
  fi
}

# same_output A B: the same VTU and PVD files, stage histories and probe tables, byte for
# byte (a resumed run's tables hold no row twice and lose none).
same_output() {
  local a=$1 b=$2 n=0
  local files="./*.vtu ./*.pvd ./*_history.csv ./probes/*.csv"
  diff <(cd "$a" && ls $files) <(cd "$b" && ls $files) >/dev/null ||
    fail "$a and $b hold different VTU/PVD/CSV files"
  for f in $(cd "$a" && ls $files); do
    cmp -s "$a/$f" "$b/$f" || fail "$f differs between $a and $b"
    n=$((n + 1))
  done
  echo "same bytes: $n VTU, PVD and CSV files of $b"
}

rm -rf "$work"
mkdir -p "$work"
# The quick Case B, coarser (0.05 m cells), shorter, with grid output (which feeds the next
# step's drag, so the checkpoint must hold what it changed) and a checkpoint every 0.03 s of
# wall time.
sed -e "s|geometry = \"../../examples/case_b_2d/case_b.geo\"|geometry = \"$source_dir/examples/case_b_2d/case_b.geo\"|" \
  -e 's|^cell_size = 0.03 |cell_size = 0.05 |' \
  -e 's|^duration = 0.2 |duration = 0.05 |' \
  -e 's|^output_interval = 0.1$|output_interval = 0.02|' \
  -e 's|^duration = 1.2 |duration = 0.4 |' \
  -e 's|^grid = false|grid = true|' \
  -e 's|^\[output\]|[solver]\ncheckpoint_interval_minutes = 0.0005\n\n[output]|' \
  -e '/^\[post\]/,$d' \
  "$source_dir/verification/case_b/scene_quick.toml" >"$work/scene.toml"
# Probes, one on each point set, sampling between outputs too.
cat >>"$work/scene.toml" <<'EOF2'

[[probe]]
name = "grain"
solid_point = 0
interval = 0.004

[[probe]]
name = "drop"
liquid_point = 0
interval = 0.004
EOF2
grep -q 'checkpoint_interval_minutes = 0.0005' "$work/scene.toml" || fail "scene not edited"
grep -q 'geometry = "/' "$work/scene.toml" || fail "geometry not made absolute"

expect 0 "" "$lituya" pre "$work/scene.toml" -o "$work/whole" --quiet
cp -r "$work/whole" "$work/killed"
cp -r "$work/whole" "$work/stopped"

# 1. Uninterrupted.
expect 0 "" "$lituya" solve "$work/whole" --threads 1
[[ -f $work/whole/output/checkpoints/gravity_end.checkpoint ]] || fail "no end-of-stage checkpoint"
[[ -f $work/whole/output/checkpoints/release_end.checkpoint ]] || fail "no end-of-stage checkpoint"
[[ ! -e $work/whole/output/checkpoints/latest.checkpoint ]] ||
  fail "the within-stage checkpoint outlived its stage"

# 2. Killed within the release, after a checkpoint there, then resumed.
"$lituya" solve "$work/killed" --threads 1 >/dev/null 2>&1 &
pid=$!
checkpoints=$work/killed/output/checkpoints
for _ in $(seq 1 3000); do
  [[ -f $checkpoints/gravity_end.checkpoint && -f $checkpoints/latest.checkpoint ]] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.01
done
kill -KILL "$pid" 2>/dev/null || fail "the run ended before it could be killed within the release"
wait "$pid" 2>/dev/null
grep -Eq "state = ['\"]running" "$work/killed/output/summary.toml" || fail "the killed run's summary"
[[ -f $checkpoints/latest.checkpoint ]] || fail "no within-stage checkpoint when killed"
expect 0 "Going on from checkpoint .*latest.checkpoint \(every 0.0005 minutes, step [0-9]+, stage 'release' at t = " \
  "$lituya" solve "$work/killed" --resume --threads 1
grep -Eq "state = ['\"]completed" "$work/killed/output/summary.toml" || fail "resumed summary"
grep -Eq "resumed_from = ['\"]checkpoints/latest.checkpoint" "$work/killed/output/summary.toml" ||
  fail "the summary does not say where the run resumed from"
grep -Eq "name = ['\"]gravity" "$work/killed/output/summary.toml" ||
  fail "the resumed summary lost the report of the gravity stage"
grep -q ", resumed .* from checkpoints/latest.checkpoint" "$work/killed/output/log.txt" ||
  fail "log.txt does not record the resumption"
same_output "$work/whole/output" "$work/killed/output"
[[ -f $work/whole/output/probes/grain.csv && -f $work/whole/output/release_history.csv ]] ||
  fail "no probe table or stage history"

# Stopped by SIGINT within the release (exit code 130: the state at the stop is written as
# the last frame, after a checkpoint of it), then resumed: the same bytes as run 1 too (the
# resumed run writes its next frame over the stop's, under the same number).
"$lituya" solve "$work/stopped" --threads 1 >/dev/null 2>"$work/stopped.err" &
pid=$!
for _ in $(seq 1 3000); do
  [[ -f $work/stopped/output/release_points_0003.vtu ]] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.01
done
kill -INT "$pid" 2>/dev/null || fail "the run ended before it could be stopped within the release"
wait "$pid"
code=$?
[[ $code == 130 ]] || fail "SIGINT gave exit code $code: $(cat "$work/stopped.err")"
grep -q "stopped by SIGINT in stage 'release'" "$work/stopped.err" || fail "$(cat "$work/stopped.err")"
grep -aq "stopped by SIGINT" "$work/stopped/output/checkpoints/latest.checkpoint" ||
  fail "no checkpoint of the stopped state"
expect 0 "Going on from checkpoint .*latest.checkpoint \(stopped by SIGINT, step [0-9]+, stage 'release'" \
  "$lituya" solve "$work/stopped" --resume --threads 1
same_output "$work/whole/output" "$work/stopped/output"

# A completed run resumed: nothing left to run, still completed.
expect 0 "nothing left to run" "$lituya" solve "$work/killed" --resume --threads 1
same_output "$work/whole/output" "$work/killed/output"

# 3. The release again from the end of the gravity stage.
cp -r "$work/whole/output" "$work/whole_output"
expect 0 "Going on from checkpoint .*gravity_end.checkpoint \(end of stage 'gravity'" \
  "$lituya" solve "$work/whole" --from-stage release --threads 1
same_output "$work/whole_output" "$work/whole/output"

# 4. Refusals.
expect 1 "--force, --resume and --from-stage exclude each other" \
  "$lituya" solve "$work/whole" --resume --force
expect 1 "is the first stage" "$lituya" solve "$work/whole" --from-stage gravity
expect 1 "no stage of that name \(stages: 'gravity', 'release'\)" \
  "$lituya" solve "$work/whole" --from-stage slide
cp "$work/killed/materials.toml" "$work/materials.toml"
echo "# edited" >>"$work/killed/materials.toml"
expect 1 "release_end.checkpoint: the case files changed since the checkpoint was written" \
  "$lituya" solve "$work/killed" --resume
# materials.toml is an input of the gravity stage too.
expect 1 "gravity_end.checkpoint: the case files changed since the checkpoint was written" \
  "$lituya" solve "$work/killed" --from-stage release
cp "$work/materials.toml" "$work/killed/materials.toml"
printf 'X' | dd of="$checkpoints/release_end.checkpoint" bs=1 count=1 conv=notrunc 2>/dev/null
expect 1 "release_end.checkpoint: not a Lituya checkpoint" "$lituya" solve "$work/killed" --resume
rm -rf "$checkpoints"
expect 1 "no checkpoint to resume from" "$lituya" solve "$work/killed" --resume
expect 1 "gravity_end.checkpoint: not found: --from-stage release starts from the end of stage 'gravity'" \
  "$lituya" solve "$work/killed" --from-stage release
echo "PASS"
