#!/usr/bin/env bats
# The khepera family through player-drivers and player-serve: a K-Team
# Khepera emulated on a pseudo-terminal, probed, run (both devices, a
# velocity command traced in the interface's units), and served from
# data/config/khepera.cfg. Every wait is bounded; devices sit in
# $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${run_pid:-}" "${emulator_pid:-}" "${server_pid:-}"
}

@test "a Khepera: emulate, probe, run its position and ir, a velocity command on the line" {
  robot="$BATS_TEST_TMPDIR/khepera"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" khepera --link "$robot"
  grep -qx "khepera on $robot: position:0 ( driver \"khepera_position\" port \"$robot\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$robot"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$robot: khepera at 38400 baud, Khepera, wheels at 0,0 pulses/10 ms"* ]]
  [[ "$output" == *"    position:0 ( driver \"khepera_position\" port \"$robot\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run khepera "port=$robot" --device ir:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].data.range_count' <<<"$output")" -eq 8 ]

  run --separate-stderr timeout 60 "$player_drivers" run khepera "port=$robot" --device position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s -r '.[1].device' <<<"$output")" = position ]

  # GET_GEOM answers 1.5's scaled size; the trace frames the lines.
  run --separate-stderr timeout 60 "$player_drivers" run khepera "port=$robot" --device position:0 --req get-geom --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [[ "$stderr" == *"45 0A"* ]]  # "E\n" on the line

  # Motors on, then 100 mm/s: 12 pulses a wheel per 10 ms on the line
  # ("D,12,12"; 1.5 sent D,8,8) and the robot reports 100 mm/s back.
  run_until "a reading at 100 mm/s" 'select(.data.xspeed == 100)' \
    "$(printf '%s\n' '{"device":"position:0","request":"motor-power","data":{"value":1}}' \
      '{"device":"position:0","data":{"xspeed":100}}')" \
    khepera "port=$robot" --device position:0 --trace
  grep -q "44 2C 31 32 2C 31 32 0A" "$run_err"
  stop_cleanly "$emulator_pid"
}

@test "data/config/khepera.cfg serves the emulated robot" {
  robot="$BATS_TEST_TMPDIR/khepera"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" khepera --link "$robot"
  sed "s|\"/tmp/khepera\"|\"$robot\"|" "$repo_root/data/config/khepera.cfg" >"$BATS_TEST_TMPDIR/khepera.cfg"
  grep -q "port \"$robot\"" "$BATS_TEST_TMPDIR/khepera.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/khepera.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/khepera.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" ir:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = ir ]
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.data.xpos' <<<"$output")" -eq 0 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "info documents both drivers with 1.5's option names" {
  run timeout 30 "$player_drivers" info khepera_position
  [ "$status" -eq 0 ]
  [[ "$output" == *"encoder_res"* ]]
  [[ "$output" == *"scale_factor"* ]]
  run timeout 30 "$player_drivers" info khepera_ir
  [ "$status" -eq 0 ]
  [[ "$output" == *"pose_count"* ]]
  [[ "$output" == *"ir_calib_a"* ]]
}
