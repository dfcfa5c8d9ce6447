"""Bad input raises motostab.InputError (a ValueError) located as the command line locates it: file,
line, column and key, with the command line's own message; a computation without a result raises
motostab.ResultError; nothing is printed."""
import logging
import random

import pytest

from conftest import ENDURO, SAMPLE_TIR, WHIPPLE, run_cli


def write_bad_scenario(tmp_path, mass):
    """The benchmark scenario with rear_frame.mass_kg replaced by `mass`; returns the file and the line and
    column of the key."""
    lines = WHIPPLE.read_text().splitlines()
    row = next(i for i, l in enumerate(lines) if l.strip().startswith("mass_kg") and "rear_frame" in lines[i - 1])
    column = lines[row].index("mass_kg") + 1
    lines[row] = lines[row][:column - 1] + "mass_kg: " + repr(mass)
    path = tmp_path / "bad.yaml"
    path.write_text("\n".join(lines) + "\n")
    return path, row + 1, column


def test_a_bad_value_in_a_file_is_located_as_the_command_line_locates_it(motostab, tmp_path):
    mass = -random.Random(3).uniform(1, 90)
    path, line, column = write_bad_scenario(tmp_path, mass)
    with pytest.raises(motostab.InputError) as info:
        motostab.Scenario.load(path)
    e = info.value
    assert isinstance(e, ValueError)
    assert (e.file, e.line, e.key) == (str(path), line, "rear_frame.mass_kg")
    assert e.column == column
    assert "positive" in e.reason
    message = run_cli("check", path, cwd=tmp_path, expect=2)
    assert message.strip() == f"motostab: input error: {e}"


def test_a_bad_change_names_the_key_and_the_change(motostab, tmp_path):
    bike = motostab.Scenario.load(WHIPPLE)
    with pytest.raises(motostab.InputError) as info:
        bike.with_(**{"rear_frame.mass_kg": -3.5})
    assert info.value.key == "rear_frame.mass_kg" and info.value.file == str(WHIPPLE)
    assert "rear_frame.mass_kg=-3.5" in str(info.value)
    message = run_cli("check", WHIPPLE, "--set", "rear_frame.mass_kg=-3.5", cwd=tmp_path, expect=2)
    assert message.strip() == f"motostab: input error: {info.value}"
    with pytest.raises(motostab.InputError) as info:
        bike.with_(**{"geometry.no_such_key_m": 1.0})
    assert "no_such_key_m" in str(info.value)
    with pytest.raises(motostab.InputError) as info:
        bike.with_(**{"geometry.trail_m": float("nan")})
    assert info.value.key == "geometry.trail_m"


def test_a_bad_dict_is_an_input_error_naming_the_key(motostab):
    tree = motostab.Scenario.load(WHIPPLE).to_dict()
    tree["front_wheel"]["radius_mm"] = 350
    with pytest.raises(motostab.InputError) as info:
        motostab.Scenario.from_dict(tree, name="my bike")
    assert info.value.file == "my bike" and "radius_mm" in str(info.value)
    tree["front_wheel"].pop("radius_mm")
    tree["front_wheel"]["radius_m"] = {"a": object()}
    with pytest.raises(motostab.InputError) as info:
        motostab.Scenario.from_dict(tree)
    assert info.value.key == "front_wheel.radius_m.a"


@pytest.mark.parametrize("call, key", [
    (lambda m, s: m.sweep(s, speeds=(5, 1, 0.1)), "speeds"),
    (lambda m, s: m.sweep(s, speeds=(0, 1, 0)), "speeds"),
    (lambda m, s: m.sweep(s, speeds=(0, 1)), "speeds"),
    (lambda m, s: m.sweep(s, speeds=(0, 5, 1), threads=0), "threads"),
    (lambda m, s: m.sweep(s, speeds=(1, 5, 1), roll_deg=95), "roll_deg"),
    (lambda m, s: m.sweep(s, speeds=(0, 5, 1), roll_deg=5), "speeds"),
    (lambda m, s: m.turn_map(s, roll_deg=(5, 1, 1), speeds=(1, 5, 1)), "roll_deg"),
    (lambda m, s: m.linearize(s, -1), "speed"),
    (lambda m, s: m.trim(s), "speed"),
    (lambda m, s: m.trim(s, hands_free=True, speeds=(1, 5, 1)), "roll_deg"),
    (lambda m, s: m.simulate(s, 5, -1), "duration"),
    (lambda m, s: m.simulate(s, 5, 1, perturb=["steer-torque:x"]), "perturb"),
    (lambda m, s: m.simulate(s, 5, 1, integrator="euler"), "integrator"),
    (lambda m, s: m.uncertainty(s, method="lhs"), "method"),
    (lambda m, s: m.tyre(SAMPLE_TIR, -5, (-1, 1, 1)), "fz"),
    (lambda m, s: m.tyre(SAMPLE_TIR, 3000, (1, -1, 1)), "slip_deg"),
])
def test_bad_arguments_name_the_argument(motostab, call, key):
    with pytest.raises(motostab.InputError) as info:
        call(motostab, motostab.Scenario.load(WHIPPLE))
    assert info.value.key == key and info.value.file is None, str(info.value)


def test_a_trim_that_fails_raises_result_error(motostab):
    # The enduro with a tilted torsion axis has no upright equilibrium at standstill.
    enduro = motostab.Scenario.load(ENDURO).with_(**{
        "swingarm.compliance": "torsion",
        "swingarm.torsion": {"point_m": [0.56, 0, 0.014], "direction": [1, 0.2, 0], "stiffness_Nm_per_rad": 55200,
                             "damping_Nms_per_rad": 0.49}})
    with pytest.raises(motostab.ResultError) as info:
        motostab.sweep(enduro, speeds=(0, 2, 1))
    assert "m/s" in str(info.value)
    assert not isinstance(info.value, ValueError)


def test_nothing_is_printed_and_library_messages_are_logged(motostab, capfd, caplog, tmp_path):
    # The sample .tir file has nonzero coefficients MF 6.1 does not use: the command line warns on
    # stderr; Python logs the same lines to the "motostab" logger and prints nothing.
    with caplog.at_level(logging.INFO, logger="motostab"):
        motostab.tyre(SAMPLE_TIR, 3000, (-2, 2, 1))
        motostab.sweep(motostab.Scenario.load(WHIPPLE), speeds=(0, 1, 0.5))
    out, err = capfd.readouterr()
    assert out == "" and err == ""
    logged = [r.getMessage() for r in caplog.records if r.name == "motostab"]
    cli = run_cli("tyre", SAMPLE_TIR, "--fz", "3000", "--slip-deg", "-2:2:1", "--camber-deg", "0", "--out", "t", cwd=tmp_path)
    warnings = [line for line in cli.splitlines() if line.startswith("warning:")]
    assert warnings and logged == warnings
