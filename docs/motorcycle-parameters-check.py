#!/usr/bin/env python3
"""Check (and derive) the mass properties of scenarios/supersport.yaml and scenarios/enduro.yaml.

Python 3 standard library only. See docs/motorcycle-parameters.md for the derivation.

    python3 docs/motorcycle-parameters-check.py            # totals against seed Table 6, checks, 1-DOF modes
    python3 docs/motorcycle-parameters-check.py --solve    # also print the rear frame that matches Table 6
                                                            # exactly for the other bodies in the files

Frame D: origin at the rear contact point, x forward, y left, z up. Inertia tensors about each body's
own centre of mass, tensor components (xz = -sum m x z). The swingarm's com and inertia are given in its
frame S (origin at the pivot, x towards the rear hub, z up in the vertical plane), as the loader does
(scenario/scenario.cpp, calcSwingarmFrame).
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Seed Table 6 (vehicle + rider). Mass = "mass of the whole motorcycle" + rider mass.
# Inertias about the total CoG in D axes; the product is read as the tensor component xz = -sum m x z
# with z up (equivalently +sum m x z with z down, Sharp's C_xz); see the doc for the sign discussion.
TABLE6 = {
    "supersport": dict(mass=166.2 + 77.5, x=0.698, h=0.672, Ixx=26.7, Iyy=51.0, Izz=28.1, Ixz=3.2,
                       prec=dict(mass=1, x=3, h=3, Ixx=1, Iyy=1, Izz=1, Ixz=1)),
    "enduro": dict(mass=190.4 + 77.5, x=0.623, h=0.697, Ixx=33.4, Iyy=64.9, Izz=39.4, Ixz=1.98,
                   prec=dict(mass=1, x=3, h=3, Ixx=1, Iyy=1, Izz=1, Ixz=2)),
}
# Seed section 4: swingarm modes of the whole vehicle (Hz).
TARGET_HZ = {"supersport": (52.0, 65.0), "enduro": (38.0, 60.0)}


# ----------------------------------------------------------------------------------------------
# A minimal reader for the YAML subset used by the two scenario files: block mappings by
# indentation, '#' comments, scalars, and one-line flow mappings / sequences.
def _flow(s, i):
    def ws(i):
        while i < len(s) and s[i] in " \t":
            i += 1
        return i
    i = ws(i)
    if s[i] == "{":
        out, i = {}, ws(i + 1)
        while s[i] != "}":
            j = s.index(":", i)
            key = s[i:j].strip()
            val, i = _flow(s, j + 1)
            out[key] = val
            i = ws(i)
            if s[i] == ",":
                i = ws(i + 1)
        return out, i + 1
    if s[i] == "[":
        out, i = [], ws(i + 1)
        while s[i] != "]":
            val, i = _flow(s, i)
            out.append(val)
            i = ws(i)
            if s[i] == ",":
                i = ws(i + 1)
        return out, i + 1
    j = i
    while j < len(s) and s[j] not in ",}]":
        j += 1
    return _scalar(s[i:j].strip()), j


def _scalar(t):
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(t)
    except ValueError:
        return t.strip('"')


def load_yaml(path):
    root = {}
    stack = [(-1, root)]
    with open(path) as f:
        lines = [raw.split(" #")[0].rstrip() if not raw.lstrip().startswith("#") else "" for raw in f]
    merged = []  # join flow collections that continue on the next lines
    for line in lines:
        if merged and merged[-1].count("{") + merged[-1].count("[") > merged[-1].count("}") + merged[-1].count("]"):
            merged[-1] += " " + line.strip()
        elif line.strip():
            merged.append(line)
    if True:
        for line in merged:
            ind = len(line) - len(line.lstrip())
            key, _, rest = line.strip().partition(":")
            rest = rest.strip()
            while stack[-1][0] >= ind:
                stack.pop()
            parent = stack[-1][1]
            if rest == "":
                parent[key] = {}
                stack.append((ind, parent[key]))
            elif rest[0] in "{[":
                parent[key] = _flow(rest, 0)[0]
            else:
                parent[key] = _scalar(rest)
    return root


# ----------------------------------------------------------------------------------------------
# Small 3x3 helpers (lists of rows).
def tensor(d):
    return [[d["xx"], d["xy"], d["xz"]], [d["xy"], d["yy"], d["yz"]], [d["xz"], d["yz"], d["zz"]]]


def add(A, B, s=1.0):
    return [[A[i][j] + s * B[i][j] for j in range(3)] for i in range(3)]


def steiner(m, r):
    """Parallel-axis term m (|r|^2 1 - r r^T) (tensor components)."""
    r2 = sum(c * c for c in r)
    return [[m * ((r2 if i == j else 0.0) - r[i] * r[j]) for j in range(3)] for i in range(3)]


def rotate(R, I):
    """R I R^T, R with the body axes as columns."""
    RI = [[sum(R[i][k] * I[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    return [[sum(RI[i][k] * R[j][k] for k in range(3)) for j in range(3)] for i in range(3)]


def eig_sym3(A):
    """Eigenvalues of a symmetric 3x3 matrix (closed form)."""
    p1 = A[0][1] ** 2 + A[0][2] ** 2 + A[1][2] ** 2
    q = (A[0][0] + A[1][1] + A[2][2]) / 3
    if p1 < 1e-30:
        return sorted([A[0][0], A[1][1], A[2][2]])
    p2 = sum((A[i][i] - q) ** 2 for i in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    B = [[(A[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    detB = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0])
            + B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0]))
    r = max(-1.0, min(1.0, detB / 2))
    phi = math.acos(r) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e3, 3 * q - e1 - e3, e1])


def physical(I):
    e = eig_sym3(I)
    return e, e[0] > 0 and e[0] + e[1] >= e[2] - 1e-12


# ----------------------------------------------------------------------------------------------
def swingarm_frame(sc):
    """Origin and axes of S in D, as scenario/scenario.cpp calcSwingarmFrame."""
    P = sc["swingarm"]["pivot_m"]
    Rr = sc["rear_wheel"]["radius_m"]
    dx, dz = -P[0], Rr - P[2]
    L = math.hypot(dx, dz)
    fx = [dx / L, 0.0, dz / L]
    fz = [-fx[2], 0.0, fx[0]]
    if fz[2] < 0:
        fz = [-fz[0], 0.0, -fz[2]]
    fy = [fz[1] * fx[2] - fz[2] * fx[1], fz[2] * fx[0] - fz[0] * fx[2], fz[0] * fx[1] - fz[1] * fx[0]]
    return P, fx, fy, fz, L


def bodies(sc, with_rear_frame=True):
    """(name, mass, com in D, inertia tensor about com in D axes)."""
    out = []
    if with_rear_frame:
        rf = sc["rear_frame"]
        out.append(("rear_frame", rf["mass_kg"], rf["com_m"], tensor(rf["inertia_kgm2"])))
    ff = sc["front_frame"]
    out.append(("front_frame", ff["mass_kg"], ff["com_m"], tensor(ff["inertia_kgm2"])))
    wb = sc["geometry"]["wheelbase_m"]
    for name, x in (("rear_wheel", 0.0), ("front_wheel", wb)):
        w = sc[name]
        D, S = w["diametral_inertia_kgm2"], w["spin_inertia_kgm2"]
        out.append((name, w["mass_kg"], [x, 0.0, w["radius_m"]], [[D, 0, 0], [0, S, 0], [0, 0, D]]))
    sw = sc["swingarm"]
    P, fx, fy, fz, _ = swingarm_frame(sc)
    c = sw["com_m"]
    com = [P[i] + fx[i] * c[0] + fy[i] * c[1] + fz[i] * c[2] for i in range(3)]
    R = [[fx[i], fy[i], fz[i]] for i in range(3)]
    out.append(("swingarm", sw["mass_kg"], com, rotate(R, tensor(sw["inertia_kgm2"]))))
    return out


def totals(bs):
    m = sum(b[1] for b in bs)
    G = [sum(b[1] * b[2][i] for b in bs) / m for i in range(3)]
    I = [[0.0] * 3 for _ in range(3)]
    for _, mi, c, Ii in bs:
        I = add(add(I, Ii), steiner(mi, [c[i] - G[i] for i in range(3)]))
    return m, G, I


def solve_rear_frame(sc, t6, sign=+1):
    """Rear frame (mass, com, inertia about its com) that makes the totals equal Table 6."""
    others = bodies(sc, with_rear_frame=False)
    m_o = sum(b[1] for b in others)
    mo_c = [sum(b[1] * b[2][i] for b in others) for i in range(3)]
    M = t6["mass"]
    G = [t6["x"], 0.0, t6["h"]]
    m = M - m_o
    c = [(M * G[i] - mo_c[i]) / m for i in range(3)]
    It = [[t6["Ixx"], 0, sign * t6["Ixz"]], [0, t6["Iyy"], 0], [sign * t6["Ixz"], 0, t6["Izz"]]]
    for _, mi, ci, Ii in others:
        It = add(add(It, Ii, -1), steiner(mi, [ci[i] - G[i] for i in range(3)]), -1)
    It = add(It, steiner(m, [c[i] - G[i] for i in range(3)]), -1)
    return m, c, It


def compliance_axis(sc, mode):
    """Axis of a compliance model in S: (point, direction), seed eq. 2-10 convention of the schema."""
    sw = sc["swingarm"]
    _, _, _, _, L = swingarm_frame(sc)
    a = sw[mode]["arm_m"]
    b = math.radians(sw[mode]["beta_deg"])
    e = (math.cos(b), math.sin(b))
    p = (L - a * math.sin(b), a * math.cos(b))
    return p, e


def lever(q, p, e):
    """Lateral displacement of the in-plane point q per unit rotation about the axis (p, e)."""
    return e[1] * (q[0] - p[0]) - e[0] * (q[1] - p[1])


def one_dof(sc, mode, ky=0.0):
    """J, k and f of the swingarm + rear wheel rotating about the compliance axis (rear frame clamped).
    ky > 0 adds the rear tyre's lateral carcass spring (C_alpha Fz / sigma) at the contact point."""
    sw = sc["swingarm"]
    P, fx, _, fz, L = swingarm_frame(sc)
    p, e = compliance_axis(sc, mode)
    I = tensor(sw["inertia_kgm2"])
    c = (sw["com_m"][0], sw["com_m"][2])
    e3 = (e[0], 0.0, e[1])
    J_sw = sum(e3[i] * I[i][j] * e3[j] for i in range(3) for j in range(3)) + sw["mass_kg"] * lever(c, p, e) ** 2
    w = sc["rear_wheel"]
    J_w = w["diametral_inertia_kgm2"] + w["mass_kg"] * lever((L, 0.0), p, e) ** 2
    k = sw[mode]["stiffness_Nm_per_rad"]
    contact_D = [0.0, 0.0, 0.0]
    q = (sum((contact_D[i] - P[i]) * fx[i] for i in range(3)), sum((contact_D[i] - P[i]) * fz[i] for i in range(3)))
    k_eff = k + ky * lever(q, p, e) ** 2
    J = J_sw + J_w
    return J_sw, J_w, J, k, k_eff, math.sqrt(k / J) / (2 * math.pi), math.sqrt(k_eff / J) / (2 * math.pi)


