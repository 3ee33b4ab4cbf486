#!/usr/bin/env bats
# player-cat against a real player-serve on a free loopback port. Data comes
# from the example battery plugin (power, published at `rate` Hz) and from
# udpbroadcast (comms: each datagram heard on its port is data).

load helpers

setup() {
  cfg="$BATS_TEST_TMPDIR/battery.cfg"
  printf 'power:0 ( driver "simbattery" volts 12.6 drain 0 rate 50 )\n' > "$cfg"
}

teardown() {
  kill_left_running "${cat_pid:-}" "${server_pid:-}" "${helper_pid:-}"
}

serve_battery() {
  start_server "$BATS_TEST_TMPDIR/server.log" -p 0 --bind 127.0.0.1 -d "$battery_plugin" "$@" "$cfg"
  target="127.0.0.1:$server_port"
}

# free_port tcp|udp: a port nobody listens on right now.
free_port() {
  python3 -c 'import socket, sys
kind = socket.SOCK_STREAM if sys.argv[1] == "tcp" else socket.SOCK_DGRAM
s = socket.socket(socket.AF_INET, kind); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])' "$1"
}

# each_line_matches REGEX: every line of $output matches (and there is one).
each_line_matches() {
  [ -n "$output" ]
  while IFS= read -r line; do
    [[ "$line" =~ $1 ]] || { echo "line does not match $1: $line"; return 1; }
  done <<< "$output"
}

@test "--help shows the usage, formats, examples and exit codes on stdout" {
  run --separate-stderr "$player_cat" --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"[HOST[:PORT]] DEVICE..."* ]]
  [[ "$output" == *"Examples:"* ]]
  [[ "$output" == *"player-cat laser --format log"* ]]
  [[ "$output" == *"Exit status: 0 done"* ]]
  [[ "$output" == *"2 usage error"* ]]
  run "$player_cat" --version
  [ "$status" -eq 0 ]
  [[ "$output" == "player-cat (playerkit) "* ]]
}

@test "usage errors exit 2 with a message naming the problem" {
  run "$player_cat"
  [ "$status" -eq 2 ]
  [[ "$output" == *"name at least one device"* ]]
  run "$player_cat" lazer:0
  [ "$status" -eq 2 ]
  [[ "$output" == *"'lazer:0' is neither a device"* ]]
  run "$player_cat" localhost laser:zero
  [ "$status" -eq 2 ]
  [[ "$output" == *"'laser:zero' is not a device"* ]]
  run "$player_cat" laser --format xml
  [ "$status" -eq 2 ]
  [[ "$output" == *"--format 'xml'"* ]]
  run "$player_cat" laser power --format csv
  [ "$status" -eq 2 ]
  [[ "$output" == *"CSV on stdout takes one device"*"--csv-dir DIR"* ]]
  run "$player_cat" laser --csv-dir "$BATS_TEST_TMPDIR/x"
  [ "$status" -eq 2 ]
  [[ "$output" == *"--csv-dir writes CSV files: it needs --format csv"* ]]
  run "$player_cat" laser -n 0
  [ "$status" -eq 2 ]
  run "$player_cat" laser -n many
  [ "$status" -eq 2 ]
  run "$player_cat" laser --duration -1
  [ "$status" -eq 2 ]
  run "$player_cat" laser --field 'a..b'
  [ "$status" -eq 2 ]
  run "$player_cat" laser --mode sometimes
  [ "$status" -eq 2 ]
  run "$player_cat" laser --rate 2.5
  [ "$status" -eq 2 ]
  [[ "$output" == *"whole number"* ]]
  run "$player_cat" laser -t q
  [ "$status" -eq 2 ]
  run "$player_cat" laser --format log -t z
  [ "$status" -eq 2 ]
  run "$player_cat" laser --format log --si
  [ "$status" -eq 2 ]
  run "$player_cat" laser --no-such-flag
  [ "$status" -eq 2 ]
  run "$player_cat" --list laser
  [ "$status" -eq 2 ]
  [ ! -e "$BATS_TEST_TMPDIR/x" ]
}

@test "a refused connection is a clear error, exit 1" {
  port="$(free_port tcp)"
  run "$player_cat" "127.0.0.1:$port" power
  [ "$status" -eq 1 ]
  [[ "$output" == "player-cat: cannot connect to 127.0.0.1:$port: "* ]]
}

