#!/usr/bin/env bash
# The memory and time of `cylroll check` on a long candidate (default 10^6
# rows of t, theta, theta_dot for the case main_roll_roll), measured with
# /usr/bin/time: the candidate is streamed, so the peak memory must not grow
# with the number of rows. Usage: bench/check_rows.sh [ROWS]
set -euo pipefail
cd "$(dirname "$0")/.."
rows=${1:-1000000}
cargo build --release -q
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$rows" "$tmp/cand.csv" <<'PY'
import math, sys
n, path = int(sys.argv[1]), sys.argv[2]
# times on [0, 6] (t_s of main_roll_roll is 6.3); theta a smooth stand-in:
# the check reads, evaluates and compares every row whatever the values
with open(path, "w") as f:
    f.write("t,theta,theta_dot\n")
    for i in range(n):
        t = 6.0 * i / n
        f.write(f"{t!r},{0.05 * math.cosh(0.7 * t)!r},{0.035 * math.sinh(0.7 * t)!r}\n")
PY
echo "candidate: $rows rows, $(du -h "$tmp/cand.csv" | cut -f1)"
if [ -x /usr/bin/time ]; then
  /usr/bin/time -f "check: %e s wall, %M KB peak resident memory" \
    target/release/cylroll check "$tmp/cand.csv" --case main_roll_roll --max-rows "$rows" \
    --format csv >/dev/null || true
else
  ( time target/release/cylroll check "$tmp/cand.csv" --case main_roll_roll --max-rows "$rows" --format csv >/dev/null ) || true
fi
