#!/usr/bin/env bats
# player-drivers: every subcommand of the built tool. Emulated devices sit on
# pseudo-terminals behind symlinks in $BATS_TEST_TMPDIR, servers on loopback;
# every wait is bounded. Cases needing a hardware driver (sicklms200, p2os_*)
# are skipped while `player-drivers list` does not show it.

load helpers

setup() {
  # Twenty position samples 50 ms apart, replayed with autorewind.
  log="$BATS_TEST_TMPDIR/positions.log"
  {
    printf '## Player version 1.5 \n## File version 0.0.0 \n'
    for i in $(seq 0 19); do
      printf '%d.%02d robot 6665 position 00 %d.%02d +0.%02d0 +0.200 +1.571 +0.000 +0.000 +0.000 0\n' \
        $((1000 + i / 20)) $((i * 5 % 100)) $((1000 + i / 20)) $((i * 5 % 100)) "$i"
    done
  } > "$log"
}

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}" "${run_pid:-}" "${holder_pid:-}" "${second_emulator_pid:-}"
}

# listed DRIVER: `player-drivers list` shows it (it is built).
listed() {
  "$player_drivers" list --json | jq -s -e --arg name "$1" 'any(.[]; .name == $name)' >/dev/null
}

@test "--help has examples for each subcommand and the exit codes" {
  run --separate-stderr "$player_drivers" --help
  [ "$status" -eq 0 ]
  for sub in "list" "info sicklms200" "run sicklms200" "probe /dev/ttyUSB0" "emulate p2os"; do
    [[ "$output" == *"player-drivers $sub"* ]]
  done
  [[ "$output" == *"Exit status: 0 done"* ]]
  [[ "$output" == *"2 usage error"* ]]
  for sub in run probe emulate; do
    run --separate-stderr "$player_drivers" "$sub" --help
    [ "$status" -eq 0 ]
    [[ "$output" == *"Examples:"* ]]
    [[ "$output" == *"Exit status:"* ]]
  done
  run "$player_drivers" --version
  [[ "$output" == "player-drivers (playerkit) "* ]]
  run "$player_drivers"
  [ "$status" -eq 2 ]
}

@test "list: a row per driver, JSON lines, and one interface" {
  run --separate-stderr "$player_drivers" list
  [ "$status" -eq 0 ]
  [[ "${lines[0]}" == "DRIVER "*"INTERFACES"*"ACCESS"*"HARDWARE"*"SUMMARY" ]]
  [[ "$output" == *$'\nlifomcom '*" mcom "*" a "*" no "*"LIFO message stacks"* ]]
  [[ "$output" == *$'\nnull '* ]]
  run --separate-stderr bash -c "'$player_drivers' list --json | jq -r 'select(.name == \"readlog\") | .access'"
  [ "$output" = "r" ]
  run --separate-stderr bash -c "'$player_drivers' list --json | jq -s 'length'"
  [ "$output" -ge 7 ]
  run --separate-stderr "$player_drivers" list --interface mcom
  [ "$status" -eq 0 ]
  [[ "$output" == *$'\nlifomcom '* ]]
  [[ "$output" != *$'\nnull '* ]]
  [[ "$output" != *"Families"* ]]
  run "$player_drivers" list --interface lazer
  [ "$status" -eq 2 ]
  [[ "$output" == *"did you mean 'laser'?"* ]]
}

@test "list and run take drivers from -d plugins" {
  [ -f "$battery_plugin" ] || skip "the example plugin is not built"
  run --separate-stderr "$player_drivers" -d "$battery_plugin" list --interface power
  [ "$status" -eq 0 ]
  [[ "$output" == *"simbattery "* ]]
  run --separate-stderr timeout 30 "$player_drivers" run -d "$battery_plugin" simbattery volts=12.6 drain=0 rate=50 -n 3 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r .device <<<"$output" | sort -u)" = "power" ]
  [ "${#lines[@]}" -eq 3 ]
}

