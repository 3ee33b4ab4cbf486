#!/usr/bin/env bats
# player-log on the Radish logs in tests/data/radish (counts from
# `zcat LOG | awk '{print $1}' | sort | uniq -c`), and record against a real
# player-serve serving the example battery plugin (power:0 at 50 Hz).

load helpers

radish="$repo_root/tests/data/radish"

setup() {
  cfg="$BATS_TEST_TMPDIR/battery.cfg"
  printf 'power:0 ( driver "simbattery" volts 12.6 drain 0 rate 50 )\n' > "$cfg"
}

teardown() {
  kill_left_running "${record_pid:-}" "${server_pid:-}"
}

serve_battery() {
  start_server "$BATS_TEST_TMPDIR/server.log" -p 0 --bind 127.0.0.1 -d "$battery_plugin" "$cfg"
  target="127.0.0.1:$server_port"
}

# count_of NAME: the count info --json gives a device or record.
count_of() {
  python3 -c 'import json, sys
d = json.load(sys.stdin); s = d.get("devices") or d.get("records")
print(s[sys.argv[1]]["count"] if sys.argv[1] in s else 0)' "$1"
}

@test "--help shows subcommands, examples and exit codes" {
  run --separate-stderr "$player_log" --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"info"* && "$output" == *"convert"* && "$output" == *"cut"* && "$output" == *"record"* ]]
  [[ "$output" == *"Examples:"* ]]
  [[ "$output" == *"Exit status: 0 done"* ]]
}

@test "info counts the three Radish logs exactly" {
  run --separate-stderr "$player_log" info "$radish/intel-corrected.log.gz"
  [ "$status" -eq 0 ]
  [[ "$output" == *"format:    CARMEN"* ]]
  [[ "$output" =~ FLASER\ +910 ]]
  [[ "$output" =~ ODOM\ +14541 ]]
  [[ "$output" == *"skipped:   NEFF 910"* ]]
  [[ "$output" == *"malformed: 0"* ]]
  [ "$("$player_log" info --json "$radish/freiburg-079-corrected.log.gz" | count_of FLASER)" -eq 4791 ]
  [ "$("$player_log" info --json "$radish/freiburg-079-corrected.log.gz" | count_of ODOM)" -eq 9725 ]
  [ "$("$player_log" info --json "$radish/csail-corrected.log.gz" | count_of FLASER)" -eq 406 ]
  [ "$("$player_log" info --json "$radish/csail-corrected.log.gz" | count_of ODOM)" -eq 2394 ]
  [ "$("$player_log" info --json "$radish/csail-corrected.log.gz" | count_of PARAM)" -eq 119 ]
}

@test "convert CARMEN -> Player -> CARMEN keeps every scan and its values" {
  "$player_log" convert "$radish/intel-corrected.log.gz" -o "$BATS_TEST_TMPDIR/intel.player.log"
  head -n 2 "$BATS_TEST_TMPDIR/intel.player.log" | grep -q '^## File version 0.0.0'
  info="$("$player_log" info --json "$BATS_TEST_TMPDIR/intel.player.log")"
  [ "$(count_of laser:0 <<< "$info")" -eq 910 ]
  [ "$(count_of truth:0 <<< "$info")" -eq 910 ]
  [ "$(count_of position:0 <<< "$info")" -eq $((910 + 14541)) ]
  "$player_log" convert "$BATS_TEST_TMPDIR/intel.player.log" -o "$BATS_TEST_TMPDIR/intel.carmen.log" --to carmen
  [ "$(grep -c '^FLASER' "$BATS_TEST_TMPDIR/intel.carmen.log")" -eq 910 ]
  [ "$(grep -c '^ODOM' "$BATS_TEST_TMPDIR/intel.carmen.log")" -eq 14541 ]
  # Every range of every scan within the file's precision (1 cm for scans with 81.83 m readings).
  python3 - "$radish/intel-corrected.log.gz" "$BATS_TEST_TMPDIR/intel.carmen.log" <<'PY'
import gzip, sys
def scans(lines):
    return [[float(v) for v in l.split()[2:2 + int(l.split()[1])]] for l in lines if l.startswith("FLASER ")]
a = scans(gzip.open(sys.argv[1], "rt")); b = scans(open(sys.argv[2]))
assert len(a) == len(b) == 910, (len(a), len(b))
for i, (x, y) in enumerate(zip(a, b)):
    assert len(x) == len(y), i
    assert all(abs(p - q) <= 0.0051 for p, q in zip(x, y)), (i, x, y)
PY
}

