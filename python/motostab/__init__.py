"""motostab from Python: stability of motorcycles and bicycles on Simbody multibody models.

The same libraries, strict input checks and results as the ``motostab`` command line, returned as
typed objects with NumPy arrays instead of files (docs/python.md)::

    import motostab
    bike = motostab.Scenario.load("scenarios/whipple-benchmark.yaml")
    sweep = motostab.sweep(bike, speeds=(0, 10, 0.1))
    sweep.critical_speeds      # [CriticalSpeed(mode='weave', speed_mps=4.29..., direction='stabilising'), ...]

Bad input raises :class:`InputError` (a ValueError naming file, line, column and key); a computation
that cannot give a result raises :class:`ResultError`. Nothing is printed: messages of the libraries
(e.g. unused .tir coefficients) go to the ``logging`` logger "motostab" at INFO level. The GIL is
released while motostab computes, so other Python threads run meanwhile.
"""
from __future__ import annotations

import logging
import os
import tempfile
from typing import Any, Callable, Mapping, Optional, Sequence, Tuple, Union

from ._errors import InputError, ResultError
from . import _core
from ._results import (CriticalSpeed, Diagnosis, Linearization, ModeShape, Simulation, Study, Sweep, Trim, TurnMap,
                       TyreCurve, Uncertainty)

__all__ = ["Scenario", "sweep", "turn_map", "linearize", "trim", "simulate", "study", "uncertainty", "diagnose",
           "tyre", "InputError", "ResultError", "CriticalSpeed", "Trim", "Linearization", "Sweep", "TurnMap",
           "Simulation", "ModeShape", "Study", "Uncertainty", "Diagnosis", "TyreCurve"]

logging.getLogger("motostab").addHandler(logging.NullHandler())  # silent unless the user configures logging

SpeedGrid = Tuple[float, float, float]  #: (start, stop, step) in m/s, as the command line's START:STOP:STEP
PathLike = Union[str, "os.PathLike[str]"]
_DEFAULTS = _core.defaults()


def _grid(speeds: Optional[Sequence[float]], name: str = "speeds") -> Optional[Tuple[float, float, float]]:
    if speeds is None:
        return None
    values = tuple(speeds)
    if len(values) != 3:
        raise InputError(f"{name}: expected (start, stop, step) in m/s", key=name,
                         reason="expected (start, stop, step) in m/s")
    return tuple(float(v) for v in values)  # type: ignore[return-value]


class Scenario:
    """A vehicle and its settings, read and checked as the command line reads a scenario file.

    Immutable: :meth:`with_` returns a changed copy. Each change is typed as ``--set`` is (a number
    keeps every digit, a string switches a model, a dict or list replaces a section), and the result is
    checked by the same strict reader: a bad value raises :class:`InputError` naming the key and the
    change.
    """

    __slots__ = ("_handle",)

    def __init__(self, handle: "_core.Scenario"):
        self._handle = handle

    @classmethod
    def load(cls, path: PathLike) -> "Scenario":
        """Reads a scenario YAML file (docs/scenario-format.md); relative paths in it are relative to it."""
        return cls(_core.Scenario.load(os.fspath(path)))

    @classmethod
    def from_dict(cls, tree: Mapping[str, Any], name: str = "<dict>") -> "Scenario":
        """A scenario from nested dicts and lists with the keys of a scenario file; ``name`` stands for
        the file in messages, and relative paths in it are relative to the working folder."""
        return cls(_core.Scenario.from_tree(dict(tree), name))

    def with_(self, changes: Optional[Mapping[str, Any]] = None, /, **values: Any) -> "Scenario":
        """A copy with values changed by key path, as ``--set`` changes them:
        ``bike.with_(**{"geometry.trail_m": 0.1})``, ``bike.with_({"swingarm.compliance": "twist"})``,
        ``bike.with_(steer_damper={"damping_Nms_per_rad": 0.4})``."""
        merged = dict(changes or {})
        merged.update(values)
        return Scenario(self._handle.with_changes(merged))

    @property
    def name(self) -> str:
        return self._handle.name

    @property
    def description(self) -> str:
        return self._handle.description

    @property
    def file(self) -> str:
        """The file it was read from (or the name given to :meth:`from_dict`)."""
        return self._handle.file

    @property
    def overrides(self) -> list:
        """The changes applied, as ``path=value`` text (the ``--set`` arguments that reproduce them)."""
        return self._handle.overrides

    @property
    def speeds(self) -> SpeedGrid:
        """The scenario's speed grid ``speeds_mps`` (start, stop, step), m/s: the default of sweeps."""
        return self._handle.speeds

    @property
    def wheelbase_m(self) -> float:
        return self._handle.wheelbase_m

    def __getitem__(self, path: str) -> float:
        """The number at a key path, e.g. ``bike["geometry.trail_m"]`` (the key's unit)."""
        return self._handle.get(path)

    def parameters(self) -> dict:
        """Every scalar of the vehicle's measured description by key path (the parameters diagnosis and
        uncertainty studies change), in the keys' units."""
        return self._handle.parameters()

    def to_dict(self) -> dict:
        """The scenario tree with the changes applied (numbers as int and float); ``from_dict`` reads it."""
        return self._handle.to_dict()

    def to_yaml(self) -> str:
        """The scenario tree with the changes applied, as YAML text."""
        return self._handle.to_yaml()

    def save(self, path: PathLike) -> None:
        """Writes :meth:`to_yaml` to ``path`` (complete or not at all), e.g. to run a command on it."""
        path = os.fspath(path)
        folder = os.path.dirname(os.path.abspath(path))
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".motostab-", suffix=".yaml")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(self.to_yaml())
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise

    def __repr__(self) -> str:
        changes = f", {len(self.overrides)} changes" if self.overrides else ""
        return f"<motostab.Scenario {self.name!r} from {self.file!r}{changes}>"


