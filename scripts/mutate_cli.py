#!/usr/bin/env python3
"""Seeded mutation testing of the motostab command line (docs/testing.md, "Mutated inputs").

Each trial takes one bundled input (a scenario, measured data, a BicycleParameters file, a .tir file, a lab
test, a response CSV, or command-line option values), applies one mutation drawn from the kinds of bad input
motostab must refuse (numbers replaced by extreme or non-finite values, keys deleted, repeated or misspelt,
YAML aliases nested, a second YAML document, a byte order mark, duplicated CSV columns, truncation, byte
flips, a path that is a device or a folder, a range without a bound...), runs the command that reads it,
and checks the one exit-code scheme: 0 (outputs complete: every JSON parses and holds no NaN, no CSV cell is nan or inf), 2 (the
message names the input), 3 (valid input, no result), never 1 (a bug), a signal or a hang.

  scripts/mutate_cli.py [--count N] [--seed S] [--motostab PATH] [--timeout SECONDS] [--keep DIR]

Prints the exit-code distribution and every finding (exit 1, a signal, a timeout, an exit 0 with a
non-finite or unparsable output, an exit 2 without a location); exits 1 if there is a finding.
"""
import argparse
import collections
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCEN = os.path.join(ROOT, "scenarios")
EX = os.path.join(ROOT, "examples")
BP = os.path.join(ROOT, "tests/data/measured-data/BicycleParameters/data/bicycles")
TIR = os.path.join(ROOT, "tests/data/reference/MF61-sample-tir/sample_MF61_ExternData.tir")

EXTREME_NUMBERS = ["0", "-1", "1e300", "-1e300", "1e-300", "1e6", "5e4", ".nan", "nan", "inf", "-.inf", "0x10",
                   "1e999", "abc", "", "[1, 2]", "{a: 1}", "1e13", "-0", "3e-13", "1e12"]


def read(path):
    with open(path, encoding="utf-8", errors="surrogateescape") as f:
        return f.read()


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write(text)


# ---- mutations of text --------------------------------------------------------------------------------

