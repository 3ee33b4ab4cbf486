#!/usr/bin/env bats
# The rflex family through player-drivers and player-serve: an RFLEX robot
# (B21r, ATRV-Jr, Magellan Pro) emulated on a pseudo-terminal, probed, run
# as a whole robot, traced, and served from its data/config file. Every
# wait is bounded; devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "an RFLEX robot: emulate, probe, run all seven devices, a request traced" {
  robot="$BATS_TEST_TMPDIR/robot"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" rflex --link "$robot" model=b21r
  grep -qx "rflex on $robot: position:0 ( driver \"rflex_position\" port \"$robot\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$robot"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$robot: rflex at 115200 baud, an RFLEX controller (battery 26.4 V)"* ]]
  [[ "$output" == *"    position:0 ( driver \"rflex_position\" port \"$robot\" )"* ]]

  # The whole robot on the one line; its sonar in millimetres (5 m of open space).
  run --separate-stderr timeout 60 "$player_drivers" run rflex "port=$robot" --device sonar -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data.range_count' <<<"$output")" -eq 24 ]
  [ "$(jq -s -r '.[1].data.ranges[0]' <<<"$output")" -ge 4990 ]

  # MOTOR_POWER 0 sets the brake (port 2, opcode 11), after the start-up's
  # report request; leaving, the robot is stopped and braked.
  run --separate-stderr timeout 60 "$player_drivers" run rflex "port=$robot" --device position \
    --req motor-power value=0 --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [[ "$stderr" == *"> 1B 02 02 00 22 08 00 01 86 A0 00 00 00 03 0C 1B 03"* ]]
  [[ "$stderr" == *"> 1B 02 02 00 0B 00 09 1B 03"* ]]
  [[ "$stderr" == *"< 1B 02 01 "*" 01 09 "* ]]  # the status reply
  stop_cleanly "$emulator_pid"
}

@test "rflex: a silent line is refused with the reason" {
  robot="$BATS_TEST_TMPDIR/robot"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" rflex --link "$robot" \
    --fault silent-start=60
  run --separate-stderr timeout 60 "$player_drivers" run rflex "port=$robot" connect_timeout=0.5 -n 1
  [ "$status" -ne 0 ]
  [[ "$stderr" == *"no RFLEX controller answered within 0.5 s"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/rflex-*.cfg each serve their emulated robot" {
  for model in b21r atrvjr magellan; do
    robot="$BATS_TEST_TMPDIR/rflex-$model"
    start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" rflex --link "$robot" \
      "model=$model"
    sed "s|\"/tmp/rflex-$model\"|\"$robot\"|" "$repo_root/data/config/rflex-$model.cfg" >"$BATS_TEST_TMPDIR/$model.cfg"
    grep -q "rflex_serial_port \"$robot\"" "$BATS_TEST_TMPDIR/$model.cfg"
    run "$player_serve" --check "$BATS_TEST_TMPDIR/$model.cfg"
    [ "$status" -eq 0 ]
    start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/$model.cfg"
    run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 sonar:0 power:0 -n 6 --format json
    [ "$status" -eq 0 ]
    [ "$(jq -s '[.[] | select(.device == "sonar")] | length' <<<"$output")" -ge 1 ]
    [ "$(jq -s '[.[] | select(.device == "power")][0].data.charge' <<<"$output")" -gt 100 ]
    stop_cleanly "$server_pid"
    stop_cleanly "$emulator_pid"
  done
}