@test "a peer that never greets times out, exit 1" {
  # The kernel accepts the connection into the backlog; nobody ever writes.
  python3 -c 'import socket, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(4)
print(s.getsockname()[1], flush=True); time.sleep(300)' > "$BATS_TEST_TMPDIR/port" &
  helper_pid=$!
  wait_for_lines --pid "$helper_pid" "$BATS_TEST_TMPDIR/port" 1
  run "$player_cat" "127.0.0.1:$(cat "$BATS_TEST_TMPDIR/port")" power --timeout 0.3
  [ "$status" -eq 1 ]
  [[ "$output" == *"within the timeout"* ]]
}

@test "--list prints the devices with their drivers and needs no device" {
  printf 'power:0 ( driver "simbattery" )\nmcom:2 ( driver "lifomcom" )\n' > "$cfg"
  serve_battery
  run --separate-stderr "$player_cat" "$target" --list
  [ "$status" -eq 0 ]
  [ "$output" = "$(printf 'power:0 simbattery\nmcom:2 lifomcom')" ]
}

@test "an unknown device is named with what the server has, exit 1" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power:0 laser:3
  [ "$status" -eq 1 ]
  [ -z "$output" ]
  [[ "$stderr" == *"127.0.0.1:$server_port has no device laser:3"* ]]
  [[ "$stderr" == *"power:0 simbattery"* ]]
}

@test "a device whose driver cannot set up is access 'e', exit 1" {
  # udpbroadcast cannot listen on a UDP port held by a socket that does not share it.
  python3 -c 'import socket, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("0.0.0.0", 0))
print(s.getsockname()[1], flush=True); time.sleep(300)' > "$BATS_TEST_TMPDIR/port" &
  helper_pid=$!
  wait_for_lines --pid "$helper_pid" "$BATS_TEST_TMPDIR/port" 1
  printf 'comms:0 ( driver "udpbroadcast" addr "127.0.0.1" port %s )\n' "$(cat "$BATS_TEST_TMPDIR/port")" > "$cfg"
  serve_battery
  run --separate-stderr "$player_cat" "$target" comms
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"comms:0 (driver udpbroadcast)"*"could not be opened"*"access 'e'"* ]]
  [[ "$stderr" == *"comms:0 udpbroadcast"* ]]
}

@test "text: one readable line per message, -n counts them" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power:0 -n 3
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 3 ]
  each_line_matches '^power:0 t=[0-9]{10}\.[0-9]{6} charge=126$'
  [ -z "$stderr" ]
}

@test "json: one object per line with time, timestamp, device, index, type and data" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power -n 2 --format json
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  python3 - "$output" <<'PY'
import json, sys
for line in sys.argv[1].splitlines():
    m = json.loads(line)
    assert set(m) == {"time", "timestamp", "device", "index", "type", "data"}, m
    assert (m["device"], m["index"], m["type"], m["data"]) == ("power", 0, "data", {"charge": 126}), m
    assert m["time"] > 1e9 and m["timestamp"] > 1e9, m
PY
}

@test "csv: a header row, then rows" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power --format csv -n 2
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 3 ]
  [ "${lines[0]}" = "time,timestamp,device,index,charge" ]
  [[ "${lines[1]}" =~ ^[0-9]{10}\.[0-9]{6},[0-9]{10}\.[0-9]{6},power,0,126$ ]]
  [[ "${lines[2]}" =~ ^[0-9]{10}\.[0-9]{6},[0-9]{10}\.[0-9]{6},power,0,126$ ]]
}

@test "csv --csv-dir writes one file per device" {
  printf 'power:0 ( driver "simbattery" volts 12.6 drain 0 rate 50 )\npower:1 ( driver "simbattery" volts 24.0 drain 0 rate 50 )\n' > "$cfg"
  serve_battery
  run --separate-stderr "$player_cat" "$target" power:0 power:1 --format csv --csv-dir "$BATS_TEST_TMPDIR/csv" --once
  [ "$status" -eq 0 ]
  [ -z "$output" ]
  [ "$(head -n 1 "$BATS_TEST_TMPDIR/csv/power_0.csv")" = "time,timestamp,device,index,charge" ]
  [[ "$(sed -n 2p "$BATS_TEST_TMPDIR/csv/power_0.csv")" == *",power,0,126" ]]
  [[ "$(sed -n 2p "$BATS_TEST_TMPDIR/csv/power_1.csv")" == *",power,1,240" ]]
  [ "$(wc -l < "$BATS_TEST_TMPDIR/csv/power_1.csv")" -eq 2 ]
}

