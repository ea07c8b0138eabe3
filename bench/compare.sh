#!/bin/sh
# Runs cylroll's benchmark tasks (CPU time, `benches/tasks.rs` in CPU mode) and
# the project's anchor tools of bench/anchors (a hand-written C/MPFR tanh-sinh,
# Boost.Math over MPFR, python-flint/Arb, mpmath, heyoka) in one run on this
# machine, then prints the table of CPU times and ratios (bench/ratios.py); then
# the whole-process rows (bench/cold.sh) and the friction rows (cylroll's
# commands as processes beside heyoka on the frictional motion,
# bench/anchors/heyoka_friction.py, table by bench/anchors/friction_table.py).
#
# Usage (from anywhere):
#   bench/compare.sh                 # digits 30,100,300,1000 (T3 at 30,100), friction
#                                    # at the same digits: about an hour on 2 cores
#   bench/compare.sh --quick         # digits 30,100 only (friction too), no mpmath T3
#   bench/compare.sh --tools ours,c-mpfr,boost   # a subset (tools: ours, c-mpfr,
#                                    # boost, flint, mpmath, heyoka, friction)
#   bench/compare.sh --friction      # the friction part alone (= --tools friction)
#   bench/compare.sh --quick --friction-digits 30,100,300,1000   # friction at other digits
#   bench/compare.sh --out DIR       # keep the raw results in DIR (default: a temp dir)
#   NO_COLD=1 bench/compare.sh       # without the whole-process rows (bench/cold.sh)
#   FRICTION_TIME_LIMIT=600 bench/compare.sh   # seconds per heyoka friction measurement
#                                    # (default 900; heyoka at 1000 digits may not finish)
#   PAIRS=31 bench/compare.sh --friction   # pairs of the library's every-column / θ-only calls (15)
#
# Needs: cargo; gcc, g++, libmpfr-dev, libgmp-dev, libboost-dev (Boost 1.74
# headers), hyperfine (whole-process rows); python3 with venv: the Python anchors
# run in target/bench-venv, made on first use by bench/anchors/venv.sh (heyoka,
# python-flint, mpmath, numpy, sympy from PyPI). The compiled anchors are kept
# in target/bench-anchors. The reference values (Arb balls) are
# bench/anchors/ref, made by bench/anchors/reference.py.
# The machine may be shared: the table uses CPU-time medians (best-of for the C
# anchor, as it reports), and `uptime` is printed before and after. T1r and T2r
# are cylroll's proved T1 and θs (`--rigorous`: interval enclosures proving
# every digit), set beside Arb, the one anchor that proves its result.
set -eu

ROOT=$(cd "$(dirname "$0")/.." && pwd)
ANCH=$ROOT/bench/anchors
REF=$ANCH/ref
BIN=$ROOT/target/bench-anchors
DIGITS=30,100,300,1000
T3_DIGITS=30,100
MPMATH_T3=30
TOOLS=ours,c-mpfr,boost,flint,mpmath,heyoka,friction
FRICTION_DIGITS=
OUT=
while [ $# -gt 0 ]; do
    case "$1" in
        --quick) DIGITS=30,100; MPMATH_T3= ;;
        --digits) DIGITS=$2; shift ;;
        --tools) TOOLS=$2; shift ;;
        --friction) TOOLS=friction ;;
        --friction-digits) FRICTION_DIGITS=$2; shift ;;
        --out) OUT=$2; shift ;;
        *) echo "unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
want() { case ",$TOOLS," in *",$1,"*) return 0 ;; *) return 1 ;; esac; }
FRICTION_DIGITS=${FRICTION_DIGITS:-$DIGITS}
SPACED=$(echo "$DIGITS" | tr ',' ' ')
# T3 runs at the digits of both lists
T3_RUN=
for d in $(echo "$T3_DIGITS" | tr ',' ' '); do
    case ",$DIGITS," in *",$d,"*) T3_RUN="$T3_RUN${T3_RUN:+,}$d" ;; esac
done
# friction rows of every column: at 30 and 100 digits
ROWS_RUN=
for d in 30 100; do
    case ",$FRICTION_DIGITS," in *",$d,"*) ROWS_RUN="$ROWS_RUN${ROWS_RUN:+,}$d" ;; esac
done

if [ -z "$OUT" ]; then OUT=$(mktemp -d); fi
mkdir -p "$OUT" "$BIN"
OUT=$(cd "$OUT" && pwd)
R="$OUT/results"
mkdir -p "$R"
find "$R" -maxdepth 1 -type f -delete
cp "$REF/reference.json" "$REF/T3_reference.txt" "$R"/
PY=$("$ANCH/venv.sh")
# a compiled anchor, rebuilt when its source is newer
build() {  # build NAME SOURCE COMPILER FLAGS...
    name=$1; src=$2; shift 2
    if [ ! -x "$BIN/$name" ] || [ "$src" -nt "$BIN/$name" ]; then
        echo "== compiling $name" >&2
        "$@" -o "$BIN/$name" "$src" -lmpfr -lgmp -lm
    fi
}