@test "info: options, requests, manual section and a config; unknown names suggest" {
  run --separate-stderr "$player_drivers" info lifomcom
  [ "$status" -eq 0 ]
  [[ "$output" == *"section 7.26 of the Player 1.5 manual"* ]]
  [[ "$output" == *"Requests:"*"PUSH"* ]]
  [[ "$output" == *$'Config:\n  mcom:0 ( driver "lifomcom" )'* ]]
  run --separate-stderr "$player_drivers" info readlog
  [[ "$output" == *"  autorewind  int "* ]]
  run --separate-stderr "$player_drivers" info udpbroadcast --json
  [ "$(jq -r '.options[] | select(.name == "port") | .default' <<<"$output")" = "6013" ]
  run "$player_drivers" info lifomcon
  [ "$status" -eq 2 ]
  [[ "$output" == *"no driver or driver family 'lifomcon'; did you mean 'lifomcom'?"* ]]
}

@test "info sicklms200: its options with type, default, unit and allowed values" {
  listed sicklms200 || skip "sicklms200 is not built"
  run --separate-stderr "$player_drivers" info sicklms200
  [ "$status" -eq 0 ]
  [[ "$output" =~ port\ +port\ +\"[^\"]+\" ]]  # the driver's documented default, quoted
  [[ "$output" =~ rate\ +int\ +38400\ +baud\ +.*9600,\ 38400\ or\ 500000 ]]
  [[ "$output" =~ reply_timeout\ +float\ +1\ +s\ +.*0.05\ to\ 30 ]]
  run --separate-stderr "$player_drivers" info sickpls --json
  [ "$(jq -r '.options[] | select(.name == "rate") | .default' <<<"$output")" = "9600" ]
  [ "$(jq -r '.options[] | select(.name == "delay") | .unit' <<<"$output")" = "s" ]
}

@test "info of a family numbers its devices" {
  listed p2os_position || skip "the p2os drivers are not built"
  run --separate-stderr "$player_drivers" info p2os
  [ "$status" -eq 0 ]
  [[ "$output" == *"p2os: a family of 11 drivers"* ]]
  [[ "$output" == *"position:0 ( driver \"p2os_position\" )"* ]]
  [[ "$output" == *"position:2 ( driver \"p2os_gyro\" )"* ]]
}

@test "run: data as player-cat prints it, -n and --format json" {
  run --separate-stderr timeout 30 "$player_drivers" run readlog filename="$log" autorewind=1 --device position:0 -n 3 --format json --si
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 3 ]
  [ "$(jq -r '.device + ":" + (.index | tostring)' <<<"$output" | sort -u)" = "position:0" ]
  [ "$(jq -r '.data.ypos' <<<"${lines[0]}")" = "0.2" ]
  run --separate-stderr timeout 30 "$player_drivers" run readlog filename="$log" autorewind=1 --device position:0 -n 2 --field xpos
  [ "$status" -eq 0 ]
  [[ "${lines[0]}" == "position:0 t="*" xpos="* ]]
}

@test "run null and lifomcom: nothing to print, exit 0 at --duration" {
  run --separate-stderr timeout 30 "$player_drivers" run null --duration 0.5 --format json
  [ "$status" -eq 0 ]
  [ -z "$output" ]
  run --separate-stderr timeout 30 "$player_drivers" run lifomcom --duration 0.5 --format json
  [ "$status" -eq 0 ]
  [ -z "$output" ]
}

@test "run --req prints the reply and exits with its status" {
  run --separate-stderr timeout 30 "$player_drivers" run lifomcom --req push channel=news data.data=hello
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type + " " + .device + " " + .request' <<<"$output")" = "ack mcom push" ]
  # Each run is a fresh device: nothing to pop, and lifomcom says NACK.
  run --separate-stderr timeout 30 "$player_drivers" run lifomcom --req pop channel=news
  [ "$status" -eq 3 ]
  [ "$(jq -r .type <<<"$output")" = "nack" ]
  run timeout 30 "$player_drivers" run lifomcom --req pusj
  [ "$status" -eq 2 ]
  [[ "$output" == *"--req"* ]]
}

@test "run --stdin sends player-send's JSON lines and ends with them" {
  run --separate-stderr bash -c "printf '%s\n' \
    '{\"device\":\"mcom:0\",\"request\":\"push\",\"data\":{\"channel\":\"news\",\"data\":{\"data\":\"hi\"}}}' \
    '{\"device\":\"mcom:0\",\"request\":\"pop\",\"data\":{\"channel\":\"news\"}}' \
    | timeout 30 '$player_drivers' run lifomcom --stdin"
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  [ "$(jq -r '.request + " " + .type' <<<"${lines[1]}")" = "pop ack" ]
  [ "$(jq -r '.data.data.data' <<<"${lines[1]}")" = "hi" ]
}

@test "run --serve lets player-cat read the devices meanwhile" {
  "$player_drivers" run readlog filename="$log" autorewind=1 --device position:0 --serve 0 --bind 127.0.0.1 \
    >/dev/null 2>"$BATS_TEST_TMPDIR/run.err" &
  run_pid=$!
  wait_for_line --pid "$run_pid" "$BATS_TEST_TMPDIR/run.err" 'listening on port [0-9]+'
  port="$(sed -n 's/.*listening on port \([0-9][0-9]*\).*/\1/p' "$BATS_TEST_TMPDIR/run.err" | head -n 1)"
  [ -n "$port" ]
  grep -q "(127.0.0.1): position:0 (readlog)" "$BATS_TEST_TMPDIR/run.err"
  run --separate-stderr timeout 30 "$player_cat" "127.0.0.1:$port" position:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  run --separate-stderr timeout 30 "$player_cat" "127.0.0.1:$port" --list
  [[ "$output" == "position:0 readlog" ]]
  stop_cleanly "$run_pid"
}

@test "run --record writes a Player log" {
  rec="$BATS_TEST_TMPDIR/rec.log"
  run --separate-stderr timeout 30 "$player_drivers" run readlog filename="$log" autorewind=1 --device position:0 -n 5 --record "$rec"
  [ "$status" -eq 0 ]
  grep -q '^## Player version 1.5' "$rec"
  [ "$(grep -c ' position 00 ' "$rec")" -ge 3 ]
}

@test "run --stats prints each device's rate every second on stderr" {
  run --separate-stderr timeout 30 "$player_drivers" run readlog filename="$log" autorewind=1 --device position:0 --duration 2.5 --stats --format json
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"stats position:0 readlog: "*" Hz ("*", interval "*" ms, jitter "*" ms"* ]]
  [ "$(grep -c '^stats position:0 ' <<<"$stderr")" -ge 1 ]
}

