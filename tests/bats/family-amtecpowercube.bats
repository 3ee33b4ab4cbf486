#!/usr/bin/env bats
# The amtecpowercube family through player-drivers and player-serve: an
# Amtec PowerCube wrist emulated on a pseudo-terminal, probed, run, traced,
# and served from data/config. Every wait is bounded; devices sit in
# $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a PowerCube wrist: emulate, probe, run (homed at start-up), a request traced" {
  cube="$BATS_TEST_TMPDIR/cube"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" amtecpowercube --link "$cube" \
    pan_start=-20 tilt_start=15
  grep -qx "amtecpowercube on $cube: ptz:0 ( driver \"amtecpowercube\" port \"$cube\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$cube"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$cube: amtecpowercube at 38400 baud, Amtec PowerCube wrist, pan module 12 and tilt module 11"* ]]
  [[ "$output" == *"    ptz:0 ( driver \"amtecpowercube\" port \"$cube\" )"* ]]

  # Homing drove both modules from where they stood to 0.
  run --separate-stderr timeout 60 "$player_drivers" run amtecpowercube "port=$cube" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data.pan' <<<"$output")" -eq 0 ]
  [ "$(jq -s -r '.[1].data.tilt' <<<"$output")" -eq 0 ]

  # Velocity control stops both modules (a velocity of 0 to the pan module on
  # the line); leaving, the driver halts them (the sheet's HALT, 02 escaped).
  run --separate-stderr timeout 60 "$player_drivers" run amtecpowercube "port=$cube" --req control-mode mode=0 --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [[ "$stderr" == *"> 02 05 86 0B 11 00 00 00 00 28 03"* ]]
  [[ "$stderr" == *"> 02 05 81 10 82 0E 03"* ]]
  stop_cleanly "$emulator_pid"
}

@test "a PowerCube wrist missing its tilt module: probe names it, run refuses" {
  cube="$BATS_TEST_TMPDIR/cube"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" amtecpowercube --link "$cube" modules=pan
  run --separate-stderr timeout 60 "$player_drivers" probe "$cube"
  [ "$status" -eq 0 ]
  [[ "$output" == *"only the pan module 12 answers"* ]]
  run --separate-stderr timeout 60 "$player_drivers" run amtecpowercube "port=$cube" -n 1
  [ "$status" -ne 0 ]
  [[ "$stderr" == *"tilt module 11 does not answer"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/amtecpowercube.cfg serves the emulated wrist" {
  cube="$BATS_TEST_TMPDIR/amtecpowercube"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" amtecpowercube --link "$cube"
  sed "s|\"/tmp/amtecpowercube\"|\"$cube\"|" "$repo_root/data/config/amtecpowercube.cfg" >"$BATS_TEST_TMPDIR/cube.cfg"
  grep -q "port \"$cube\"" "$BATS_TEST_TMPDIR/cube.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/cube.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/cube.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" ptz:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = ptz ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}
