"""The command: ``python -m cylroll.conformance ENGINE [--cases NAMES] [--dt LIST]
[--out DIR] [--set KEY=VALUE ...]`` (also ``cylroll-conformance``).

Exit codes: 0 every check passes, 1 some check fails, 2 bad usage (an unknown
engine or case, an engine that is not installed, a malformed list).
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
import time
from typing import Any, List, Optional

#: The built-in engines: name -> "module:Class" (imported only when asked for).
ENGINES = {
    "pybullet": "cylroll.conformance.pybullet_adapter:PybulletAdapter",
    "pymunk": "cylroll.conformance.pymunk_adapter:PymunkAdapter",
    "mujoco": "cylroll.conformance.mujoco_adapter:MujocoAdapter",
    "example": "cylroll.conformance.examples:PenaltyDiscs",
}
EXTRAS = {"pybullet": "pybullet", "pymunk": "pymunk", "mujoco": "mujoco"}


class UsageError(Exception):
    pass


def load_adapter(spec: str) -> Any:
    """An adapter instance from a built-in name or ``package.module:Class``."""
    target = ENGINES.get(spec, spec)
    if ":" not in target:
        raise UsageError(f"unknown engine {spec!r}: expected one of {', '.join(ENGINES)} "
                         "or module:Class")
    mod, _, cls = target.partition(":")
    try:
        return getattr(importlib.import_module(mod), cls)()
    except ImportError as e:
        hint = (f" (pip install './python[{EXTRAS[spec]}]' or pip install {EXTRAS[spec]})"
                if spec in EXTRAS else "")
        raise UsageError(f"engine {spec!r} cannot be imported: {e}{hint}") from None
    except AttributeError:
        raise UsageError(f"engine {spec!r}: module {mod} has no class {cls}") from None


def _value(text: str) -> Any:
    try:
        return json.loads(text)
    except ValueError:
        return text


def parser() -> argparse.ArgumentParser:
    from .scorecard import BATTERY, MIN_ROWS
    ap = argparse.ArgumentParser(
        prog="cylroll-conformance",
        description="Score a physics engine on the cylinder-on-cylinder problem against "
                    "cylroll's reference. Exit 0: every check passes, 1: some fail, 2: bad usage.")
    ap.add_argument("engine", help=f"{' | '.join(ENGINES)} | module:Class (your own adapter)")
    ap.add_argument("--cases", default=",".join(BATTERY),
                    help="golden case names, comma-separated (default: %(default)s)")
    ap.add_argument("--dt", default="2e-3,1e-3,5e-4",
                    help="time steps, comma-separated, >= 3 for an observed order "
                         "(default: %(default)s)")
    ap.add_argument("--out", default="conformance-out", help="output directory (default: %(default)s)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="an adapter setting (VALUE read as JSON, else as text); repeatable")
    ap.add_argument("--max-rows", default="300",
                    help=f"rows per run compared with the reference, {MIN_ROWS} to 10^6 "
                         "(default: %(default)s)")
    ap.add_argument("-q", "--quiet", action="store_true")
    return ap


def main(argv: Optional[List[str]] = None) -> int:
    ap = parser()
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    log = (lambda s: None) if a.quiet else (lambda s: print(s, file=sys.stderr, flush=True))
    try:
        import cylroll
        cases = [c.strip() for c in a.cases.split(",") if c.strip()]
        known = set(cylroll.golden.names())
        bad = [c for c in cases if c not in known]
        if not cases or bad:
            raise UsageError(f"unknown case(s) {', '.join(bad) or '(none given)'}: "
                             f"expected names of cylroll.golden.names(): {', '.join(sorted(known))}")
        try:
            dts = [float(x) for x in a.dt.split(",") if x.strip()]
        except ValueError:
            raise UsageError(f"--dt {a.dt!r}: expected numbers separated by commas") from None
        if not dts or any(not (0 < d < 0.1) for d in dts) or len(set(dts)) != len(dts):
            raise UsageError(f"--dt {a.dt!r}: expected distinct steps between 0 and 0.1")
        from .scorecard import MIN_ROWS
        try:
            max_rows = int(a.max_rows)
        except ValueError:
            max_rows = -1
        if not MIN_ROWS <= max_rows <= 10**6:
            raise UsageError(f"--max-rows {a.max_rows!r}: expected a whole number from "
                             f"{MIN_ROWS} to 10^6 (fewer rows would leave theta's error and the "
                             "observed order unmeasured)")
        settings = {}
        for kv in a.set:
            k, eq, v = kv.partition("=")
            if not eq or not k.strip():
                raise UsageError(f"--set {kv!r}: expected KEY=VALUE")
            settings[k.strip()] = _value(v.strip())
        adapter = load_adapter(a.engine)
    except UsageError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    from .scorecard import scorecard, write
    t0 = time.perf_counter()
    card = scorecard(adapter, cases, dts, settings, max_rows, log)
    write(card, a.out)
    n_fail = sum(not ch["pass"] for c in card["cases"] for ch in c["checks"])
    n_all = sum(len(c["checks"]) for c in card["cases"])
    log(f"{card['engine']['name']} {card['engine']['version']}: {n_all - n_fail}/{n_all} checks "
        f"pass, {time.perf_counter() - t0:.1f} s; wrote {a.out}/scorecard.json and index.html")
    return 0 if card["passed"] else 1
