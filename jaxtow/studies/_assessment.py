"""The whole assessment of one tow (``jaxtow study``): resistance budget, required bollard
pull, operating speed and transit time per sea state; equilibria and stability in calm water
and in each sea state with a verdict; a stability map around the design point; the
time-domain check from a disturbed start; the wave drift of the hull; and the validity
flags and estimates every number depends on. Numbers only: `jaxtow.reports.tow_report_html`
and the command line turn them into files."""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field

import jax
import jax.numpy as jnp
import numpy as np

from .. import resistance
from .._dynamics import all_valid, at_tug_speed, validity
from .._equilibrium import equilibria
from .._interrupt import requested as interrupt_requested
from .._metrics import fishtail_metrics, trajectory
from .._results import sweep
from .._simulate import initial_state, simulate
from .._stability import MARGINAL, STABILITY_LABELS, STABLE, stability
from .._units import RHO_SEA, G
from ..drift import irregular_sailing_drift
from ..waves import DEFAULT_OMEGA, Jonswap
from ._advice import yaw_advice
from ._criteria import assessment
from ._resistance import evaluate

__all__ = ["Steps", "TowStudy", "tow_study", "verdict", "VERDICTS", "VALIDITY_WORDS"]

#: Plain-words verdicts of a set of equilibria (`verdict`).
VERDICTS = {
    "follows": "follows the tug: the straight-behind equilibrium is stable",
    "sheers": "sheers to one side: only off-axis equilibria are stable",
    "fishtails": "fishtails: no equilibrium is stable (a limit cycle or divergence)",
    "marginal": "marginal: the best equilibrium is at the stability boundary (|max Re λ| "
    "within the stability tolerance)",
    "invalid": "no equilibrium found (the towline is slack at every heading)",
}
#: The validity flags in plain words (the report's warnings).
VALIDITY_WORDS = {
    "line_taut": "the towline goes slack",
    "moving_ahead": "the barge turns stern first (u' <= 0: outside the manoeuvring model, "
    "whose derivatives are for ahead motion)",
    "froude_ok": "the Froude number is 0.15 or more (the drift theory is for slow ships)",
    "no_separation": "the tow speed exceeds the waves' orbital velocity (U >= omega_p Hs/2): "
    "the forward-speed drift theory assumes the flow does not separate",
    "tau_ok": "tau = omega U / g exceeds 1/4 (Aranha's forward-speed correction is a "
    "small-tau theory)",
    "encounter_positive": "the tow overtakes some of the waves (encounter frequency <= 0)",
    "heading_in_table": "the relative wave heading is outside the drift table",
    "yaw_rate_damping": "the drift table has no sectional moments (no yaw-rate damping)",
}
#: An equilibrium within this heading of ψ = 0 counts as straight behind [deg].
STRAIGHT_DEG = 1.0


class Steps:
    """The study's steps: progress on stderr (``[k/n] label ... done in t s``), and, with a
    ``store`` (`jaxtow.io.StepStore`), each step's result stored as it finishes and a stored
    step read back instead of run (``[k/n] label: resumed``). ``current`` is the label of the
    step running (the one named when a study stops early)."""

    def __init__(self, total: int, enabled: bool = True, stream=None, store=None):
        self.total, self.enabled, self.k = total, enabled, 0
        self.stream = stream or sys.stderr
        self.store = store
        self.times: dict = {}
        self.current = ""

    def _say(self, text: str) -> None:
        if self.enabled:
            self.stream.write(f"[{self.k}/{self.total}] {text}\n")
            self.stream.flush()

    def run(self, key: str, label: str, fn, *args, **kw):
        """Step ``key`` (its name in the store), shown as ``label``: ``fn(*args, **kw)``.
        A Ctrl-C that arrived, even one swallowed on its way (`jaxtow._interrupt`), stops
        the study here, before the step or after it is stored."""
        if interrupt_requested():
            raise KeyboardInterrupt
        self.k += 1
        self.current = label
        if self.store is not None and (out := self.store.get(key)) is not None:
            self._say(f"{label}: resumed")
            return out
        t0 = time.perf_counter()
        self._say(f"{label} ...")
        out = fn(*args, **kw)
        self.times[label] = time.perf_counter() - t0
        if self.store is not None:
            self.store.put(key, out)
        self._say(f"{label}: done in {self.times[label]:.1f} s")
        if interrupt_requested():
            raise KeyboardInterrupt
        return out


