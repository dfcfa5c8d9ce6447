"""The result types of motostab's calls: typed, read-only records of NumPy arrays and numbers.

Units are in the names where they are not 1/s, m/s or rad (``speed_mps``, ``roll_deg``, ``fy_N``);
eigenvalues are in 1/s (real part: growth rate; imaginary part: rad/s). Each type is built from the
dict the extension returns, in one function (``_from_core``), so a change of a C++ result struct is
adapted here and in python/convert.cpp only.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Dict, List, Mapping, Optional, Tuple

import numpy as np

__all__ = ["CriticalSpeed", "Trim", "Linearization", "Sweep", "TurnMap", "Simulation", "ModeShape", "Study",
           "Uncertainty", "Diagnosis", "TyreCurve"]


def _ranges(pairs: List[List[float]]) -> np.ndarray:
    return np.array(pairs, dtype=float).reshape(-1, 2)


@dataclass(frozen=True)
class CriticalSpeed:
    """A speed where a labelled mode's real part changes sign (summary.json ``critical_speeds``)."""

    mode: str          #: the mode's label (weave, capsize, wobble, ...)
    speed_mps: float   #: m/s, bracketed to the sweep's tolerance (1e-9 m/s; maps 1e-6 m/s)
    direction: str     #: "stabilising" (real part + to - as speed rises) or "destabilising"


@dataclass(frozen=True)
class Trim:
    """A trim: straight running, or a steady turn (the keys of ``motostab trim``'s trim.json)."""

    speed_mps: float                 #: the rear contact point's speed along its path, m/s
    roll_rad: float                  #: rad, > 0 leans right
    steer_rad: float                 #: rad, > 0 steers left
    pitch_rad: float                 #: rear frame, rad, > 0 nose down
    steer_torque_Nm: float           #: N m, > 0 turns the front frame left
    drive_torque_Nm: float           #: N m
    yaw_rate_radps: float            #: rad/s, > 0 turns left
    path_radius_m: Optional[float]   #: the rear contact point's path radius, m; None when straight
    lateral_acceleration_mps2: float  #: speed x yaw rate, m/s^2, > 0 left
    residual: float                  #: infinity norm of the trim residual
    iterations: int                  #: Newton iterations
    tyres: Dict[str, float]          #: the contact model's outputs by name (forces N, angles rad)
    #: hands-free only: whether this (the default) turn continues from straight running
    continues_from_straight_running: Optional[bool] = None
    #: hands-free only: every turn found, sorted by speed, each with the keys above and ``default``
    hands_free_turns: Optional[List[Dict[str, Any]]] = None

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Trim":
        return cls(**d)


@dataclass(frozen=True, eq=False)
class Linearization:
    """x' = A x + B u about a trim (``motostab linearize``: A.csv, B.csv, eigenvalues, eigenvectors)."""

    A: np.ndarray                #: (states, states), 1/s and the states' units
    B: np.ndarray                #: (states, inputs), per N m
    state_names: List[str]       #: the rows and columns of A
    input_names: List[str]       #: steer_torque, drive_torque, roll_torque (N m)
    eigenvalues: np.ndarray      #: (states,) complex, 1/s
    eigenvectors: np.ndarray     #: (states, states) complex; column k belongs to eigenvalue k (unit 2-norm)
    labels: np.ndarray           #: (states,) str, each eigenvalue's mode at this speed
    speed_mps: float             #: m/s
    roll_rad: float              #: rad (0 for straight running)
    heading_frame: bool          #: linearised about a steady turn, in the heading frame
    trim: Trim                   #: the trim it is linearised about

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Linearization":
        d = dict(d)
        d["labels"] = np.array(d["labels"], dtype=str)
        d["trim"] = Trim._from_core(d["trim"])
        return cls(**d)