{
    echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(uname -sr)"
    echo "commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet HEAD -- src benches bench 2>/dev/null || echo ' (with local changes)')"
    echo "start: $(date -u '+%Y-%m-%d %H:%M UTC'), uptime:$(uptime | sed 's/.*up[^,]*,//')"
} > "$R/machine.txt"
cat "$R/machine.txt"

cd "$OUT"
if want c-mpfr || want ours; then
    build mpfr_ops "$ANCH/mpfr_ops.c" gcc -O2
    "$BIN/mpfr_ops" > "$R/mpfr_ops.md"
fi
if want ours; then
    echo "== cylroll" >&2
    (cd "$ROOT" && cargo bench --bench tasks --no-run -q 2>/dev/null || cargo bench --bench tasks --no-run)
    (cd "$ROOT" && CYLROLL_BENCH=cpu CYLROLL_BENCH_REF="$REF" CYLROLL_BENCH_DIGITS="$DIGITS" \
        cargo bench --bench tasks -q -- T1 T2 T2b T1r T2r T3 T3rows) > "$R/cylroll.jsonl"
fi
if want c-mpfr; then
    echo "== ts_mpfr.c" >&2
    build ts_mpfr "$ANCH/ts_mpfr.c" gcc -O2
    # shellcheck disable=SC2086
    "$BIN/ts_mpfr" $SPACED > "$R/ts_mpfr.jsonl"
    # evaluations of the first level within 10^-d of the reference: the floor
    T1REF=$("$PY" -c 'import json, sys; print(json.load(open(sys.argv[1]))["T1"]["mid"])' "$REF/reference.json")
    {
        echo '{"rows": ['
        sep=
        for d in $SPACED; do
            printf '%s' "$sep"; "$BIN/ts_mpfr" --count "$d" "$T1REF"; sep=','
        done
        echo ']}'
    } > "$R/evals.json"
fi
if want boost; then
    echo "== Boost" >&2
    build bench_boost "$ANCH/bench_boost.cpp" g++ -O2 -std=c++17
    TEND=$("$PY" -c 'import json, sys; print(json.load(open(sys.argv[1]))["T3"]["t_end"])' "$REF/reference.json")
    # shellcheck disable=SC2086
    "$BIN/bench_boost" --t3-end "$TEND" --t3-out "$R" --t3-digits "${T3_RUN:-0}" $SPACED > "$R/boost.jsonl"
fi
if want flint; then
    echo "== python-flint" >&2
    "$PY" "$ANCH/bench_flint.py" --out "$R" --digits "$DIGITS" --t3-digits "${T3_RUN:-30}" --tasks T1,T2,T2b${T3_RUN:+,T3}
fi
if want mpmath; then
    echo "== mpmath" >&2
    if [ -n "$MPMATH_T3" ] && [ -n "$T3_RUN" ]; then
        "$PY" "$ANCH/bench_mpmath.py" --out "$R" --digits "$DIGITS" --t3-digits "$MPMATH_T3" --tasks T1,T2,T2b,T3
    else
        "$PY" "$ANCH/bench_mpmath.py" --out "$R" --digits "$DIGITS" --tasks T1,T2,T2b
    fi
fi
if want heyoka && [ -n "$T3_RUN" ]; then
    echo "== heyoka" >&2
    "$PY" "$ANCH/bench_heyoka.py" --out "$R" --digits "$T3_RUN"
fi
if want ours || want c-mpfr || want boost || want flint || want mpmath || want heyoka; then
    echo "end: $(date -u '+%Y-%m-%d %H:%M UTC'), uptime:$(uptime | sed 's/.*up[^,]*,//')" >> "$R/machine.txt"
    "$PY" "$ROOT/bench/ratios.py" "$R"
fi
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
# friction: cylroll's commands as processes and its library calls (divan, wall
# time; and the every-column / θ-only pair in alternation, CPU) beside heyoka
if want friction; then
    echo "== friction: cylroll library (divan, and the pair in alternation)" >&2
    (cd "$ROOT" && cargo build --release -q && cargo bench --bench tasks -q -- t3_friction) > "$R/cylroll_friction_divan.txt" 2>&1
    # (the library pair at 30 and 100 digits, the benchmark's only friction grid)
    (cd "$ROOT" && CYLROLL_BENCH=cpu CYLROLL_BENCH_DIGITS=30,100 CYLROLL_BENCH_PAIRS="${PAIRS:-15}" \
        cargo bench --bench tasks -q -- T3friction_pair) > "$R/cylroll_friction_pair.jsonl" \
        2> "$R/cylroll_friction_pair.err" \
        || echo "the library pair failed: see $R/cylroll_friction_pair.err" >&2
    echo "== friction: heyoka and the cylroll commands" >&2
    "$PY" "$ANCH/heyoka_friction.py" --digits "$FRICTION_DIGITS" --rows-digits "${ROWS_RUN:-0}" \
        --time-limit "${FRICTION_TIME_LIMIT:-900}" --out "$R/heyoka_friction.json" >/dev/null
    echo
    echo "### Friction"
    echo
    "$PY" "$ANCH/friction_table.py" "$R"
fi
echo "raw results: $R" >&2
