#!/usr/bin/env bats
# The Flock of Birds family from the command line: the emulated bird on a
# pseudo-terminal behind a symlink in $BATS_TEST_TMPDIR, probed, run and
# served from data/config/flockofbirds.cfg; every wait is bounded.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a Flock of Birds: emulate, probe, run, a trace of the start-up" {
  bird="$BATS_TEST_TMPDIR/bird"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" flockofbirds --link "$bird"
  grep -qx "flockofbirds on $bird: position3d:0 ( driver \"flockofbirds\" port \"$bird\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$bird"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$bird: flockofbirds at 115200 baud, Flock of Birds, 36\" position scaling"* ]]
  [[ "$output" == *"    position3d:0 ( driver \"flockofbirds\" port \"$bird\" )"* ]]

  # The built-in motion stays in front of the transmitter: x 200..400 mm.
  run --separate-stderr timeout 60 "$player_drivers" run flockofbirds "port=$bird" -n 3 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 3 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position3d ]
  jq -s -e 'all(.[]; .data.xpos >= 199 and .data.xpos <= 401)' <<<"$output" >/dev/null

  # POINT, POSITION/ANGLES, EXAMINE VALUE 3, STREAM on the line; POINT last.
  run --separate-stderr timeout 60 "$player_drivers" run flockofbirds "port=$bird" -n 1 --trace
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"> 42"* ]]
  [[ "$stderr" == *"> 59"* ]]
  [[ "$stderr" == *"> 4F 03"* ]]
  [[ "$stderr" == *"> 40"* ]]
  [ "$(grep ' > ' <<<"$stderr" | tail -n 1 | awk '{print $NF}')" = 42 ]  # the stream stopped at the end
  stop_cleanly "$emulator_pid"
}

@test "a Flock of Birds following a trajectory file at 72-inch scaling and 9600 baud" {
  bird="$BATS_TEST_TMPDIR/bird"
  printf '# t x y z azimuth elevation roll\n0 1200 -300 250 -90 0 10\n' >"$BATS_TEST_TMPDIR/poses.txt"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" \
    flockofbirds "trajectory=$BATS_TEST_TMPDIR/poses.txt" scaling=72 baud=9600 --link "$bird"

  run --separate-stderr timeout 60 "$player_drivers" probe "$bird"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$bird: flockofbirds at 9600 baud, Flock of Birds, 72\" position scaling"* ]]
  [[ "$output" == *"add baudrate 9600"* ]]

  # 1.5's form of the speed, B9600's value; Z's sign inverted, -90 deg as 270.
  run --separate-stderr timeout 60 "$player_drivers" run flockofbirds "port=$bird" baudrate=13 -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.data.xpos' <<<"$output")" -ge 1199 ]
  [ "$(jq -r '.data.xpos' <<<"$output")" -le 1201 ]
  [ "$(jq -r '.data.zpos' <<<"$output")" -le -249 ]
  [ "$(jq -r '.data.yaw' <<<"$output")" -eq 972000 ]
  stop_cleanly "$emulator_pid"
}

@test "emulate flockofbirds refuses a bad trajectory, naming its line" {
  printf '0 1 2 3 4 5 6\n0 1 2 3 4 5 6\n' >"$BATS_TEST_TMPDIR/poses.txt"
  run --separate-stderr timeout 30 "$player_drivers" emulate flockofbirds "trajectory=$BATS_TEST_TMPDIR/poses.txt" \
    --link "$BATS_TEST_TMPDIR/bird" --duration 1
  [ "$status" -ne 0 ]
  [[ "$stderr" == *"trajectory line 2: the time must increase"* ]]
}

@test "data/config/flockofbirds.cfg serves the emulated bird" {
  bird="$BATS_TEST_TMPDIR/flockofbirds"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" flockofbirds --link "$bird"
  sed "s|\"/tmp/flockofbirds\"|\"$bird\"|" "$repo_root/data/config/flockofbirds.cfg" >"$BATS_TEST_TMPDIR/flockofbirds.cfg"
  grep -q "port \"$bird\"" "$BATS_TEST_TMPDIR/flockofbirds.cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/flockofbirds.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position3d:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position3d ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "player-serve --check refuses a baudrate the bird does not have, at its place" {
  printf 'position3d:0\n(\n  driver "flockofbirds"\n  port "/tmp/bird"\n  baudrate 1000\n)\n' >"$BATS_TEST_TMPDIR/bad.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/bad.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"bad.cfg:5:12: flockofbirds: baudrate must be 2400"* ]]
}
