#!/usr/bin/env bats
# The er1 family through player-drivers and player-serve: an Evolution
# Robotics ER1 emulated on a pseudo-terminal, probed, run (a velocity
# command traced as the RCM's bytes, and the robot moving), in the other
# motor wiring, and served from data/config/er1.cfg. Every wait is bounded;
# devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${run_pid:-}" "${emulator_pid:-}" "${server_pid:-}"
}

@test "an ER1: emulate, probe, run, a velocity command on the line" {
  robot="$BATS_TEST_TMPDIR/er1"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" er1 --link "$robot"
  grep -qx "er1 on $robot: position:0 ( driver \"er1_position\" port \"$robot\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$robot"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$robot: er1_position at 230400 baud, ER1 Robot Control Module, motor counts 0 and 0"* ]]
  [[ "$output" == *"    position:0 ( driver \"er1_position\" port \"$robot\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run er1_position "port=$robot" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data.xpos' <<<"$output")" -eq 0 ]

  run --separate-stderr timeout 60 "$player_drivers" run er1_position "port=$robot" --req get-geom
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [ "$(jq -r '.data.size[0]' <<<"$output")" -eq 450 ]

  # 100 mm/s: the sheet's worked example for the mirrored motor 0
  # (trunc(10 x 16819.8), negated), its mirror image for motor 1, and the
  # robot reporting the speed back.
  run_until "a reading at about 100 mm/s" 'select(.data.xspeed >= 90 and .data.xspeed <= 110)' \
    '{"device":"position:0","data":{"xspeed":100}}' er1_position "port=$robot" --trace
  grep -q "00 8B 00 11 FF FD 6E FA" "$run_err"
  grep -q "01 55 00 11 00 02 91 06" "$run_err"
  # Leaving, the driver stopped the motors (STOP_1 to motor 1 on the line).
  grep -q "01 CB 00 34 00 00" "$run_err"
  stop_cleanly "$emulator_pid"
}

@test "an ER1 with its left motor on port 1: motor_dir -1 drives it forward when asked" {
  # Swapped motors leave a pure turn unchanged (each motor is mirrored too)
  # but reverse a straight drive, and the driver's own odometry cannot tell:
  # only the emulated robot's true pose (--stats) shows which way it went.
  robot="$BATS_TEST_TMPDIR/er1"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" er1 --link "$robot" motor_dir=-1 --stats
  run_until "a reading 5 cm ahead" 'select(.data.xpos >= 50)' '{"device":"position:0","data":{"xspeed":100}}' \
    er1_position "port=$robot" motor_dir=-1
  # The robot itself went forward: x of at least 0.05 m in a stats line.
  wait_for_line --pid "$emulator_pid" "$BATS_TEST_TMPDIR/emulate.err" \
    'left motor on port 1, at \(([1-9][0-9]*\.[0-9]{2}|0\.(0[5-9]|[1-9][0-9])), '
  stop_cleanly "$emulator_pid"
}

@test "data/config/er1.cfg serves the emulated robot" {
  robot="$BATS_TEST_TMPDIR/er1"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" er1 --link "$robot"
  sed "s|\"/tmp/er1\"|\"$robot\"|" "$repo_root/data/config/er1.cfg" >"$BATS_TEST_TMPDIR/er1.cfg"
  grep -q "port \"$robot\"" "$BATS_TEST_TMPDIR/er1.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/er1.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/er1.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]
  [ "$(jq -s -r '.[0].data.xpos' <<<"$output")" -eq 0 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "info documents er1_position with 1.5's option names, and a bad motor_dir is refused at its place" {
  run timeout 30 "$player_drivers" info er1_position
  [ "$status" -eq 0 ]
  [[ "$output" == *"axle"* ]]
  [[ "$output" == *"motor_dir"* ]]
  [[ "$output" == *"/dev/usb/ttyUSB0"* ]]
  printf 'position:0 ( driver "er1_position" port "/tmp/er1" motor_dir 2 )\n' >"$BATS_TEST_TMPDIR/bad.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/bad.cfg"
  [ "$status" -ne 0 ]
  [[ "$output" == *"bad.cfg:1:"*"er1_position: motor_dir must be one of -1, 1 (got 2)"* ]]
}
