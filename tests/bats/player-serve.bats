#!/usr/bin/env bats
# player-serve as a daemon: start-up errors, signals, plugins.

load helpers

setup() {
  cfg="$BATS_TEST_TMPDIR/mailbox.cfg"
  printf 'mcom:0 ( driver "lifomcom" )\n' > "$cfg"
}

teardown() {
  kill_left_running "${server_pid:-}"
}

@test "SIGTERM shuts the server down cleanly with exit 0" {
  start_server "$BATS_TEST_TMPDIR/log" -p 0 "$cfg"
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
  grep -q "received SIGTERM" "$BATS_TEST_TMPDIR/log"
  grep -q "all devices shut down" "$BATS_TEST_TMPDIR/log"
}

@test "SIGINT does the same" {
  start_server "$BATS_TEST_TMPDIR/log" -p 0 "$cfg"
  kill -INT "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
}

@test "the config file may come before the options" {
  start_server "$BATS_TEST_TMPDIR/log" "$cfg" -p 0 -v
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
}

@test "a port in use is a clear error, exit 1" {
  start_server "$BATS_TEST_TMPDIR/first.log" -p 0 "$cfg"
  run "$player_serve" -p "$server_port" "$cfg"
  [ "$status" -eq 1 ]
  [[ "$output" == *"port $server_port is already in use"* ]]
}

@test "a bad configuration is reported as file:line:col, exit 2" {
  printf 'mcom:0 ( driver "lifomcom" )\nlaser:0 ( driver "lifomcom" )\n' > "$cfg"
  run "$player_serve" -p 0 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"$cfg:2:1: driver 'lifomcom' does not serve interface 'laser' (it serves mcom)"* ]]
}

@test "a driver that is not built is reported where it is named, exit 2" {
  # rwi_laser needs RWI Mobility (CORBA), which Debian 12 cannot build.
  printf '\n  laser:0 ( driver "rwi_laser" )\n' > "$cfg"
  run timeout 20 "$player_serve" -p 0 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"$cfg:2:"*"rwi_laser"* ]]
}

@test "usage errors exit 2" {
  run "$player_serve" -p notaport "$cfg"
  [ "$status" -eq 2 ]
  run "$player_serve" --no-such-flag "$cfg"
  [ "$status" -eq 2 ]
  run "$player_serve" -p
  [ "$status" -eq 2 ]
}

@test "Gazebo's flag says it is not available; -s takes a world file, not 1.5's Stage directory" {
  run "$player_serve" -s /tmp -p 0 --bind 127.0.0.1 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"/tmp: cannot read the world file: it is a directory"* ]]
  run "$player_serve" -g 0 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"Gazebo (-g) is not available"* ]]
}

@test "-t udp says that only TCP is available" {
  run "$player_serve" -t udp "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"transport 'udp' is not available"* ]]
}

@test "-d loads a driver plugin; a missing plugin is an error, exit 1" {
  printf 'power:0 ( driver "simbattery" rate 5 )\n' > "$cfg"
  start_server "$BATS_TEST_TMPDIR/log" -p 0 -d "$battery_plugin" "$cfg"
  grep -q "loaded plugin" "$BATS_TEST_TMPDIR/log"
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
  run "$player_serve" -p 0 -d "$BATS_TEST_TMPDIR/missing.so" "$cfg"
  [ "$status" -eq 1 ]
  [[ "$output" == *"cannot load plugin $BATS_TEST_TMPDIR/missing.so"* ]]
}

@test "the server answers a client with the banner first" {
  start_server "$BATS_TEST_TMPDIR/log" -p 0 --bind 127.0.0.1 "$cfg"
  # fd 3 belongs to bats
  exec 5<>"/dev/tcp/127.0.0.1/$server_port"
  read_bytes --log "$BATS_TEST_TMPDIR/log" 5 12 "$BATS_TEST_TMPDIR/banner" "the banner's first 12 bytes"
  exec 5<&-
  [ "$(cat "$BATS_TEST_TMPDIR/banner")" = "Player v.1.5" ]
}