@test "run names a refused option as typed and refuses options no driver reads" {
  run timeout 30 "$player_drivers" run readlog filename="$log" --device position:0 speed=-1
  [ "$status" -eq 2 ]
  [[ "$output" == *"option speed=-1: readlog: "* ]]
  [[ "$output" != *"<player-drivers run>"* ]]
  run timeout 30 "$player_drivers" run null colour=red
  [ "$status" -eq 2 ]
  [[ "$output" == *"option colour=red: null does not read 'colour'"* ]]
  run timeout 30 "$player_drivers" run nul
  [ "$status" -eq 2 ]
  [[ "$output" == *"did you mean 'null'?"* ]]
  run timeout 30 "$player_drivers" run null port=/dev/tty\"x
  [ "$status" -eq 2 ]
}

@test "emulate and probe: each emulated device is found, with its config line" {
  robot="$BATS_TEST_TMPDIR/robot"
  laser="$BATS_TEST_TMPDIR/laser"
  pls="$BATS_TEST_TMPDIR/pls"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" \
    p2os baud=38400 model=p3at sicklms200 sickpls --link "$robot" --link "$laser" --link "$pls" \
    --map "$repo_root/data/maps/stage-cave.png"
  grep -qx "p2os on $robot: position:0 ( driver \"p2os_position\" port \"$robot\" )" "$BATS_TEST_TMPDIR/emulate.out"
  grep -qx "sicklms200 on $laser: laser:0 ( driver \"sicklms200\" port \"$laser\" )" "$BATS_TEST_TMPDIR/emulate.out"
  grep -q "map .*stage-cave.yaml: 500 x 500 cells of 0.032 m" "$BATS_TEST_TMPDIR/emulate.err"
  [ -L "$robot" ] && [ -L "$laser" ] && [ -L "$pls" ]

  run --separate-stderr timeout 60 "$player_drivers" probe "$robot" "$laser" "$pls"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$robot: p2os at 38400 baud, Pioneer p3at \"playerkit\""* ]]
  [[ "$output" == *"    position:0 ( driver \"p2os_position\" port \"$robot\" )"* ]]
  [[ "$output" == *"$laser: sicklms200 at 9600 baud, LMS200;30106"* ]]
  [[ "$output" == *"$pls: sickpls at 9600 baud, PLS"* ]]
  run --separate-stderr timeout 60 "$player_drivers" probe "$laser" --json
  [ "$(jq -r '.driver + " " + (.baud | tostring)' <<<"$output")" = "sicklms200 9600" ]

  stop_cleanly "$emulator_pid"
  [ ! -e "$robot" ] && [ ! -L "$robot" ]
}