def verdict(psi, max_real, valid, stab_codes) -> str:
    """The key of `VERDICTS` for equilibria at headings ``psi`` [rad] with ``max_real``,
    found by the solver where ``valid``, and `jaxtow.classify` codes ``stab_codes`` (−1
    stable, 0 marginal, 1 unstable)."""

    psi, ok, codes = np.asarray(psi), np.asarray(valid, bool), np.asarray(stab_codes)
    stable = ok & (codes == STABLE)
    if not ok.any():
        return "invalid"
    straight = np.abs(np.degrees(psi)) < STRAIGHT_DEG
    if (stable & straight).any():
        return "follows"
    if stable.any():
        return "sheers"
    if (ok & (codes == MARGINAL)).any():
        return "marginal"
    return "fishtails"


@dataclass
class TowStudy:
    """What `tow_study` computed: ``summary`` (JSON-ready numbers, verdicts, estimates,
    validity), ``datasets`` (name → xarray.Dataset), and the raw pieces the figures need
    (``runs``: name → (traj, metrics); ``budgets``: sea state → speeds and loads)."""

    tow: object
    summary: dict = field(default_factory=dict)
    datasets: dict = field(default_factory=dict)
    runs: dict = field(default_factory=dict)
    budgets: dict = field(default_factory=dict)
    drift_curves: dict = field(default_factory=dict)


def _equilibria_record(model):
    eqs = equilibria(model)
    st = stability(model, eqs.state)
    found = np.asarray(eqs.valid)
    rows: list = []
    flags_all: dict[str, bool] = {}
    for i in range(len(eqs)):
        flags = validity(model, eqs.state[i])
        bools = {k: bool(v) for k, v in flags.items() if jnp.asarray(v).dtype == bool}
        ok = bool(eqs.valid[i]) and bool(all_valid(flags))
        rows.append(
            dict(
                psi_deg=float(np.degrees(eqs.psi[i])),
                gamma_deg=float(np.degrees(eqs.gamma[i])),
                tension=float(eqs.tension[i]),
                max_real=float(st.max_real[i]),
                stability=STABILITY_LABELS[int(st.stability[i])],
                valid=ok,
                failed_flags=[k for k, v in bools.items() if not v],
            )
        )
        for k, v in bools.items():
            flags_all[k] = flags_all.get(k, True) and v
    key = verdict(eqs.psi, st.max_real, found, np.asarray(st.stability))
    text = VERDICTS[key]
    outside = sorted(k for k, v in flags_all.items() if not v)
    if outside and key != "invalid":
        text += "; OUTSIDE the model's validity: " + "; ".join(
            [VALIDITY_WORDS.get(str(k), str(k)) for k in outside]
        )
    return dict(
        equilibria=rows,
        verdict=key,
        verdict_text=text,
        validity=flags_all,
        outside_validity=outside,
    )


def _catenary_record(model, water_depth):
    """Sag, end tension, effective stiffness and seabed clearance of a catenary towline at
    the calm-water equilibrium nearest straight behind (SI)."""

    eqs = equilibria(model)
    k = int(np.argmin(np.where(np.asarray(eqs.valid), np.abs(np.asarray(eqs.psi)), np.inf)))
    l = eqs.state[k, 3]
    line, sc = model.towline, model.reference_scales
    sag = float(line.sag(l)) * sc.length
    out = dict(
        span_m=float(l) * sc.length,
        horizontal_tension=float(line.tension(l) * sc.force),
        end_tension=float(line.end_tension(l) * sc.force),
        sag_m=sag,
        effective_stiffness_nd=float(line.stiffness(l)),
        elastic_stiffness_nd=float(getattr(line, "series_EA", line.EA) / line.l0),
    )
    if water_depth is not None:
        out.update(
            water_depth=water_depth,
            seabed_clearance_m=water_depth - sag,
            seabed_clear=bool(water_depth - sag > 0),
        )
    return out


