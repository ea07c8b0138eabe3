#!/bin/sh
# Makes the Python environment of the anchors, target/bench-venv, once:
# heyoka (Taylor ODE integrator, MPFR reals), python-flint (Arb), mpmath,
# numpy and sympy from PyPI. Prints the interpreter's path.
# Usage: bench/anchors/venv.sh       (from anywhere; ~1 minute the first time)
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
V=${CYLROLL_BENCH_VENV:-$ROOT/target/bench-venv}
if ! "$V/bin/python" -c 'import heyoka, flint, mpmath, numpy, sympy' 2>/dev/null; then
    mkdir -p "$(dirname "$V")"
    python3 -m venv "$V" >&2
    "$V/bin/pip" install -q --upgrade pip >&2
    "$V/bin/pip" install -q heyoka python-flint mpmath numpy sympy >&2
fi
echo "$V/bin/python"
