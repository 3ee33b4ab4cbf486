#!/usr/bin/env bats
# player-send against a real player-serve on a free loopback port: commands
# that really leave (udpbroadcast datagrams heard by a UDP listener), requests
# that round-trip (lifomcom push then pop), every exit code, --stdin, --help.

load helpers

setup() {
  udp_port="$(python3 -c 'import socket
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.bind(("127.0.0.1", 0))
print(s.getsockname()[1])')"
  cfg="$BATS_TEST_TMPDIR/send.cfg"
  # alwayson keeps the udpbroadcast socket open between player-send runs: a
  # device shut down as its last client leaves may drop a command it has not
  # yet sent (player-send only knows that the server has read the command).
  cat >"$cfg" <<EOF
mcom:0 ( driver "lifomcom" )
comms:0 ( driver "udpbroadcast" addr "127.255.255.255" port $udp_port alwayson 1 )
power:0 ( driver "simbattery" rate 20 )
EOF
  helper_pids=()
}

teardown() {
  kill_left_running "${helper_pids[@]}" "${server_pid:-}"
}

serve() {
  start_server "$BATS_TEST_TMPDIR/server.log" -p 0 -d "$battery_plugin" "$@" "$cfg"
  server="127.0.0.1:$server_port"
}

# json_get PATH: the value at PATH (dot-separated keys and list indices) of the
# JSON object on stdin; strings bare, anything else as JSON.
json_get() {
  python3 -c 'import json, sys
value = json.loads(sys.stdin.read())
for key in sys.argv[1].split("."):
    value = value[int(key)] if isinstance(value, list) else value[key]
print(value if isinstance(value, str) else json.dumps(value))' "$1"
}

# listen_udp COUNT OUT: collects COUNT datagrams sent to the comms port into OUT
# (one hex line each), the way another udpbroadcast peer would hear them; gives
# up after PLAYERKIT_WAIT_TIMEOUT (30 s) without one. Returns once the socket is
# bound; sets listener_pid.
listen_udp() {
  local ready="$BATS_TEST_TMPDIR/listener.ready"
  python3 -c 'import socket, sys
port, count, out, ready, timeout = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4], float(sys.argv[5])
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
s.bind(("0.0.0.0", port))
s.settimeout(timeout)
open(ready, "w").close()
with open(out, "w") as f:
    for _ in range(count):
        data, _ = s.recvfrom(65536)
        f.write(data.hex() + "\n")
        f.flush()' "$udp_port" "$1" "$2" "$ready" "${PLAYERKIT_WAIT_TIMEOUT:-30}" &
  listener_pid=$!
  helper_pids+=("$listener_pid")
  wait_for_file --pid "$listener_pid" "$ready"
}

@test "a command really leaves: udpbroadcast sends it as a datagram, exit 0" {
  serve
  listen_udp 1 "$BATS_TEST_TMPDIR/heard"
  run --separate-stderr "$player_send" "$server" comms:0 cmd 'msg=[104,105,33]'
  [ "$status" -eq 0 ]
  [ -z "$output" ]
  wait_for_exit "$listener_pid"
  [ "$exit_status" -eq 0 ]
  [ "$(cat "$BATS_TEST_TMPDIR/heard")" = "686921" ]
}

@test "a request round-trips: lifomcom push then pop, replies as JSON, exit 0" {
  serve
  run --separate-stderr "$player_send" "$server" mcom:0 req push channel=news data.data=hello data.full=1
  [ "$status" -eq 0 ]
  [ "$(json_get type <<<"$output")" = "ack" ]
  [ "$(json_get request <<<"$output")" = "push" ]
  run --separate-stderr "$player_send" "$server" mcom:0 req pop channel=news
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 1 ]
  [ "$(json_get type <<<"$output")" = "ack" ]
  [ "$(json_get device <<<"$output")" = "mcom" ]
  [ "$(json_get data.channel <<<"$output")" = "news" ]
  [ "$(json_get data.data.data <<<"$output")" = "hello" ]
}

@test "the player device answers without opening anything: devlist and driverinfo" {
  serve
  run --separate-stderr "$player_send" "$server" player req devlist
  [ "$status" -eq 0 ]
  [ "$(json_get data.device_count <<<"$output")" = "3" ]
  [ "$(json_get data.devices.0.code <<<"$output")" = "26" ]
  run --separate-stderr "$player_send" "$server" player req driverinfo id.code=26 id.index=0 "id.port=$server_port"
  [ "$status" -eq 0 ]
  [ "$(json_get data.driver_name <<<"$output")" = "lifomcom" ]
}

@test "NACK exits 3: an empty mcom channel, DATA in a push mode, a plugin without requests" {
  serve
  run --separate-stderr "$player_send" "$server" mcom:0 req pop channel=empty
  [ "$status" -eq 3 ]
  [ "$(json_get type <<<"$output")" = "nack" ]
  [ "$(json_get data <<<"$output")" = "{}" ]
  run --separate-stderr "$player_send" "$server" player req data
  [ "$status" -eq 3 ]
  [ "$(json_get type <<<"$output")" = "nack" ]
  run --separate-stderr "$player_send" "$server" power:0 req main-power
  [ "$status" -eq 3 ]
  [ "$(json_get device <<<"$output")" = "power" ]
}

