#!/usr/bin/env bats
# Logs without usable times (lib/log/log_clock.hpp): the Örebro log of
# tests/data/radish stamps every scan 0 and its odometry with garbage. Tools
# read it in file order on a synthetic 10 Hz clock and say so once on stderr.

load helpers

orebro="$repo_root/tests/data/radish/orebro-corrected.log.gz"

setup() {
  cd "$BATS_TEST_TMPDIR"
}

teardown() {
  kill_left_running "${server_pid:-}"
}

# json_value KEY.PATH < FILE
json_value() {
  python3 -c 'import json, sys
v = json.load(sys.stdin)
for k in sys.argv[1].split("."): v = v[k]
print(v)' "$1"
}

@test "info on Orebro: synthetic times, sane rates, one warning" {
  run --separate-stderr "$player_log" info "$orebro"
  [ "$status" -eq 0 ]
  [[ "$output" == *"times:     492 of 492 timestamps unusable"*"using file order with a synthetic 10 Hz clock"* ]]
  [[ "$output" =~ FLASER\ +237\ +4\.826\ Hz ]]   # 236 intervals over 48.9 s of the 10 Hz clock
  [[ "$output" =~ ODOM\ +255\ +5\.173\ Hz ]]
  [[ "$output" == *"backwards: 0 "* ]]
  [ "$(grep -c 'timestamps unusable' <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == *"orebro-corrected.log.gz: 492 of 492 timestamps unusable (255 at 0,"* ]]
  json="$("$player_log" info --json "$orebro" 2>/dev/null)"
  [ "$(json_value times.repair <<< "$json")" = "synthetic" ]
  [ "$(json_value times.synthetic_rate_hz <<< "$json")" = "10.0" ]
  python3 -c 'import json, sys
d = json.loads(sys.argv[1])
for name, s in d["records"].items():
    assert s["rate_hz"] is None or 0 < s["rate_hz"] <= 10, (name, s)' "$json"
}

@test "a log with good times says nothing about them" {
  "$player_log" convert "$orebro" -o orebro.player.log 2>/dev/null
  run --separate-stderr "$player_log" info orebro.player.log
  [ "$status" -eq 0 ]
  [[ "$output" != *"times:"* ]]
  [ -z "$stderr" ]
  [[ "$output" =~ laser:0\ +237 ]]
}

@test "perturb keeps Orebro's file order; localize from the truth tracks it; eval matches by scan order" {
  "$amcl_offline" map "$orebro" -o orebro.pgm --resolution 0.05 2>/dev/null
  run --separate-stderr "$amcl_offline" perturb "$orebro" -o plain.log --seed 1 --scale-error 0 --rot-scale-error 0 \
    --drift 0 --trans-noise 0 --rot-noise 0 --slip-noise 0
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"final drift 0.00 m, "*"0.00 deg"* ]]
  diff <(zcat "$orebro" | cut -d' ' -f1) <(cut -d' ' -f1 plain.log)

  "$amcl_offline" perturb "$orebro" -o odom.log --seed 1 2>/dev/null
  run --separate-stderr "$amcl_offline" localize odom.log --map orebro.yaml --init-pose truth -o estimate.csv
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"237 scans"*"no real-time factor: the log has no usable times"* ]]
  [ "$(grep -c 'timestamps unusable' <<< "$stderr")" -eq 1 ]
  # rows in file order on the synthetic clock: strictly increasing times
  awk -F, 'NR > 2 && $1 <= last { exit 1 } NR > 1 { last = $1 }' estimate.csv

  run --separate-stderr "$amcl_offline" eval estimate.csv --truth "$orebro"
  [ "$status" -eq 0 ]
  [[ "$output" == *"matched 237 of 237 estimates by scan order"* ]]
  "$amcl_offline" eval estimate.csv --truth "$orebro" --json 2>/dev/null > eval.json
  [ "$(json_value matched_by < eval.json)" = "scan_order" ]
  # Guard against losing it outright, over three filter seeds: the position
  # within 0.2 m RMSE every time (measured 0.09-0.14 m over seeds 0-15). The
  # heading within 2 deg RMSE in two of three: on this log, whose scans are
  # 0.94 m apart, the weights can collapse onto one particle, and in 2 of
  # seeds 0-15 that particle is 38 or 76 degrees off for one scan (seed 0
  # here: 2.8 deg RMSE; docs/amcl.md).
  headings_within=0
  for seed in 0 1 2; do
    "$amcl_offline" localize odom.log --map orebro.yaml --init-pose truth --seed "$seed" -o "seed$seed.csv" 2>/dev/null
    "$amcl_offline" eval "seed$seed.csv" --truth "$orebro" --json 2>/dev/null > eval.json
    python3 -c 'import json
d = json.load(open("eval.json"))["all"]
assert d["position_rmse_m"] < 0.2, d'
    if python3 -c 'import json, sys
sys.exit(0 if json.load(open("eval.json"))["all"]["heading_rmse_rad"] < 0.035 else 1)'; then
      headings_within=$((headings_within + 1))
    fi
  done
  [ "$headings_within" -ge 2 ]
}

@test "replay serves Orebro's scans in file order" {
  "$player_log" convert "$orebro" -o expected.log 2>/dev/null
  start_replay "$BATS_TEST_TMPDIR/replay.err" "$orebro" -p 0 --bind 127.0.0.1 --burst
  timeout 60 "$player_cat" "127.0.0.1:$server_port" laser:0 -n 237 --format log > served.log
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
  diff <(awk '$4 == "laser"' expected.log | cut -d' ' -f6-) <(awk '$4 == "laser"' served.log | cut -d' ' -f6-)
  [ "$(grep -c 'timestamps unusable' "$BATS_TEST_TMPDIR/replay.err")" -eq 1 ]
}