def _strength_record(tow, model, summary):
    """The towline's catalogue segments and the largest end tension of the valid equilibria
    (calm and every sea state) against the weakest segment's MBL."""
    sc = model.reference_scales
    line = model.towline
    recs = [summary["calm"]] + list(summary.get("sea_states", {}).values())
    T = max((e["tension"] for r in recs for e in r["equilibria"] if e["valid"]), default=None)
    weakest = min(tow.line_info, key=lambda s: s["mbl_kN"])
    out = dict(segments=tow.line_info, weakest=weakest["name"], mbl_kN=weakest["mbl_kN"])
    if T is not None:
        end = T
        if hasattr(line, "end_tension"):
            end = float(line.end_tension(line.length_at_tension(T)))
        out.update(
            max_end_tension_kN=end * sc.force / 1e3,
            utilisation=end * sc.force / 1e3 / weakest["mbl_kN"],
        )
    if tow.tug is not None:
        out["mbl_over_bollard_pull"] = weakest["mbl_kN"] * 1e3 / float(tow.tug.bollard_pull)
    return out


def _linspace(spec):
    lo, hi, n = spec
    return np.linspace(lo, hi, int(n))


def tow_study(
    tow,
    *,
    progress: bool = True,
    map_xp=None,
    map_l0=None,
    time_domain: bool | None = None,
    t1: float | None = None,
    n_save: int = 2001,
    speeds=None,
    store=None,
) -> TowStudy:
    """Run the whole assessment of ``tow`` (a `jaxtow.tow.Tow`). The grids, the run length
    and the speeds default to the tow file's ``[study]``; the keywords override them (the
    tests use small grids). Steps the tow cannot take (no manoeuvring model, no tug, no
    sea state) are listed in ``summary['skipped']`` with the reason.

    Nothing finished is lost: a step that fails, or a Ctrl-C, ends the study there and what
    finished is returned, with ``summary['incomplete']`` = {``step``: the step's label,
    ``error``: what went wrong, ``interrupted``: True for a Ctrl-C}. With ``store`` (a
    `jaxtow.io.StepStore`) each step's result is stored as it finishes and a stored step is
    read back instead of run, so a killed study resumes with the same results."""
    opts = dict(tow.study)
    map_xp = _linspace(opts["map_xp"] if map_xp is None else map_xp)
    map_l0 = _linspace(opts["map_l0"] if map_l0 is None else map_l0)
    do_td = opts["time_domain"] if time_domain is None else time_domain
    t1 = opts["t1"] if t1 is None else t1
    speeds = _linspace(opts["speeds"] if speeds is None else speeds)
    has_model = tow.vessel is not None and tow.towline is not None
    seas = list(tow.sea_states)
    res = TowStudy(tow)
    n_steps = 2 + (  # drift and criteria; the model's steps and the advice
        has_model * (3 + bool(tow.tug) + (len(seas) if opts["sea_states"] else 0) + bool(do_td))
    )
    steps = Steps(n_steps, enabled=progress, store=store)
    res.summary = summary = _particulars(tow)
    summary["skipped"] = {}
    try:
        _drift_step(tow, seas, steps, res)
        if not has_model:
            summary["skipped"]["stability, resistance and time domain"] = (
                "the tow file has no manoeuvring model ([vessel] derivatives or preset, and "
                "[towline])"
            )
        else:
            _model_steps(tow, seas, speeds, steps, res, progress=progress)
            _map(tow.model(), map_xp, map_l0, progress, steps, res)
            if do_td:
                _time_domain(tow.model(), opts, t1, n_save, steps, res)
            else:
                summary["skipped"]["time domain"] = "switched off in [study]"
        summary["assessment"] = steps.run(
            "criteria", "guideline criteria", assessment, tow, summary
        )
        if has_model:
            summary["advice"] = steps.run(
                "advice",
                "advice: the smallest change that makes the tow follow the tug",
                _advice,
                tow,
                summary,
            )
    except Exception as e:  # noqa: BLE001 - the study keeps what finished and names the failure
        summary["incomplete"] = dict(
            step=steps.current, error=f"{type(e).__name__}: {e}", interrupted=False
        )
    except KeyboardInterrupt:
        summary["incomplete"] = dict(
            step=steps.current, error="interrupted (Ctrl-C)", interrupted=True
        )
    summary["step_times_s"] = steps.times
    return res