def beta_eq10(sw):
    """Static twist-axis angle from seed eq. 10 with the modal axes at beta_b and beta_t."""
    ub = sw["bending"]["arm_m"] / sw["bending"]["stiffness_Nm_per_rad"]
    ut = sw["torsion"]["arm_m"] / sw["torsion"]["stiffness_Nm_per_rad"]
    bb, bt = math.radians(sw["bending"]["beta_deg"]), math.radians(sw["torsion"]["beta_deg"])
    beta = math.degrees(math.atan2(ub * math.sin(bb) + ut * math.sin(bt), ub * math.cos(bb) + ut * math.cos(bt)))
    utw = sw["twist"]["arm_m"] / sw["twist"]["stiffness_Nm_per_rad"]
    mag = math.hypot(ub * math.cos(bb) + ut * math.cos(bt), ub * math.sin(bb) + ut * math.sin(bt))
    eq7 = (sw["twist"]["arm_m"] ** 2 / sw["twist"]["stiffness_Nm_per_rad"],
           sw["bending"]["arm_m"] ** 2 / sw["bending"]["stiffness_Nm_per_rad"]
           + sw["torsion"]["arm_m"] ** 2 / sw["torsion"]["stiffness_Nm_per_rad"])
    # Modal-axis angle difference that would also satisfy the magnitude of eq. 8-9.
    cosd = (utw ** 2 - ub ** 2 - ut ** 2) / (2 * ub * ut)
    return beta, (eq7[1] / eq7[0] - 1), (mag / utw - 1), math.degrees(math.acos(max(-1, min(1, cosd))))