@dataclass(frozen=True, eq=False)
class Sweep:
    """Eigenvalues over speed, tracked and labelled, with the critical speeds (``motostab sweep``).

    Column ``j`` of ``eigenvalues`` is one tracked root; ``labels[k, j]`` is its mode at speed ``k`` (as
    ``eigenvalues.csv`` has it), ``branch_labels[j]`` the mode it has at most speeds:
    ``sweep.eigenvalues[sweep.labels == "weave"]`` are the weave's eigenvalues wherever a root is the weave.
    """

    scenario: str                         #: the scenario's name
    speeds: np.ndarray                    #: (speeds,) m/s
    eigenvalues: np.ndarray               #: (speeds, roots) complex, 1/s (eigenvalues.csv)
    labels: np.ndarray                    #: (speeds, roots) str, each root's mode label at each speed
    branch_labels: np.ndarray             #: (roots,) str, the label each tracked root has at most speeds
    critical_speeds: List[CriticalSpeed]  #: every sign change of a root's real part, by speed
    stable_ranges: np.ndarray             #: (k, 2) m/s, stable ranges bounded by the critical speeds
    stable_grid_ranges: np.ndarray        #: (k, 2) m/s, the runs of stable grid speeds
    roll_deg: Optional[float]             #: the steady turns' roll angle, deg; None for straight running
    state_names: List[str]                #: the states of A
    A: np.ndarray                         #: (speeds, states, states) the linear models' A
    summary: Dict[str, Any] = field(repr=False)  #: summary.json as a dict

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Sweep":
        summary = d["summary"]
        branch_labels = np.array(d["branch_labels"], dtype=str).reshape(-1)
        roll = d["roll_rad"]
        return cls(
            scenario=d["scenario"],
            speeds=d["speeds"],
            eigenvalues=d["eigenvalues"],
            labels=np.array(d["labels"], dtype=str).reshape(d["eigenvalues"].shape),
            branch_labels=branch_labels,
            critical_speeds=[CriticalSpeed(c["mode"], c["speed_mps"], c["direction"]) for c in summary["critical_speeds"]],
            stable_ranges=_ranges(summary["stable_speed_ranges_mps"]),
            stable_grid_ranges=_ranges(summary["stable_grid_ranges_mps"]),
            roll_deg=None if math.isnan(roll) else math.degrees(roll),
            state_names=list(d["state_names"]),
            A=d["A"],
            summary=summary,
        )


@dataclass(frozen=True, eq=False)
class TurnMap:
    """A speed x roll map of steady turns (``motostab sweep --roll-deg A:B:STEP``): one sweep per roll,
    the modes labelled consistently across roll."""

    scenario: str
    rolls_deg: np.ndarray     #: (rolls,) deg
    speeds: np.ndarray        #: (speeds,) m/s, the same for every roll
    eigenvalues: np.ndarray   #: (rolls, speeds, roots) complex, 1/s
    labels: np.ndarray        #: (rolls, speeds, roots) str
    sweeps: List[Sweep]       #: one per roll

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "TurnMap":
        sweeps = [Sweep._from_core(s) for s in d["sweeps"]]
        return cls(scenario=d["scenario"], rolls_deg=np.degrees(d["rolls_rad"]), speeds=sweeps[0].speeds,
                   eigenvalues=np.stack([s.eigenvalues for s in sweeps]),
                   labels=np.stack([s.labels for s in sweeps]), sweeps=sweeps)


@dataclass(frozen=True, eq=False)
class Simulation:
    """A nonlinear perturbation run (``motostab simulate``: timeseries.csv). ``sim["roll_rate"]`` is a
    signal; ``columns`` lists them (docs/simulation.md: q and u by name, steer_torque, forward_speed, ...)."""

    columns: List[str]           #: signal names, "time" first
    samples: np.ndarray          #: (samples, columns), the signals' units (s, rad, m, rad/s, m/s, N m, N, J)
    time: np.ndarray             #: (samples,) s (a view of samples[:, 0])
    signals: Dict[str, np.ndarray]  #: name -> (samples,) view of its column
    trim: Dict[str, float]       #: the trim (time 0, no perturbation) in the same columns
    status: str                  #: "completed", "fell" (|roll| over the fall limit) or "failed"
    message: str                 #: why it ended early, else ""
    end_time_s: float            #: last sample time, s
    steps: int                   #: integrator steps
    integrator: str              #: the integrator used
    wall_seconds: float          #: wall-clock time of the integration, s

    def __getitem__(self, name: str) -> np.ndarray:
        return self.signals[name]

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Simulation":
        samples, columns = d["samples"], list(d["columns"])
        signals = {name: samples[:, j] for j, name in enumerate(columns)}
        return cls(columns=columns, samples=samples, time=signals["time"], signals=signals,
                   trim=dict(zip(columns, d["trim_row"].tolist())), status=d["status"], message=d["message"],
                   end_time_s=d["end_time_s"], steps=d["steps"], integrator=d["integrator"],
                   wall_seconds=d["wall_seconds"])


