#!/usr/bin/env bats
# The nomad family through player-drivers and player-serve: a Nomad 200
# emulated behind its server on a loopback TCP port (as Nomadic's Nserver
# listened), run by host and port, traced, driven by a client and served
# from data/config. There is no serial probe: a Nomad is found by its
# server's address. Every wait is bounded.

load helpers

teardown() {
  kill_left_running "${run_pid:-}" "${emulator_pid:-}" "${server_pid:-}"
}

# start_nomad: the emulated robot on a free port; sets nomad_port.
start_nomad() {
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" nomad --tcp 0 "$@"
  nomad_port="$(sed -n 's/^nomad on tcp:127.0.0.1:\([0-9]*\): .*/\1/p' "$BATS_TEST_TMPDIR/emulate.out")"
  [ -n "$nomad_port" ]
  grep -qx "nomad on tcp:127.0.0.1:$nomad_port: nomad:0 ( driver \"nomad\" port \"tcp:127.0.0.1:$nomad_port\" )" \
    "$BATS_TEST_TMPDIR/emulate.out"
}

@test "a Nomad 200: emulate on TCP, run by host and port, no serial probe claims it" {
  start_nomad
  run --separate-stderr timeout 60 "$player_drivers" run nomad host=127.0.0.1 "port=$nomad_port" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].data.sonar[0]' <<<"$output")" -eq 6477 ]  # 255 inches: nothing in sight

  # The emulator's own config line runs unchanged.
  run --separate-stderr timeout 60 "$player_drivers" run nomad "port=tcp:127.0.0.1:$nomad_port" -n 1 --format json
  [ "$status" -eq 0 ]

  # The probe asks serial families only; none takes the Nomad's server for its device.
  run --separate-stderr timeout 60 "$player_drivers" probe "tcp:127.0.0.1:$nomad_port"
  [ "$status" -ne 0 ]
  [[ "$output$stderr" == *"no supported device answered"* ]]

  run timeout 30 "$player_drivers" info nomad
  [ "$status" -eq 0 ]
  [[ "$output" == *"host"* ]]
  [[ "$output" == *"7019"* ]]
  stop_cleanly "$emulator_pid"
}

@test "a client's velocity goes out as VM, the robot moves, and leaving stops it" {
  start_nomad
  run_until "a reading 10 cm on" 'select(.data.x > 100)' \
    '{"device":"nomad:0","data":{"vel_trans":254,"vel_steer":0,"vel_turret":0}}' \
    nomad "port=tcp:127.0.0.1:$nomad_port" --trace
  stderr=$(cat "$run_err")
  output=$(cat "$readings")
  # The reference's setup: CONNECT_ROBOT (102), CT, CONF_TM 5, ZR, AC 300s, SP 200/450/450.
  [[ "$stderr" == *"> 00 66 00 02 00 00 00 01"* ]]
  [[ "$stderr" == *"> 00 1A 00 01 00 00 00 05"* ]]
  [[ "$stderr" == *"> 00 14 00 00"* ]]
  [[ "$stderr" == *"> 00 0B 00 03 00 00 00 C8 00 00 01 C2 00 00 01 C2"* ]]
  # 254 mm/s = 100 tenths of an inch a second.
  [[ "$stderr" == *"> 00 0C 00 03 00 00 00 64 00 00 00 00 00 00 00 00"* ]]
  [ "$(jq -s '[.[] | select(.data.x > 100)] | length' <<<"$output")" -gt 0 ]
  [ "$(jq -s -r '.[-1].data.vel_trans' <<<"$output")" -eq 254 ]
  # Leaving, the driver stopped the robot (VM 0 0 0 after the last GS).
  last_vm="$(grep '> 00 0C 00 03' <<<"$stderr" | tail -n 1)"
  [[ "$last_vm" == *"> 00 0C 00 03 00 00 00 00 00 00 00 00 00 00 00 00"* ]]
  stop_cleanly "$emulator_pid"
}

@test "data/config/nomad.cfg serves the emulated robot as nomad, position and sonar" {
  start_nomad
  sed "s|^  port 7019$|  port $nomad_port|" "$repo_root/data/config/nomad.cfg" >"$BATS_TEST_TMPDIR/nomad.cfg"
  grep -q "port $nomad_port" "$BATS_TEST_TMPDIR/nomad.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/nomad.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/nomad.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = position ]
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" sonar:0 -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.data.range_count' <<<"$output")" -eq 16 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "1.5's form is read unchanged, and a bad port is refused at its place" {
  printf '%s\n' 'nomad:0 ( driver "nomad" serial_device "/tmp/nomad-direct-serial" serial_speed 9600 )' \
    'position:0 ( driver "nomad_position" nomad_index 0 )' \
    'sonar:0 ( driver "nomad_sonar" nomad_index 0 )' >"$BATS_TEST_TMPDIR/nomad15.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/nomad15.cfg"
  [ "$status" -eq 0 ]
  printf 'nomad:0 ( driver "nomad" port 70190 )\n' >"$BATS_TEST_TMPDIR/bad.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/bad.cfg"
  [ "$status" -ne 0 ]
  [[ "$output" == *"bad.cfg:1:"*"nomad: port must be the Nomad server's TCP port"* ]]
  printf 'position:0 ( driver "nomad_position" nomad_index 1 )\n' >"$BATS_TEST_TMPDIR/missing.cfg"
  run "$player_serve" --check "$BATS_TEST_TMPDIR/missing.cfg"
  [ "$status" -ne 0 ]
  [[ "$output" == *"no nomad:1 on port 6665"* ]]
}

@test "the emulated Nomad carries an emulated laser and sees the map with its sonar" {
  laser="$BATS_TEST_TMPDIR/laser"
  start_nomad sicklms200 --link "$laser" --map "$repo_root/data/maps/stage-cave.png"
  grep -q "rides on the emulated robot" "$BATS_TEST_TMPDIR/emulate.err"
  grep -qx "sicklms200 on $laser: laser:0 ( driver \"sicklms200\" port \"$laser\" )" "$BATS_TEST_TMPDIR/emulate.out"
  run --separate-stderr timeout 60 "$player_drivers" run nomad "port=tcp:127.0.0.1:$nomad_port" -n 2 --format json
  [ "$status" -eq 0 ]
  # Walls in sight: some sonar reads short of its 255 inches (6477 mm).
  [ "$(jq -s '[.[-1].data.sonar[] | select(. < 6477)] | length' <<<"$output")" -gt 0 ]
  run --separate-stderr timeout 60 "$player_drivers" run sicklms200 "port=$laser" -n 1 --format json
  [ "$status" -eq 0 ]
  stop_cleanly "$emulator_pid"
}
