"""Measurements on an engine's own output, with no reference: events found in
noisy signals, and the engine's faults (cone violation, penetration, energy,
spurious contact losses, force chatter).

Every event finder asks for a condition that *lasts* (``hold`` seconds of the
signal's own time, or to the end of the data), so that single-step chatter is
not taken for the event:

- slip onset at a contact: the friction force reaching the cone,
  |F| ≥ (1 − ``cone_eps``) μ N, for good (method ``"cone"``), the time moved
  back to where a line fitted to the ratio's rise before it reaches 1; where the
  engine exposes no forces or μ is not finite, the slip speed leaving ~0 for
  good (|s| > ``slip_tol``; method ``"speed"``), moved back along the growth of
  \\|s\\| to where it left the noise floor;
- parting: the contact open for good (N12 ≤ ``force_tol`` where the engine
  exposes forces, else gap > ``gap_tol``); the event is the last closed
  sample before it; openings that close again before it are spurious
  contact losses;
- impact: after the parting, cylinder 2 reaching the floor (y2 − r2 ≤ 0) or
  cylinder 1 again (the contact closed again).
"""

from __future__ import annotations

import math
from typing import Any, Dict, List, Mapping, Optional, Tuple

import numpy as np

__all__ = ["DEFAULTS", "lasting_runs", "first_lasting", "slip_onset", "parting", "impact",
           "cone_violation", "force_chatter", "measure"]

#: Default thresholds (in the case's units: velocities over sqrt(g r), forces over m2 g,
#: lengths over r, times in seconds of the engine's time); recorded in the scorecard.
DEFAULTS: Dict[str, float] = dict(
    hold=0.02,          # a condition must last this long (s) to count as an event
    cone_eps=2e-3,      # |F| >= (1 - cone_eps) mu N is "on the cone"
    slip_tol=1e-3,      # |slip speed| / sqrt(g r) above this is slipping
    slip_floor=1e-5,    # ... and below this it is ~0 (the walk back stops there)
    force_tol=1e-6,     # N / (m2 g) above this: the contact carries force
    gap_tol=1e-5,       # gap / r below this: closed (engines that expose no forces)
    gap_open=1e-3,      # a parting must open the gap to at least this (/ r)
    n_min=1e-2,         # cone ratios only where N / (m g) > n_min (not near parting)
    spike_factor=2.0,   # a force sample above spike_factor x its local median is a spike
    spike_window=15,    # samples of the local median
)


def lasting_runs(mask: np.ndarray) -> List[Tuple[int, int]]:
    """Runs [i, j) of consecutive True in ``mask``."""
    m = np.asarray(mask, dtype=bool)
    if m.size == 0:
        return []
    d = np.diff(np.concatenate([[0], m.astype(np.int8), [0]]))
    starts = np.flatnonzero(d == 1)
    ends = np.flatnonzero(d == -1)
    return list(zip(starts.tolist(), ends.tolist()))


def first_lasting(t: np.ndarray, mask: np.ndarray, hold: float, start: int = 0,
                  stop: Optional[int] = None) -> Optional[int]:
    """The first index i in [start, stop) where ``mask`` holds from t[i] for at
    least ``hold`` (or to ``stop``, the end of the window, and then over at least
    3 samples)."""
    stop = len(mask) if stop is None else stop
    for i, j in lasting_runs(np.asarray(mask)[start:stop]):
        i += start
        j += start
        if t[j - 1] - t[i] >= hold or (j == stop and j - i >= 3):
            return i
    return None