@test "ERR exits 4: a request to a device the server does not serve" {
  serve
  run --separate-stderr "$player_send" "$server" laser:0 req get-geom
  [ "$status" -eq 4 ]
  [ "$(json_get type <<<"$output")" = "err" ]
  [ "$(json_get device <<<"$output")" = "laser" ]
  [[ "$stderr" == *"laser:0 is not served on this port"* ]]
}

@test "a command to a device that cannot be opened is not sent, exit 4" {
  serve
  run --separate-stderr "$player_send" "$server" position:0 cmd xspeed=200
  [ "$status" -eq 4 ]
  [[ "$stderr" == *"command not sent: position:0 is not served on this port"* ]]
}

@test "a device whose set-up fails: exit 4 for a command, ERR for a request" {
  # A socket that does not share the UDP port makes udpbroadcast's set-up fail.
  sed -i 's/ alwayson 1//' "$cfg"
  python3 -c 'import socket, sys, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.bind(("0.0.0.0", int(sys.argv[1])))
open(sys.argv[2], "w").close()
time.sleep(300)' "$udp_port" "$BATS_TEST_TMPDIR/taken" &
  helper_pids+=("$!")
  wait_for_file --pid "$!" "$BATS_TEST_TMPDIR/taken"
  serve
  run --separate-stderr "$player_send" "$server" comms:0 cmd 'msg=[1]'
  [ "$status" -eq 4 ]
  [[ "$stderr" == *"comms:0 (driver udpbroadcast) could not be opened"* ]]
  # comms defines no requests: raw bytes through --stdin reach it all the same.
  run --separate-stderr "$player_send" --stdin "$server" <<<'{"type":"req","device":"comms:0","data":{"raw":[0]}}'
  [ "$status" -eq 4 ]
  [ "$(json_get type <<<"$output")" = "err" ]
  [[ "$stderr" == *"sending the request anyway"* ]]
}

@test "connection refused and timeouts exit 1" {
  closed_port="$(python3 -c 'import socket
s = socket.socket()
s.bind(("127.0.0.1", 0))
print(s.getsockname()[1])')"
  run --separate-stderr "$player_send" "127.0.0.1:$closed_port" player req devlist
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"cannot connect to 127.0.0.1:$closed_port"* ]]

  # A listener that never sends the banner.
  python3 -c 'import socket, time
s = socket.socket()
s.bind(("127.0.0.1", 0))
s.listen(1)
print(s.getsockname()[1], flush=True)
time.sleep(300)' >"$BATS_TEST_TMPDIR/silent.port" &
  helper_pids+=("$!")
  wait_for_nonempty --pid "$!" "$BATS_TEST_TMPDIR/silent.port"
  run --separate-stderr "$player_send" --timeout 0.3 "127.0.0.1:$(cat "$BATS_TEST_TMPDIR/silent.port")" player req devlist
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"within the timeout"* ]]
}

@test "--key authenticates; a wrong key is refused, exit 1" {
  serve -k secret
  run --separate-stderr "$player_send" --key secret "$server" mcom:0 req pop channel=none
  [ "$status" -eq 3 ]
  run --separate-stderr "$player_send" --key wrong "$server" player req devlist
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"authentication refused"* ]]
  # Without the key the server hangs up at the first message: --stdin says where it stopped.
  run --separate-stderr "$player_send" --stdin "$server" <<<'{"device":"mcom:0","request":"pop","data":{}}'
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"line 1: the server closed the connection"*"stopped at line 1"* ]]
}

@test "usage errors exit 2 and say what is allowed, before connecting" {
  run --separate-stderr "$player_send" lazer:0 req get-geom
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"unknown interface 'lazer' (did you mean laser?)"* ]]
  run --separate-stderr "$player_send" position:0 req get-geo
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"position has no request 'get-geo' (did you mean get-geom?)"*"set-odom"* ]]
  run --separate-stderr "$player_send" position:0 cmd xsped=200
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"unknown field 'xsped'"*"xspeed"* ]]
  run --separate-stderr "$player_send" position:0 cmd state=300
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"state: 300 is out of range [0, 255]"* ]]
  run --separate-stderr "$player_send" laser:0 cmd x=1
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"laser takes no commands"*"get-geom"* ]]
  run --separate-stderr "$player_send" position:0 jump
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"expected 'cmd' or 'req'"* ]]
  run --separate-stderr "$player_send" position:0 cmd xspeed200
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"expected FIELD=VALUE"* ]]
  run --separate-stderr "$player_send" --rate 5 position:0 cmd xspeed=1
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--rate"*"--stdin"* ]]
  run --separate-stderr "$player_send" --no-such-flag
  [ "$status" -eq 2 ]
}

