#!/usr/bin/env bash
# Crash recovery of dem_run (docs/RELIABILITY.md): a run killed with
# SIGKILL mid-way and resumed from its newest checkpoint ends in the same
# state (its hash) with the same tables, byte for byte, as a run never
# interrupted.
#   dem_run_resume.sh DEM_RUN CASE WORK_DIR CHECKPOINT_CYCLES KILL_AFTER [VTK_INTERVAL]
# The run is killed once it has written a checkpoint at cycle KILL_AFTER or
# later. With VTK_INTERVAL both runs write ParaView files too, and those
# (vtk/ and the .pvd series) must be the same as well.
set -euo pipefail
dem_run=$1 case_file=$2 work=$3 every=$4 kill_after=$5 vtk_interval=${6:-}
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
vtk=()
[ -z "$vtk_interval" ] || vtk=(--vtk-interval "$vtk_interval")

"$dem_run" "$case_file" --out "$work/whole" --threads 1 "${vtk[@]}" >"$work/whole.log" 2>&1 ||
  fail "the whole run failed: $(cat "$work/whole.log")"

"$dem_run" "$case_file" --out "$work/killed" --threads 1 "${vtk[@]}" --checkpoint-cycles "$every" --checkpoint-keep 2 \
  >"$work/killed.log" 2>&1 &
pid=$!
# Kill it once a checkpoint at kill_after or later is written (the run goes on past it).
newest() { ls "$work/killed/checkpoints/" 2>/dev/null | sed -n 's/^checkpoint-0*\([0-9][0-9]*\)\.resume$/\1/p' | sort -n | tail -n 1; }
for _ in $(seq 1 1500); do
  [ "$(newest)" != "" ] && [ "$(newest)" -ge "$kill_after" ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.02
done
kill -9 "$pid" 2>/dev/null || fail "the run ended before it could be killed: lower the checkpoint interval"
wait "$pid" 2>/dev/null || true
ls "$work/killed/checkpoints"
# A kill between writing a checkpoint and pruning the oldest (io's
# CheckpointStore::write) leaves one more than --checkpoint-keep: with a
# checkpoint every few milliseconds (the biaxial case) that happens.
[ "$(ls "$work/killed/checkpoints/"*.resume | wc -l)" -le 3 ] ||
  fail "more checkpoints kept than --checkpoint-keep 2 (and the one written just before the kill)"

"$dem_run" "$case_file" --out "$work/killed" --threads 1 "${vtk[@]}" --resume >"$work/resumed.log" 2>&1 ||
  fail "the resumed run failed: $(cat "$work/resumed.log")"
grep "resumed from the checkpoint at cycle" "$work/resumed.log"
whole=$(grep '^state hash' "$work/whole.log")
resumed=$(grep '^state hash' "$work/resumed.log")
[ "$whole" = "$resumed" ] || fail "different end states: $whole against $resumed"
echo "$resumed in both"
for table in "$work"/whole/*.csv; do
  name=$(basename "$table")
  cmp "$table" "$work/killed/$name" || fail "$name differs"
done
echo "every table the same: $(cd "$work/whole" && ls *.csv | tr '\n' ' ')"
if [ -n "$vtk_interval" ]; then
  diff -r "$work/whole/vtk" "$work/killed/vtk" >/dev/null || fail "the ParaView steps (vtk/) differ"
  for series in "$work"/whole/*.pvd; do
    cmp "$series" "$work/killed/$(basename "$series")" || fail "$(basename "$series") differs"
  done
  echo "the ParaView series the same: $(ls "$work/whole/vtk" | wc -l) files in vtk/ and $(cd "$work/whole" && ls *.pvd | tr '\n' ' ')"
fi

# A checkpoint directory of another case is refused.
cp -r "$work/killed/checkpoints" "$work/other_checkpoints"
sed 's/^name: .*/name: "another"/' "$case_file" >"$work/another.case.txtpb"
if "$dem_run" "$work/another.case.txtpb" --out "$work/killed" --resume >"$work/other.log" 2>&1; then
  fail "a resume of another case ran"
fi
grep -q "belongs to another case" "$work/other.log" || fail "no reason given: $(cat "$work/other.log")"
echo "PASS"
