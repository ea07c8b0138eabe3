"""Helpers shared by the Python anchors of bench/anchors: the virtual environment,
CPU-time measurement and the result files. No mathematics here.

Every anchor runs from the project root (or anywhere: paths are resolved from
this file) and re-executes itself under the project's benchmark venv,
target/bench-venv (made by bench/anchors/venv.sh), when its imports are missing.
"""
import json
import os
import platform
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
VENV = os.environ.get("CYLROLL_BENCH_VENV", os.path.join(ROOT, "target", "bench-venv"))
VENV_PY = os.path.join(VENV, "bin", "python")
REF_DIR = os.path.join(HERE, "ref")


def in_venv(modules):
    """Import `modules`; if one is missing, build the venv (bench/anchors/venv.sh)
    and re-execute this script under it."""
    try:
        for m in modules:
            __import__(m)
        return
    except ImportError:
        pass
    if os.path.realpath(sys.prefix) == os.path.realpath(VENV):
        raise SystemExit(f"the venv {VENV} lacks one of {modules}: run bench/anchors/venv.sh")
    if not os.path.exists(VENV_PY):
        subprocess.run(["sh", os.path.join(HERE, "venv.sh")], check=True)
    os.execv(VENV_PY, [VENV_PY] + sys.argv)


def cpu():
    """CPU seconds of this process (user + system)."""
    return time.process_time()


def measure(fn, min_runs=3, max_runs=9, budget_s=15.0):
    """Calls fn() repeatedly. Returns (last value, median CPU s, median wall s, runs).
    At least min_runs calls, then more until budget_s of wall time or max_runs."""
    cpus, walls, val = [], [], None
    start = time.perf_counter()
    while True:
        c, w = cpu(), time.perf_counter()
        val = fn()
        cpus.append(cpu() - c)
        walls.append(time.perf_counter() - w)
        n = len(cpus)
        if n >= max_runs or (n >= min_runs and time.perf_counter() - start > budget_s):
            return val, statistics.median(cpus), statistics.median(walls), n


def first_call(fn):
    """(value, CPU s, wall s) of one call."""
    c, w = cpu(), time.perf_counter()
    v = fn()
    return v, cpu() - c, time.perf_counter() - w


def load_ref():
    return json.load(open(os.path.join(REF_DIR, "reference.json")))


def t3_grid_strings():
    """T3's end time (a decimal string, taken as exact) and its 1000 points
    t_i = t_end * i / 999."""
    return load_ref()["T3"]["t_end"], 1000


class Results:
    """Rows of one tool, written to RESULTS_DIR/<tool>.json in the layout
    bench/ratios.py reads: {"meta": ..., "rows": [{tool, task, digits, method,
    value, cold_s, cpu_median_s, ...}]}."""

    def __init__(self, out_dir, tool, version):
        self.dir, self.tool, self.version, self.rows = out_dir, tool, version, []
        os.makedirs(out_dir, exist_ok=True)

    def add(self, task, digits, method, value, cold_s, cpu_median_s, wall_median_s, runs, **extra):
        row = dict(tool=self.tool, task=task, digits=digits, method=method, value=value,
                   cold_s=cold_s, cpu_median_s=cpu_median_s, warm_median_s=wall_median_s,
                   runs=runs, **extra)
        self.rows.append(row)
        print(f"{self.tool:7s} {task:4s} {digits:5d} {method[:40]:40s} cold {cold_s:.4g} s  "
              f"warm cpu {cpu_median_s:.4g} s  ({runs} runs)  {value[:30]}", file=sys.stderr, flush=True)
        self.save()

    def table(self, digits, values):
        """T3's 1000 values of this tool at `digits`, one a line."""
        with open(os.path.join(self.dir, f"T3_{self.tool}_{digits}.txt"), "w") as f:
            f.write("\n".join(values) + "\n")

    def save(self):
        meta = dict(tool=self.tool, version=self.version, python=sys.version.split()[0],
                    machine=platform.machine(), loadavg=open("/proc/loadavg").read().split()[:3],
                    date=time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime()))
        with open(os.path.join(self.dir, f"{self.tool}.json"), "w") as f:
            json.dump(dict(meta=meta, rows=self.rows), f, indent=1)


def digits_list(s):
    return [int(x) for x in s.split(",") if x.strip()]
