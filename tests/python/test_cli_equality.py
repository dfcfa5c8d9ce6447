"""The Python calls give the command line's results to the last digit: each test runs the built
`motostab` on the same scenario and values (drawn at random, seeded) and compares every number of its
CSV and JSON files (17 significant digits, which read back to the same double) with what Python returns."""
import math
import os
import random

import numpy as np
import pytest

from conftest import ENDURO, SAMPLE_TIR, SOURCE, SUPERSPORT, WHIPPLE, read_csv, read_json, run_cli

KOOIJMAN = SOURCE / "scenarios" / "kooijman-silvercity.yaml"


def number(text):
    """A CSV cell as a float; an empty cell is an undefined value (NaN in Python, null in JSON)."""
    return float(text) if text != "" else math.nan


def check_sweep_csv(rows, sweep):
    """eigenvalues.csv (speed-major, one row per branch) against sweep.speeds, eigenvalues and labels."""
    n, roots = sweep.eigenvalues.shape
    assert len(rows) == n * roots
    for i, row in enumerate(rows):
        k, b = divmod(i, roots)
        assert number(row["speed_mps"]) == sweep.speeds[k]
        assert row["mode"] == sweep.labels[k, b]
        assert number(row["real"]) == sweep.eigenvalues[k, b].real
        assert number(row["imag"]) == sweep.eigenvalues[k, b].imag
        assert number(row["frequency_hz"]) == sweep.eigenvalues[k, b].imag / (2 * math.pi)


def check_summary(summary, sweep):
    """summary.json against the sweep's critical speeds and stable ranges."""
    assert summary == sweep.summary
    assert [(c["mode"], c["speed_mps"], c["direction"]) for c in summary["critical_speeds"]] == \
        [(c.mode, c.speed_mps, c.direction) for c in sweep.critical_speeds]
    assert np.array_equal(np.array(summary["stable_speed_ranges_mps"]).reshape(-1, 2), sweep.stable_ranges)
    assert np.array_equal(np.array(summary["stable_grid_ranges_mps"]).reshape(-1, 2), sweep.stable_grid_ranges)


def test_sweep_of_a_changed_bicycle_equals_the_command_line(motostab, tmp_path):
    rng = random.Random(11)
    trail = rng.uniform(0.07, 0.09)
    start = rng.choice([0.0, 0.5, 1.0])
    speeds = (start, start + 8.0, rng.choice([0.25, 0.5]))
    run_cli("sweep", WHIPPLE, "--set", f"geometry.trail_m={trail!r}", "--speeds", ":".join(map(repr, speeds)),
            "--out", "out", cwd=tmp_path)
    bike = motostab.Scenario.load(WHIPPLE).with_(**{"geometry.trail_m": trail})
    sweep = motostab.sweep(bike, speeds=speeds)
    check_sweep_csv(read_csv(tmp_path / "out" / "eigenvalues.csv"), sweep)
    check_summary(read_json(tmp_path / "out" / "summary.json"), sweep)
    assert {c.mode for c in sweep.critical_speeds} >= {"weave", "capsize"}


def test_motorcycle_sweep_and_turn_sweep_equal_the_command_line(motostab, tmp_path):
    rng = random.Random(12)
    roll = round(rng.uniform(5, 30), 3)
    run_cli("sweep", ENDURO, "--set", "swingarm.compliance=twist", "--speeds", "5:40:5", "--out", "straight", cwd=tmp_path)
    run_cli("sweep", ENDURO, "--speeds", "10:30:5", "--roll-deg", repr(roll), "--out", "turn", cwd=tmp_path)
    enduro = motostab.Scenario.load(ENDURO)
    straight = motostab.sweep(enduro.with_({"swingarm.compliance": "twist"}), speeds=(5, 40, 5))
    turn = motostab.sweep(enduro, speeds=(10, 30, 5), roll_deg=roll)
    check_sweep_csv(read_csv(tmp_path / "straight" / "eigenvalues.csv"), straight)
    check_summary(read_json(tmp_path / "straight" / "summary.json"), straight)
    check_sweep_csv(read_csv(tmp_path / "turn" / "eigenvalues.csv"), turn)
    check_summary(read_json(tmp_path / "turn" / "summary.json"), turn)
    assert straight.roll_deg is None and turn.roll_deg == pytest.approx(roll, abs=1e-12)


