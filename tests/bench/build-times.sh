#!/bin/sh
# The README's two commands, timed side by side on fresh clones (issue 29, docs/performance.md
# "Build and test time"): commit BASE (default 39613c5) and HEAD are cloned into two fresh
# folders, and each command runs from scratch (no target/, GMP/MPFR compiled again: the
# gmp-mpfr-sys cache is turned off) on each clone, alternating, ROUNDS times (default 2).
# Prints one line per run and appends it to $OUT (default target/build-times.txt).
# Needs the README's prerequisites (m4). Takes about an hour on a 2-core machine; never run in
# CI. Give it the machine: other builds running beside it inflate every number.
# Usage: tests/bench/build-times.sh [BASE] [ROUNDS]; COMMANDS=test (or main) times one command.
set -eu
cd "$(dirname "$0")/../.."
repo=$PWD
base=${1:-39613c5}
rounds=${2:-2}
out=${OUT:-$repo/target/build-times.txt}
commands=${COMMANDS:-main test}
work=$(mktemp -d)
mkdir -p "$(dirname "$out")"
git clone -q "$repo" "$work/base" && git -C "$work/base" checkout -q "$base"
git clone -q "$repo" "$work/head"
export GMP_MPFR_SYS_CACHE=_
set -f # the main command's expression holds '*': no pathname expansion of its words
main_cmd() { # the README's main command in clone $1, quotes removed
    sed -n 's/^\(cargo run [^#]*-- eval [^#]*\)$/\1/p' "$1/README.md" | head -n 1 | tr -d '"'
}
base_main=$(main_cmd "$work/base")
head_main=$(main_cmd "$work/head")
[ -n "$base_main" ] && [ -n "$head_main" ] || { echo "error: no main command in a README" >&2; exit 1; }
run() { # run LABEL DIR COMMAND...
    label=$1; dir=$2; shift 2
    rm -rf "$dir/target"
    start=$(date +%s.%N)
    if (cd "$dir" && "$@" >"$work/$label.log" 2>&1); then rc=0; else rc=$?; fi
    end=$(date +%s.%N)
    passed=$(grep -o '[0-9]* passed' "$work/$label.log" | awk '{s += $1} END {print s + 0}')
    line=$(printf '%s rc=%s wall=%.0fs tests_passed=%s' "$label" "$rc" "$(echo "$end - $start" | bc)" "$passed")
    echo "$line" | tee -a "$out"
}
i=1
while [ "$i" -le "$rounds" ]; do
    case " $commands " in *" main "*)
        # shellcheck disable=SC2086 # the command's words are split on purpose
        run "base-main-$i" "$work/base" $base_main
        # shellcheck disable=SC2086
        run "head-main-$i" "$work/head" $head_main
    esac
    case " $commands " in *" test "*)
        run "base-test-$i" "$work/base" cargo test --workspace
        run "head-test-$i" "$work/head" cargo test --workspace
    esac
    i=$((i + 1))
done
rm -rf "$work"