@test "a pan-tilt unit: emulate, probe (no other family takes its echo), run, a request" {
  ptu="$BATS_TEST_TMPDIR/ptu"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" ptu46 --link "$ptu"
  grep -qx "ptu46 on $ptu: ptz:0 ( driver \"ptu46\" port \"$ptu\" )" "$BATS_TEST_TMPDIR/emulate.out"

  # Fresh from power-up the unit echoes what it is sent: every family's
  # probe at 9600 asks it before the PTU-46's does.
  run --separate-stderr timeout 60 "$player_drivers" probe "$ptu"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$ptu: ptu46 at 9600 baud, PTU-46, 185.1428 arc-seconds a pan position"* ]]
  [[ "$output" == *"    ptz:0 ( driver \"ptu46\" port \"$ptu\" )"* ]]

  run --separate-stderr timeout 60 "$player_drivers" run ptu46 "port=$ptu" -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].data.panspeed' <<<"$output")" -eq 51 ]

  run --separate-stderr timeout 60 "$player_drivers" run ptu46 "port=$ptu" --req control-mode mode=0 --trace
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]
  [[ "$stderr" == *"> 63 76 20"* ]]  # "cv " on the line
  stop_cleanly "$emulator_pid"
}

@test "data/config/ptu46.cfg serves the emulated unit" {
  ptu="$BATS_TEST_TMPDIR/ptu46"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" ptu46 --link "$ptu"
  sed "s|\"/tmp/ptu46\"|\"$ptu\"|" "$repo_root/data/config/ptu46.cfg" >"$BATS_TEST_TMPDIR/ptu46.cfg"
  grep -q "port \"$ptu\"" "$BATS_TEST_TMPDIR/ptu46.cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/ptu46.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" ptz:0 -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[0].device' <<<"$output")" = ptz ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "emulate on a TCP port, probed as tcp:HOST:PORT" {
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sicklms200 --tcp 0 --stats
  port="$(sed -n 's/^sicklms200 on tcp:127.0.0.1:\([0-9]*\): .*/\1/p' "$BATS_TEST_TMPDIR/emulate.out")"
  [ -n "$port" ]
  run --separate-stderr timeout 60 "$player_drivers" probe "tcp:127.0.0.1:$port"
  [ "$status" -eq 0 ]
  [[ "$output" == "tcp:127.0.0.1:$port: sicklms200, LMS200;30106"* ]]
  # --stats: a line a second; one after the probe counts its bytes.
  wait_for_line --pid "$emulator_pid" "$BATS_TEST_TMPDIR/emulate.err" "^stats sicklms200 tcp:127.0.0.1:$port: in [1-9]"
  stop_cleanly "$emulator_pid"
}

@test "probe refuses a missing port and says so" {
  run timeout 30 "$player_drivers" probe "$BATS_TEST_TMPDIR/ttyUSB0"
  [ "$status" -eq 1 ]
  [[ "$output" == *"no such port $BATS_TEST_TMPDIR/ttyUSB0; is the adapter plugged in?"* ]]
  run --separate-stderr timeout 30 "$player_drivers" probe "$BATS_TEST_TMPDIR/ttyUSB0" --json
  [ "$status" -eq 1 ]
  [ "$(jq -r .port_unusable <<<"$output")" = "true" ]
}