def _advice(tow, summary: dict) -> list:
    """`yaw_advice` for the calm water if its yaw criterion fails; else for every sea state at
    the design speed whose criterion fails. (A tow that fishtails in calm water needs the
    calm-water change first; a sea state at its operating speed gets none of its own: one
    of the changes is the tow speed itself.)"""
    failing = [
        ch["key"][len("yaw_") :]
        for ch in summary["assessment"]["checks"]
        if ch["key"].startswith("yaw_") and not ch["passed"]
    ]
    if "calm water" in failing:
        return yaw_advice(tow.model(), "calm water")
    out = []
    for s in tow.sea_states:
        if f"sea state {s.name}" in failing:
            out += yaw_advice(tow.sea_model(s), f"sea state {s.name}")
    return out


def _drift_step(tow, seas, steps: Steps, res: TowStudy) -> None:
    """The hull's drift source and its mean drift (`_hull_drift`)."""

    def drift():
        q, desc = tow.drift()
        return desc, *_hull_drift(tow, q, seas)

    desc, record, curves = steps.run("drift", "wave drift of the hull", drift)
    res.summary["drift_source"] = desc
    res.summary.update(record)
    res.drift_curves.update(curves)


def _model_steps(tow, seas, speeds, steps: Steps, res: TowStudy, *, progress: bool) -> None:
    """Resistance, and the equilibria in calm water and in each sea state."""
    summary, model = res.summary, tow.model()
    summary["stability_coefficient_c"] = float(model.vessel.stability_coefficient())
    summary["towline"] = _towline_record(model, tow)
    if tow.tug is not None:
        summary.update(_resistance(tow, seas, speeds, steps, res))
    else:
        summary["skipped"]["resistance"] = "the tow file has no [tug]"
    design = float(tow.scales.u_tug)
    ops = {  # the sea states whose operating speed differs from the design speed
        r["sea_state"]: r["operating_speed"]
        for r in summary.get("resistance", [])
        if r["status"] == "successful" and abs(r["operating_speed"] - design) > 1e-3
    }
    if tow.study["sea_states"]:
        steps.total += len(ops)
    summary["calm"] = steps.run(
        "calm", "equilibria and stability in calm water", _equilibria_record, model
    )
    if tow.study["sea_states"]:
        summary["sea_states"] = {}
        for s in seas:
            summary["sea_states"][s.name] = _sea_state_record(tow, s, steps, ops.get(s.name))
    if tow.line_info:
        summary["towline"]["strength"] = _strength_record(tow, model, summary)


def _particulars(tow) -> dict:
    """The tow as the summary names it: its particulars, sailing form, estimates, warnings
    (the drift source is added by the drift step)."""
    sc = tow.scales
    return dict(
        tow=tow.name,
        description=tow.resolved["tow"].get("description", ""),
        source=tow.source,
        design_speed=float(sc.u_tug),
        length=sc.length,
        breadth=float(tow.resolved["vessel"]["breadth"]),
        draft=sc.draft,
        force_scale=float(sc.force),  # ½ρTLU² [N]: T' and EA' times this are in N
        time_scale=sc.length / float(sc.u_tug),  # L/U [s]: t' times this is in s
        drift_source="",
        sailing_form=tow.form,
        assumed=[list(a) for a in tow.assumed],
        warnings=list(tow.warnings),
    )


