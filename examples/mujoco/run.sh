#!/usr/bin/env bash
# Reproduce reports/engines.md: MuJoCo simulations of cylroll's main case, judged by cylroll.
# Not part of `cargo test` or CI. Takes a few minutes.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
PY="${PYTHON:-python3}"

"$PY" -c "import mujoco, numpy" 2>/dev/null || "$PY" -m pip install mujoco
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$ROOT/target}"
(cd "$ROOT" && cargo build --release --quiet)
"$PY" "$HERE/experiments.py" "$CARGO_TARGET_DIR/release/cylroll"
"$PY" "$HERE/friction.py" "$CARGO_TARGET_DIR/release/cylroll"
