#!/usr/bin/env bats
# The sonyevid30 family through player-drivers and player-serve: a Sony
# EVI-D30 emulated on a pseudo-terminal, probed, run, traced, asked a raw
# VISCA inquiry, pointed by a client and served from data/config. Every wait
# is bounded; devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${cat_pid:-}" "${emulator_pid:-}" "${server_pid:-}"
}

@test "an EVI-D30: emulate, probe, run, a raw VISCA inquiry" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sonyevid30 --link "$cam"
  grep -qx "sonyevid30 on $cam: ptz:0 ( driver \"sonyevid30\" port \"$cam\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$cam"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$cam: sonyevid30 at 9600 baud, VISCA camera 1 (Sony EVI-D30), pan 0 tilt 0 degrees"* ]]
  [[ "$output" == *"    ptz:0 ( driver \"sonyevid30\" port \"$cam\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run sonyevid30 "port=$cam" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data | "\(.pan) \(.tilt) \(.zoom)"' <<<"$output")" = "0 0 30" ]

  # The zoom position inquiry (09 04 47) through GENERIC_CONFIG: its answer packet back.
  run --separate-stderr timeout 60 "$player_drivers" run sonyevid30 "port=$cam" --req generic \
    'config=[9,4,71]' --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [ "$(jq -c '.data.config' <<<"$output")" = "[144,80,0,0,0,0,255]" ]
  [[ "$stderr" == *"> 81 09 06 12 FF"* ]]  # the start-up's pan/tilt inquiry, a packet a line
  [[ "$stderr" == *"< 90 50 00 00 00 00 FF"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/sonyevid30.cfg serves the emulated camera, and a client points it" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sonyevid30 --link "$cam"
  sed "s|\"/tmp/sonyevid30\"|\"$cam\"|" "$repo_root/data/config/sonyevid30.cfg" >"$BATS_TEST_TMPDIR/sonyevid30.cfg"
  grep -q "port \"$cam\"" "$BATS_TEST_TMPDIR/sonyevid30.cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/sonyevid30.cfg"
  # A reader keeps the device subscribed (the last client leaving sends the camera home).
  "$player_cat" "localhost:$server_port" ptz:0 --format json >"$BATS_TEST_TMPDIR/cat.out" 2>/dev/null &
  cat_pid=$!
  wait_for_lines --pid "$cat_pid" "$BATS_TEST_TMPDIR/cat.out" 1
  run --separate-stderr timeout 60 "$player_send" "localhost:$server_port" ptz:0 cmd pan=30 tilt=10 zoom=20
  [ "$status" -eq 0 ]
  # Reached, and read back to the wire's whole degrees.
  wait_for_line --pid "$cat_pid" "$BATS_TEST_TMPDIR/cat.out" '"pan":30,.*"tilt":10,.*"zoom":20'
  stop_cleanly "$cat_pid"
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}