@test "--stdin sends every line in order at --rate" {
  serve
  listen_udp 5 "$BATS_TEST_TMPDIR/heard"
  for i in 1 2 3 4 5; do
    printf '{"device":"comms:0","data":{"msg":[%d]}}\n' "$((48 + i))"
  done >"$BATS_TEST_TMPDIR/lines"
  start=$(date +%s.%N)
  run --separate-stderr "$player_send" --stdin --rate 20 "$server" <"$BATS_TEST_TMPDIR/lines"
  end=$(date +%s.%N)
  [ "$status" -eq 0 ]
  wait_for_exit "$listener_pid"
  [ "$exit_status" -eq 0 ]
  [ "$(tr '\n' ' ' <"$BATS_TEST_TMPDIR/heard")" = "31 32 33 34 35 " ]
  # Five messages at 20 Hz are four gaps of 50 ms: a lower bound, which load cannot break.
  python3 -c 'import sys; sys.exit(0 if float(sys.argv[2]) - float(sys.argv[1]) >= 0.2 else 1)' "$start" "$end"
}

@test "--stdin takes the short and the full form; requests print their replies" {
  serve
  cat >"$BATS_TEST_TMPDIR/lines" <<'EOF'
{"device":"mcom:0","request":"push","data":{"channel":"c","data":{"data":"first"}}}

{"type":"req","device":"mcom","index":0,"request":"push","time":1.5,"data":{"channel":"c","data":{"data":"second"}}}
{"device":"mcom:0","request":"pop","data":{"channel":"c"}}
EOF
  run --separate-stderr "$player_send" --stdin "$server" <"$BATS_TEST_TMPDIR/lines"
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 3 ]
  [ "$(json_get type <<<"${lines[0]}")" = "ack" ]
  [ "$(json_get data.data.data <<<"${lines[2]}")" = "second" ]
}

@test "--stdin: a NACK does not stop the feed, and sets the exit status" {
  serve
  cat >"$BATS_TEST_TMPDIR/lines" <<'EOF'
{"device":"mcom:0","request":"pop","data":{"channel":"c"}}
{"device":"mcom:0","request":"push","data":{"channel":"c","data":{"data":"x"}}}
{"device":"mcom:0","request":"pop","data":{"channel":"c"}}
EOF
  run --separate-stderr "$player_send" --stdin "$server" <"$BATS_TEST_TMPDIR/lines"
  [ "$status" -eq 3 ]
  [ "${#lines[@]}" -eq 3 ]
  [ "$(json_get type <<<"${lines[0]}")" = "nack" ]
  [ "$(json_get data.data.data <<<"${lines[2]}")" = "x" ]
}

@test "--stdin: a bad line stops with its number; the lines before were sent, none after" {
  serve
  cat >"$BATS_TEST_TMPDIR/lines" <<'EOF'
{"device":"mcom:0","request":"push","data":{"channel":"c","data":{"data":"one"}}}
{"device":"mcom:0","request":"push","dta":{}}
{"device":"mcom:0","request":"push","data":{"channel":"c","data":{"data":"three"}}}
EOF
  run --separate-stderr "$player_send" --stdin "$server" <"$BATS_TEST_TMPDIR/lines"
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"line 2: unknown key 'dta'"* ]]
  [[ "$stderr" == *"stopped at line 2"* ]]
  # The stack holds "one" only: line 3 was never sent.
  run --separate-stderr "$player_send" "$server" mcom:0 req pop channel=c
  [ "$status" -eq 0 ]
  [ "$(json_get data.data.data <<<"$output")" = "one" ]
  run --separate-stderr "$player_send" "$server" mcom:0 req pop channel=c
  [ "$status" -eq 3 ]
}

@test "--help lists every interface's commands and requests with their fields" {
  run --separate-stderr "$player_send" --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"  cmd: xpos ypos yaw xspeed yspeed yawspeed state type"* ]]
  [[ "$output" == *"  req get-geom: base pose and footprint (no fields)"* ]]
  [[ "$output" == *"  req push: push a message onto a channel; fields: type channel (text) data.full data.data (text)"* ]]
  [[ "$output" == *"  req nameservice: look up a robot name and get its port; fields: name (text) port"* ]]
  [[ "$output" == *"  req set-odom: set the odometric pose; fields: x y theta"* ]]
  [[ "$output" == *"Exit status:"* ]]
  # The whole catalog is in --help; --list INTERFACE prints one section of it.
  catalog="$("$player_send" --list all)"
  [[ "$output" == *"$catalog"* ]]
  run --separate-stderr "$player_send" --list mcom
  [ "$status" -eq 0 ]
  [ "${lines[0]}" = "mcom" ]
  [[ "$output" != *"position"* ]]
  run --separate-stderr "$player_send" --list lazer
  [ "$status" -eq 2 ]
}