@test "probe refuses a busy port and names the process holding it" {
  laser="$BATS_TEST_TMPDIR/laser"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sicklms200 --link "$laser"
  python3 -c 'import fcntl, os, sys, time
fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY)
fcntl.flock(fd, fcntl.LOCK_EX)
print("held", flush=True)
time.sleep(300)' "$laser" >"$BATS_TEST_TMPDIR/holder.out" &
  holder_pid=$!
  wait_for_line --pid "$holder_pid" "$BATS_TEST_TMPDIR/holder.out" '^held$'
  run timeout 30 "$player_drivers" probe "$laser"
  [ "$status" -eq 1 ]
  [[ "$output" == *"$laser is busy: held by pid $holder_pid (python3, holds the lock); stop it or pick another port"* ]]
  kill_left_running "$holder_pid"
  holder_pid=""
  # Free again: found.
  run --separate-stderr timeout 60 "$player_drivers" probe "$laser"
  [ "$status" -eq 0 ]
}

@test "probe refuses a port a player-drivers run holds" {
  listed sicklms200 || skip "sicklms200 is not built"
  laser="$BATS_TEST_TMPDIR/laser"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sicklms200 --link "$laser"
  "$player_drivers" run sicklms200 port="$laser" --format json >"$BATS_TEST_TMPDIR/run.out" 2>"$BATS_TEST_TMPDIR/run.err" &
  run_pid=$!
  wait_for_nonempty --pid "$run_pid" --log "$BATS_TEST_TMPDIR/run.err" "$BATS_TEST_TMPDIR/run.out"
  run timeout 30 "$player_drivers" probe "$laser"
  [ "$status" -eq 1 ]
  [[ "$output" == *"$laser is busy: held by pid $run_pid (player-drivers, holds the lock)"* ]]
  stop_cleanly "$run_pid"
}

@test "run a laser driver against the emulator" {
  listed sicklms200 || skip "sicklms200 is not built"
  laser="$BATS_TEST_TMPDIR/laser"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" sicklms200 pose=0,0,0 --link "$laser" \
    --map "$repo_root/data/maps/stage-cave.png"
  run --separate-stderr timeout 60 "$player_drivers" run sicklms200 port="$laser" -n 2 --format json --si --trace
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  [ "$(jq -r .device <<<"${lines[0]}")" = "laser" ]
  [ "$(jq '.data.ranges | length' <<<"${lines[0]}")" -eq 361 ]
  [[ "$stderr" == *"trace laser:0 "*" > 02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53"* ]]
  run timeout 60 "$player_drivers" run sicklms200 port="$laser" rate=19200 -n 1
  [ "$status" -eq 2 ]
  [[ "$output" == *"option rate=19200: sicklms200: rate must be one of"* ]]
}

@test "run a Pioneer's family against the emulator" {
  listed p2os_position || skip "the p2os drivers are not built"
  robot="$BATS_TEST_TMPDIR/robot"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" p2os --link "$robot"
  run --separate-stderr timeout 60 "$player_drivers" run p2os port="$robot" --device position:0 -n 2 --format json --stats
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 2 ]
  [ "$(jq -r '.device + ":" + (.index | tostring)' <<<"${lines[0]}")" = "position:0" ]
}

@test "emulate refuses unknown emulators and options, and stops at --duration" {
  run timeout 30 "$player_drivers" emulate sicklms
  [ "$status" -eq 2 ]
  [[ "$output" == *"no emulator 'sicklms'; there are p2os, sicklms200, sickpls"* ]]
  run timeout 30 "$player_drivers" emulate sicklms200 noise=loud --duration 1
  [ "$status" -eq 2 ]
  [[ "$output" == *"sicklms200: noise=loud: expected a number"* ]]
  run timeout 30 "$player_drivers" emulate p2os --map "$repo_root/tests/data/maps/cave.pnm"
  [ "$status" -eq 2 ]
  [[ "$output" == *"give its scale with --map-scale"* ]]
  run --separate-stderr timeout 30 "$player_drivers" emulate p2os --duration 0.5
  [ "$status" -eq 0 ]
  [[ "$output" == "p2os on /dev/pts/"* ]]
}