@test "log: the Player log header, then writelog's data lines" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power --format log -n 2
  [ "$status" -eq 0 ]
  [ "${lines[0]}" = "## Player version 1.5 " ]
  [ "${lines[1]}" = "## File version 0.0.0 " ]
  # a data line (volts, lib/log's power layout), the round's sync line, the
  # second data line; times with microseconds
  [ "${#lines[@]}" -eq 5 ]
  prefix="^[0-9]{10}\.[0-9]{6} 127\.0\.0\.1 $server_port"
  [[ "${lines[2]}" =~ $prefix\ power\ 00\ [0-9]{10}\.[0-9]{6}\ 12\.6$ ]]
  [[ "${lines[3]}" =~ $prefix\ sync\ 00\ [0-9]{10}\.[0-9]{6}\ $ ]]
  [[ "${lines[4]}" =~ $prefix\ power\ 00\ [0-9]{10}\.[0-9]{6}\ 12\.6$ ]]
}

@test "--once prints one message per device, then exits" {
  printf 'power:0 ( driver "simbattery" drain 0 rate 50 )\npower:1 ( driver "simbattery" drain 0 rate 50 )\n' > "$cfg"
  serve_battery
  run --separate-stderr "$player_cat" "$target" power:0 power:1 --once
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  [ "$(grep -c '^power:0 ' <<< "$output")" -eq 1 ]
  [ "$(grep -c '^power:1 ' <<< "$output")" -eq 1 ]
}

@test "--duration stops after that long with status 0" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power --duration 0.5
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -ge 1 ]
  each_line_matches '^power:0 t='
}

@test "--field prints just those paths; a field the data lacks is a usage error" {
  serve_battery
  # a device after --field is a device, not a second field
  run --separate-stderr "$player_cat" "$target" --field charge power --once
  [ "$status" -eq 0 ]
  [[ "$output" =~ ^power:0\ t=[0-9.]+\ charge=126$ ]]
  run --separate-stderr "$player_cat" "$target" power --once --field charge --format json
  [ "$status" -eq 0 ]
  [[ "$output" == *'"data":{"charge":126}'* ]]
  run --separate-stderr "$player_cat" "$target" power --once --field charge --format csv
  [ "${lines[0]}" = "time,timestamp,device,index,charge" ]
  run --separate-stderr "$player_cat" "$target" power --once --field ranges.0
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"power:0 has no field 'ranges.0'; its data has: charge"* ]]
}

@test "--mode: each data mode delivers data" {
  serve_battery
  for mode in push-new push-all pull-new pull-all; do
    run --separate-stderr "$player_cat" "$target" power --mode "$mode" --rate 25 -n 2
    [ "$status" -eq 0 ]
    [ "${#lines[@]}" -eq 2 ]
    each_line_matches '^power:0 t=[0-9.]+ charge=126$'
  done
  run --separate-stderr "$player_cat" "$target" power --mode pull-all --rate 0.5 --once
  [ "$status" -eq 0 ]
}

@test "--rate: rounds come no closer than 1/rate (server frequency, or pull pacing)" {
  serve_battery
  # A lower bound only, on the wall clock: the server never pushes sooner than
  # 1/frequency and player-cat never asks sooner than 1/rate, so 5 rounds at
  # 4 Hz span at least 1 s (at the default 10 Hz they would take 0.4 s). The
  # data's own timestamps are not used: each round carries the driver's latest
  # sample, whose age a loaded machine changes from round to round.
  for mode in push-all pull-all; do
    local start end
    start=$(date +%s.%N)
    run --separate-stderr "$player_cat" "$target" power --mode "$mode" --rate 4 -n 5
    end=$(date +%s.%N)
    [ "$status" -eq 0 ]
    [ "${#lines[@]}" -eq 5 ]
    awk -v s="$start" -v e="$end" 'BEGIN { exit !(e - s >= 0.95) }'
  done
}

@test "--key authenticates; a wrong or missing key is an error, exit 1" {
  serve_battery -k secret
  run --separate-stderr "$player_cat" "$target" power --key secret --once
  [ "$status" -eq 0 ]
  [[ "$output" == "power:0 t="* ]]
  run --separate-stderr "$player_cat" "$target" power --key wrong --once
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"authentication refused"* ]]
  run --separate-stderr "$player_cat" "$target" power --once --timeout 0.3
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"pass --key"* ]]
}

