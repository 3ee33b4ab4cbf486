#!/usr/bin/env bats
# Bounded inputs and safe messages (docs/limits.md): small hostile inputs cost
# little memory and time, messages never copy raw bytes of input to the
# terminal, and player-serve --check refuses what serving would refuse.

load helpers

teardown() {
  kill_left_running "${server_pid:-}"
}

# A Player log of one position line, for readlog and -r.
write_player_log() {
  printf '## Player version 1.5 \n## File version 0.0.0 \n0000001000.000 h 6665 position 00 0000001000.000 +01.000 +02.000 +0.000 +0.000 +0.000 +0.000 0 \n' > "$1"
}

# has_raw_escape TEXT: true when TEXT holds an ESC byte.
has_raw_escape() {
  [[ "$1" == *$'\e'* ]]
}

@test "include \"/dev/zero\" is refused at once, at the include" {
  cfg="$BATS_TEST_TMPDIR/zero.cfg"
  printf 'laser:0 ( driver "null" )\ninclude "/dev/zero"\n' > "$cfg"
  run timeout 10 "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [ "$output" = "$cfg:2:9: cannot read include file '/dev/zero': it is not a regular file (a device, a pipe or a socket) (looked for /dev/zero)" ]
}

@test "a configuration that is a directory or too large is refused, naming it" {
  run "$player_serve" --check "$BATS_TEST_TMPDIR"
  [ "$status" -eq 2 ]
  [ "$output" = "$BATS_TEST_TMPDIR: cannot read config file: it is a directory, not a file" ]
  big="$BATS_TEST_TMPDIR/big.cfg"
  head -c 1100000 /dev/zero | tr '\0' '#' > "$big"
  run "$player_serve" --check "$big"
  [ "$status" -eq 2 ]
  [[ "$output" == "$big: cannot read config file: too large: a configuration with its includes may have 1048576 bytes at most" ]]
}

@test "a long misspelt driver name: no suggestion search, the name cut in the message" {
  cfg="$BATS_TEST_TMPDIR/long.cfg"
  name="$(head -c 60000 /dev/zero | tr '\0' 'd')"
  printf 'laser:0 ( driver "sicklms200%s" )\n' "$name" > "$cfg"
  run timeout 10 "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == "$cfg:1:18: unknown driver 'sicklms200ddd"*"…' for laser:0" ]]
  [ "${#output}" -lt 300 ]
}

@test "control characters of a configuration reach the terminal escaped" {
  cfg="$BATS_TEST_TMPDIR/escape.cfg"
  printf 'laser:0 ( driver "x\033[2J\033]0;owned\007" )\n' > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  ! has_raw_escape "$output"
  [ "$output" = "$cfg:1:18: unknown driver 'x\\x1b[2J\\x1b]0;owned\\x07' for laser:0" ]
}

@test "a gzip log of one huge line: the line is reported, not kept or printed" {
  log="$BATS_TEST_TMPDIR/bomb.log.gz"
  { write_player_log /dev/stdout; printf '0000001001.000 h 6665 position 00 0000001001.000 '
    head -c 50000000 /dev/zero | tr '\0' '9'; printf '\n'; } | gzip -1 > "$log"
  run --separate-stderr timeout 60 "$player_log" info "$log"
  [ "$status" -eq 0 ]
  [[ "$output$stderr" == *"bomb.log.gz:4:1048577: line longer than 1048576 bytes"* ]]
  [ "${#output}" -lt 5000 ]
  [ "${#stderr}" -lt 5000 ]
}

@test "amcl-offline map: a resolution that would need too many cells names one that fits" {
  run --separate-stderr timeout 60 "$amcl_offline" map "$repo_root/tests/data/radish/intel-corrected.log.gz" \
    -o "$BATS_TEST_TMPDIR/map.pgm" --resolution 0.0001
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"amcl-offline: a map of "*" cells ("*" million) is more than the limit of 50 million at a resolution of 0.0001 m (the area seen so far, "*" fits at "*" m or coarser)"* ]]
  [ ! -e "$BATS_TEST_TMPDIR/map.pgm" ]
}

@test "a map image declaring billions of pixels is refused from its header" {
  printf 'P5\n100000 100000\n255\n' > "$BATS_TEST_TMPDIR/huge.pgm"
  write_player_log "$BATS_TEST_TMPDIR/run.log"
  cfg="$BATS_TEST_TMPDIR/amcl.cfg"
  printf 'position:0 ( driver "readlog" filename "run.log" )\nlaser:0 ( driver "readlog" filename "run.log" )\nlocalize:0 ( driver "amcl" map_file "huge.pgm" map_scale 0.05 )\n' > "$cfg"
  run timeout 10 "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == "$cfg:3:37: amcl: cannot load the map: $BATS_TEST_TMPDIR/huge.pgm: a map of 100000 x 100000 cells (10000 million) is more than the limit of 50 million" ]]
}

