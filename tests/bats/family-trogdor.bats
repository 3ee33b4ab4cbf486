#!/usr/bin/env bats
# The trogdor family through player-drivers and player-serve: a Botrics
# O-Bot emulated on a pseudo-terminal, probed, run, driven with its bytes
# traced, and served from data/config/trogdor.cfg. Every wait is bounded;
# devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${run_pid:-}" "${emulator_pid:-}" "${server_pid:-}"
}

@test "a Trogdor: emulate, probe, run, a request, a velocity command traced" {
  robot="$BATS_TEST_TMPDIR/trogdor"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" trogdor --link "$robot" counts=4242
  grep -qx "trogdor on $robot: position:0 ( driver \"trogdor\" port \"$robot\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$robot"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$robot: trogdor at 57600 baud, Botrics O-Bot (Trogdor) cerebellum, wheel counters 4242 / 4242"* ]]
  [[ "$output" == *"    position:0 ( driver \"trogdor\" port \"$robot\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run trogdor "port=$robot" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]

  # GET_GEOM: the 450 mm square of 1.5; INIT (FD FC FB) on the line first.
  run --separate-stderr timeout 60 "$player_drivers" run trogdor "port=$robot" --req get-geom --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [ "$(jq -r '.data.size[0]' <<<"$output")" -eq 450 ]
  [[ "$stderr" == *"> FD FC FB"* ]]

  # 500 mm/s: 33 units a wheel ('v', 33, 33, XOR), reported back as 498 mm/s.
  run_until "a reading at 498 mm/s" 'select(.data.xspeed == 498)' '{"device":"position:0","data":{"xspeed":500}}' \
    trogdor "port=$robot" --trace
  grep -q "> 76 21 00 00 00 21 00 00 00 76" "$run_err"
  stop_cleanly "$emulator_pid"
}

@test "player-drivers info trogdor documents its option and requests" {
  run --separate-stderr "$player_drivers" info trogdor
  [ "$status" -eq 0 ]
  [[ "$output" == *"/dev/usb/ttyUSB1"* ]]
  [[ "$output" == *"MOTOR_POWER"* ]]
  [[ "$output" == *"7.42"* ]]
}

@test "data/config/trogdor.cfg serves the emulated robot" {
  robot="$BATS_TEST_TMPDIR/trogdor"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" trogdor --link "$robot"
  sed "s|\"/tmp/trogdor\"|\"$robot\"|" "$repo_root/data/config/trogdor.cfg" >"$BATS_TEST_TMPDIR/trogdor.cfg"
  grep -q "port \"$robot\"" "$BATS_TEST_TMPDIR/trogdor.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/trogdor.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/trogdor.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}
