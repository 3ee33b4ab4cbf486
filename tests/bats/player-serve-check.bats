#!/usr/bin/env bats
# player-serve --check: configuration validation from the command line.

load helpers

# A Player log of one position line, and a map beside a copy of
# post-hoc-localization.cfg: what its readlog (-r) and amcl devices need.
write_replay_log() {
  printf '## Player version 1.5 \n## File version 0.0.0 \n0000001000.000 h 6665 position 00 0000001000.000 +01.000 +02.000 +0.000 +0.000 +0.000 +0.000 0 \n' > "$1"
}

@test "--check lists the devices of a valid configuration and exits 0" {
  cp "$repo_root/data/config/post-hoc-localization.cfg" "$BATS_TEST_TMPDIR/"
  { printf 'P2\n8 8\n255\n'; for _ in $(seq 1 64); do printf '254 '; done; printf '\n'; } > "$BATS_TEST_TMPDIR/intel-lab-map.pgm"
  printf 'image: intel-lab-map.pgm\nresolution: 0.5\norigin: [-2.0, -2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' \
    > "$BATS_TEST_TMPDIR/intel-lab-map.yaml"
  write_replay_log "$BATS_TEST_TMPDIR/run.log"
  run "$player_serve" --check -r "$BATS_TEST_TMPDIR/run.log" "$BATS_TEST_TMPDIR/post-hoc-localization.cfg"
  [ "$status" -eq 0 ]
  [[ "${lines[0]}" == *"post-hoc-localization.cfg: 3 devices, served on port 6665" ]]
  [[ "$output" =~ localize:0\ +driver\ amcl ]]
  [[ "$output" != *"not in this build"* ]]
  [[ "$output" == *'map_file "intel-lab-map.yaml"'* ]]
}

@test "--check shows robot names and always-on devices" {
  run "$player_serve" --check "$repo_root/data/config/messaging.cfg"
  [ "$status" -eq 0 ]
  [[ "$output" =~ mcom:0\ +driver\ lifomcom,\ robot\ mailbox ]]  # built in: no mark
  run "$player_serve" --check "$repo_root/data/config/record.cfg"
  [[ "$output" =~ null:0\ +driver\ writelog,\ always\ on ]]
}

@test "--check -p changes the port of devices outside robot sections" {
  write_replay_log "$BATS_TEST_TMPDIR/run.log"
  run "$player_serve" --check -p 7000 -r "$BATS_TEST_TMPDIR/run.log" "$repo_root/data/config/replay.cfg"
  [ "$status" -eq 0 ]
  [[ "${lines[0]}" == *"served on port 7000" ]]
}

@test "a broken configuration is reported as file:line:col and exits 2" {
  cfg="$BATS_TEST_TMPDIR/broken.cfg"
  printf 'position:0 (driver "readlog")\nlazer:1 ()\n' > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == "$cfg:2:1: unknown interface 'lazer'"* ]]
}

@test "a missing configuration file is an error naming the file, exit 2" {
  run "$player_serve" --check "$BATS_TEST_TMPDIR/nope.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"nope.cfg"* ]]
}

@test "no configuration file and no world is a usage error, exit 2" {
  run "$player_serve"
  [ "$status" -eq 2 ]
  [[ "$output" == *"nothing to serve: give a configuration file, -s WORLD, or both"* ]]
}

@test "--help shows examples and exit codes; --version names the protocol" {
  run "$player_serve" --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"Examples:"* ]]
  [[ "$output" == *"Exit status"* ]]
  run "$player_serve" --version
  [ "$status" -eq 0 ]
  [[ "$output" == *"Player protocol 1.5"* ]]
}

# check_refuses_bad_ports INTERFACE DRIVER COLUMN: --check refuses both
# malformed tcp: ports at the value's file:line:col (COLUMN), the same way
# for every family's one `port` option.
check_refuses_bad_ports() {
  local interface="$1" driver="$2" column="$3" cfg="$BATS_TEST_TMPDIR/$2.cfg" port
  printf '%s:0 ( driver "%s" port "%s/ttyUSB0" )\n' "$interface" "$driver" "$BATS_TEST_TMPDIR" > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 0 ] || skip "$driver is not built: $output"
  for port in tcp:localhost tcp:localhost:99999; do
    printf '%s:0 ( driver "%s" port "%s" )\n' "$interface" "$driver" "$port" > "$cfg"
    run "$player_serve" --check "$cfg"
    [ "$status" -eq 2 ]
    [[ "$output" == "$cfg:1:$column: $driver: port is not a serial port or tcp:HOST:PORT: bad port '$port'"* ]]
  done
}

@test "--check refuses a sicklms200 port that is no tty path or tcp:HOST:PORT, at its value" {
  check_refuses_bad_ports laser sicklms200 36
}

@test "--check refuses a sickpls port that is no tty path or tcp:HOST:PORT, at its value" {
  check_refuses_bad_ports laser sickpls 33
}

@test "--check refuses a p2os port that is no tty path or tcp:HOST:PORT, at its value" {
  check_refuses_bad_ports position p2os_position 42
}

@test "every bundled configuration passes --check as the demo checks it (a world's with its world)" {
  # Replays need their log and map (the first test checks post-hoc-localization.cfg with them).
  for cfg in "$repo_root"/data/config/*.cfg; do
    grep -q '"readlog"' "$cfg" && continue
    world=$(sed -n 's/^#.*player-serve -s \([^ ]*\) .*/\1/p' "$cfg" | head -n 1)
    if [ -n "$world" ]; then
      run "$player_serve" --check -s "$repo_root/$world" "$cfg"
    else
      run "$player_serve" --check "$cfg"
    fi
    [ "$status" -eq 0 ] || { echo "$cfg: $output"; return 1; }
  done
}