@dataclass(frozen=True)
class ModeShape:
    """The weave's shape at one speed (seed Fig. 12): components (name, amplitude relative to the
    largest, phase relative to steer in deg)."""

    speed_mps: float
    eigenvalue: complex
    components: List[Tuple[str, float, float]]


@dataclass(frozen=True, eq=False)
class Study:
    """The seed paper's swingarm study (``motostab study``): one sweep per compliance variant at the
    identified and at the scaled ("halved") stiffness, weave shapes, and report.md as text."""

    scenario: str
    nominal: Dict[str, Sweep]
    halved: Dict[str, Sweep]
    weave_shapes: List[ModeShape]
    report: str = field(repr=False)

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Study":
        return cls(scenario=d["scenario"], nominal={n: Sweep._from_core(s) for n, s in d["nominal"]},
                   halved={n: Sweep._from_core(s) for n, s in d["halved"]},
                   weave_shapes=[ModeShape(v, l, list(c)) for v, l, c in d["weave_shapes"]], report=d["report"])


@dataclass(frozen=True, eq=False)
class Uncertainty:
    """An uncertainty study (``motostab uncertainty``): summary.json as ``summary``, report.md as
    ``report``, and per task (nominal, the 2P first-order neighbours, then the samples) its parameter
    values and first crossings."""

    summary: Dict[str, Any] = field(repr=False)  #: summary.json (critical_speeds, sensitivities, fans)
    report: str = field(repr=False)              #: report.md
    parameter_paths: List[str]                   #: the uncertain parameters' key paths
    modes: List[str]                             #: the modes of first_crossings' columns
    parameters: np.ndarray                       #: (tasks, parameters), each key's unit
    first_crossings: np.ndarray                  #: (tasks, modes) m/s, NaN where the mode does not cross
    succeeded: np.ndarray                        #: (tasks,) bool
    reasons: List[str]                           #: why each failed task failed ("" when it succeeded)

    @property
    def critical_speeds(self) -> Dict[str, Dict[str, Any]]:
        """Per mode: mean_mps, std_mps, p05_mps, p50_mps, p95_mps, fraction, first_order_std_mps, ..."""
        return self.summary["critical_speeds"]

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "Uncertainty":
        return cls(**d)


@dataclass(frozen=True, eq=False)
class Diagnosis:
    """What the model gets wrong against measured data and its cause (``motostab diagnose``):
    diagnosis.json as ``summary``, report.md as ``report``, the extended scenario, and per observation
    the measured and predicted values."""

    summary: Dict[str, Any] = field(repr=False)
    report: str = field(repr=False)
    causes: List[str]                 #: the causes named, in order
    extended: Any                     #: the scenario with every cause (a motostab.Scenario; extended.yaml)
    extended_overrides: List[str]     #: its changes, "path=value"
    observed: np.ndarray              #: (observations,) measured values (1/s, rad/s, or the column's unit)
    sigma: np.ndarray                 #: (observations,) their noise standard deviations
    predicted_before: np.ndarray      #: (observations,) by the base scenario
    predicted_after: np.ndarray       #: (observations,) by the extended scenario
    speed_mps: np.ndarray             #: (observations,) m/s
    time_s: np.ndarray                #: (observations,) s for response samples, NaN for eigenvalues
    component: List[str]              #: each observation's mode part or signal (weave.real, run1.roll_rate, ...)


@dataclass(frozen=True, eq=False)
class TyreCurve:
    """A .tir file's steady-state forces over slip angle (``motostab tyre``: forces.csv), ISO-W signs,
    and its small-slip figures at the load."""

    fz_N: np.ndarray
    slip_angle_rad: np.ndarray
    camber_rad: np.ndarray
    slip_ratio: np.ndarray
    fx_N: np.ndarray
    fy_N: np.ndarray
    mz_Nm: np.ndarray
    mx_Nm: np.ndarray
    my_Nm: np.ndarray
    fit_type: int                        #: FITTYP (61 or 62)
    speed_mps: float                     #: the forward speed used (the file's LONGVL unless given)
    cornering_stiffness_N_per_rad: float  #: dFy/dalpha (ISO sign: negative for a usual tyre)
    camber_stiffness_N_per_rad: float    #: dFy/dgamma
    slip_stiffness_N: float              #: dFx/dkappa
    relaxation_length_m: float           #: lateral, at the load, camber and speed
    longitudinal_relaxation_length_m: float  #: reported only

    @classmethod
    def _from_core(cls, d: Mapping[str, Any]) -> "TyreCurve":
        return cls(**d)
