#!/usr/bin/env python3
"""Derives scenarios/browser-jason-rider.yaml: the Browser bicycle with rider Jason and his passive upper
body (`rider_lean`), from the BicycleParameters measurements (Moore et al. 2010; data in
tests/data/measured-data/BicycleParameters, BSD 2-Clause):

- bicycles/Browser/Parameters/BrowserBenchmark.txt: the bicycle in Meijaard (2007) form (z down);
- riders/Jason/Parameters/JasonBrowserBenchmark.txt: the whole rider seated on it (Yeadon model);
- riders/Jason/RawData/JasonYeadonMeas.txt: Ls4L = 0.493 m, hip joint centre to shoulder joint centre;
- riders/Jason/RawData/JasonBrowserYeadonCFG.txt: somersault 0.175 rad (trunk leaning forward);
- bicycles/Browser/RawData/BrowserMeasured.txt: hbb, lcs, lst, lsp, lamst locate the saddle (hip).

The upper body (head, arms, trunk: HAT) is an estimate from Winter (2009), "Biomechanics and motor
control of human movement", Table 4.1: mass 0.678 of the body, radius of gyration about its CoM 0.496 of
the hip-to-shoulder length (about the axes across the trunk); about the trunk's long axis a third of that
(estimate). Winter's CoM, 0.626 of that length above the hip, is inconsistent with Jason's Yeadon totals
seated on the Browser with the hip at the saddle: the rest (frame and legs) would have a negative roll
inertia. The CoM is taken at 0.5 of the length (0.25 m above the hip, the arms reaching forward and down
to the handlebar), where the rest keeps principal moments of 1.3-3.2 kg m^2. Lean stiffness and damping: estimates (no measured
passive values found), k above the upper body's gravity stiffness m g d so the rider alone is upright-stable.
Run: python3 docs/rider-lean-parameters.py  (prints the YAML sections)."""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data", "measured-data", "BicycleParameters", "data")


def read(path):
    out = {}
    for line in open(os.path.join(DATA, path)):
        if "=" in line and not line.lstrip().startswith("#"):
            k, v = line.split("=", 1)
            out[k.strip()] = float(v.split("+/-")[0].split(",")[0])
    return out


bike = read("bicycles/Browser/Parameters/BrowserBenchmark.txt")
rider = read("riders/Jason/Parameters/JasonBrowserBenchmark.txt")
meas = read("bicycles/Browser/RawData/BrowserMeasured.txt")
L = 0.493       # Ls4L, JasonYeadonMeas.txt (cm * 0.01)
theta = 0.175   # somersault, JasonBrowserYeadonCFG.txt


def body(m, x, z, Ixx, Iyy, Izz, Ixz):
    """Design frame (z up): z and I_xz change sign from the benchmark frame."""
    return dict(m=m, c=[x, 0.0, -z], I=[[Ixx, 0, -Ixz], [0, Iyy, 0], [-Ixz, 0, Izz]])


def about_origin(b):
    m, c, I = b["m"], b["c"], b["I"]
    r2 = sum(v * v for v in c)
    return [[I[i][j] + m * ((r2 if i == j else 0) - c[i] * c[j]) for j in range(3)] for i in range(3)]


def add(a, b):
    m = a["m"] + b["m"]
    c = [(a["m"] * a["c"][i] + b["m"] * b["c"][i]) / m for i in range(3)]
    Io = [[x + y for x, y in zip(ra, rb)] for ra, rb in zip(about_origin(a), about_origin(b))]
    r2 = sum(v * v for v in c)
    I = [[Io[i][j] - m * ((r2 if i == j else 0) - c[i] * c[j]) for j in range(3)] for i in range(3)]
    return dict(m=m, c=c, I=I)


frame = body(bike["mB"], bike["xB"], bike["zB"], bike["IBxx"], bike["IByy"], bike["IBzz"], bike["IBxz"])
jason = body(rider["mB"], rider["xB"], rider["zB"], rider["IBxx"], rider["IByy"], rider["IBzz"], rider["IBxz"])
rear = add(frame, jason)

# Saddle (hip joint centre): bottom bracket from the chain stay and its height, then up the seat tube
# (lamst from the horizontal) by seat tube plus seat post.
rR = bike["rR"]
bb_x = math.sqrt(meas["lcs"] ** 2 - (meas["hbb"] - rR) ** 2)
hip_x = bb_x - (meas["lst"] + meas["lsp"]) * math.cos(meas["lamst"])
hip_z = meas["hbb"] + (meas["lst"] + meas["lsp"]) * math.sin(meas["lamst"])

m_hat = 0.678 * rider["mB"]
d = 0.5 * L
c_hat = [hip_x + d * math.sin(theta), 0.0, hip_z + d * math.cos(theta)]
b = m_hat * (0.496 * L) ** 2        # across the trunk
a = b / 3                           # about the trunk's long axis (estimate)
s, c = math.sin(theta), math.cos(theta)
I_hat = dict(xx=a * s * s + b * c * c, yy=b, zz=a * c * c + b * s * s, xz=(a - b) * s * c)
k = 4 * m_hat * 9.81 * d            # four times the gravity stiffness (estimate)
damping = 0.2 * 2 * math.sqrt(k * (I_hat["xx"] + m_hat * d * d))   # 20 % of critical (estimate)

f = lambda v: f"{v:.6g}"
print(f"rear_frame:  # Browser frame + Jason (BicycleParameters)\n  mass_kg: {f(rear['m'])}\n"
      f"  com_m: [{f(rear['c'][0])}, 0, {f(rear['c'][2])}]\n"
      f"  inertia_kgm2: {{xx: {f(rear['I'][0][0])}, yy: {f(rear['I'][1][1])}, zz: {f(rear['I'][2][2])}, "
      f"xy: 0, xz: {f(rear['I'][0][2])}, yz: 0}}")
print(f"rider_lean:\n  hinge_height_m: {f(hip_z)}\n  mass_kg: {f(m_hat)}\n  com_m: [{f(c_hat[0])}, 0, {f(c_hat[2])}]\n"
      f"  inertia_kgm2: {{xx: {f(I_hat['xx'])}, yy: {f(I_hat['yy'])}, zz: {f(I_hat['zz'])}, xy: 0, xz: {f(I_hat['xz'])}, yz: 0}}\n"
      f"  stiffness_Nm_per_rad: {f(k)}\n  damping_Nms_per_rad: {f(damping)}")
print(f"# hip at x = {hip_x:.4f} m; front frame, wheels, geometry: BrowserBenchmark.txt")
