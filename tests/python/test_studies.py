"""diagnose from Python against the command line on the Kooijman et al. (2008) data (a few candidates,
no robustness reruns: seconds), and the objects study and uncertainty return."""
import numpy as np
import pytest

from conftest import SOURCE, read_json, run_cli

KOOIJMAN = SOURCE / "scenarios" / "kooijman-silvercity.yaml"
MEASURED = SOURCE / "examples" / "diagnosis" / "kooijman2008.yaml"
CANDIDATES = ["tyre_crown", "steer_damper"]


def test_diagnosis_equals_the_command_line(motostab, tmp_path):
    run_cli("diagnose", KOOIJMAN, MEASURED, "--candidates", ",".join(CANDIDATES), "--no-robustness", "--threads", "2",
            "--out", "diag", cwd=tmp_path)
    stages = []
    d = motostab.diagnose(motostab.Scenario.load(KOOIJMAN), MEASURED, candidates=CANDIDATES, robustness=False,
                          threads=2, progress=lambda stage, done, total: stages.append((stage, done, total)))
    assert read_json(tmp_path / "diag" / "diagnosis.json") == d.summary
    with open(tmp_path / "diag" / "report.md") as f:
        assert f.read() == d.report
    # Kooijman et al. (2008) data want rounded tyres (docs/diagnosis.md): the crown radius is named.
    assert d.causes == ["tyre_crown"]
    assert 0.010 < d.extended["rear_wheel.crown_radius_m"] < 0.040
    assert d.extended_overrides == d.summary["extended_overrides"]
    n = len(d.observed)
    assert all(len(a) == n for a in (d.sigma, d.predicted_before, d.predicted_after, d.speed_mps, d.time_s, d.component))
    # The extension fits better: the normalised residuals shrink.
    before = np.sqrt(np.mean(((d.observed - d.predicted_before) / d.sigma) ** 2))
    after = np.sqrt(np.mean(((d.observed - d.predicted_after) / d.sigma) ** 2))
    assert after < before
    assert stages and stages[0][0] == "reference sweep"


def test_a_candidate_that_matches_nothing_is_an_input_error(motostab):
    with pytest.raises(motostab.InputError) as info:
        motostab.diagnose(motostab.Scenario.load(KOOIJMAN), MEASURED, candidates=["no_such_candidate*"], robustness=False)
    assert info.value.key == "candidates"


def test_a_progress_callback_that_raises_stops_nothing_and_is_raised(motostab):
    def progress(stage, done, total):
        raise KeyError("stop")
    with pytest.raises(KeyError):
        motostab.diagnose(motostab.Scenario.load(KOOIJMAN), MEASURED, candidates=["steer_damper"], robustness=False,
                          progress=progress)


def test_uncertainty_object(motostab):
    u = motostab.uncertainty(motostab.Scenario.load(KOOIJMAN), samples=3, seed=2, speeds=(3, 7, 0.5))
    p = len(u.parameter_paths)
    assert u.parameters.shape == (1 + 2 * p + 3, p) and u.first_crossings.shape == (1 + 2 * p + 3, 3)
    assert u.succeeded.dtype == bool and u.succeeded.all()
    assert u.modes == ["weave", "capsize", "wobble"]
    # The nominal task's weave crossing is the nominal scenario's own weave speed.
    sweep = motostab.sweep(motostab.Scenario.load(KOOIJMAN), speeds=(3, 7, 0.5))
    weave = [c.speed_mps for c in sweep.critical_speeds if c.mode == "weave"][0]
    assert u.first_crossings[0, 0] == weave
    assert u.critical_speeds["weave"]["fraction"] == 1
