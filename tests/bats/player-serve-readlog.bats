#!/usr/bin/env bats
# player-serve -r/-f (readlog) and writelog, end to end with player-cat.

load helpers

setup() {
  log="$BATS_TEST_TMPDIR/run.log"
  # Three position samples logged 0.2 s apart, data times 0.05 s before.
  cat > "$log" <<'LOG'
## Player version 1.5 
## File version 0.0.0 
1000.000 robot 6665 position 00 999.950 +0.100 +0.200 +1.571 +0.000 +0.000 +0.000 0
1000.100 robot 6665 sync 00 1000.100 
1000.200 robot 6665 position 00 1000.150 +0.300 +0.200 +1.571 +0.000 +0.000 +0.000 0
1000.400 robot 6665 position 00 1000.350 +0.500 +0.200 +1.571 +0.000 +0.000 +0.000 0
LOG
  cfg="$BATS_TEST_TMPDIR/replay.cfg"
  printf 'position:0 ( driver "readlog" )\n' > "$cfg"
}

teardown() {
  kill_left_running "${server_pid:-}"
}

@test "-r replays every logged sample to a client with its logged time" {
  # Half speed: samples 0.4 s apart, several server rounds each (a sensor
  # device hands clients its newest sample only, so faster would merge them).
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 -r "$log" -f 0.5 "$cfg"
  run --separate-stderr timeout 20 "$player_cat" "localhost:$server_port" position:0 -n 3 --format log
  [ "$status" -eq 0 ]
  data=$(grep ' position 00 ' <<<"$output")
  [ "$(wc -l <<<"$data")" -eq 3 ]
  # Token 5 is the logged data time; the x fields come back as logged.
  [ "$(awk '{print $6}' <<<"$data" | tr '\n' ' ')" = "0000000999.950000 0000001000.150000 0000001000.350000 " ]
  [ "$(awk '{print $7}' <<<"$data" | tr '\n' ' ')" = "+00.100 +00.300 +00.500 " ]
  # The server's own clock is log time: header times are the logged ones.
  [ "$(awk '{print $1}' <<<"$data" | tr '\n' ' ')" = "0000001000.000000 0000001000.200000 0000001000.400000 " ]
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
}

@test "writelog records the replay and loses nothing on SIGTERM" {
  rec="$BATS_TEST_TMPDIR/rec.log"
  printf 'position:0 ( driver "readlog" )\nnull:0 ( driver "writelog" filename "%s" devices ["position:0"] alwayson 1 )\n' \
    "$rec" > "$cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 -r "$log" -f 4 "$cfg"
  has_three() { [ "$(grep -c ' position 00 ' "$rec" 2>/dev/null || true)" -ge 3 ]; }
  wait_until --pid "$server_pid" --log "$BATS_TEST_TMPDIR/serve.err" --log "$rec" "3 position lines in rec.log" has_three
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
  [ "$(head -n 2 "$rec")" = "$(printf '## Player version 1.5 \n## File version 0.0.0 ')" ]
  [ "$(grep ' position 00 ' "$rec" | awk '{print $6, $7}' | tr '\n' ' ')" = \
    "0000000999.950000 +00.100 0000001000.150000 +00.300 0000001000.350000 +00.500 " ]
  # Every line is complete: it ends with its newline.
  [ "$(tail -c 1 "$rec" | od -An -c | tr -d ' ')" = '\n' ]
}

@test "-r with a missing log is a configuration error naming the file" {
  run "$player_serve" -p 0 -r "$BATS_TEST_TMPDIR/nope.log" "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"nope.log"* ]]
}

@test "-f must be above 0" {
  run "$player_serve" -p 0 -r "$log" -f 0 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"replay speed"* ]]
}

@test "readlog without -r or filename is refused" {
  run "$player_serve" -p 0 "$cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"readlog: no log file"* ]]
}