def slip_onset(t: np.ndarray, slip: np.ndarray, F: np.ndarray, N: np.ndarray,
               mu: Optional[float], stop: Optional[int], vscale: float, fscale: float,
               o: Mapping[str, float] = DEFAULTS) -> Optional[Dict[str, Any]]:
    """The first lasting slip of one contact before index ``stop`` (the parting):
    {"index", "method"} or None."""
    stop = len(t) if stop is None else stop
    # (row 0 has no forces: they belong to a step)
    if mu is not None and 0 < mu < math.inf and np.all(np.isfinite(F[1:stop])) \
            and np.all(np.isfinite(N[1:stop])):
        Fz, Nz = np.nan_to_num(F), np.nan_to_num(N)
        loaded = Nz > o["n_min"] * fscale
        on = loaded & (np.abs(Fz) >= (1 - o["cone_eps"]) * mu * np.abs(Nz))
        # a contact that chatters open while it slides does not end the slip: unloaded
        # samples neither break a run on the cone nor start one
        i = None
        for a, b in lasting_runs((on | ~loaded)[:stop]):
            first_on = a + int(np.argmax(on[a:b])) if np.any(on[a:b]) else None
            if first_on is not None and np.count_nonzero(on[a:b]) >= 3 and \
                    (t[b - 1] - t[first_on] >= o["hold"] or b == stop):
                i = first_on
                break
        if i is not None:
            # the threshold 1 − cone_eps is crossed early by cone_eps / (rate of the ratio):
            # extend the ratio's rise over the samples before i to where it reaches 1
            ratio = np.where(loaded, np.abs(Fz) / (mu * np.where(loaded, np.abs(Nz), 1.0)), 0.0)
            j = i
            while j > 1 and loaded[j - 1] and ratio[j - 1] >= 1 - 10 * o["cone_eps"] \
                    and ratio[j - 1] < ratio[j] + o["cone_eps"]:
                j -= 1
            t_on = float(t[i])
            if i - j >= 3:
                a, b = np.polyfit(t[j:i], ratio[j:i], 1)
                if a > 0:
                    t_on = float(min(max((1.0 - b) / a, t[j]), t[i] + o["hold"]))
            return dict(index=i, method="cone", t=t_on)
    s = np.abs(slip)
    i = first_lasting(t, s > o["slip_tol"] * vscale, o["hold"], 0, stop)
    if i is None:
        return None
    j = i
    while j > 0 and s[j - 1] < s[j] and s[j - 1] > o["slip_floor"] * vscale:
        j -= 1
    return dict(index=j, method="speed")


def parting(t: np.ndarray, closed: np.ndarray, gap: np.ndarray, lscale: float,
            o: Mapping[str, float] = DEFAULTS) -> Dict[str, Any]:
    """The parting of the cylinders: ``index`` (the last closed sample before the
    contact opens for good, None if it never does), ``losses`` (openings that
    close again before it: spurious contact losses), ``first_close``."""
    closed = np.asarray(closed, dtype=bool)
    idx = np.flatnonzero(closed)
    if idx.size == 0:
        return dict(index=None, losses=0, first_close=None, loss_times=[])
    first = int(idx[0])
    losses: List[float] = []
    for i, j in lasting_runs(~closed[first:]):
        i += first
        j += first
        lasting = t[j - 1] - t[i] >= o["hold"] or j == len(closed)
        if lasting and np.max(gap[i:j]) > o["gap_open"] * lscale:
            return dict(index=i - 1, losses=len(losses), first_close=first,
                        loss_times=losses[:20])
        losses.append(float(t[i]))
    return dict(index=None, losses=len(losses), first_close=first, loss_times=losses[:20])


def impact(t: np.ndarray, closed: np.ndarray, floor_gap2: np.ndarray,
           after: Optional[int]) -> Optional[Dict[str, Any]]:
    """After index ``after`` (the parting), the first sample where cylinder 2
    reaches the floor (y2 − r2 ≤ 0) or cylinder 1 again (closed)."""
    if after is None:
        return None
    k0 = after + 1
    while k0 < len(closed) and closed[k0]:
        k0 += 1
    for k in range(k0, len(t)):
        if floor_gap2[k] <= 0.0:
            return dict(index=k, surface="floor")
        if closed[k]:
            return dict(index=k, surface="cylinder")
    return None


def cone_violation(F: np.ndarray, N: np.ndarray, mu: Optional[float], mask: np.ndarray,
                   fscale: float, o: Mapping[str, float] = DEFAULTS) -> Optional[float]:
    """max |F| / (μ N) − 1 over the loaded samples of ``mask``; None without a
    finite μ > 0 or without forces."""
    if mu is None or not 0 < mu < math.inf:
        return None
    m = mask & np.isfinite(F) & np.isfinite(N) & (N > o["n_min"] * fscale)
    if not np.any(m):
        return None
    return float(np.max(np.abs(F[m]) / (mu * N[m])) - 1.0)


