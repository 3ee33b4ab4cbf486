#!/usr/bin/env bats
# The experiment end to end, with the tools a user has (scripts/sim-experiment,
# as README.md shows it and scripts/demo runs it): player-serve -s simulates
# data/worlds/simple.world (Player 1.5's cave, one Pioneer with a laser) five
# times faster than real time, player-send drives the robot round a loop with
# position goals, player-log record records odometry, laser and the
# simulator's truth, and amcl-offline localizes the recording on the world's
# own bitmap, given as Player 1.5 users gave it to amcl (cave.pnm, 0.03 m a
# pixel, negated), placed where the world put it (its bottom-left corner at
# 0,0). Then --picture, and determinism across speedups.

load helpers

worlds="$repo_root/data/worlds"

teardown() {
  kill_left_running "${server_pid:-}"
}

@test "scripts/sim-experiment: a loop in the cave, recorded and localized within 5 cm of the simulator's truth" {
  tools="$build_dir/tools"
  run env PATH="$tools/player-serve:$tools/player-send:$tools/player-cat:$tools/player-log:$tools/amcl-offline:$PATH" \
    OUT="$BATS_TEST_TMPDIR/experiment" "$repo_root/scripts/sim-experiment"
  echo "$output"  # shown only if the test fails: what the script said
  [ "$status" -eq 0 ]
  [[ "$output" == *"all "* ]]
  cd "$BATS_TEST_TMPDIR/experiment"
  # A scan every 0.2 s of about 65 s of simulation, nearly all kept.
  run "$player_log" info run.log --json
  [ "$status" -eq 0 ]
  scans=$(printf '%s' "$output" | python3 -c 'import json, sys; print(json.load(sys.stdin)["devices"]["laser:0"]["count"])')
  [ "$scans" -gt 250 ]
  run "$amcl_offline" eval estimate.csv --truth run.log --json
  [ "$status" -eq 0 ]
  printf '%s' "$output" | python3 -c '
import json, sys
result = json.load(sys.stdin)
rmse = result["all"]["position_rmse_m"]
print("position RMSE %.3f m over %d of %d estimates" % (rmse, result["matched"], result["estimates"]), file=sys.stderr)
# An estimate whose moment lies in a gap of over 1 s of lost truth samples is unmatched.
assert result["matched"] >= 0.9 * result["estimates"], result
assert rmse < 0.05, rmse
assert result["all"]["heading_rmse_rad"] < 0.035, result'
  # The picture of the run, written when the server stopped.
  [ "$(head -c 8 run.png | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ]
  grep -q "wrote the picture run.png" serve.log
}

@test "--picture: written on the simulation device's byte 3 (a command, or a request answered once written) and at the end" {
  start_server "$BATS_TEST_TMPDIR/serve.log" -s "$worlds/simple.world" -p 0 --bind 127.0.0.1 \
    --picture "$BATS_TEST_TMPDIR/world.png"
  run "$player_send" "127.0.0.1:$server_port" simulation:0 cmd cmd=3
  [ "$status" -eq 0 ]
  wait_for_nonempty --pid "$server_pid" --log "$BATS_TEST_TMPDIR/serve.log" "$BATS_TEST_TMPDIR/world.png"
  rm "$BATS_TEST_TMPDIR/world.png"
  run "$player_send" "127.0.0.1:$server_port" --stdin <<<'{"type":"req","device":"simulation:0","data":{"raw":[3]}}'
  [ "$status" -eq 0 ]
  [[ "$output" == *'"type":"ack"'* ]]
  [ -s "$BATS_TEST_TMPDIR/world.png" ]  # the ACK comes once it is written
  rm "$BATS_TEST_TMPDIR/world.png"
  kill -INT "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
  [ -s "$BATS_TEST_TMPDIR/world.png" ]
  [ "$(grep -c "wrote the picture $BATS_TEST_TMPDIR/world.png" "$BATS_TEST_TMPDIR/serve.log")" -eq 3 ]
}

@test "--picture is refused over the world file, in a missing directory, and without -s" {
  run "$player_serve" -s "$worlds/simple.world" -p 0 --bind 127.0.0.1 --picture "$worlds/simple.world"
  [ "$status" -eq 2 ]
  [[ "$output" == *"simple.world"* ]]
  run "$player_serve" -s "$worlds/simple.world" -p 0 --bind 127.0.0.1 --picture "$BATS_TEST_TMPDIR/no/run.png"
  [ "$status" -eq 2 ]
  [[ "$output" == *"the directory $BATS_TEST_TMPDIR/no does not exist"* ]]
  printf 'null:0 ( driver "null" )\n' >"$BATS_TEST_TMPDIR/a.cfg"
  run "$player_serve" -p 0 --bind 127.0.0.1 --picture "$BATS_TEST_TMPDIR/run.png" "$BATS_TEST_TMPDIR/a.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"--picture runs a simulation; it needs -s WORLD"* ]]
}

# record_circling SPEEDUP SEED LOG PORT: 5 simulated seconds of two robots
# circling under their initial velocity (a noisy laser on one), written by
# writelog. PORT 0 picks a free one (then in server_port); the port is in
# every log line, so runs compared byte for byte share one.
record_circling() {
  printf 'null:0 ( driver "writelog" filename "%s" devices ["position:0" "laser:0" "truth:0" "position:1" "sonar:1" "truth:1"] alwayson 1 )\n' \
    "$3" >"$BATS_TEST_TMPDIR/record.cfg"
  start_server "$BATS_TEST_TMPDIR/serve-$1-$2.log" -s "$BATS_TEST_TMPDIR/circling.world" -p "$4" --bind 127.0.0.1 \
    --speedup "$1" --seed "$2" --sim-time 5 "$BATS_TEST_TMPDIR/record.cfg"
  wait_for_line --pid "$server_pid" "$BATS_TEST_TMPDIR/serve-$1-$2.log" "the simulation stops at 5"
  kill -INT "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
}

@test "the same seed records byte-identical logs at 2x, 10x and as fast as possible; another seed other laser noise" {
  # example-4a.world's robots set moving by `velocity`, r0's laser with Stage's noise [c p a].
  cp "$worlds/stage-cave.png" "$BATS_TEST_TMPDIR/"
  sed -e 's/fov 180 samples 180 )/fov 180 samples 180 noise [0.0004 0.01 0.1] )/' \
      -e 's/color "red" /color "red" velocity [0.3 0 0 12] /' \
      -e 's/color "blue" )/color "blue" velocity [0.2 0 0 -15] )/' \
      "$worlds/example-4a.world" >"$BATS_TEST_TMPDIR/circling.world"
  grep -q 'velocity \[0.2 0 0 -15\]' "$BATS_TEST_TMPDIR/circling.world"
  record_circling 2 7 "$BATS_TEST_TMPDIR/slow.log" 0
  local port=$server_port
  record_circling 10 7 "$BATS_TEST_TMPDIR/fast.log" "$port"
  record_circling 0 7 "$BATS_TEST_TMPDIR/fastest.log" "$port"
  record_circling 10 8 "$BATS_TEST_TMPDIR/other-seed.log" "$port"
  # Every step is in: 2 header lines, then 50 steps of a sync line and six samples.
  [ "$(wc -l <"$BATS_TEST_TMPDIR/slow.log")" -eq 352 ]
  cmp "$BATS_TEST_TMPDIR/slow.log" "$BATS_TEST_TMPDIR/fast.log"
  cmp "$BATS_TEST_TMPDIR/slow.log" "$BATS_TEST_TMPDIR/fastest.log"
  # The other seed: the same times and positions, other laser noise.
  python3 - "$BATS_TEST_TMPDIR/slow.log" "$BATS_TEST_TMPDIR/other-seed.log" <<'PY'
import sys
def samples(path):
    found = {}
    for line in open(path):
        fields = line.split()
        if line.startswith("#") or fields[3] == "sync":
            continue
        found[(fields[3], fields[4], fields[5])] = fields[6:]
    return found
slow, other = (samples(path) for path in sys.argv[1:])
assert slow.keys() == other.keys(), len(slow.keys() ^ other.keys())
lasers = [key for key in slow if key[0] == "laser"]
assert lasers and all(slow[key] != other[key] for key in lasers), len(lasers)
positions = [key for key in slow if key[0] == "position"]
assert positions and all(slow[key] == other[key] for key in positions)
PY
}