def replace_number(text, rng):
    spans = [m.span() for m in re.finditer(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?(?![\w.])", text)]
    if not spans:
        return text, "no number"
    a, b = rng.choice(spans)
    new = rng.choice(EXTREME_NUMBERS)
    return text[:a] + new + text[b:], "number %r -> %r" % (text[a:b], new)


def yaml_lines(text):
    return [i for i, l in enumerate(text.split("\n")) if re.match(r"^\s*[A-Za-z_][\w.]*\s*:", l)]


def pick_key_line(text, rng):
    """The lines of `text` and the index of a key line drawn at random (None when there is none)."""
    lines = text.split("\n")
    idx = yaml_lines(text)
    return lines, (rng.choice(idx) if idx else None)


def delete_key(text, rng):
    lines, i = pick_key_line(text, rng)
    if i is None:
        return text, "no key"
    return "\n".join(lines[:i] + lines[i + 1:]), "deleted %r" % lines[i].strip()


def repeat_key(text, rng):
    lines, i = pick_key_line(text, rng)
    if i is None:
        return text, "no key"
    return "\n".join(lines[:i + 1] + [lines[i]] + lines[i + 1:]), "repeated %r" % lines[i].strip()


def misspell_key(text, rng):
    lines, i = pick_key_line(text, rng)
    if i is None:
        return text, "no key"
    m = re.match(r"^(\s*)([A-Za-z_][\w.]*)(\s*:.*)$", lines[i])
    key = m.group(2)
    k = rng.randrange(len(key))
    bad = key[:k] + (key[k].upper() if key[k].islower() else key[k].lower() if key[k].isupper() else "x") + key[k + 1:]
    lines[i] = m.group(1) + bad + m.group(3)
    return "\n".join(lines), "misspelt %s -> %s" % (key, bad)


def alias_bomb(text, rng):
    width, levels = rng.randint(5, 12), rng.randint(3, 9)
    bomb = "zz0: &zz0 [%s]\n" % ", ".join(["x"] * width)
    for l in range(1, levels + 1):
        bomb += "zz%d: &zz%d [%s]\n" % (l, l, ", ".join(["*zz%d" % (l - 1)] * width))
    return bomb + text, "alias bomb %dx%d" % (width, levels)


def wide_alias(text, rng):
    return "zzbase: &zzb [%s]\nzzcopies: [%s]\n" % (", ".join(["0"] * 1000), ", ".join(["*zzb"] * 150)) + text, "wide alias"


def second_document(text, rng):
    return text + "\n---\nname: second\n", "second document"


def byte_order_mark(text, rng):
    return "\ufeff" + text, "BOM"


def truncate(text, rng):
    n = rng.randrange(len(text)) if text else 0
    return text[:n], "truncated at %d" % n


def flip_bytes(text, rng):
    chars = list(text)
    for _ in range(rng.randint(1, 4)):
        if chars:
            i = rng.randrange(len(chars))
            chars[i] = rng.choice(":,[]{}&*!|>-#'\"\t \n0.e+")
    return "".join(chars), "byte flips"


def duplicate_column(text, rng):
    lines = text.split("\n")
    for i, l in enumerate(lines):
        if l and not l.startswith("#"):
            cols = l.split(",")
            c = rng.choice(cols)
            lines[i] = l + "," + c
            for j in range(i + 1, len(lines)):
                if lines[j] and not lines[j].startswith("#"):
                    lines[j] += "," + lines[j].split(",")[cols.index(c)]
            return "\n".join(lines), "duplicated column %s" % c
    return text, "no header"


def bp_mutation(text, rng):
    lines = [l for l in text.split("\n") if l.strip()]
    i = rng.randrange(len(lines))
    name, _, value = lines[i].partition("=")
    kind = rng.randrange(5)
    if kind == 0:
        lines.append(lines[i])
        return "\n".join(lines), "repeated " + name.strip()
    if kind == 1:
        lines[i] = name + "= " + value.split("+/-")[0].strip() + "+/-" + rng.choice(["abc", "0x10", "-1", "", "nan"])
        return "\n".join(lines), "bad sigma on " + name.strip()
    if kind == 2:
        n = name.strip()
        lines[i] = (n[:-1] + n[-1].swapcase() if n[-1].isalpha() else n + "x") + " =" + value
        return "\n".join(lines), "misspelt " + n
    if kind == 3:
        lines[i] = name + "= " + rng.choice(EXTREME_NUMBERS)
        return "\n".join(lines), "bad value on " + name.strip()
    del lines[i]
    return "\n".join(lines), "missing " + name.strip()


TEXT_MUTATIONS = [replace_number] * 6 + [delete_key, repeat_key, misspell_key, alias_bomb, wide_alias, second_document,
                                         byte_order_mark, truncate, flip_bytes]
CSV_MUTATIONS = [replace_number] * 5 + [duplicate_column, byte_order_mark, truncate, flip_bytes]


# ---- cases: an input, a mutation and the command that reads it -----------------------------------------

def copy_tree(src_files, dst):
    for f in src_files:
        shutil.copy(f, os.path.join(dst, os.path.basename(f)))


def scenario_case(rng, work):
    name = rng.choice(["whipple-benchmark", "enduro", "kooijman-silvercity", "balance-assist", "browser-jason-rider",
                       "whipple-benchmark-tyres"])
    text, what = rng.choice(TEXT_MUTATIONS)(read(os.path.join(SCEN, name + ".yaml")), rng)
    write(os.path.join(work, "s.yaml"), text)
    cmd = rng.choice([["check", "s.yaml"], ["sweep", "s.yaml", "--speeds", "3:5:1"],
                      ["linearize", "s.yaml", "--speed", "4"], ["trim", "s.yaml", "--speed", "4", "--roll-deg", "5"]])
    return cmd, "scenario %s: %s" % (name, what)


def set_case(rng, work):
    path = rng.choice(["geometry.trail_m", "rear_frame.mass_kg", "rear_frame.com_m[2]", "front_wheel.radius_m",
                       "steer_controller", "steer_damper", "name", "gravity_mps2", "rear_frame.inertia_kgm2",
                       "speeds_mps", "description"])
    value = rng.choice(EXTREME_NUMBERS + ["../victim", "/tmp/x", "{roll_rate_Nms_per_rad: 1e300}",
                                          "{delay_s: -1}", "{a: &a [1, 1], b: &b [*a, *a], c: [*b]}", "1\n---\n2",
                                          "{damping_Nms_per_rad: 5, damping_Nms_per_rad: 6}"])
    cmd = ["sweep", os.path.join(SCEN, "whipple-benchmark.yaml"), "--speeds", "3:5:1", "--set", path + "=" + value]
    return cmd, "--set %s=%s" % (path, value)


def option_case(rng, work):
    wb = os.path.join(SCEN, "whipple-benchmark.yaml")
    choices = [
        ["sweep", wb, "--speeds", rng.choice(["5:5:1", "5:", ":5:1", "0:1e9:1e-9", "1:2:0", "nan:1:1", "2:1:1", "0:10"])],
        ["sweep", wb, "--speeds", "3:5:1", "--roll-deg", rng.choice(["5:", "0:20:0.001", "89", "-89", "0:10:5", "85"])],
        ["sweep", wb, "--speeds", "3:4:1", "--threads", rng.choice(["0", "257", "2", "x"])],
        ["uncertainty", os.path.join(SCEN, "kooijman-silvercity.yaml"), "--speeds", "3:5:1",
         "--samples", rng.choice(["0", "1000000000", "-1", "1e3", "2"]), "--seed", rng.choice(["1", "-1", "x"])],
        ["tyre", TIR, "--fz", rng.choice(["0", "4000", "-1", "1e8"]), "--slip-deg", rng.choice(["-5:5:1", "5:", "0:0:1"]),
         "--camber-deg", "0"],
        ["check", rng.choice(["/dev/zero", work, "/nonexistent.yaml"])],
        ["simulate", wb, "--speed", rng.choice(["5", "0", "-1"]), "--duration", rng.choice(["0.2", "0", "inf"]),
         "--perturb", rng.choice(["roll-rate:0.1", "roll-rate:nan", "steer-torque:1:0.1:0.1"])],
        ["trim", wb, "--roll-deg", rng.choice(["3", "85"]), "--hands-free", "--speeds", rng.choice(["1:2:0.5", "1:8:1"])],
    ]
    cmd = rng.choice(choices)
    return cmd, "options " + " ".join(cmd[2:])


def measured_case(rng, work):
    src = rng.choice([(os.path.join(EX, "diagnosis", "kooijman2008.yaml"), os.path.join(EX, "diagnosis", "kooijman2008-weave.csv")),
                      (os.path.join(EX, "balance-assist", "weave.yaml"), os.path.join(EX, "balance-assist", "weave.csv"))])
    yaml_text = read(src[0]).replace("../../tests/data/", os.path.join(ROOT, "tests/data") + "/")
    csv_text = read(src[1])
    if rng.random() < 0.5:
        yaml_text, what = rng.choice(TEXT_MUTATIONS + [lambda t, r: (t.replace("eigenvalues:", "eigenvalues:") +
                                                                      "\n", "none")])(yaml_text, rng)
    else:
        csv_text, what = rng.choice(CSV_MUTATIONS)(csv_text, rng)
    for f in os.listdir(os.path.dirname(src[0])):
        shutil.copy(os.path.join(os.path.dirname(src[0]), f), os.path.join(work, f))
    write(os.path.join(work, os.path.basename(src[0])), yaml_text)
    write(os.path.join(work, os.path.basename(src[1])), csv_text)
    scenario = os.path.join(SCEN, "kooijman-silvercity.yaml" if "kooijman" in src[0] else "balance-assist.yaml")
    cmd = ["diagnose", scenario, os.path.basename(src[0]), "--candidates", "parameter:rear_frame.mass_kg",
           "--no-robustness", "--folds", "2"]
    return cmd, "measured %s: %s" % (os.path.basename(src[0]), what)


def bp_case(rng, work):
    bike = rng.choice(["Benchmark", "Browser", "Silver", "Pista", "Crescendo"])
    text, what = bp_mutation(read(os.path.join(BP, bike, "Parameters", bike + "Benchmark.txt")), rng)
    write(os.path.join(work, "bike.txt"), text)
    return ["import", "bike.txt", "--format", "bicycleparameters", "--out", "bike.yaml"], "%s: %s" % (bike, what)


def tir_case(rng, work):
    text, what = rng.choice([replace_number] * 4 + [truncate, flip_bytes, byte_order_mark])(read(TIR), rng)
    write(os.path.join(work, "t.tir"), text)
    return ["tyre", "t.tir", "--fz", "4000", "--slip-deg", "-5:5:1", "--camber-deg", "2"], "tir: " + what


def identification_case(rng, work):
    test = rng.choice(["static", "frf", "cog", "inertia"])
    for f in os.listdir(os.path.join(EX, "identification")):
        shutil.copy(os.path.join(EX, "identification", f), os.path.join(work, f))
    target = rng.choice([test + ".yaml"] + ([test + ".csv"] if test in ("static", "cog") else ["hit1.csv"] if test == "frf" else []))
    text = read(os.path.join(work, target))
    muts = CSV_MUTATIONS if target.endswith(".csv") else TEXT_MUTATIONS
    text, what = rng.choice(muts)(text, rng)
    write(os.path.join(work, target), text)
    return ["identify", test, test + ".yaml"], "identify %s, %s: %s" % (test, target, what)


def response_case(rng, work):
    rows = ["time_s,roll_rate,steer_rate"]
    for i in range(200):
        t = 0.01 * i
        rows.append("%.3f,%.6f,%.6f" % (t, math.exp(-0.5 * t) * math.sin(6 * t), 0.3 * math.exp(-0.5 * t) * math.cos(6 * t)))
    text, what = rng.choice(CSV_MUTATIONS)("\n".join(rows) + "\n", rng)
    write(os.path.join(work, "r.csv"), text)
    return ["identify", "response", "r.csv", "--signal", "roll_rate", "--signal", "steer_rate"], "response csv: " + what


CASES = [scenario_case] * 5 + [set_case] * 3 + [option_case] * 3 + [measured_case] * 2 + [bp_case] * 2 + \
        [tir_case] * 2 + [identification_case] * 2 + [response_case]


# ---- checks ----------------------------------------------------------------------------------------------

def non_finite_json(path):
    try:
        with open(path) as f:
            json.load(f, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except Exception as e:  # noqa: BLE001
        return "%s: %s" % (os.path.basename(path), e)
    return ""


NON_FINITE_CELL = re.compile(r"^[+-]?(nan|inf|infinity)$", re.IGNORECASE)


def non_finite_csv(path):
    """The first cell of a CSV output that reads as NaN or infinity (an undefined value is an empty cell)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for n, line in enumerate(f, 1):
            for cell in line.rstrip("\n").split(","):
                if NON_FINITE_CELL.match(cell.strip().strip('"')):
                    return "%s:%d: %s" % (os.path.basename(path), n, cell.strip())
    return ""


def check_outputs(work):
    for root, _, files in os.walk(work):
        for f in files:
            bad = ""
            if f.endswith(".json"):
                bad = non_finite_json(os.path.join(root, f))
            elif f.endswith(".csv"):
                bad = non_finite_csv(os.path.join(root, f))
            if bad:
                return bad
    return ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--count", type=int, default=300)
    ap.add_argument("--seed", type=int, default=29)
    ap.add_argument("--motostab", default=os.path.join(ROOT, "build", "apps", "motostab"))
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--keep", help="keep the work folders of findings here")
    ap.add_argument("--log", help="write every trial (mutation, command, exit code, last message line) to this file")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    codes = collections.Counter()
    by_kind = collections.defaultdict(collections.Counter)
    findings = []
    log = open(a.log, "w") if a.log else None
    for trial in range(a.count):
        work = tempfile.mkdtemp(prefix="motostab_mutate_")
        case = rng.choice(CASES)
        cmd, what = case(rng, work)
        full = [a.motostab] + cmd
        try:
            p = subprocess.run(full, cwd=work, capture_output=True, text=True, errors="replace", timeout=a.timeout,
                               preexec_fn=lambda: __import__("resource").setrlimit(
                                   __import__("resource").RLIMIT_AS, (4 << 30, 4 << 30)))
            code, out = p.returncode, p.stdout + p.stderr
        except subprocess.TimeoutExpired:
            code, out = "timeout", ""
        codes[code] += 1
        by_kind[case.__name__][code] += 1
        problem = ""
        if code == 0:
            problem = check_outputs(work)
        elif code == 2 and not out.strip():
            problem = "exit 2 without a message"
        elif code not in (2, 3):
            problem = "exit %s" % code
        last = out.strip().split("\n")[-1][:300] if out.strip() else ""
        if log:
            log.write("%d\t%s\t%s\t%s\t%s\n" % (trial, code, what, " ".join(cmd), last))
        if problem:
            findings.append((trial, what, " ".join(cmd), problem, last))
            if a.keep:
                shutil.copytree(work, os.path.join(a.keep, "trial%04d" % trial))
        shutil.rmtree(work, ignore_errors=True)
    print("mutated inputs run: %d (seed %d)" % (a.count, a.seed))
    print("exit codes: " + ", ".join("%s: %d" % (k, v) for k, v in sorted(codes.items(), key=lambda kv: str(kv[0]))))
    for kind, c in sorted(by_kind.items()):
        print("  %-20s %s" % (kind, ", ".join("%s: %d" % (k, v) for k, v in sorted(c.items(), key=lambda kv: str(kv[0])))))
    for f in findings:
        print("FINDING trial %d: %s\n  motostab %s\n  %s | %s" % f)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