def _hull_drift(tow, q, seas) -> tuple[dict, dict]:
    """The head-sea surge drift of the hull against the short-wave wall limit, and the
    mean drift in each sea state at rest and at the design speed (no model needed): the
    summary's record and the figure's curve."""
    w = np.asarray(q.omega)
    fx = np.asarray(jax.vmap(lambda x: q(x, 0.0))(jnp.asarray(w))[:, 0])
    # Faltinsen's short-wave limit of head-sea surge drift on a wall-sided bow: ½ρgB
    wall = 0.5 * RHO_SEA * G * float(tow.resolved["vessel"]["breadth"])
    rows = []
    for s in seas:
        if float(s.hs) <= 0:
            continue
        S = Jonswap(hs=s.hs, tp=s.tp, gamma=s.gamma)(DEFAULT_OMEGA)
        row = dict(sea_state=s.name, hs=float(s.hs), tp=float(s.tp))
        for tag, u in (("stationary", 0.0), ("design_speed", float(tow.scales.u_tug))):
            F = irregular_sailing_drift(q, DEFAULT_OMEGA, S, 0.0, u, 0.0, form=tow.form)
            row[f"fx_{tag}"] = float(F[0])
        rows.append(row)
    record = {
        "head_sea_surge_at_highest_omega_over_wall_limit": float(-fx[-1] / wall),
        "mean_drift": rows,
    }
    return record, {"head_sea_fx": (w, fx)}


def _towline_record(model, tow) -> dict:
    line = model.towline
    out = dict(
        l0=float(line.l0),
        xp=float(line.xp),
        yp=float(line.yp),  # pyright: ignore[reportAttributeAccessIssue]
        EA_nd=float(getattr(line, "series_EA", line.EA)),  # pyright: ignore[reportAttributeAccessIssue]
        length_m=float(line.l0) * tow.scales.length,
    )
    if hasattr(line, "sag"):  # a line with weight: its catenary at the calm equilibrium
        out["catenary"] = _catenary_record(model, tow.water_depth)
    return out


def _resistance(tow, seas, speeds, steps: Steps, res: TowStudy) -> dict:
    """Per sea state: the required pull, operating speed and transit time, and the budget
    over the speeds (for the figures)."""
    tr = tow.resistance()

    def budget():
        rows = [evaluate(tr, tow.tug, s, 0.0, tow.route_length) for s in seas]
        # the figures reach past every operating point (the [study] speeds may stop short)
        top = max(
            [float(speeds[-1])]
            + [1.1 * r["operating_speed"] for r in rows if "operating_speed" in r]
        )
        u = speeds if top <= float(speeds[-1]) else np.linspace(float(speeds[0]), top, speeds.size)
        budgets = {}
        for s in seas:
            b = resistance.resistance_grid(tr, s, jnp.asarray(u), jnp.array([float(s.tp)]))
            budgets[s.name] = dict(
                speeds=u,
                components=np.asarray(b.resistance[:, 0]),
                total=np.asarray(b.total[:, 0]),
                pull=np.asarray(tow.tug.pull(jnp.asarray(u))),
            )
        return rows, budgets

    rows, budgets = steps.run("resistance", "resistance, bollard pull and operating speed", budget)
    res.budgets.update(budgets)
    return dict(
        resistance=rows,
        components=list(resistance.COMPONENTS),
        tug=dict(
            bollard_pull=float(tow.tug.bollard_pull),
            free_speed=float(tow.tug.max_speed),
            efficiency=float(tow.tug.efficiency),
        ),
        route_length_m=tow.route_length,
    )


#: The validity flags of the forward-speed drift theory: outside them, the verdict is also
#: given under the bounds that still hold (`BOUND_FORMS`).
SPEED_FLAGS = ("no_separation", "froude_ok", "tau_ok", "encounter_positive")
#: The drift forms the verdict is repeated with where the forward-speed theory is outside its
#: validity: the zero-speed drift (no speed correction) and the thesis's form (which counts
#: the encounter-frequency shift twice: the largest speed effect of the three).
BOUND_FORMS = {"stationary": "zero-speed drift", "thesis": "the thesis's form"}


def _with_bounds(tow, s, rec: dict) -> dict:
    """``rec`` with ``bounds`` (form → verdict key, and ``changes``: whether any differs from
    the verdict) where a forward-speed validity flag fails."""
    if not set(rec["outside_validity"]) & set(SPEED_FLAGS):
        return rec
    verdicts = {
        form: _equilibria_record(tow.sea_model(s, form=form))["verdict"]
        for form in BOUND_FORMS
        if form != tow.form
    }
    rec["bounds"] = dict(
        verdicts=verdicts, changes=any(v != rec["verdict"] for v in verdicts.values())
    )
    words = ", ".join(f"{BOUND_FORMS[f]}: {v}" for f, v in verdicts.items())
    rec["verdict_text"] += f". Under the bounds that still hold ({words}) the verdict " + (
        "CHANGES: it rests on the forward-speed theory"
        if rec["bounds"]["changes"]
        else "is the same"
    )
    return rec