@test "--check refuses an empty configuration" {
  cfg="$BATS_TEST_TMPDIR/empty.cfg"
  printf '# no devices\n' > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [ "$output" = "$cfg: no devices declared, nothing to serve" ]
}

@test "--check refuses a writelog file that is a directory or in no directory, creating nothing" {
  write_player_log "$BATS_TEST_TMPDIR/run.log"
  cfg="$BATS_TEST_TMPDIR/record.cfg"
  printf 'position:0 ( driver "readlog" filename "run.log" )\nnull:0 ( driver "writelog" filename "%s" devices ["position:0"] alwayson 1 )\n' \
    "$BATS_TEST_TMPDIR" > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [ "$output" = "$cfg:2:37: writelog: filename \"$BATS_TEST_TMPDIR\" is a directory" ]
  printf 'position:0 ( driver "readlog" filename "run.log" )\nnull:0 ( driver "writelog" filename "%s/nowhere/out.log" devices ["position:0"] )\n' \
    "$BATS_TEST_TMPDIR" > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == "$cfg:2:37: writelog: filename \"$BATS_TEST_TMPDIR/nowhere/out.log\": directory $BATS_TEST_TMPDIR/nowhere does not exist" ]]
  # A writelog of a device that is not declared.
  printf 'null:0 ( driver "writelog" filename "%s/out.log" devices ["laser:0"] )\n' "$BATS_TEST_TMPDIR" > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [ "$output" = "$cfg:1:1: writelog: no device laser:0@6665 to record" ]
  [ ! -e "$BATS_TEST_TMPDIR/out.log" ]
}

@test "--check refuses an amcl map that is a directory and a readlog file that is missing" {
  write_player_log "$BATS_TEST_TMPDIR/run.log"
  cfg="$BATS_TEST_TMPDIR/amcl.cfg"
  printf 'position:0 ( driver "readlog" filename "run.log" )\nlaser:0 ( driver "readlog" filename "run.log" )\nlocalize:0 ( driver "amcl" map_file "." map_scale 0.05 )\n' > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == "$cfg:3:37: amcl: cannot load the map: $BATS_TEST_TMPDIR/.: it is a directory, not a file" ]]
  printf 'laser:0 ( driver "readlog" filename "gone.log" )\n' > "$cfg"
  run "$player_serve" --check "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"cannot open $BATS_TEST_TMPDIR/gone.log: No such file or directory" ]]
}

@test "player-serve --bogus names the unknown flag, even without CONFIG" {
  run "$player_serve" --bogus
  [ "$status" -eq 2 ]
  [ "${lines[0]}" = "The following argument was not expected: --bogus" ]
  [ "${lines[1]}" = "Run with --help for more information." ]
  run "$player_serve" $'--bo\e[2Jgus' "$repo_root/data/config/messaging.cfg"
  [ "$status" -eq 2 ]
  ! has_raw_escape "$output"
  [ "${lines[0]}" = 'The following argument was not expected: --bo\x1b[2Jgus' ]
}

@test "every tool quotes an unknown flag back escaped, exit 2" {
  for tool in "$player_cat" "$player_send" "$player_log" "$amcl_offline" "$build_dir/tools/drivers/player-drivers"; do
    run --separate-stderr "$tool" $'--bo\e[2Jgus'
    [ "$status" -eq 2 ]
    ! has_raw_escape "$stderr"
    [[ "$stderr" == *'--bo\x1b[2Jgus'* ]]
  done
}

@test "player-serve -r with a missing log fails before listening, naming the file" {
  run timeout 20 "$player_serve" -p 0 -r "$BATS_TEST_TMPDIR/nonexistent.log" "$repo_root/data/config/replay.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" != *"listening"* ]]
  [ "$output" = "player-serve: error: cannot open $BATS_TEST_TMPDIR/nonexistent.log: No such file or directory" ]
}

@test "player-serve -r with a CARMEN log says so and what replays it" {
  log="$repo_root/tests/data/radish/intel-corrected.log.gz"
  run timeout 20 "$player_serve" -p 0 -r "$log" "$repo_root/data/config/replay.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" != *"listening"* ]]
  [[ "$output" == *"$log is a CARMEN log; readlog replays Player text logs: serve it with \`player-log replay $log\`"* ]]
  run "$player_serve" --check -r "$log" "$repo_root/data/config/replay.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"is a CARMEN log"* ]]
}

@test "player-send --stdin stops at a line over the cap" {
  cfg="$BATS_TEST_TMPDIR/mailbox.cfg"
  printf 'mcom:0 ( driver "lifomcom" )\n' > "$cfg"
  start_server "$BATS_TEST_TMPDIR/server.log" -p 0 "$cfg"
  run --separate-stderr bash -c "head -c 2000000 /dev/zero | tr '\\0' x | timeout 20 '$player_send' --stdin 127.0.0.1:$server_port"
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"player-send: line 1: line longer than 1048576 bytes"* ]]
  [ "${#stderr}" -lt 1000 ]
}
