#!/usr/bin/env bash
# Reproduce reports/engines.md: MuJoCo simulations of cylroll's main case, judged by cylroll's
# Python package. Not part of `cargo test` or CI (test_mujoco.py is, when mujoco is
# installed). Takes a few minutes.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
PY="${PYTHON:-python3}"

"$PY" -c "import mujoco, numpy" 2>/dev/null || "$PY" -m pip install mujoco
# the oracle: the cylroll package built from this checkout (maturin, as pip's build backend)
"$PY" -m pip install --quiet "$ROOT/python"
"$PY" "$HERE/experiments.py"
"$PY" "$HERE/friction.py"
