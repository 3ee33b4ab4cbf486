#!/usr/bin/env bats
# The garminnmea family through player-drivers and player-serve: a GPS
# receiver emulated on a pseudo-terminal (generated fixes, or a real Garmin
# log played back), probed, run, traced, and served from data/config.
# Every wait is bounded; devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a GPS receiver: emulate, probe (no other family takes its sentences), run a fix as JSON" {
  gps="$BATS_TEST_TMPDIR/gps"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" garminnmea --link "$gps"
  grep -qx "garminnmea on $gps: gps:0 ( driver \"garminnmea\" port \"$gps\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$gps"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$gps: garminnmea at 4800 baud, Garmin GPS receiver ("*"GPGGA"*")"* ]]
  [[ "$output" == *"    gps:0 ( driver \"garminnmea\" port \"$gps\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run garminnmea "port=$gps" dgps_enable=0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].data.latitude' <<<"$output")" -eq 7348444 ]
  [ "$(jq -s -r '.[0].data.longitude' <<<"$output")" -eq -25549644 ]
  [ "$(jq -s -r '.[0].data.quality' <<<"$output")" -eq 1 ]
  stop_cleanly "$emulator_pid"
}

@test "a GPS receiver: --trace shows one NMEA sentence a line" {
  gps="$BATS_TEST_TMPDIR/gps"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" garminnmea --link "$gps"
  run --separate-stderr timeout 60 "$player_drivers" run garminnmea "port=$gps" dgps_enable=0 -n 3 --trace
  [ "$status" -eq 0 ]
  # Bytes in hex, a whole sentence a line: "$GPRMC," ... CR LF, "$PGRME,15.0,M,".
  grep -q '< 24 47 50 52 4D 43 2C .* 0D 0A$' <<<"$stderr"
  grep -q '< 24 50 47 52 4D 45 2C 31 35 2E 30 2C 4D 2C .* 0D 0A$' <<<"$stderr"
  [ -z "$(grep '^trace gps:0 .* < ' <<<"$stderr" | grep -v ' < 24 .* 0D 0A$')" ]
  stop_cleanly "$emulator_pid"
}

@test "a GPS receiver: a real Garmin 48 log played back, fixes at its times of day" {
  gps="$BATS_TEST_TMPDIR/gps"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" garminnmea --link "$gps" \
    "log=$repo_root/tests/data/gpsd-garmin/garmin48.log" loop=1 rate=4
  run --separate-stderr timeout 60 "$player_drivers" run garminnmea "port=$gps" dgps_enable=0 -n 4 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 4 ]
  # 45 deg 27.458' S, 167 deg 09.165' E in 1/60 arc-seconds, between 22:53:08 and 22:53:35 UTC
  # (on 2001-06-06 once an RMC gave the date; a GGA heard before it has the time of day alone).
  [ "$(jq -s -r '[.[].data.latitude] | unique | .[]' <<<"$output")" -eq -9818849 ]
  [ "$(jq -s -r '[.[].data.longitude] | unique | .[]' <<<"$output")" -eq 36104994 ]
  jq -s -e 'all(.[]; .data.time_sec % 86400 >= 82388 and .data.time_sec % 86400 <= 82415)' <<<"$output"
  jq -s -e 'all(.[]; .data.time_sec < 86400 or (.data.time_sec >= 991867988 and .data.time_sec <= 991868015))' <<<"$output"
  stop_cleanly "$emulator_pid"
}

@test "a GPS receiver: bad checksums on the line are counted and skipped" {
  gps="$BATS_TEST_TMPDIR/gps"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" garminnmea --link "$gps" \
    period=0.1 --fault bad-checksum=0.3
  run --separate-stderr timeout 60 "$player_drivers" run garminnmea "port=$gps" dgps_enable=0 -n 20 --format json --stats
  [ "$status" -eq 0 ]
  [ "$(jq -s '[.[] | select(.data.latitude == 7348444)] | length' <<<"$output")" -eq 20 ]
  [[ "$stderr" == *"checksum_errors"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/garminnmea.cfg serves the emulated receiver" {
  gps="$BATS_TEST_TMPDIR/gps"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" garminnmea --link "$gps" period=0.2
  sed "s|\"/tmp/gps\"|\"$gps\"|" "$repo_root/data/config/garminnmea.cfg" >"$BATS_TEST_TMPDIR/garminnmea.cfg"
  grep -q "port \"$gps\"" "$BATS_TEST_TMPDIR/garminnmea.cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/garminnmea.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" gps:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = gps ]
  [ "$(jq -s -r '.[0].data.latitude' <<<"$output")" -eq 7348444 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}