def test_turn_map_equals_the_command_line(motostab, tmp_path):
    run_cli("sweep", WHIPPLE, "--speeds", "3:7:1", "--roll-deg", "2:6:2", "--out", "map", cwd=tmp_path)
    m = motostab.turn_map(motostab.Scenario.load(WHIPPLE), roll_deg=(2, 6, 2), speeds=(3, 7, 1))
    rows = read_csv(tmp_path / "map" / "map.csv")
    n_roll, n, roots = m.eigenvalues.shape
    assert (n_roll, n) == (3, 5) and len(rows) == n_roll * n * roots
    for i, row in enumerate(rows):  # roll-major, then branch, then speed
        j, rest = divmod(i, roots * n)
        b, k = divmod(rest, n)
        assert number(row["roll_deg"]) == pytest.approx(m.rolls_deg[j], abs=1e-12)
        assert number(row["speed_mps"]) == m.speeds[k]
        assert row["mode"] == m.labels[j, k, b]
        assert number(row["real"]) == m.eigenvalues[j, k, b].real
        assert number(row["imag"]) == m.eigenvalues[j, k, b].imag


def test_linearize_and_trim_equal_the_command_line(motostab, tmp_path):
    rng = random.Random(13)
    speed = rng.uniform(8, 40)
    roll = rng.uniform(5, 35)
    run_cli("linearize", SUPERSPORT, "--speed", repr(speed), "--out", "lin", cwd=tmp_path)
    run_cli("linearize", SUPERSPORT, "--speed", repr(speed), "--roll-deg", repr(roll), "--out", "turnlin", cwd=tmp_path)
    run_cli("trim", SUPERSPORT, "--speed", repr(speed), "--roll-deg", repr(roll), "--out", "trim", cwd=tmp_path)
    bike = motostab.Scenario.load(SUPERSPORT)
    for folder, lin in (("lin", motostab.linearize(bike, speed)),
                        ("turnlin", motostab.linearize(bike, speed, roll_deg=roll))):
        a_rows = read_csv(tmp_path / folder / "A.csv")
        assert [r["state"] for r in a_rows] == lin.state_names
        assert np.array_equal(np.array([[number(r[s]) for s in lin.state_names] for r in a_rows]), lin.A)
        b_rows = read_csv(tmp_path / folder / "B.csv")
        assert np.array_equal(np.array([[number(r[s]) for s in lin.input_names] for r in b_rows]), lin.B)
        ev = read_csv(tmp_path / folder / "eigenvalues.csv")
        assert [r["mode"] for r in ev] == list(lin.labels)
        assert np.array_equal(np.array([complex(number(r["real"]), number(r["imag"])) for r in ev]), lin.eigenvalues)
        vec = read_csv(tmp_path / folder / "eigenvectors.csv")
        n = len(lin.eigenvalues)
        assert np.array_equal(np.array([[complex(number(r[f"re_{k}"]), number(r[f"im_{k}"])) for k in range(n)] for r in vec]),
                              lin.eigenvectors)
        meta = read_json(tmp_path / folder / "linear_model.json")
        assert (meta["speed_mps"], meta["roll_rad"], meta["heading_frame"]) == (lin.speed_mps, lin.roll_rad, lin.heading_frame)
    turn = motostab.trim(bike, speed, roll_deg=roll)
    # a turn at a given speed has no hands-free keys: None in Python, absent from trim.json
    assert {k: v for k, v in turn.__dict__.items() if k not in ("continues_from_straight_running", "hands_free_turns")} \
        == read_json(tmp_path / "trim" / "trim.json")
    assert turn.continues_from_straight_running is None and turn.hands_free_turns is None


def test_hands_free_trim_equals_the_command_line(motostab, tmp_path):
    run_cli("trim", WHIPPLE, "--hands-free", "--roll-deg", "3", "--speeds", "1:8:0.5", "--out", "free", cwd=tmp_path)
    free = motostab.trim(motostab.Scenario.load(WHIPPLE), roll_deg=3, hands_free=True, speeds=(1, 8, 0.5))
    assert read_json(tmp_path / "free" / "trim.json") == free.__dict__
    assert abs(free.steer_torque_Nm) < 1e-8


def test_simulation_equals_the_command_line(motostab, tmp_path):
    rng = random.Random(14)
    rate = round(rng.uniform(0.1, 0.5), 6)
    run_cli("simulate", WHIPPLE, "--speed", "5", "--duration", "1.5", "--perturb", f"roll-rate:{rate!r}",
            "--perturb", "steer-torque:0.5:0.2:0.1", "--out", "sim", cwd=tmp_path)
    sim = motostab.simulate(motostab.Scenario.load(WHIPPLE), 5, 1.5,
                            perturb=[f"roll-rate:{rate!r}", "steer-torque:0.5:0.2:0.1"])
    rows = read_csv(tmp_path / "sim" / "timeseries.csv")
    assert list(rows[0].keys()) == sim.columns
    assert np.array_equal(np.array([[number(r[c]) for c in sim.columns] for r in rows]), sim.samples)
    assert sim.status == "completed" and sim.time[-1] == pytest.approx(1.5)


