#!/bin/sh
# The Hertz benchmark in this crate and in its peers, side by side, single
# thread: `benches/peers/run.sh 256 512 1024`. Installs tamaas and
# ContactMechanics from PyPI into benches/peers/.venv on first use.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
sizes=${*:-256 512}
if [ ! -x "$here/.venv/bin/python" ]; then
    python3 -m venv "$here/.venv"
    "$here/.venv/bin/pip" install -q numpy tamaas contactmechanics
fi
cd "$here/../.."
cargo build --release --example hertz_benchmark
export RAYON_NUM_THREADS=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
./target/release/examples/hertz_benchmark $sizes > "$here/rust.csv"
cat "$here/rust.csv"
"$here/.venv/bin/python" "$here/peers.py" "$here/rust.csv" $sizes