def sweep(scenario: Scenario, speeds: Optional[SpeedGrid] = None, *, roll_deg: Optional[float] = None,
          threads: int = 1) -> Sweep:
    """Eigenvalues over speed, modes tracked and labelled, critical speeds (``motostab sweep``).

    speeds: (start, stop, step) in m/s; default the scenario's speeds_mps. roll_deg: about steady turns
    at this roll angle (deg, > 0 right; speeds must start above 0). threads: worker threads as
    ``--threads`` (results then agree with one thread to the trim tolerance, not to the bit).
    """
    return Sweep._from_core(_core.sweep(scenario._handle, _grid(speeds), roll_deg, threads))


def turn_map(scenario: Scenario, roll_deg: Sequence[float], speeds: Optional[SpeedGrid] = None, *,
             threads: int = 1) -> TurnMap:
    """A speed x roll map of steady turns over roll_deg = (first, last, step) in deg (``motostab sweep
    --roll-deg A:B:STEP``); speeds start above 0."""
    return TurnMap._from_core(_core.turn_map(scenario._handle, _grid(speeds), _grid(roll_deg, "roll_deg"), threads))


def linearize(scenario: Scenario, speed: float, *, roll_deg: Optional[float] = None) -> Linearization:
    """A, B, eigenvalues, eigenvectors and mode labels about the trim at ``speed`` m/s (``motostab
    linearize``); with roll_deg about the steady turn at that roll (deg)."""
    return Linearization._from_core(_core.linearize(scenario._handle, float(speed), roll_deg))


def trim(scenario: Scenario, speed: Optional[float] = None, *, roll_deg: float = 0.0, hands_free: bool = False,
         speeds: Optional[SpeedGrid] = None) -> Trim:
    """The steady turn at ``speed`` m/s and ``roll_deg`` (``motostab trim``). hands_free: zero steer
    torque, the speed solved by a search over ``speeds`` (default the scenario's speeds_mps); ``speed``
    then picks among several turns."""
    return Trim._from_core(_core.trim(scenario._handle, speed, float(roll_deg), hands_free, _grid(speeds)))


def simulate(scenario: Scenario, speed: float, duration: float, *, perturb: Sequence[str] = (),
             speed_control: str = "pi", integrator: str = "auto",
             accuracy: float = _DEFAULTS["simulate"]["accuracy"],
             output_step: float = _DEFAULTS["simulate"]["output_step"],
             fall_limit_deg: float = _DEFAULTS["simulate"]["fall_limit_deg"], roll_deg: float = 0.0) -> Simulation:
    """The nonlinear response from the trim at ``speed`` m/s over ``duration`` s (``motostab simulate``).

    perturb: the command line's ``--perturb`` specs, e.g. ``"steer-torque:5:0.1:0.2"``,
    ``"roll-rate:0.5"`` (docs/simulation.md). A fall ends the run with status "fell"; an integrator
    failure raises :class:`ResultError` with the samples up to it as ``error.result``.
    """
    result = Simulation._from_core(_core.simulate(scenario._handle, float(speed), float(duration), list(perturb),
                                                  speed_control, integrator, float(accuracy), float(output_step),
                                                  float(fall_limit_deg), float(roll_deg)))
    if result.status == "failed":
        raise ResultError(result.message, result)
    return result


