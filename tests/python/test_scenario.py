"""motostab.Scenario: load, typed changes (with_), dicts in and out, YAML out; each variant read by
the command line's strict reader."""
import random

import numpy as np
import pytest

from conftest import ENDURO, WHIPPLE, run_cli


def test_load_reads_the_file(motostab):
    bike = motostab.Scenario.load(WHIPPLE)
    assert bike.name == "whipple-benchmark" and bike.file == str(WHIPPLE)
    assert bike.speeds == (0.0, 10.0, 0.1)
    assert bike.wheelbase_m == 1.02
    assert bike["geometry.trail_m"] == 0.08 and bike["rear_frame.com_m[2]"] == 0.9
    assert bike.parameters()["front_frame.inertia_kgm2.xz"] == 0.00756
    assert bike.overrides == []


def test_with_changes_a_copy_by_typed_values(motostab):
    bike = motostab.Scenario.load(WHIPPLE)
    rng = random.Random(5)
    trail, mass = rng.uniform(0.05, 0.1), rng.uniform(60, 100)
    changed = bike.with_({"geometry.trail_m": trail}, **{"rear_frame.mass_kg": mass})
    assert changed["geometry.trail_m"] == trail and changed["rear_frame.mass_kg"] == mass  # every digit kept
    assert bike["geometry.trail_m"] == 0.08  # the original is unchanged
    assert changed.overrides == [f"geometry.trail_m={trail!r}", f"rear_frame.mass_kg={mass!r}"]
    # A section as a dict, a model switch as a string, an integer as a number.
    damped = bike.with_(steer_damper={"damping_Nms_per_rad": 0.4}, **{"speeds_mps.stop": 12})
    assert damped["steer_damper.damping_Nms_per_rad"] == 0.4 and damped.speeds[1] == 12
    twist = motostab.Scenario.load(ENDURO).with_(**{"swingarm.compliance": "twist"})
    assert "swingarm.compliance=twist" in twist.overrides


def test_a_change_gives_what_the_same_set_gives_on_the_command_line(motostab, tmp_path):
    trail = random.Random(6).uniform(0.05, 0.1)
    bike = motostab.Scenario.load(WHIPPLE).with_(**{"geometry.trail_m": trail})
    run_cli("linearize", WHIPPLE, "--speed", "4", "--set", f"geometry.trail_m={trail!r}", "--out", "lin", cwd=tmp_path)
    lin = motostab.linearize(bike, 4)
    import csv
    with open(tmp_path / "lin" / "A.csv") as f:
        rows = list(csv.DictReader(f))
    assert np.array_equal(np.array([[float(r[s]) for s in lin.state_names] for r in rows]), lin.A)


def test_dicts_and_yaml_round_trip(motostab, tmp_path):
    bike = motostab.Scenario.load(WHIPPLE).with_(**{"geometry.trail_m": 0.0812345678901234})
    tree = bike.to_dict()
    assert tree["geometry"]["trail_m"] == 0.0812345678901234
    assert tree["rear_frame"]["com_m"] == [0.3, 0, 0.9] and isinstance(tree["rear_frame"]["com_m"][1], int)
    again = motostab.Scenario.from_dict(tree, name="from a dict")
    assert again.file == "from a dict" and again.parameters() == bike.parameters()
    assert np.array_equal(motostab.linearize(again, 3.3).A, motostab.linearize(bike, 3.3).A)
    path = tmp_path / "saved.yaml"
    bike.save(path)
    saved = motostab.Scenario.load(path)
    assert saved.parameters() == bike.parameters()
    run_cli("check", path, cwd=tmp_path)  # the command line reads what save writes


def test_numpy_values_are_numbers(motostab):
    bike = motostab.Scenario.load(WHIPPLE)
    changed = bike.with_(**{"geometry.trail_m": np.float64(0.07), "rear_frame.com_m": np.array([0.31, 0.0, 0.91])})
    assert changed["geometry.trail_m"] == 0.07 and changed["rear_frame.com_m[0]"] == 0.31
