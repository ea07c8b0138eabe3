"""The scorecard: an engine run on golden cases at several steps, held against
the reference (through :mod:`cylroll.conformance.reference` only), written as
``scorecard.json`` and ``index.html``."""

from __future__ import annotations

import html
import json
import math
import numbers
import os
import time
from typing import Any, Callable, Dict, List, Optional, Sequence

import numpy as np

import cylroll

from . import reference
from .runner import RunResult, observed_order, run_case

__all__ = ["BATTERY", "TOLERANCES", "CORE_TOLERANCES", "QUANTITIES", "score_case", "scorecard",
           "write"]

#: The default battery: rolling, Coulomb at three μ (slip then flight; the
#: contact opening at the cone), frictionless, a held lower cylinder.
BATTERY = ("mujoco_main", "main_mu_0_3", "main_mu_1", "main_mu_10", "slip_slip", "fixed_roll")

#: The checks' tolerances (case units: radians, r, m2 g r).
TOLERANCES: Dict[str, float] = dict(
    theta_error=2e-3,        # max |Δθ| before slip, at the smallest dt
    order_min=0.8,           # observed order of the θ error
    slip_onset=2e-3,         # |Δθ| of a slip onset, at the smallest dt
    parting=1e-2,            # |Δθ| of the parting (against θ* on the part branch)
    cone=1e-2,               # max |F|/(μN) − 1
    penetration=1e-3,        # max penetration / r
    contact_losses=0,        # spurious contact losses before the parting
    energy_increase=1e-3,    # max (E − E0) / (m2 g r) before the parting
)

#: The tolerances of ``cylroll check``'s scoring core in each run (``check``):
#: rtol, atol in units of each column's scale, events in radians of θ.
CORE_TOLERANCES: Dict[str, float] = dict(rtol=1e-3, atol=1e-3, event_tol=1e-2)

#: Quantities compared with the reference (the forces only where the engine exposes them).
QUANTITIES = ("theta", "theta_dot", "x1", "x1_dot", "phi1", "phi1_dot", "phi2", "phi2_dot",
              "x2", "x2_dot", "y2", "y2_dot", "s1", "s12", "F1", "N1", "F21", "N12")
FORCES = ("F1", "N1", "F21", "N12")


