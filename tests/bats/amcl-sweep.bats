#!/usr/bin/env bats
# amcl-offline sweep (tools/amcl-offline/sweep_*.cpp): two bundled logs x two
# sigma-hit values x two seeds, run here by `sweep run -j 2` and again by GNU
# parallel from the planned jobs.txt; the filter is deterministic for a seed,
# so both give one table (wall time and real-time factor aside). The Slurm
# array script is checked by its text and by running one task's line as
# Slurm would; slurm itself is not needed.

load helpers

radish="$repo_root/tests/data/radish"

setup() {
  cd "$BATS_TEST_TMPDIR"
}

# Maps of the two logs (about a second) and a spec of 8 runs in ./sweep.json.
make_spec() {
  "$amcl_offline" map "$radish/orebro-corrected.log.gz" -o orebro.pgm 2>/dev/null
  "$amcl_offline" map "$radish/freiburg-101-corrected.log.gz" -o fr101.pgm 2>/dev/null
  cat >sweep.json <<JSON
{"logs": [{"name": "orebro", "log": "$radish/orebro-corrected.log.gz", "map": "orebro.yaml", "perturb_seed": 1},
          {"name": "fr101", "log": "$radish/freiburg-101-corrected.log.gz", "map": "fr101.yaml", "perturb_seed": 1}],
 "start": "truth",
 "parameters": {"sigma-hit": [0.1, 0.2]},
 "seeds": [1, 2]}
JSON
}

# The table without its last two columns (wall time, real-time factor).
figures() {
  cut -d, -f1-9 "$1"
}

@test "sweep run -j 2 and GNU parallel over the same jobs give one table" {
  command -v parallel >/dev/null || skip "GNU parallel is not installed"
  make_spec
  run --separate-stderr timeout 120 "$amcl_offline" sweep run sweep.json -o local -j 2 --table local.csv --plot rmse.png
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"8 runs, 2 at a time"* ]]
  [[ "$stderr" == *"[8/8] "* ]]
  [[ "$stderr" == *"8 runs: 8 ok, 0 failed, 0 missing"* ]]
  [ "$(head -n 1 local.csv)" = "log,sigma-hit,seed,status,rmse_m,max_m,rmse_deg,converged_s,lost,wall_s,realtime" ]
  [ "$(grep -c ',ok,' local.csv)" -eq 8 ]
  grep -q '^orebro,0.1,1,ok,' local.csv
  grep -q '^fr101,0.2,2,ok,' local.csv
  # Tracking from the truth on these logs: every run well under half a metre.
  awk -F, 'NR > 1 && $5 >= 0.2 { exit 1 }' local.csv
  [ "$(head -c 4 rmse.png | tail -c 3)" = "PNG" ]
  [ -s local/runs/orebro_sigma-hit=0.1_seed=1.csv ]
  [ "$(wc -l <local/jobs.txt)" -eq 8 ]

  # The same sweep planned elsewhere and run by GNU parallel, ':' the local machine as an ssh login.
  run "$amcl_offline" sweep plan sweep.json -o parallel
  [ "$status" -eq 0 ]
  echo ':' >hosts
  timeout 120 parallel --will-cite --jobs 2 --sshloginfile hosts --joblog parallel/joblog <parallel/jobs.txt
  [ "$(awk 'NR > 1 && $7 == 0' parallel/joblog | wc -l)" -eq 8 ]
  run --separate-stderr "$amcl_offline" sweep collect parallel -o parallel.csv
  [ "$status" -eq 0 ]
  diff <(figures local.csv) <(figures parallel.csv)
  # The jobs differ only in their directory.
  diff <(sed "s|$BATS_TEST_TMPDIR/local/|DIR/|g" local/jobs.txt) <(sed "s|$BATS_TEST_TMPDIR/parallel/|DIR/|g" parallel/jobs.txt)
}

@test "the Slurm array: task i runs line i+1 of jobs.txt; collect counts the rest missing" {
  make_spec
  run "$amcl_offline" sweep plan sweep.json -o slurm
  [ "$status" -eq 0 ]
  dir="$BATS_TEST_TMPDIR/slurm"
  grep -qx '#SBATCH --array=0-7' slurm/sweep.sbatch
  grep -qx "#SBATCH --output=$dir/runs/slurm-%A_%a.out" slurm/sweep.sbatch
  grep -qx "line=\$(sed -n \"\$((SLURM_ARRAY_TASK_ID + 1))p\" $dir/jobs.txt)" slurm/sweep.sbatch
  [ -x slurm/sweep.sbatch ]
  if command -v sbatch >/dev/null && command -v slurmd >/dev/null; then
    echo "# sbatch is installed, but this test does not start a cluster" >&3
  fi
  # What one array task does, without Slurm: task 5 is the sixth run.
  SLURM_ARRAY_TASK_ID=5 timeout 60 bash slurm/sweep.sbatch
  [ -s slurm/runs/fr101_sigma-hit=0.1_seed=2.eval.json ]
  run --separate-stderr "$amcl_offline" sweep collect slurm --format markdown
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"8 runs: 1 ok, 0 failed, 7 missing"* ]]
  [[ "$output" == *"| fr101 | 0.1 | 2 | ok | "* ]]
  [ "$(grep -c '| missing |' <<<"$output")" -eq 7 ]
}

@test "a failed run is reported, the others finish, and the exit status says so" {
  "$amcl_offline" map "$radish/orebro-corrected.log.gz" -o orebro.pgm 2>/dev/null
  cat >bad.json <<JSON
{"logs": [{"name": "orebro", "log": "$radish/orebro-corrected.log.gz", "map": "orebro.yaml"}],
 "parameters": {"laser-beams": [0, 30]}, "seeds": [1]}
JSON
  run --separate-stderr timeout 60 "$amcl_offline" sweep run bad.json -o bad -j 2 --format json
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"orebro_laser-beams=0_seed=1 FAILED (exit status 1"* ]]
  [[ "$stderr" == *"orebro_laser-beams=30_seed=1 done in"* ]]
  [[ "$stderr" == *"1 ok, 1 failed, 0 missing"* ]]
  [[ "$stderr" == *"orebro_laser-beams=0_seed=1 failed; its stderr: $BATS_TEST_TMPDIR/bad/runs/orebro_laser-beams=0_seed=1.err"* ]]
  grep -q 'laser_max_beams must be at least 1' bad/runs/orebro_laser-beams=0_seed=1.err
  python3 -c 'import json, sys
runs = json.loads(sys.argv[1])["runs"]
assert [r["status"] for r in runs] == ["failed", "ok"], runs
assert runs[1]["position_rmse_m"] < 0.3, runs' "$output"
}

@test "a bad spec is a usage error naming the place" {
  printf '{"logs": [\n  {"log": "a.log", "map": "a.yaml",}\n]}\n' >syntax.json
  run --separate-stderr "$amcl_offline" sweep plan syntax.json -o out
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"syntax.json:2:"*": syntax error"* ]]
  printf '{"logs": [{"log": "a.log", "map": "a.yaml"}], "parameters": {"seed": [1, 2]}}\n' >field.json
  run --separate-stderr "$amcl_offline" sweep run field.json -o out
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"field.json: parameters.seed: not a localize flag a sweep may vary"* ]]
  [ ! -e out ]
}