def test_tyre_curve_equals_the_command_line(motostab, tmp_path):
    rng = random.Random(15)
    fz, camber, kappa = rng.uniform(1000, 6000), rng.uniform(-5, 5), rng.uniform(-0.05, 0.05)
    run_cli("tyre", SAMPLE_TIR, "--fz", repr(fz), "--slip-deg", "-12:12:0.5", "--camber-deg", repr(camber),
            "--slip-ratio", repr(kappa), "--out", "tyre", cwd=tmp_path)
    curve = motostab.tyre(SAMPLE_TIR, fz, (-12, 12, 0.5), camber_deg=camber, slip_ratio=kappa)
    rows = read_csv(tmp_path / "tyre" / "forces.csv")
    for column in rows[0]:
        assert np.array_equal(np.array([number(r[column]) for r in rows]), getattr(curve, column)), column


def test_uncertainty_equals_the_command_line(motostab, tmp_path):
    run_cli("uncertainty", KOOIJMAN, "--samples", "6", "--seed", "7", "--speeds", "2:8:0.5", "--threads", "2",
            "--out", "unc", cwd=tmp_path)
    u = motostab.uncertainty(motostab.Scenario.load(KOOIJMAN), samples=6, seed=7, speeds=(2, 8, 0.5), threads=2)
    assert read_json(tmp_path / "unc" / "summary.json") == u.summary
    with open(tmp_path / "unc" / "report.md") as f:
        assert f.read() == u.report
    samples = read_csv(tmp_path / "unc" / "samples.csv")
    first = 1 + 2 * len(u.parameter_paths)  # the nominal and the first-order neighbours come first
    for i, row in enumerate(samples):
        for j, path in enumerate(u.parameter_paths):
            assert number(row[path]) == u.parameters[first + i, j]
        for j, mode in enumerate(u.modes):
            assert np.array_equal(number(row[f"{mode}_speed_mps"]), u.first_crossings[first + i, j], equal_nan=True)


def test_study_report_equals_the_command_line(motostab, tmp_path):
    run_cli("study", SUPERSPORT, "--no-findings", "--speeds", "10:30:4", "--compare", "rigid,twist", "--shape-speeds", "18",
            "--out", "study", cwd=tmp_path)
    s = motostab.study(motostab.Scenario.load(SUPERSPORT), speeds=(10, 30, 4), compare=["rigid", "twist"],
                       shape_speeds=[18])
    with open(tmp_path / "study" / "report.md") as f:
        assert f.read() == s.report
    assert list(s.nominal) == ["rigid", "twist"] and list(s.halved) == ["rigid", "twist"]
    for stiffness, variants in (("nominal", s.nominal), ("halved", s.halved)):
        for name, sweep in variants.items():
            check_sweep_csv(read_csv(tmp_path / "study" / stiffness / name / "eigenvalues.csv"), sweep)
            check_summary(read_json(tmp_path / "study" / stiffness / name / "summary.json"), sweep)


def test_a_scenario_with_a_plugin_library_equals_the_command_line(motostab, tmp_path):
    # The example contact plugin (examples/plugins/vertical_spring_contact.cpp), named by the scenario.
    plugin = os.environ["MOTOSTAB_EXAMPLE_PLUGIN"]
    text = WHIPPLE.read_text()
    scenario = tmp_path / "sprung.yaml"
    scenario.write_text(text + f"plugins: [{plugin}]\n")
    changes = ["contact={model: example_vertical_spring, stiffness_N_per_m: 1.0e5}"]
    run_cli("sweep", scenario, "--set", changes[0], "--speeds", "1:5:1", "--out", "out", cwd=tmp_path)
    sprung = motostab.Scenario.load(scenario).with_(contact={"model": "example_vertical_spring", "stiffness_N_per_m": 1.0e5})
    sweep = motostab.sweep(sprung, speeds=(1, 5, 1))
    check_sweep_csv(read_csv(tmp_path / "out" / "eigenvalues.csv"), sweep)
    assert "bounce" in set(sweep.labels[0])  # the springs let the bicycle bounce
    # The plugin declares its stiffness a measured field: a parameter of the scenario that selects it.
    assert sprung.parameters()["contact.stiffness_N_per_m"] == 1.0e5
    # `motostab fields --plugin` lists the library's declaration beside the built-in ones.
    listed = run_cli("fields", "contact", "--plugin", plugin, cwd=tmp_path)
    assert "(`contact.model`: `example_vertical_spring`)" in listed and "| `stiffness_N_per_m` | N/m | > 0 |" in listed
    assert "example_vertical_spring" not in run_cli("fields", "contact", cwd=tmp_path)
    assert "not a bare name searched" in run_cli("fields", "--plugin", os.path.basename(plugin), cwd=tmp_path, expect=2)