@test "convert to JSON lines and CSV" {
  run --separate-stderr "$player_log" convert "$radish/csail-corrected.log.gz" -o - --to jsonl --devices laser:0
  [ "$status" -eq 0 ]
  [ "$(wc -l <<< "$output")" -eq 406 ]
  python3 -c 'import json, sys
for l in sys.stdin: m = json.loads(l); assert m["device"] == "laser" and m["data"]["range_count"] == 361, m' <<< "$output"
  "$player_log" convert "$radish/csail-corrected.log.gz" -o "$BATS_TEST_TMPDIR/odom.csv" --devices position:0
  head -n 1 "$BATS_TEST_TMPDIR/odom.csv" | grep -q '^time,timestamp,device,index,'
  [ "$(wc -l < "$BATS_TEST_TMPDIR/odom.csv")" -eq $((1 + 406 + 2394)) ]
  # several devices in one CSV table: a usage error naming the way out
  run --separate-stderr "$player_log" convert "$radish/csail-corrected.log.gz" -o - --to csv
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--devices"* ]]
}

@test "cut keeps a time window and the named devices" {
  "$player_log" convert "$radish/intel-corrected.log.gz" -o "$BATS_TEST_TMPDIR/intel.log"
  "$player_log" cut "$BATS_TEST_TMPDIR/intel.log" -o "$BATS_TEST_TMPDIR/part.log" --start 100 --end 200 --devices laser:0
  info="$("$player_log" info --json "$BATS_TEST_TMPDIR/part.log")"
  python3 -c 'import json, sys
d = json.loads(sys.argv[1]); assert list(d["devices"]) == ["laser:0"], d
first = float(sys.argv[2]); assert first + 100 <= d["start"] and d["end"] <= first + 200, d' \
    "$info" "$("$player_log" info --json "$BATS_TEST_TMPDIR/intel.log" | python3 -c 'import json,sys; print(json.load(sys.stdin)["start"])')"
  # every kept line is byte for byte a line of the input
  grep -v '^##' "$BATS_TEST_TMPDIR/part.log" | head -n 20 | while IFS= read -r line; do
    grep -qxF -- "$line" "$BATS_TEST_TMPDIR/intel.log"
  done
}

@test "record from a real server: count, and SIGTERM leaves every line complete" {
  serve_battery
  run --separate-stderr "$player_log" record "$target" power:0 -o "$BATS_TEST_TMPDIR/five.log" -n 5
  [ "$status" -eq 0 ]
  [ "$("$player_log" info --json --strict "$BATS_TEST_TMPDIR/five.log" | count_of power:0)" -eq 5 ]

  "$player_log" record "$target" power:0 -o "$BATS_TEST_TMPDIR/long.log" 2>"$BATS_TEST_TMPDIR/record.err" &
  record_pid=$!
  has_ten() { [ "$(grep -c ' power ' "$BATS_TEST_TMPDIR/long.log" 2>/dev/null || true)" -ge 10 ]; }
  wait_until --pid "$record_pid" --log "$BATS_TEST_TMPDIR/record.err" "10 power lines in long.log" has_ten
  kill -TERM "$record_pid"
  wait_for_exit "$record_pid"
  [ "$exit_status" -eq 0 ]
  [ "$(tail -c 1 "$BATS_TEST_TMPDIR/long.log" | od -An -c | tr -d ' ')" = '\n' ]
  run --separate-stderr "$player_log" info --strict "$BATS_TEST_TMPDIR/long.log"
  [ "$status" -eq 0 ]
  [ "$(grep -c ' power ' "$BATS_TEST_TMPDIR/long.log")" -ge 10 ]
}

@test "record - keeps player-cat's log lines" {
  serve_battery
  "$player_cat" "$target" power:0 --format log -n 4 | "$player_log" record - -o "$BATS_TEST_TMPDIR/piped.log"
  [ "$("$player_log" info --json --strict "$BATS_TEST_TMPDIR/piped.log" | count_of power:0)" -eq 4 ]
  printf '## Player version 1.5 \nnot a log line\n' | "$player_log" record - -o "$BATS_TEST_TMPDIR/bad.log" 2>"$BATS_TEST_TMPDIR/err"
  grep -q 'stdin:2:' "$BATS_TEST_TMPDIR/err"
  run "$player_log" record - -o "$BATS_TEST_TMPDIR/bad.log" --strict <<< "not a log line"
  [ "$status" -eq 1 ]
}

@test "usage errors exit 2, missing files exit 1" {
  run "$player_log"
  [ "$status" -eq 2 ]
  run "$player_log" convert "$radish/intel-corrected.log.gz"
  [ "$status" -eq 2 ]
  run "$player_log" convert "$radish/intel-corrected.log.gz" -o - --to xml
  [ "$status" -eq 2 ]
  [[ "$output" == *"xml"* ]]
  run "$player_log" cut x.log -o - --devices nosuch:0
  [ "$status" -eq 2 ]
  run "$player_log" record localhost:7000 -o x.log
  [ "$status" -eq 2 ]
  run --separate-stderr "$player_log" info "$BATS_TEST_TMPDIR/missing.log"
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"missing.log"* ]]
  port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  run "$player_log" record "127.0.0.1:$port" power:0 -o "$BATS_TEST_TMPDIR/x.log" --timeout 1
  [ "$status" -eq 1 ]
}

# Output files (docs/compatibility.md, "Output files"): never over an input,
# written through a temporary renamed at the end, .gz written compressed.

