#!/usr/bin/env bash
# The simulator behind the server (issue 15): N robots of sim_bench's cave-100
# world (a 180-beam 8 m laser each) served by `player-serve -s` at --speedup 1,
# one player-cat client per robot reading its position and laser at the
# server's default 10 Hz, all on loopback. Prints, for the measured window:
#   * the server's CPU (share of one core, and of the whole machine);
#   * how much simulated time passed per wall second (1.00: kept real time),
#     from the laser timestamps each client saw;
#   * each client's laser rate (min / median / max over the clients).
#
#   bench/sim_server_load.sh                 # 100 robots, 20 s
#   bench/sim_server_load.sh 50 30           # 50 robots, 30 s
#   PLAYERKIT_BUILD_DIR=build bench/sim_server_load.sh
#
# Build first (Release, as every benchmark):
#   BUILD_DIR=build-bench CMAKE_ARGS="-DBUILD_TESTING=OFF" scripts/build sim_bench player-serve player-cat
# The clients run on the same machine as the server and compete with it.
set -euo pipefail
cd "$(dirname "$0")/.."

robots=${1:-100}
seconds=${2:-20}
build=${PLAYERKIT_BUILD_DIR:-build-bench}
for program in bench/sim_bench tools/player-serve/player-serve tools/player-cat/player-cat; do
  [ -x "$build/$program" ] || { echo "sim_server_load: $build/$program is missing; build it first (see the top of this script)" >&2; exit 2; }
done

work=$(mktemp -d)
server_pid=""
cleanup() {
  [ -n "$server_pid" ] && kill "$server_pid" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# cave-100's world with `robots` robots: sim_bench writes the 100-robot file;
# fewer are the first lines of robots in it.
"$build/bench/sim_bench" --only cave-100 --write-world "$work/all.world" --worlds "$(pwd)/data/worlds"
awk -v keep="$robots" '/^bench_robot / { if (++n > keep) next } { print }' "$work/all.world" >"$work/bench.world"

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
"$build/tools/player-serve/player-serve" -s "$work/bench.world" -p "$port" --bind 127.0.0.1 2>"$work/server.log" &
server_pid=$!
for _ in $(seq 100); do
  grep -q "listening" "$work/server.log" 2>/dev/null && break
  sleep 0.1
done
grep -q "listening" "$work/server.log" || { cat "$work/server.log" >&2; exit 1; }

# Robot k's devices are position:k and laser:k on the one port.
clients=()
for (( k = 0; k < robots; ++k )); do
  timeout $(( seconds + 30 )) "$build/tools/player-cat/player-cat" "127.0.0.1:$port" "position:$k" "laser:$k" \
    --duration "$(( seconds + 4 ))" -t a >"$work/client-$k.txt" 2>"$work/client-$k.err" &
  clients+=($!)
done
sleep 2  # every client subscribed and receiving

cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$server_pid/stat"; }
# The simulation clock: simulation:0's data is stamped with simulated time.
sim_time() {
  "$build/tools/player-cat/player-cat" "127.0.0.1:$port" simulation:0 --once -t a | awk '{ sub("t=", "", $2); print $2 }'
}
ticks_per_second=$(getconf CLK_TCK)
start_ticks=$(cpu_ticks)
start_wall=$(date +%s.%N)
start_sim=$(sim_time)
sleep "$seconds"
end_sim=$(sim_time)
end_ticks=$(cpu_ticks)
end_wall=$(date +%s.%N)
for pid in "${clients[@]}"; do wait "$pid" 2>/dev/null || true; done

python3 - "$work" "$robots" "$start_wall" "$end_wall" "$start_sim" "$end_sim" "$start_ticks" "$end_ticks" \
  "$ticks_per_second" "$(nproc)" <<'EOF_PY'
import statistics, sys
work, robots = sys.argv[1], int(sys.argv[2])
start_wall, end_wall, start_sim, end_sim = map(float, sys.argv[3:7])
start_ticks, end_ticks, hz, cores = map(int, sys.argv[7:11])
wall = end_wall - start_wall
sim = end_sim - start_sim
cpu = (end_ticks - start_ticks) / hz
rates, silent = [], 0
for k in range(robots):
    scans = 0
    with open(f"{work}/client-{k}.txt") as lines:
        for line in lines:
            fields = line.split()
            if len(fields) >= 2 and fields[0] == f"laser:{k}" and fields[1].startswith("t="):
                if start_sim <= float(fields[1][2:]) < end_sim:
                    scans += 1
    if scans == 0:
        silent += 1
    rates.append(scans / wall)
print(f"robots {robots} (180-beam lasers), {wall:.1f} s measured, {cores} cores shared with the clients")
print(f"simulated time per wall second: {sim / wall:.3f}")
print(f"server CPU: {cpu / wall * 100:.0f} % of one core ({cpu / wall / cores * 100:.0f} % of the machine)")
print(f"scans per client per wall second: min {min(rates):.2f}, median {statistics.median(rates):.2f}, "
      f"max {max(rates):.2f}; clients without scans: {silent}")
EOF_PY
