#!/usr/bin/env bats
# The rwi_* drivers: RWI's Mobility middleware cannot be had, so a
# configuration naming them is refused, at the driver's name, with the
# reason and the rflex_* section to use instead: by player-serve --check,
# by player-serve at start, and in player-drivers info.

load helpers

teardown() {
  kill_left_running "${server_pid:-}"
}

write_config() {
  cat >"$BATS_TEST_TMPDIR/b21r.cfg" <<'CFG'
# Player 1.5's form for a B21r through Mobility.
position:0
(
  driver "rwi_position"
  name "B21R"
)
sonar:0
(
  driver "rwi_sonar"
  array "lower"
)
CFG
}

@test "--check refuses rwi_position at its name, with the reason and the rflex section" {
  write_config
  run --separate-stderr "$player_serve" --check "$BATS_TEST_TMPDIR/b21r.cfg"
  [ "$status" -ne 0 ]
  [[ "$stderr" == *"b21r.cfg:4:10: driver 'rwi_position' cannot run: RWI's Mobility middleware"* ]]
  [[ "$stderr" == *"position:0 ( driver \"rflex_position\" rflex_serial_port \"/dev/ttyR0\""* ]]
}

@test "player-serve refuses to start on an rwi_* configuration" {
  for driver in rwi_sonar rwi_laser rwi_bumper rwi_power; do
    interface=$(sed 's/rwi_//' <<<"$driver")
    printf '%s:0\n(\n  driver "%s"\n)\n' "$interface" "$driver" >"$BATS_TEST_TMPDIR/$driver.cfg"
    run --separate-stderr timeout 30 "$player_serve" -p 0 "$BATS_TEST_TMPDIR/$driver.cfg"
    [ "$status" -ne 0 ]
    [[ "$stderr" == *"$driver.cfg:3:10: driver '$driver' cannot run: RWI's Mobility middleware"* ]]
  done
  [[ "$stderr" == *"power:0 ( driver \"rflex_power\""* ]]
}

@test "player-drivers info rwi_position says why and what to use" {
  run --separate-stderr "$player_drivers" info rwi_position
  [ "$status" -eq 0 ]
  [[ "$output" == *"unavailable"* ]]
  [[ "$output" == *"RWI's Mobility middleware"* ]]
  [[ "$output" == *"driver \"rflex_position\""* ]]
}
