# Shared setup for the command-line tests. PLAYERKIT_BUILD_DIR points at the build
# tree (scripts/test sets it); by default ./build at the top of the repository.
repo_root="$(cd "$(dirname "${BATS_TEST_FILENAME}")/../.." && pwd)"
build_dir="${PLAYERKIT_BUILD_DIR:-$repo_root/build}"
player_serve="$build_dir/tools/player-serve/player-serve"
wire_roundtrip="$build_dir/examples/wire-roundtrip/wire-roundtrip"
bats_require_minimum_version 1.5.0
