#!/usr/bin/env bats
# The segwayrmp family through player-drivers and player-serve: a Segway RMP
# emulated behind an slcan adapter on a pseudo-terminal, probed, run,
# traced, and served from data/config/segwayrmp.cfg; 1.5's canio "kvaser"
# refused with the way out. Every wait is bounded; devices sit in
# $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a Segway RMP: emulate, probe (through its slcan adapter), run, a request traced" {
  rmp="$BATS_TEST_TMPDIR/rmp"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" segwayrmp --link "$rmp" battery=90
  grep -qx "segwayrmp on $rmp: position:0 ( driver \"segwayrmp\" port \"$rmp\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$rmp"
  [ "$status" -eq 0 ]
  # A pseudo-terminal has no speed: on a slow (sanitized) run the adapter's
  # first answer may miss the 115200 attempt's window and come at the next rate.
  [[ "$output" == *"$rmp: segwayrmp at "*" baud, Segway RMP behind an slcan adapter, 500 kbit/s"* ]]
  [[ "$output" == *"    position:0 ( driver \"segwayrmp\" port \"$rmp\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run segwayrmp "port=$rmp" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]
  [ "$(jq -s -r '.[1].data.xpos' <<<"$output")" -eq 0 ]

  # The adapter opened at 500 kbit/s ("S6", "O"), the request answered, the
  # robot told to stop ("t413" with zero speeds) and the channel closed ("C").
  run --separate-stderr timeout 60 "$player_drivers" run segwayrmp "port=$rmp" --req get-geom --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [ "$(jq -r '.data.size[1]' <<<"$output")" -eq 610 ]
  [[ "$stderr" == *"> 53 36 0D"* ]]
  [[ "$stderr" == *"> 4F 0D"* ]]
  [[ "$stderr" == *"> 74 34 31 33 38 30 30 30 30 30 30 30 30 30 30 30 30 30 30 30 30 0D"* ]]
  [[ "$stderr" == *"> 43 0D"* ]]
  stop_cleanly "$emulator_pid"
}

@test "segwayrmp: 1.5's canio \"kvaser\" is refused at --check with the way out" {
  printf 'position:0 ( driver "rmpposition" canio "kvaser" )\n' >"$BATS_TEST_TMPDIR/kvaser.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/kvaser.cfg"
  [ "$status" -ne 0 ]
  [[ "$output" == *"kvaser.cfg:1:41"* ]]
  [[ "$output" == *"canio \"socketcan\" and device \"can0\""* ]]
  run --separate-stderr "$player_drivers" info segwayrmp
  [ "$status" -eq 0 ]
  [[ "$output" == *"canio"* ]]
  [[ "$output" == *"RMP_SHUTDOWN"* ]]
}

@test "data/config/segwayrmp.cfg serves the emulated robot: position, position3d, power" {
  rmp="$BATS_TEST_TMPDIR/segwayrmp"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" segwayrmp --link "$rmp"
  sed "s|\"/tmp/segwayrmp\"|\"$rmp\"|" "$repo_root/data/config/segwayrmp.cfg" >"$BATS_TEST_TMPDIR/segwayrmp.cfg"
  grep -q "port \"$rmp\"" "$BATS_TEST_TMPDIR/segwayrmp.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/segwayrmp.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/segwayrmp.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 position3d:0 power:0 -n 6 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s '[.[] | select(.device == "position")] | length' <<<"$output")" -ge 1 ]
  [ "$(jq -s '[.[] | select(.device == "position3d")] | length' <<<"$output")" -ge 1 ]
  [ "$(jq -s -r '[.[] | select(.device == "power")][0].data.charge' <<<"$output")" -eq 720 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "segwayrmp carries an emulated laser, and takes the shared robot options" {
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" \
    segwayrmp pose=1,2,90 odometry_scale=0.02 watchdog=0.5 sicklms200 mount=0.2,0,0 \
    --link "$BATS_TEST_TMPDIR/rmp" --link "$BATS_TEST_TMPDIR/laser"
  grep -q "^segwayrmp on $BATS_TEST_TMPDIR/rmp: " "$BATS_TEST_TMPDIR/emulate.out"
  grep -q "^sicklms200 on $BATS_TEST_TMPDIR/laser: " "$BATS_TEST_TMPDIR/emulate.out"
  wait_for_line --pid "$emulator_pid" "$BATS_TEST_TMPDIR/emulate.err" "sicklms200 rides on the emulated robot"
  stop_cleanly "$emulator_pid"
}