def study(scenario: Scenario, speeds: Optional[SpeedGrid] = None, *,
          compare: Sequence[str] = _DEFAULTS["study"]["compare"],
          stiffness_scale: float = _DEFAULTS["study"]["stiffness_scale"], damping_scale: Optional[float] = None,
          shape_speeds: Sequence[float] = _DEFAULTS["study"]["shape_speeds"],
          threads: int = _DEFAULTS["study"]["threads"], roll_deg: float = 0.0) -> Study:
    """The seed paper's swingarm study (``motostab study``): the compliance variants ``compare`` at
    identified stiffness and at ``stiffness_scale`` times it (damping scaled by ``damping_scale``,
    default its square root), weave shapes at ``shape_speeds`` (m/s), the report as text."""
    return Study._from_core(_core.study(scenario._handle, _grid(speeds), list(compare), float(stiffness_scale),
                                        damping_scale, [float(v) for v in shape_speeds], threads, float(roll_deg)))


def uncertainty(scenario: Scenario, *, samples: int = _DEFAULTS["uncertainty"]["samples"],
                seed: int = _DEFAULTS["uncertainty"]["seed"], method: str = "mc",
                speeds: Optional[SpeedGrid] = None, threads: int = 1) -> Uncertainty:
    """Critical-speed distributions and sensitivities from the scenario's ``uncertainty`` section
    (``motostab uncertainty`` on one process). method: "mc" (``samples`` draws) or "sobol" (``samples``
    base rows, samples x (P + 2) sweeps). Results are the same for any number of threads."""
    return Uncertainty._from_core(_core.uncertainty(scenario._handle, int(samples), int(seed), method, _grid(speeds),
                                                    threads))


def diagnose(scenario: Scenario, measurements: PathLike, *, candidates: Optional[Sequence[str]] = None,
             max_causes: int = _DEFAULTS["diagnose"]["max_causes"], folds: Optional[int] = None, threads: int = 1,
             robustness: bool = True,
             progress: Optional[Callable[[str, int, int], None]] = None) -> Diagnosis:
    """What the scenario gets wrong against measured data (docs/measured-data-format.md), its cause and
    the extended scenario (``motostab diagnose``). candidates: names or globs (default all);
    robustness=False skips the reruns (``--no-robustness``); progress(stage, done, total) is called as
    the work proceeds."""
    d = dict(_core.diagnose(scenario._handle, os.fspath(measurements), None if candidates is None else list(candidates),
                            max_causes, 0 if folds is None else folds, threads, robustness, progress))
    extended_overrides = d.pop("extended_overrides")
    extended = Scenario(scenario._handle.with_assignments(extended_overrides))
    return Diagnosis(extended=extended, extended_overrides=extended_overrides, **d)


def tyre(path: PathLike, fz: float, slip_deg: Union[SpeedGrid, Sequence[float]], *, camber_deg: float = 0.0,
         slip_ratio: float = 0.0, speed: Optional[float] = None) -> TyreCurve:
    """The steady-state forces of a Magic Formula .tir file (MF 6.1/6.2) at load ``fz`` N over slip
    angles (``motostab tyre``): slip_deg is (first, last, step) in deg as ``--slip-deg A:B:STEP`` when a
    tuple of three, else the angles themselves (a list or array, deg). speed: m/s for the rolling
    resistance (default the file's LONGVL)."""
    is_range = isinstance(slip_deg, tuple) and len(slip_deg) == 3
    angles = [float(v) for v in (slip_deg if not hasattr(slip_deg, "tolist") else slip_deg.tolist())]  # type: ignore[union-attr]
    return TyreCurve._from_core(_core.tyre_curve(os.fspath(path), float(fz), angles, is_range, float(camber_deg),
                                                 float(slip_ratio), speed))
