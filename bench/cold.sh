#!/bin/sh
# Whole-process times of the `cylroll` command at high precision, side by side
# with the project's hand-written C/MPFR tanh-sinh (bench/anchors/ts_mpfr.c) run
# as a one-shot program (`ts_mpfr --once D`: one T1 integral, nodes generated,
# no verification) at the same digits, in one run on this machine. Each row is a
# goal of issue 17; ratios are cylroll / C (below 1: cylroll is faster).
#
# Usage: bench/cold.sh [--out DIR]     (about 2 minutes)
# Needs: cargo, gcc, libmpfr-dev, libgmp-dev, hyperfine, python3.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$(mktemp -d)
while [ $# -gt 0 ]; do
    case "$1" in
        --out) OUT=$2; shift ;;
        *) echo "unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
mkdir -p "$OUT"
command -v hyperfine >/dev/null || { echo "cold.sh needs hyperfine (apt-get install -y hyperfine)" >&2; exit 2; }
(cd "$ROOT" && cargo build --release -q)
B="$ROOT/target/release/cylroll"
gcc -O2 -o "$OUT/ts_mpfr" "$ROOT/bench/anchors/ts_mpfr.c" -lmpfr -lgmp -lm
C="$OUT/ts_mpfr --once"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores; $(date -u '+%Y-%m-%d %H:%M UTC'); load:$(uptime | sed 's/.*load average://')"
M="--theta0 1/10"
# name|digits|runs|goal|command
cat > "$OUT/rows.txt" <<ROWS
time --to 9/10 --digits 100|100|40|1.2|$B time --to 9/10 $M --digits 100
time --to 9/10 --digits 1000|1000|5|1.0|$B time --to 9/10 $M --digits 1000
separation --digits 1000|1000|5|2|$B separation $M --digits 1000
trajectory --t-end 5 --steps 100 --digits 1000|1000|3|8|$B trajectory $M --t-end 5 --steps 100 --digits 1000
separation --digits 2000|2000|3|2|$B separation $M --digits 2000
ROWS
i=0
while IFS='|' read -r name d runs goal cmd; do
    i=$((i + 1))
    hyperfine -N -w 1 -r "$runs" --export-json "$OUT/row$i.json" "$cmd" "$C $d" >/dev/null 2>&1
    echo "$name|$d|$goal|$OUT/row$i.json"
done < "$OUT/rows.txt" > "$OUT/index.txt"
python3 - "$OUT/index.txt" <<'PY'
import json, statistics, sys
def ms(s):
    return f"{s * 1e3:.3g} ms" if s < 1 else f"{s:.3g} s"
print("| task (identical solid cylinders, roll/roll, θ0 = 1/10) | cylroll wall | C wall | ratio | cylroll CPU | C CPU | ratio | goal | met |")
print("|---|---|---|---|---|---|---|---|---|")
for line in open(sys.argv[1]):
    name, d, goal, path = line.rstrip("\n").split("|")
    res = json.load(open(path))["results"]
    ours, c = (statistics.median(r["times"]) for r in res)
    ours_cpu, c_cpu = (r["user"] + r["system"] for r in res)
    ratio, cpu_ratio = ours / c, ours_cpu / c_cpu
    met = "yes" if cpu_ratio <= float(goal) else "NO"
    print(f"| `{name}` | {ms(ours)} | {ms(c)} | {ratio:.2f}× | {ms(ours_cpu)} | {ms(c_cpu)} | {cpu_ratio:.2f}× | ≤ {goal}× | {met} |")
print()
print("Whole-process times (hyperfine -N, one warm-up run): wall = median, CPU = mean user +")
print("system; the goal is judged on CPU time, the steadier figure on a shared machine. The C")
print("program is bench/anchors/ts_mpfr.c, run once per process (`ts_mpfr --once D`).")
PY
