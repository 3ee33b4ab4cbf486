#!/usr/bin/env bats
# The reb family through player-drivers and player-serve: a UMass UBot's
# Robotics Extension Board emulated on a pseudo-terminal, probed, run (its
# three devices on one line), traced, and served from data/config. Every
# wait is bounded; devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a UBot: emulate, probe, run its power and ir devices, a request traced" {
  reb="$BATS_TEST_TMPDIR/reb"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" reb --link "$reb" battery=7.6
  grep -qx "reb on $reb: position:0 ( driver \"reb_position\" port \"$reb\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$reb"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$reb: reb at 38400 baud, REB with LPRSerCom (UBot)"* ]]
  [[ "$output" == *"    position:0 ( driver \"reb_position\" port \"$reb\" )"* ]]

  # The battery in decivolts (1.5 reported millivolts).
  run --separate-stderr timeout 60 "$player_drivers" run reb "port=$reb" --device power:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data.charge' <<<"$output")" -eq 76 ]

  # The IR sensors' poses; on the line the emitters go on ("Y,1") and, as
  # the last device leaves, the motors stop and the emitters go off.
  run --separate-stderr timeout 60 "$player_drivers" run reb "port=$reb" --device ir:0 --req pose --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [ "$(jq -r '.data.poses.pose_count' <<<"$output")" -eq 8 ]
  [[ "$stderr" == *"> 59 2C 31 0D"* ]]
  [[ "$stderr" == *"> 59 2C 30 0D"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/reb.cfg serves the emulated UBot" {
  reb="$BATS_TEST_TMPDIR/reb"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" reb --link "$reb"
  sed "s|\"/tmp/reb\"|\"$reb\"|" "$repo_root/data/config/reb.cfg" >"$BATS_TEST_TMPDIR/reb.cfg"
  grep -q "port \"$reb\"" "$BATS_TEST_TMPDIR/reb.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/reb.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/reb.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" power:0 -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.data.charge' <<<"$output")" -eq 72 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}