@test "-t a, d and z: absolute, delta and zero-based times" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power -n 3 -t a
  each_line_matches '^power:0 t=[0-9]{10}\.[0-9]{6} '
  now="$(date +%s)"
  first="$(sed -n 's/^power:0 t=\([0-9]*\)\..*/\1/p' <<< "${lines[0]}")"
  # the server and this shell share a clock
  [ $((now - first)) -lt 600 ] && [ $((first - now)) -lt 600 ]
  run --separate-stderr "$player_cat" "$target" power -n 3 -t z --mode push-all --rate 50
  [[ "${lines[0]}" == "power:0 t=0.000000 charge=126" ]]
  [[ "${lines[2]}" =~ ^power:0\ t=0\.[0-9]{6}\ charge=126$ ]]
  [ "${lines[2]}" != "${lines[0]}" ]
  run --separate-stderr "$player_cat" "$target" power -n 3 -t d --mode push-all --rate 50
  [[ "${lines[0]}" == "power:0 t=0.000000 charge=126" ]]
  each_line_matches '^power:0 t=[0-9]+\.[0-9]{6} charge=126$'
  run --separate-stderr "$player_cat" "$target" power -n 2 -t z --format json
  [[ "${lines[0]}" == *'"time":0.0'* ]]
}

@test "--si prints SI units: 126 decivolts are 12.6 V" {
  serve_battery
  run --separate-stderr "$player_cat" "$target" power --once --si --format json
  [ "$status" -eq 0 ]
  python3 - "$output" <<'PY'
import json, sys
m = json.loads(sys.argv[1])
assert m["device"] == "power" and abs(m["data"]["charge"] - 12.6) < 1e-9, m
PY
  run --separate-stderr "$player_cat" "$target" power --once --si
  [ "$output" != "${output/charge=12.6/}" ]
}

@test "comms: a UDP datagram heard by udpbroadcast is printed as data" {
  udp_port="$(free_port udp)"
  printf 'comms:0 ( driver "udpbroadcast" addr "127.0.0.1" port %s )\n' "$udp_port" > "$cfg"
  serve_battery
  "$player_cat" "$target" comms --format json -n 1 > "$BATS_TEST_TMPDIR/out" 2>"$BATS_TEST_TMPDIR/err" &
  cat_pid=$!
  # Datagrams sent before player-cat subscribed are lost: send until one is heard.
  send_until_heard() {
    printf 'hi' > "/dev/udp/127.0.0.1/$udp_port"
    ! kill -0 "$cat_pid" 2>/dev/null
  }
  wait_until --pid "$server_pid" --log "$BATS_TEST_TMPDIR/err" --log "$BATS_TEST_TMPDIR/server.log" \
    "player-cat to hear a datagram sent to UDP port $udp_port" send_until_heard
  wait_for_exit "$cat_pid"
  [ "$exit_status" -eq 0 ]
  [[ "$(cat "$BATS_TEST_TMPDIR/out")" == *'"data":{"msg":[104,105]}'*'"device":"comms"'* ]]
}

@test "piped into head: exits quietly with status 0" {
  serve_battery
  run bash -c "'$player_cat' '$target' power --mode push-all --rate 50 2>'$BATS_TEST_TMPDIR/err' | head -n 2; echo \"status=\${PIPESTATUS[0]}\""
  [ "${#lines[@]}" -eq 3 ]
  [ "${lines[2]}" = "status=0" ]
  [ ! -s "$BATS_TEST_TMPDIR/err" ]
}

@test "SIGINT and SIGTERM stop cleanly with exit 0, lines already out" {
  serve_battery
  for signal in INT TERM; do
    "$player_cat" "$target" power > "$BATS_TEST_TMPDIR/out" 2>"$BATS_TEST_TMPDIR/err" &
    cat_pid=$!
    # Lines show up while player-cat runs: stdout is flushed per line.
    wait_for_lines --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/out" --log "$BATS_TEST_TMPDIR/err" "$BATS_TEST_TMPDIR/out" 2
    kill "-$signal" "$cat_pid"
    wait_for_exit "$cat_pid"
    [ "$exit_status" -eq 0 ]
    [ ! -s "$BATS_TEST_TMPDIR/err" ]
    output="$(cat "$BATS_TEST_TMPDIR/out")"
    each_line_matches '^power:0 t=[0-9.]+ charge=126$'
  done
}

@test "the server going away is an error, exit 1" {
  serve_battery
  "$player_cat" "$target" power > "$BATS_TEST_TMPDIR/out" 2>"$BATS_TEST_TMPDIR/err" &
  cat_pid=$!
  wait_for_lines --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/out" --log "$BATS_TEST_TMPDIR/err" "$BATS_TEST_TMPDIR/out" 1
  kill -TERM "$server_pid"
  wait_for_exit "$cat_pid"
  [ "$exit_status" -eq 1 ]
  grep -q "player-cat: .*connection" "$BATS_TEST_TMPDIR/err"
}
