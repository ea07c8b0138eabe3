#!/bin/sh
# Runs cylroll's benchmark tasks (CPU time, `benches/tasks.rs` in CPU mode) and
# the anchor tools of ../shared/bench (hand-written C/MPFR tanh-sinh, Boost.Math,
# python-flint/Arb, mpmath, heyoka) in one run on this machine, then prints the
# table of CPU times and ratios (bench/ratios.py).
#
# Usage (from anywhere):
#   bench/compare.sh                 # digits 30,100,300,1000 (T3 at 30,100): ~20-40 min
#   bench/compare.sh --quick         # digits 30,100 only, no mpmath T3
#   bench/compare.sh --tools ours,c-mpfr,boost   # a subset
#   bench/compare.sh --out DIR       # keep the raw results in DIR (default: a temp dir)
#   NO_COLD=1 bench/compare.sh       # without the whole-process rows (bench/cold.sh)
#
# Needs: cargo; gcc, g++, libmpfr-dev, libgmp-dev, libboost-dev (Boost 1.74 headers);
# python3 with mpmath, python-flint, heyoka, numpy. See ../shared/bench/README.md.
# The anchors write their results into their own folder, so they run in a copy of
# it: ../shared/bench/results is never touched. The machine may be shared: the
# table uses CPU-time medians (best-of for the C anchor, as it reports), and
# `uptime` is printed before and after. T1r and T2r are cylroll's proved T1 and
# θs (`--rigorous`: interval enclosures proving every digit), set beside Arb, the
# one anchor that proves its result.
set -eu

ROOT=$(cd "$(dirname "$0")/.." && pwd)
ANCH=${CYLROLL_ANCHORS:-$ROOT/../shared/bench}
DIGITS=30,100,300,1000
T3_DIGITS=30,100
MPMATH_T3=30
TOOLS=ours,c-mpfr,boost,flint,mpmath,heyoka
OUT=
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) DIGITS=30,100; MPMATH_T3= ;;
        --digits) DIGITS=$2; shift ;;
        --tools) TOOLS=$2; shift ;;
        --out) OUT=$2; shift ;;
        *) echo "unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
want() { case ",$TOOLS," in *",$1,"*) return 0 ;; *) return 1 ;; esac; }
SPACED=$(echo "$DIGITS" | tr ',' ' ')
# T3 runs at the digits of both lists
T3_RUN=
for d in $(echo "$T3_DIGITS" | tr ',' ' '); do
    case ",$DIGITS," in *",$d,"*) T3_RUN="$T3_RUN${T3_RUN:+,}$d" ;; esac
done

if [ -z "$OUT" ]; then OUT=$(mktemp -d); fi
mkdir -p "$OUT"
cp -r "$ANCH"/* "$OUT"/
R="$OUT/results"
mkdir -p "$R"
# fresh results, except the references
find "$R" -maxdepth 1 -type f ! -name 'reference.json' ! -name 'T3_reference.txt' ! -name 'evals.json' -delete

{
    echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(uname -sr)"
    echo "start: $(date -u '+%Y-%m-%d %H:%M UTC'), uptime:$(uptime | sed 's/.*up[^,]*,//')"
} > "$R/machine.txt"
cat "$R/machine.txt"

cd "$OUT"
if want c-mpfr || want ours; then
    gcc -O2 -o mpfr_ops mpfr_ops.c -lmpfr -lgmp -lm
    ./mpfr_ops > "$R/mpfr_ops.md"
fi
if want ours; then
    echo "== cylroll" >&2
    (cd "$ROOT" && cargo bench --bench tasks --no-run -q 2>/dev/null || cargo bench --bench tasks --no-run)
    (cd "$ROOT" && CYLROLL_BENCH=cpu CYLROLL_BENCH_REF="$ANCH/results" CYLROLL_BENCH_DIGITS="$DIGITS" \
        cargo bench --bench tasks -q -- T1 T2 T2b T1r T2r T3 T3rows) > "$R/cylroll.jsonl"
fi
if want c-mpfr; then
    echo "== ts_mpfr.c" >&2
    gcc -O2 -o ts_mpfr ts_mpfr.c -lmpfr -lgmp -lm
    # shellcheck disable=SC2086
    ./ts_mpfr $SPACED > "$R/ts_mpfr.jsonl"
fi
if want boost; then
    echo "== Boost" >&2
    g++ -O2 -std=c++17 -o bench_boost bench_boost.cpp -lmpfr -lgmp
    # shellcheck disable=SC2086
    ./bench_boost $SPACED > "$R/boost.jsonl" 2>/dev/null
fi
if want flint; then
    echo "== python-flint" >&2
    python3 bench_flint.py --digits "$DIGITS" --t3-digits "${T3_RUN:-30}" --tasks T1,T2,T2b${T3_RUN:+,T3} > /dev/null
fi
if want mpmath; then
    echo "== mpmath" >&2
    if [ -n "$MPMATH_T3" ] && [ -n "$T3_RUN" ]; then
        python3 bench_mpmath.py --digits "$DIGITS" --t3-digits "$MPMATH_T3" --tasks T1,T2,T2b,T3 > /dev/null
    else
        python3 bench_mpmath.py --digits "$DIGITS" --tasks T1,T2,T2b > /dev/null
    fi
fi
if want heyoka && [ -n "$T3_RUN" ]; then
    echo "== heyoka" >&2
    python3 bench_heyoka.py --digits "$T3_RUN" > /dev/null
fi
echo "end: $(date -u '+%Y-%m-%d %H:%M UTC'), uptime:$(uptime | sed 's/.*up[^,]*,//')" >> "$R/machine.txt"
python3 "$ROOT/bench/ratios.py" "$R"
# whole-process rows: the command run once per process against the C
# tanh-sinh run once per process (bench/cold.sh, issue 17's goals)
if want ours && want c-mpfr && [ -z "${NO_COLD:-}" ]; then
    echo
    echo "### Whole process"
    echo
    if command -v hyperfine >/dev/null; then
        "$ROOT/bench/cold.sh" --out "$OUT/cold"
    else
        echo "(skipped: bench/cold.sh needs hyperfine)"
    fi
fi
echo "raw results: $R" >&2