def _at_speed(model, speed: float) -> dict:
    """`_equilibria_record` of the model at tow speed ``speed`` [m/s], with the scales its
    non-dimensional numbers refer to."""
    model = at_tug_speed(model, speed)
    sc = model.reference_scales
    assert sc is not None  # at_tug_speed needs (and keeps) the model's scales
    rec = _equilibria_record(model)
    rec.update(speed=speed, force_scale=float(sc.force), time_scale=sc.length / float(sc.u_tug))
    return rec


def _sea_state_record(tow, s, steps: Steps, operating_speed: float | None = None) -> dict:
    """Equilibria and stability in sea state ``s`` at the design speed and, where it differs,
    at the sea state's operating speed (``at_operating_speed``): a tow that follows the tug
    at one speed may not at the other."""
    rec = steps.run(
        f"sea state {s.name}",
        f"equilibria and stability in sea state {s.name!r}",
        lambda: _with_bounds(tow, s, _equilibria_record(tow.sea_model(s))),
    )
    if operating_speed is not None:
        rec["at_operating_speed"] = steps.run(
            f"sea state {s.name} at its operating speed",
            f"equilibria and stability in sea state {s.name!r} at its operating speed "
            f"{operating_speed:.2f} m/s",
            _at_speed,
            tow.sea_model(s),
            operating_speed,
        )
    notes = []
    if any(float(a) != 0.0 for a in (s.wave_angle, s.wind_angle)):
        notes.append(
            "waves and wind taken from ahead of the course in the stability model; "
            "their directions enter the resistance budget only"
        )
    rec.update(hs=float(s.hs), tp=float(s.tp), wind_speed=float(s.wind_speed), notes=notes)
    return rec


def _map(model, map_xp, map_l0, progress: bool, steps: Steps, res: TowStudy) -> None:
    """The calm-water stability map around the design point, and the share of it where the
    straight-behind equilibrium is stable."""

    def stability_map():
        return sweep(model, {"xp": map_xp, "l0": map_l0}, progress=progress)

    ds = steps.run("map", "stability map around the design point (x_p', l0')", stability_map)
    res.datasets["map_xp_l0"] = ds
    straight = ds["max_real"].where(ds["valid"] & (ds["branch"] == 0)).max("equilibrium")
    stable = (straight < 0).values
    res.summary["map"] = dict(
        xp=[float(map_xp[0]), float(map_xp[-1]), int(map_xp.size)],
        l0=[float(map_l0[0]), float(map_l0[-1]), int(map_l0.size)],
        straight_stable_share=float(np.mean(stable)),
    )


def _time_domain(model, opts: dict, t1: float, n_save: int, steps: Steps, res: TowStudy) -> None:
    """The calm-water run from the [study]'s disturbed start, and its fishtailing metrics."""

    def run():
        y0 = initial_state(model, psi0=math.radians(opts["psi0_deg"]), y0=opts["y0"])
        sim = simulate(model, y0, t1=t1, n_save=n_save)
        met = fishtail_metrics(model, sim)
        flags = {k: bool(np.all(np.asarray(v))) for k, v in sim.validity.items()}
        return trajectory(model, sim), met, flags

    traj, met, flags = steps.run("time domain", "time-domain check from a disturbed start", run)
    res.runs["calm"] = (traj, met)
    res.summary["time_domain"] = dict(
        psi0_deg=opts["psi0_deg"],
        y0=opts["y0"],
        t1=t1,
        outcome=met["outcome"],
        path_width=met["path_width"],
        yaw_range=met["yaw_range"],
        slewing_period=met["slewing_period"],
        ended_early=bool(met["ended_early"]),
        validity=flags,
    )
