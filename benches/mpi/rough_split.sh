#!/bin/bash
# The split-run table of BENCHMARKS.md ("Split across MPI ranks"): the rough
# film of examples/scenes/rough_film_split.toml at N cells a side under one
# force, on one process (both cores) and split across 2 and 4 MPI ranks (one
# thread each), with wall time and peak memory per process from
# /usr/bin/time and the memory `check --ranks` predicts.
#
#     cargo build --release --features mpi
#     benches/mpi/rough_split.sh 4096 8192
#
# On a grid of 2048^2 cells or more every run takes the two-level
# preconditioner by itself (ContactSolver::set_automatic_coarse_blocks),
# split runs too since 2026-12-05 (fortieth session): their rows here are
# whole rows of blocks of 16.
set -euo pipefail
cd "$(dirname "$0")/../.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
tool="$PWD/target/release/layered-contact"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for n in "$@"; do
    # The same 1 mm side, cut-off at 4 cells, one force of 20 kPa.
    spacing=$(python3 -c "print(1e-3 / $n)")
    cutoff=$(python3 -c "print(4e-3 / $n)")
    sed -e "s/^cells = .*/cells = $n/" -e "s/^spacing = .*/spacing = $spacing/" \
        -e "s/^short_cutoff = .*/short_cutoff = $cutoff/" -e 's/^kind = "force_cycle"/kind = "force"/' \
        -e 's/^max_force = .*/force = 2e-2/' -e '/^steps = /d' \
        examples/scenes/rough_film_split.toml > "$work/rough$n.toml"
    for np in 1 2 4; do
        "$tool" check "$work/rough$n.toml" --ranks "$np" | tail -1
        echo "== N = $n, $np process(es), $(date -u +%FT%H:%M:%S) UTC, load $(cut -d' ' -f1 /proc/loadavg)"
        if [ "$np" = 1 ]; then
            /usr/bin/time -f "one process: wall %e s, peak %M kB" \
                "$tool" run "$work/rough$n.toml" -o "$work/out$n-$np" 2>&1 | grep -v '^\[' | grep -v wrote
        else
            RAYON_NUM_THREADS=1 mpirun -np "$np" -x RAYON_NUM_THREADS \
                /usr/bin/time -f "rank: wall %e s, peak %M kB" \
                "$tool" run "$work/rough$n.toml" -o "$work/out$n-$np" 2>&1 | grep -v '^\[' | grep -v wrote
        fi
        tail -1 "$work/out$n-$np/curve.csv"
    done
done