def fmt(v, n):
    return f"{v:.{n}f}"


def main():
    solve = "--solve" in sys.argv
    ok = True
    for name in ("supersport", "enduro"):
        sc = load_yaml(os.path.join(ROOT, "scenarios", name + ".yaml"))
        t6 = TABLE6[name]
        pr = t6["prec"]
        bs = bodies(sc)
        m, G, I = totals(bs)
        rows = [("mass_kg", m, t6["mass"], pr["mass"]),
                ("CoG x from rear contact (m)", G[0], t6["x"], pr["x"]),
                ("CoG height (m)", G[2], t6["h"], pr["h"]),
                ("roll  Ixx about CoG (kg m^2)", I[0][0], t6["Ixx"], pr["Ixx"]),
                ("pitch Iyy about CoG (kg m^2)", I[1][1], t6["Iyy"], pr["Iyy"]),
                ("yaw   Izz about CoG (kg m^2)", I[2][2], t6["Izz"], pr["Izz"]),
                ("product xz = -sum m x z (kg m^2)", I[0][2], t6["Ixz"], pr["Ixz"])]
        print(f"== {name}: whole vehicle + rider, design frame D, about the total CoG")
        print(f"   {'quantity':34s} {'model':>12s} {'Table 6':>9s}  match")
        for lab, got, want, n in rows:
            match = fmt(got, n) == fmt(want, n)
            ok &= match
            print(f"   {lab:34s} {got:12.5f} {fmt(want, n):>9s}  {'yes' if match else 'NO'}")
        print(f"   lateral terms: y_G = {G[1]:.2e} m, xy = {I[0][1]:.2e}, yz = {I[1][2]:.2e} kg m^2")
        print("   bodies (mass, com, principal moments about own CoM, PD + triangle inequality):")
        for bname, mi, c, Ii in bs:
            e, good = physical(Ii)
            ok &= good
            print(f"     {bname:12s} {mi:8.3f} kg  com [{c[0]:.4f}, {c[1]:.1f}, {c[2]:.4f}]  "
                  f"principal [{e[0]:.4f}, {e[1]:.4f}, {e[2]:.4f}]  {'ok' if good else 'VIOLATED'}")
        # Static loads, tyre relaxation lengths.
        W = m * sc["gravity_mps2"]
        Ff = W * G[0] / sc["geometry"]["wheelbase_m"]
        Fr = W - Ff
        print(f"   static loads: rear {Fr:.1f} N, front {Ff:.1f} N")
        for end, Fz in (("rear", Fr), ("front", Ff)):
            c = sc["contact"][end]
            ky = c["cornering_stiffness_per_rad"] * Fz / c["relaxation_length_m"]
            print(f"   {end} tyre: C_alpha = {c['cornering_stiffness_per_rad'] * Fz:.0f} N/rad, sigma = "
                  f"{c['relaxation_length_m']:.3f} m, lateral carcass stiffness C_alpha/sigma = {ky:.0f} N/m")
        # Swingarm axes (seed eq. 7, 10) and the 1-DOF modal estimate.
        sw = sc["swingarm"]
        beta, r7, r89, dreq = beta_eq10(sw)
        print(f"   eq. 10 with beta_b = {sw['bending']['beta_deg']}, beta_t = {sw['torsion']['beta_deg']} deg: "
              f"beta = {beta:.2f} deg (file: {sw['twist']['beta_deg']}); eq. 7 residual {r7:+.2%}; "
              f"eq. 8-9 magnitude residual {r89:+.2%} (zero if beta_b - beta_t = {dreq:.1f} deg)")
        P, fx, fy, fz, L = swingarm_frame(sc)
        incl = math.degrees(math.atan2(P[2] - sc["rear_wheel"]["radius_m"], P[0]))
        print(f"   swingarm: length {L:.4f} m, pivot {incl:.2f} deg above the rear hub")
        Fr_c = sc["contact"]["rear"]
        ky_r = Fr_c["cornering_stiffness_per_rad"] * Fr / Fr_c["relaxation_length_m"]
        for mode, target in zip(("bending", "torsion"), TARGET_HZ[name]):
            J_sw, J_w, J, k, k_eff, f, f_ty = one_dof(sc, mode, ky_r)
            print(f"   1-DOF {mode:8s}: J = {J_sw:.4f} (swingarm) + {J_w:.4f} (rear wheel) = {J:.4f} kg m^2, "
                  f"k = {k:.0f} N m/rad -> f = {f:.1f} Hz (paper {target:.0f} Hz); "
                  f"with the rear tyre's lateral spring {f_ty:.1f} Hz; df/dJ = {-f / (2 * J):.1f} Hz per kg m^2")
        J_sw, J_w, J, k, _, f, _ = one_dof(sc, "twist")
        print(f"   1-DOF twist   : J = {J:.4f} kg m^2, k = {k:.0f} N m/rad -> f = {f:.1f} Hz")
        if solve:
            for sign in (+1, -1):
                mr, cr, Ir = solve_rear_frame(sc, t6, sign)
                e, good = physical(Ir)
                print(f"   solved rear frame (Table 6 product read as xz = {sign * t6['Ixz']:+}): mass {mr:.4f} kg, "
                      f"com [{cr[0]:.5f}, 0, {cr[2]:.5f}], xx {Ir[0][0]:.4f}, yy {Ir[1][1]:.4f}, zz {Ir[2][2]:.4f}, "
                      f"xz {Ir[0][2]:.4f}; principal {[round(v, 3) for v in e]} {'ok' if good else 'VIOLATED'}")
        print()
    print("ALL CHECKS PASSED" if ok else "SOME CHECKS FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