@test "cut and convert refuse to write over their input, whatever its spelling" {
  mkdir "$BATS_TEST_TMPDIR/out" && cd "$BATS_TEST_TMPDIR/out"
  zcat "$radish/intel-corrected.log.gz" | head -n 200 > carmen.log
  "$player_log" convert carmen.log -o a.log 2>/dev/null
  before="$(sha256sum < a.log)"
  ln -s a.log link.log
  ln a.log hard.log
  for spelling in a.log ./a.log "$PWD/a.log" link.log hard.log; do
    run --separate-stderr "$player_log" cut a.log -o "$spelling"
    [ "$status" -eq 2 ]
    [[ "$stderr" == "player-log: cannot write $spelling: it is the input a.log (the same file)"* ]]
    run --separate-stderr "$player_log" convert a.log -o "$spelling" --to carmen
    [ "$status" -eq 2 ]
  done
  [ "$(sha256sum < a.log)" = "$before" ]
  [ -L link.log ]
  # Nothing else was left behind: no temporaries.
  [ "$(ls | sort | tr '\n' ' ')" = "a.log carmen.log hard.log link.log " ]
}

@test "a corrupt .gz: the error names the file once, with the byte and line; convert and cut leave no output" {
  mkdir "$BATS_TEST_TMPDIR/out" && cd "$BATS_TEST_TMPDIR/out"
  "$player_log" convert "$radish/intel-corrected.log.gz" -o whole.log.gz 2>/dev/null
  [ "$(head -c 2 whole.log.gz | od -An -tx1 | tr -d ' ')" = "1f8b" ]
  head -c 40000 whole.log.gz > cut.log.gz
  run --separate-stderr "$player_log" convert cut.log.gz -o out.carmen --to carmen
  [ "$status" -eq 1 ]
  [[ "$stderr" =~ player-log:\ cut\.log\.gz:\ gzip\ data\ cut\ short:\ the\ file\ ends\ at\ byte\ 40000,\ in\ line\ [0-9]+$ ]]
  [ ! -e out.carmen ]
  echo "an older output" > old.log
  run "$player_log" cut cut.log.gz -o old.log
  [ "$status" -eq 1 ]
  [ "$(cat old.log)" = "an older output" ]
  [ "$(ls | sort | tr '\n' ' ')" = "cut.log.gz old.log whole.log.gz " ]
  run --separate-stderr "$player_log" info cut.log.gz
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"cut.log.gz: gzip data cut short: the file ends at byte 40000, in line "* ]]
  [[ "$stderr" != *"cut.log.gz: cut.log.gz"* ]]
}

@test "record -o x.log.gz writes gzip that info reads; a record that cannot start leaves an older file alone" {
  serve_battery
  mkdir "$BATS_TEST_TMPDIR/out" && cd "$BATS_TEST_TMPDIR/out"
  run --separate-stderr "$player_log" record "$target" power:0 -o x.log.gz -n 20
  [ "$status" -eq 0 ]
  [ "$(head -c 2 x.log.gz | od -An -tx1 | tr -d ' ')" = "1f8b" ]
  gzip -t x.log.gz
  [ "$("$player_log" info --json --strict x.log.gz | count_of power:0)" -eq 20 ]
  "$player_log" cut x.log.gz -o y.log.gz --devices power:0
  [ "$(zcat y.log.gz | grep -c ' power ')" -eq 20 ]

  echo "yesterday's run" > run.log
  port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  run "$player_log" record "127.0.0.1:$port" power:0 -o run.log --timeout 1
  [ "$status" -eq 1 ]
  [ "$(cat run.log)" = "yesterday's run" ]
  run "$player_log" record "$target" laser:0 -o run.log
  [ "$status" -eq 1 ]
  [ "$(cat run.log)" = "yesterday's run" ]
  run "$player_log" record - -o run.log < run.log
  [ "$status" -eq 2 ]
  [ "$(cat run.log)" = "yesterday's run" ]
}

@test "record -o x.log.gz stopped by SIGTERM leaves a whole gzip file" {
  serve_battery
  "$player_log" record "$target" power:0 -o "$BATS_TEST_TMPDIR/long.log.gz" 2>"$BATS_TEST_TMPDIR/record.err" &
  record_pid=$!
  # Flushed at least once a second: the live file decodes (up to its missing end).
  has_ten() { [ "$(zcat "$BATS_TEST_TMPDIR/long.log.gz" 2>/dev/null | grep -c ' power ' || true)" -ge 10 ]; }
  wait_until --pid "$record_pid" --log "$BATS_TEST_TMPDIR/record.err" "10 power lines in long.log.gz" has_ten
  kill -TERM "$record_pid"
  wait_for_exit "$record_pid"
  [ "$exit_status" -eq 0 ]
  gzip -t "$BATS_TEST_TMPDIR/long.log.gz"
  run --separate-stderr "$player_log" info --strict "$BATS_TEST_TMPDIR/long.log.gz"
  [ "$status" -eq 0 ]
  [ "$(zcat "$BATS_TEST_TMPDIR/long.log.gz" | grep -c ' power ')" -ge 10 ]
}