def force_chatter(N: np.ndarray, stop: Optional[int], fscale: float,
                  o: Mapping[str, float] = DEFAULTS) -> Dict[str, Any]:
    """Force chatter of a normal force before ``stop``: the largest ratio of a
    sample to the median of its neighbourhood, and the number of spikes (runs of
    samples above ``spike_factor`` x that median)."""
    x = np.asarray(N[1:stop], dtype=float)     # row 0 has no forces
    w = int(o["spike_window"]) | 1
    if x.size < w or not np.all(np.isfinite(x)):
        return dict(max_ratio=None, spikes=0)
    pad = np.pad(x, w // 2, mode="edge")
    med = np.median(np.lib.stride_tricks.sliding_window_view(pad, w), axis=1)
    ok = med > o["n_min"] * fscale
    if not np.any(ok):
        return dict(max_ratio=None, spikes=0)
    ratio = np.where(ok, x / np.where(ok, med, 1.0), 0.0)
    spikes = len(lasting_runs(ratio > o["spike_factor"]))
    return dict(max_ratio=float(np.max(ratio)), spikes=spikes)


def measure(p: Mapping[str, Any], t: np.ndarray, q: Mapping[str, np.ndarray],
            has_forces: Tuple[bool, bool], mu_engine: Mapping[str, Optional[float]] = None,
            o: Optional[Mapping[str, float]] = None) -> Dict[str, Any]:
    """All engine-side measurements of one run: ``events`` (slip onsets per
    contact, parting, impact; each with index, t, theta), ``contact_losses``,
    ``chatter``, ``cone_violation`` per contact, ``penetration`` (contact,
    floor), ``energy`` (E0, largest drift and increase before the parting)."""
    o = {**DEFAULTS, **(o or {})}
    r = p["r1"] + p["r2"]
    vscale = math.sqrt(p["g"] * r)
    f2 = p["m2"] * p["g"]
    f1 = (p["m1"] + p["m2"]) * p["g"]
    theta = q["theta"]
    gap = q["gap"]
    if has_forces[1]:
        closed = np.nan_to_num(q["N12"], nan=0.0) > o["force_tol"] * f2
    else:
        closed = gap <= o["gap_tol"] * r
    part = parting(t, closed, gap, r, o)
    ip = part["index"]
    imp = impact(t, closed, q["floor_gap2"], ip)
    stop = None if ip is None else ip + 1
    end = len(t) if imp is None else imp["index"]
    mu_case = {"floor": p.get("mu_floor"), "contact": p.get("mu_contact")}

    def ev(kind, i, t_at=None, **extra):
        if t_at is None:
            return dict(kind=kind, index=int(i), t=float(t[i]), theta=float(theta[i]), **extra)
        return dict(kind=kind, index=int(i), t=t_at, theta=float(np.interp(t_at, t, theta)),
                    **extra)

    events = []
    onsets = {}
    for contact, s, F, N, fs in (("contact", q["s12"], q["F21"], q["N12"], f2),
                                 ("floor", q["s1"], q["F1"], q["N1"], f1)):
        if contact == "floor" and p["floor"] == "fixed":
            continue
        mu = mu_case[contact]
        mus = None if mu is None else mu[0]
        if mus == 0.0:
            continue            # frictionless: slipping from the start, no onset
        so = slip_onset(t, s, F, N, mus, stop, vscale, fs, o)
        if so is not None:
            onsets[contact] = so
            events.append(ev("slip_onset", so["index"], so.get("t"), contact=contact,
                              method=so["method"]))
    if ip is not None:
        events.append(ev("separation", ip, contact="contact"))
    if imp is not None:
        events.append(ev("impact", imp["index"], surface=imp["surface"]))
    events.sort(key=lambda e: e["t"])
    before = np.zeros(len(t), dtype=bool)
    before[: (stop if stop is not None else end)] = True
    cone = {}
    for contact, F, N, fs in (("contact", q["F21"], q["N12"], f2), ("floor", q["F1"], q["N1"], f1)):
        mu = mu_case[contact]
        mus = None if mu is None else mu[0]
        if mus is not None and math.isinf(mus) and mu_engine:
            mus = mu_engine.get(contact)          # rolling: the engine's own large mu
        cone[contact] = cone_violation(F, N, mus, before & (closed if contact == "contact"
                                                            else True), fs, o)
    pen_c = float(max(0.0, -np.min(gap[:end]))) if end > 0 else 0.0
    pen_f = float(max(0.0, -np.min(q["floor_gap1"][:end]))) if end > 0 else 0.0
    E = q["energy"]
    k = stop if stop is not None else end
    dE = E[:k] - E[0] if k > 0 else np.zeros(1)
    chat = force_chatter(q["N12"], stop if stop is not None else end, f2, o) \
        if has_forces[1] else dict(max_ratio=None, spikes=0)
    return dict(events=events, onsets=onsets, parting=part, impact=imp,
                contact_losses=part["losses"], contact_loss_times=part["loss_times"],
                chatter=chat, cone_violation=cone,
                penetration=dict(contact=pen_c, floor=pen_f),
                energy=dict(E0=float(E[0]), max_drift=float(np.max(np.abs(dE))),
                            max_increase=float(max(0.0, np.max(dE)))),
                thresholds=o)
