#!/usr/bin/env bash
# The box preconditioner against the two-level one (blocks of B cells) on
# the rough problems of examples/rough_benchmark.rs, one process a run, the
# two alternating at each grid size (the machine's speed wanders over
# minutes). Prints the load average before each run and the benchmark's CSV
# line and trace.
#
#   benches/rough/box_against_blocks.sh MODE B N [N ...]
#   benches/rough/box_against_blocks.sh isolated 16 512 1024 2048 4096 8192
#
# B = auto runs the solver's own choice instead of fixed blocks
# (ContactSolver::set_automatic_coarse_blocks). REFINE=1 keeps the
# roughness's cut-off fixed as N grows (rough_benchmark --refine).
set -euo pipefail
mode=$1 blocks=$2
shift 2
if [ "$blocks" = auto ]; then other=""; else other="--blocks $blocks"; fi
refine=""
if [ -n "${REFINE:-}" ]; then refine="--refine"; fi
cd "$(dirname "$0")/../.."
cargo build --release --example rough_benchmark >&2
bench=target/release/examples/rough_benchmark
for n in "$@"; do
    for option in "--box" "$other"; do
        echo "# $(date -u +%H:%M:%S) UTC, load average $(cut -d' ' -f1 /proc/loadavg): $mode${refine:+ $refine} ${option:-automatic} $n"
        # shellcheck disable=SC2086
        TRACE=1 "$bench" "$mode" $refine $option "$n" | grep -v '^#  '
    done
done