def _f(x: Any) -> Any:
    """JSON-safe floats (NaN and inf as null)."""
    if isinstance(x, dict):
        return {k: _f(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_f(v) for v in x]
    if isinstance(x, (np.floating, float)):
        x = float(x)
        return x if math.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    return x


#: The fewest rows per run compared with the reference: with one row (t = 0)
#: θ's error read 0 and the scorecard passed an engine with gravity 20% off.
MIN_ROWS = 20


def _subsample(t: np.ndarray, t_hi: float, max_rows: int) -> np.ndarray:
    idx = np.flatnonzero(t < t_hi)
    if idx.size > max_rows:
        idx = idx[np.unique(np.linspace(0, idx.size - 1, max_rows).round().astype(int))]
    return idx


def _branch(run: RunResult, win: Optional[tuple]) -> tuple:
    """Which lawful continuation the engine took where the motion is not
    unique, and the reference's branch to judge it against:
    (label, reference branch). ``part`` (it parted within the parting
    tolerance of θ*), ``stay`` (within it of the end of the closed branch),
    ``part_at`` (inside the window, away from both ends: the reference parts
    at the engine's angle), ``outside`` (it parted before θ*: not lawful; the
    closed reference up to its parting). (None, "stay") where the motion is
    unique or the engine never parted."""
    sep = run.event("separation")
    if win is None or sep is None:
        return None, "stay"
    a, b = win
    th = sep["theta"]
    tol = TOLERANCES["parting"]
    if abs(th - a) <= tol or abs(th - b) <= tol:
        return ("part", "part") if abs(th - a) < abs(th - b) else ("stay", "stay")
    if a < th < b:
        return "part_at", float(th)
    return ("outside", "stay") if th < a else ("stay", "stay")


def _compare(case: str, run: RunResult, phases: Dict[str, tuple], t_hi: float,
             max_rows: int, branch: Any = "stay") -> Dict[str, Dict[str, float]]:
    idx = _subsample(run.t, t_hi, max_rows)
    ref = reference.rows_at(case, run.t[idx], branch)
    keep = np.isin(run.t[idx], ref["t"])
    idx = idx[keep]
    t = run.t[idx]
    errors: Dict[str, Dict[str, float]] = {}
    for qn in QUANTITIES:
        if qn not in ref or (qn in FORCES and not run.has_forces[0 if qn in ("F1", "N1") else 1]):
            continue
        e = np.abs(run.q[qn][idx] - ref[qn])
        per = {}
        for ph, (a, b) in phases.items():
            m = (t >= a) & (t < b) & np.isfinite(e)
            if np.any(m):
                per[ph] = float(np.max(e[m]))
        if per:
            errors[qn] = per
    return errors


def _core_check(case: str, run: RunResult, t_hi: float, max_rows: int,
                branch: Any) -> Dict[str, Any]:
    """``cylroll check``'s scoring core on the run's rows (those before
    ``t_hi`` where every compared quantity is finite), on the branch judged
    against: its verdict per phase of the reference and the first failing
    row, at :data:`CORE_TOLERANCES`."""
    idx = _subsample(run.t, t_hi, max_rows)
    cols = [q for q in QUANTITIES if q in reference.COLUMNS and
            not (q in FORCES and not run.has_forces[0 if q in ("F1", "N1") else 1])]
    table = {"t": run.t[idx], **{q: run.q[q][idx] for q in cols}}
    ok = np.all([np.isfinite(table[q]) for q in cols], axis=0)
    table = {k: v[ok] for k, v in table.items()}
    try:
        return reference.check_table(case, table, branch, **CORE_TOLERANCES)
    except cylroll.CylrollError as e:
        return dict(error=str(e))


def _events(run: RunResult, ref_events: List[Dict[str, Any]]) -> List[Dict[str, Any]]:
    out = []
    firsts: Dict[tuple, Dict[str, Any]] = {}
    for e in ref_events:
        key = (e["kind"], e.get("contact") if e["kind"] == "slip_onset" else None)
        if e["kind"] in ("slip_onset", "separation", "impact") and key not in firsts:
            firsts[key] = e
    for e in run.measurements["events"]:
        key = (e["kind"], e.get("contact") if e["kind"] == "slip_onset" else None)
        r = firsts.pop(key, None)
        item = dict(kind=e["kind"], contact=e.get("contact"),
                    engine=dict(t=e["t"], theta=e["theta"]),
                    reference=None if r is None else dict(t=r["t"], theta=r["theta"]),
                    error=None if r is None else e["theta"] - r["theta"],
                    error_t=None if r is None or r["t"] is None else e["t"] - r["t"])
        if "method" in e:
            item["method"] = e["method"]
        out.append(item)
    for (kind, contact), r in firsts.items():
        out.append(dict(kind=kind, contact=contact, engine=None,
                        reference=dict(t=r["t"], theta=r["theta"]), error=None, error_t=None))
    return out


def score_case(adapter: Any, case: str, dts: Sequence[float],
               settings: Optional[Dict[str, Any]] = None, max_rows: int = 300,
               log: Callable[[str], None] = lambda s: None) -> Dict[str, Any]:
    """One case of the scorecard: runs at every dt, errors per quantity and
    phase, events, observed order, branch taken and checks.

    Raises ValueError for ``max_rows`` outside :data:`MIN_ROWS` to 10^6."""
    if (isinstance(max_rows, bool) or not isinstance(max_rows, numbers.Integral)
            or not MIN_ROWS <= int(max_rows) <= 10**6):
        raise ValueError(f"max_rows = {max_rows!r}: expected a whole number from {MIN_ROWS} "
                         "to 10^6")
    max_rows = int(max_rows)
    p = reference.params(case)
    bp = reference.branch_point(case)
    end = reference.closed_end(case)
    win = reference.window(case)
    # run past the latest impact of the lawful branches
    t_max = max(reference.t_max(case, b) for b in (("stay", "part") if bp else ("stay",)))
    t_end = t_max * 1.02 + 0.05
    phi2_0 = reference.phi2_start(case)
    runs, results = [], []
    for dt in sorted(dts, reverse=True):
        run = run_case(adapter, p, dt, t_end, settings, phi2_0=phi2_0)
        branch, ref_branch = _branch(run, win)
        t_hi = reference.t_max(case, ref_branch)
        note = None
        if branch == "outside":
            # parting before θ* is not lawful: the closed reference up to the parting
            t_hi = min(t_hi, run.event("separation")["t"])
            note = ("the engine parted before the branch point, where the rigid-body motion "
                    "may not part; compared with the closed branch up to its parting")
        elif branch == "part_at":
            note = (f"the engine parted inside the window where parting is lawful, at theta = "
                    f"{ref_branch:.6g}; compared with the reference parting there")
        elif branch == "part":
            note = ("the engine took the part branch at the branch point (as velocity-level "
                    "complementarity solvers do); compared with the reference's part branch")
        ref_events = reference.events(case, ref_branch)
        phases = reference.phases(case, ref_branch)
        errors = _compare(case, run, phases, t_hi, max_rows, ref_branch)
        m = run.measurements
        item = dict(dt=dt, wall_seconds=round(run.wall, 3), steps=int(len(run.t) - 1),
                    stopped=run.stopped, errors=errors, events=_events(run, ref_events),
                    branch_taken=branch, reference_branch=ref_branch,
                    contact_losses=m["contact_losses"],
                    contact_loss_times=m["contact_loss_times"], chatter=m["chatter"],
                    cone_violation=m["cone_violation"], penetration=m["penetration"],
                    energy=m["energy"], forces_exposed=dict(floor=run.has_forces[0],
                                                            contact=run.has_forces[1]))
        item["check"] = _core_check(case, run, t_hi, max_rows, ref_branch)
        if note:
            item["note"] = note
        runs.append(item)
        results.append(run)
        log(f"  {case} dt={dt:g}: {run.wall:.2f} s, {len(run.t) - 1} steps, "
            f"theta err {errors.get('theta', {})}, branch {branch}")
    # observed order: of the first phase each quantity has
    order = {}
    for qn in QUANTITIES:
        by = {}
        for r in runs:
            per = r["errors"].get(qn)
            if per:
                ph = "before_slip" if "before_slip" in per else next(iter(per))
                by[r["dt"]] = per[ph]
        o = observed_order(by)
        if o is not None:
            order[qn] = o
    finest = min(runs, key=lambda r: r["dt"])
    checks = _checks(p, finest, order, bp, end, win)
    return _f(dict(case=case, params=p["exact"], branch_point=bp,
                   closed_branch_end=None if end is None else dict(t=end["t"], theta=end["theta"]),
                   parting_window=None if win is None else list(win),
                   phases={k: list(v) for k, v in reference.phases(case).items()},
                   runs=runs, order=order,
                   branch_taken=finest["branch_taken"], checks=checks))


def _check(name, value, tol, ok, why):
    return dict(name=name, value=value, tolerance=tol, ok=ok, why=why)


def _checks(p, run, order, bp, end, win) -> List[Dict[str, Any]]:
    T = TOLERANCES
    r = p["r1"] + p["r2"]
    scale = p["m2"] * p["g"] * r
    out = []
    th = run["errors"].get("theta", {})
    ph = "before_slip" if "before_slip" in th else (next(iter(th)) if th else None)
    if ph:
        v = th[ph]
        out.append(_check(f"theta error ({ph}, dt={run['dt']:g})", v, T["theta_error"],
                          v <= T["theta_error"], "max |θ_engine − θ_ref| on the engine's grid"))
    if "theta" in order:
        v = order["theta"]
        out.append(_check("observed order of the theta error", v, T["order_min"],
                          v >= T["order_min"], "least-squares slope of log error vs log dt"))
    for e in run["events"]:
        if e["kind"] == "slip_onset":
            if e["reference"] is None and e["engine"] is not None and end is not None \
                    and abs(e["engine"]["theta"] - end["theta"]) <= T["slip_onset"]:
                v = abs(e["engine"]["theta"] - end["theta"])
                out.append(_check(f"slip onset ({e['contact']}) theta error", v, T["slip_onset"],
                                  True, "the reference's contact opens here without sliding; "
                                  "the engine reaches its cone there and slides briefly"))
            elif e["reference"] is None or e["engine"] is None:
                out.append(_check(f"slip onset ({e['contact']})", None, T["slip_onset"], False,
                                  "the engine slips where the reference does not"
                                  if e["reference"] is None else
                                  "the engine did not slip where the reference does"))
            else:
                v = abs(e["error"])
                out.append(_check(f"slip onset ({e['contact']}) theta error", v, T["slip_onset"],
                                  v <= T["slip_onset"], f"engine found by {e.get('method')}"))
    sep = next((e for e in run["events"] if e["kind"] == "separation"), None)
    taken = run["branch_taken"]
    if sep is not None and sep["engine"] is not None and taken in ("part_at", "outside"):
        th = sep["engine"]["theta"]
        v = 0.0 if taken == "part_at" else win[0] - th
        out.append(_check("parting inside the window where it is lawful", v, T["parting"],
                          taken == "part_at",
                          f"the rigid-body motion may part anywhere in [θ*, θs] = "
                          f"[{win[0]:.6g}, {win[1]:.6g}]; the engine parted at {th:.6g}"))
    elif sep is not None and sep["engine"] is not None:
        if taken == "part":
            v = abs(sep["error"]) if sep["reference"] is not None else \
                abs(sep["engine"]["theta"] - bp["theta"])
            out.append(_check("parting theta error (part branch: against the branch point)", v,
                              T["parting"], v <= T["parting"],
                              "the engine parted near θ*, the first instant the rigid-body "
                              "motion may part; judged against the reference's part branch"))
        elif sep["reference"] is not None:
            v = abs(sep["error"])
            out.append(_check("parting theta error", v, T["parting"], v <= T["parting"],
                              "the last closed sample before the contact opens for good"))
    elif sep is not None:
        out.append(_check("parting", None, T["parting"], False, "the engine never parted"))
    for c, v in (run["cone_violation"] or {}).items():
        if v is not None:
            out.append(_check(f"cone violation ({c})", v, T["cone"], v <= T["cone"],
                              "max |F|/(μN) − 1 while loaded"))
    v = run["penetration"]["contact"] / r
    out.append(_check("penetration between the cylinders / r", v, T["penetration"],
                      v <= T["penetration"], "max of −gap before the impact"))
    v = run["penetration"]["floor"] / r
    out.append(_check("penetration into the floor / r", v, T["penetration"],
                      v <= T["penetration"], "max of r1 − y1 before the impact"))
    v = run["contact_losses"]
    out.append(_check("spurious contact losses", v, T["contact_losses"],
                      v <= T["contact_losses"], "openings that close again before the parting"))
    v = run["energy"]["max_increase"] / scale
    out.append(_check("energy increase / (m2 g r)", v, T["energy_increase"],
                      v <= T["energy_increase"], "contacts never add energy"))
    for c in out:
        c["pass"] = bool(c.pop("ok"))
    return out


def scorecard(adapter: Any, cases: Sequence[str], dts: Sequence[float],
              settings: Optional[Dict[str, Any]] = None, max_rows: int = 300,
              log: Callable[[str], None] = lambda s: None) -> Dict[str, Any]:
    """The whole scorecard as a dict (the layout of ``scorecard.json``)."""
    t0 = time.perf_counter()
    out_cases = [score_case(adapter, c, dts, settings, max_rows, log) for c in cases]
    return _f(dict(
        schema="cylroll-conformance/0",
        engine=dict(name=getattr(adapter, "name", type(adapter).__name__),
                    version=str(getattr(adapter, "version", "?")),
                    settings={k: v for k, v in (getattr(adapter, "settings", {}) or {}).items()
                              if k != "dt"}),
        reference=dict(package="cylroll", version=reference.package_version()),
        dts=list(dts), tolerances=TOLERANCES, core_tolerances=CORE_TOLERANCES, cases=out_cases,
        passed=all(ch["pass"] for c in out_cases for ch in c["checks"]),
        wall_seconds=round(time.perf_counter() - t0, 2)))


def _fmt(x: Any) -> str:
    if x is None:
        return "–"
    if isinstance(x, float):
        return f"{x:.3g}"
    return html.escape(str(x))


def to_html(card: Dict[str, Any]) -> str:
    e = card["engine"]
    h = [f"<!doctype html><meta charset='utf-8'><title>cylroll conformance: {_fmt(e['name'])}"
         "</title><style>body{font-family:sans-serif;max-width:70em;margin:auto}"
         "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;"
         "padding:2px 6px;text-align:right}.fail{background:#fdd}.pass{background:#dfd}</style>",
         f"<h1>{_fmt(e['name'])} {_fmt(e['version'])}: "
         f"{'all checks pass' if card['passed'] else 'some checks fail'}</h1>",
         f"<p>dt: {', '.join(_fmt(d) for d in card['dts'])}; reference cylroll "
         f"{_fmt(card['reference']['version'])}; {_fmt(card['wall_seconds'])} s.</p>",
         "<details><summary>settings</summary><pre>"
         + html.escape(json.dumps(e["settings"], indent=1)) + "</pre></details>"]
    for c in card["cases"]:
        h.append(f"<h2>{_fmt(c['case'])}</h2>")
        bp = c.get("branch_point")
        if bp:
            h.append(f"<p>branch point θ* = {_fmt(bp['theta'])} (t* = {_fmt(bp['t'])}); "
                     f"branch taken: <b>{_fmt(c.get('branch_taken'))}</b></p>")
        h.append("<table><tr><th>check</th><th>value</th><th>tolerance</th><th>why</th></tr>")
        for ch in c["checks"]:
            cls = "pass" if ch["pass"] else "fail"
            h.append(f"<tr class='{cls}'><td style='text-align:left'>{_fmt(ch['name'])}</td>"
                     f"<td>{_fmt(ch['value'])}</td><td>{_fmt(ch['tolerance'])}</td>"
                     f"<td style='text-align:left'>{_fmt(ch['why'])}</td></tr>")
        h.append("</table>")
        phs = ["before_slip", "slipping", "after_parting"]
        h.append("<table><tr><th>quantity</th><th>order</th>"
                 + "".join(f"<th>{ph} dt={_fmt(r['dt'])}</th>" for r in c["runs"] for ph in phs)
                 + "</tr>")
        qs = sorted({q for r in c["runs"] for q in r["errors"]}, key=QUANTITIES.index)
        for q in qs:
            h.append(f"<tr><td style='text-align:left'>{q}</td><td>{_fmt(c['order'].get(q))}</td>"
                     + "".join(f"<td>{_fmt(r['errors'].get(q, {}).get(ph))}</td>"
                               for r in c["runs"] for ph in phs) + "</tr>")
        h.append("</table><table><tr><th>dt</th><th>cylroll check (per phase of the "
                 "reference)</th><th>first failure</th></tr>")
        for r in c["runs"]:
            ck = r.get("check") or {}
            if "error" in ck:
                h.append(f"<tr><td>{_fmt(r['dt'])}</td><td style='text-align:left'>"
                         f"{_fmt(ck['error'])}</td><td>–</td></tr>")
                continue
            phs = "; ".join(f"{_fmt(p['mode'])}: {'pass' if p['passed'] else 'fail'}"
                            for p in ck.get("phases", []))
            ff = ck.get("first_failure")
            first = "–" if ff is None else (f"row {_fmt(ff['row'])} (t = {_fmt(ff['t'])}), "
                                            f"{_fmt(ff['column'])}")
            cls = "pass" if ck.get("passed") else "fail"
            h.append(f"<tr class='{cls}'><td>{_fmt(r['dt'])}</td><td style='text-align:left'>"
                     f"{_fmt(ck.get('verdict'))}: {phs}</td><td>{first}</td></tr>")
        h.append("</table><table><tr><th>dt</th><th>event</th><th>engine θ</th>"
                 "<th>reference θ</th><th>error</th></tr>")
        for r in c["runs"]:
            for ev in r["events"]:
                h.append(f"<tr><td>{_fmt(r['dt'])}</td><td style='text-align:left'>"
                         f"{_fmt(ev['kind'])} {_fmt(ev.get('contact') or '')}</td>"
                         f"<td>{_fmt((ev['engine'] or {}).get('theta'))}</td>"
                         f"<td>{_fmt((ev['reference'] or {}).get('theta'))}</td>"
                         f"<td>{_fmt(ev['error'])}</td></tr>")
        h.append("</table>")
    return "\n".join(h) + "\n"


def write(card: Dict[str, Any], out: str) -> None:
    """Writes ``out/scorecard.json`` and ``out/index.html``."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "scorecard.json"), "w") as f:
        json.dump(card, f, indent=1)
        f.write("\n")
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(to_html(card))
