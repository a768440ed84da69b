#!/usr/bin/env python3
"""Double cantilever beam (mode I) of two shell arms bonded by the cohesive interface law.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--dx DX] [--ny NY] [--end T] [--every D] [--ihq N]
                        [--soften F] [--width B] [--elform N] [--nu NU] [--length L]
                        [--name NAME]

Two elastic shell arms (each its own mesh, 1.5 mm thick, 100 mm long, B = 20 mm wide) whose
surfaces touch at t = 0; the upper arm is the slave side of *CONTACT_ONE_WAY_SURFACE_TO_SURFACE
with the law of *USER_INTERFACE_FRICTION, its nodes beyond the starter crack a0 = 30 mm initially
bonded (the slave side is the segment set of the upper arm's elements beyond a0). The tips
(x = 0) are pulled apart by prescribed displacements, slowly (many periods of the arms), up to
a total opening DELTA. Elements DX long along the arms, NY across the width (NY = 1: a strip
one element wide). --soften F divides C_N by F and sigma_max by sqrt(F): the same G_Ic with a
cohesive zone F^(1/4) times longer (resolved by coarser elements). --ihq 0: the parts take the
deck's default (viscous) hourglass control. --width B: the specimen's width (20 mm). --elform N:
the arms' shell formulation (2, Belytschko-Tsay, by default; 16, fully integrated). --length L:
the arms' length (100 mm; a run stopped early needs only some 10 mm of bonded ligament beyond
the crack's reach, 1/lambda being 1.6 mm).
Poisson's ratio 0 by default (--nu NU; the arms bend in plane strain across the width,
README.md).

Writes OUTDIR/NAME.k and OUTDIR/NAME.json (the numbers check.py needs). Units: mm, t, s, MPa,
N, mJ (N mm).
"""

import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from deck_cards import card, ids  # noqa: E402

LENGTH, WIDTH, THICKNESS, A0 = 100.0, 20.0, 1.5, 30.0
E, NU, RHO = 135000.0, 0.0, 1.5e-9
# Interface: G_Ic = omega = sigma_max^2 / C_N = 0.28 N/mm.
CN, SMAX = 11600.0, 57.0
# The bonded layer resists shear as well (C_T = C_N): without it the upper arm, held by the
# interface alone, would be free to slide along the lower one.
ETA = 1.0e-7  # adhesion viscosity [MPa mm s]: Lambda = eta v / (omega g_c) ~ 1e-4 (rate independent)
VDC = 20.0
BETA_MIN = 1.0e-3
DELTA = 8.6  # total tip opening [mm]
END = 14.0e-3  # [s]
RAMP = 1.0e-3  # the tip velocity rises smoothly over this time [s]
HG_QM = 0.1  # stiffness hourglass control (IHQ 4): the arms' zero-energy modes must resist the
#              interface's nodal forces, which a viscous form (IHQ 1) cannot do at rest


def arm(first_node, first_elem, part, nx, ny, z, width, length):
    nodes, elems = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes.append((first_node + j * (nx + 1) + i, length * i / nx, width * j / ny, z))
    for j in range(ny):
        for i in range(nx):
            a = first_node + j * (nx + 1) + i
            elems.append((first_elem + j * nx + i, part, a, a + 1, a + nx + 2, a + nx + 1, i))
    return nodes, elems


def tip_curve(end, delta, ramp):
    """Displacement of one tip: the velocity rises as a half cosine over `ramp`, then stays."""
    import math
    v = 0.5 * delta / (end - 0.5 * ramp)
    pts = []
    for k in range(21):
        t = ramp * k / 20
        pts.append((t, v * (0.5 * t - 0.5 * ramp / math.pi * math.sin(math.pi * t / ramp))))
    pts.append((end, v * (end - 0.5 * ramp)))
    return pts, v


def deck(dx, ny, end, delta, every=5.0, ihq=4, soften=1.0, width=WIDTH, elform=2, nu=NU,
         length=LENGTH):
    cn, smax = CN / soften, SMAX / soften ** 0.5  # the same omega = G_Ic
    nx = round(length / dx)
    lower_nodes, lower_elems = arm(1, 1, 1, nx, ny, -0.5 * THICKNESS, width, length)
    upper_nodes, upper_elems = arm(100001, 100001, 2, nx, ny, 0.5 * THICKNESS, width, length)
    curve, v_tip = tip_curve(end, delta, min(RAMP, 0.25 * end))
    k = ["*KEYWORD\n", "*TITLE\n", f"plyform DCB (dx {dx}, {ny} across)\n"]
    k += ["*CONTROL_TERMINATION\n", card(end)]
    k += ["*CONTROL_TIMESTEP\n", card(0.0, 0.9)]
    k += ["*DATABASE_BINARY_D3PLOT\n", card(end / 14)]
    out_dt = END / 700  # the same instants for any end time
    for name in ("GLSTAT", "RCFORC", "NODOUT", "BNDOUT"):
        k += [f"*DATABASE_{name}\n", card(out_dt)]
    tip_upper = upper_nodes[0][0]
    tip_lower = lower_nodes[0][0]
    # Upper-arm nodes along the crack path (first row), every 5 mm from a0: cohesive.csv.
    step = max(1, round(every / dx))
    path = [upper_nodes[i][0] for i in range(round(A0 / dx), nx + 1, step)]
    k += ["*DATABASE_HISTORY_NODE\n"] + ids([tip_upper, tip_lower] + path)
    hgid = 1 if ihq and elform != 16 else 0  # ELFORM 16 has no zero-energy modes to control
    k += ["*PART\nlower arm (master)\n", card(1, 1, 1, 0, hgid)]
    k += ["*PART\nupper arm (slave)\n", card(2, 1, 1, 0, hgid)]
    if ihq and elform != 16:
        k += ["*HOURGLASS\n", card(1, ihq, HG_QM)]
    k += ["*SECTION_SHELL\n", card(1, elform, 0.8333, 3), card(*([THICKNESS] * 4))]
    k += ["*MAT_ELASTIC\n", card(1, RHO, E, nu)]
    k += ["*NODE\n"]
    for n, x, y, z in lower_nodes + upper_nodes:
        k.append(f"{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}\n")
    k += ["*ELEMENT_SHELL\n"]
    for e, p, a, b, c, d, _ in lower_elems + upper_elems:
        k.append(card(e, p, a, b, c, d, width=8))
    # Slave side: the upper arm's segments beyond the starter crack (the bonded ligament).
    k += ["*SET_SEGMENT_TITLE\nbonded ligament\n", card(1)]
    for e, p, a, b, c, d, i in upper_elems:
        if (i + 0.5) * dx > A0:
            k.append(card(a, b, c, d))
    tips = lambda nodes: [n for n, x, *_ in nodes if x == 0.0]
    far = [n for n, x, *_ in lower_nodes if abs(x - length) < 1e-9]
    k += ["*SET_NODE_LIST_TITLE\nupper tip\n", card(1)] + ids(tips(upper_nodes))
    k += ["*SET_NODE_LIST_TITLE\nlower tip\n", card(2)] + ids(tips(lower_nodes))
    k += ["*SET_NODE_LIST_TITLE\nfar end of the lower arm\n", card(3)] + ids(far)
    k += ["*SET_NODE_LIST_TITLE\nall nodes\n", card(4)]
    k += ids([n for n, *_ in lower_nodes + upper_nodes])
    # In-plane (x-z) problem: y, and the rotations about x and z, held everywhere; x held at
    # the far end of the lower arm (the rigid-body motion along the arms).
    k += ["*BOUNDARY_SPC_SET\n", card(4, 0, 0, 1, 0, 1, 0, 1)]
    k += ["*BOUNDARY_SPC_SET\n", card(3, 0, 1, 0, 0, 0, 0, 0)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_SET\n", card(1, 3, 2, 1, 1.0)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_SET\n", card(2, 3, 2, 1, -1.0)]
    k += ["*DEFINE_CURVE_TITLE\nopening of one tip\n", card(1)]
    k += [f"{t:20.10g}{d:20.10g}\n" for t, d in curve]
    k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n"]
    k += [card(1).rstrip("\n") + "mode I interface\n"]
    k += [card(1, 1, 0, 3), card(0.0), card(1.0, 1.0)]
    #      MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC MU_LO MU_HI
    #      VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
    uc = [1, cn, smax, smax, 0.0, 0.0, ETA, 0.0, 0.0, 1.0, 1.0e-3, 0, 0.0, 0.0, 0.0, 0.0,
          0.0, VDC, BETA_MIN, cn]
    k += ["*USER_INTERFACE_FRICTION\n", card(1, len(uc), 0)]
    k += ids(float(v) if isinstance(v, float) else v for v in uc)
    k += ["*END\n"]
    params = {
        "length": length, "width": width, "thickness": THICKNESS, "a0": A0, "E": E, "nu": nu,
        "rho": RHO, "cn": cn, "sigma_max": smax, "eta": ETA, "vdc": VDC, "delta": delta,
        "end": end, "ramp": RAMP, "elform": elform, "v_tip": v_tip, "dx": dx, "ny": ny, "interface": 1,
        "tip_upper": tip_upper, "tip_lower": tip_lower, "path_nodes": path,
        "tip_upper_nodes": [n for n, x, *_ in upper_nodes if x == 0.0],
    }
    return "".join(k), params


def main(argv):
    outdir, dx, ny, end, name, every, ihq, soften = ".", 0.5, 1, END, "dcb", 5.0, 4, 1.0
    elform, nu = 2, NU
    width, length = WIDTH, LENGTH
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--dx":
            dx = float(args.pop(0))
        elif a == "--ny":
            ny = int(args.pop(0))
        elif a == "--end":
            end = float(args.pop(0))
        elif a == "--width":
            width = float(args.pop(0))
        elif a == "--length":
            length = float(args.pop(0))
        elif a == "--soften":
            soften = float(args.pop(0))
        elif a == "--ihq":
            ihq = int(args.pop(0))
        elif a == "--elform":
            elform = int(args.pop(0))
            if elform not in (2, 16):
                sys.exit("generate.py: --elform takes 2 (Belytschko-Tsay) or 16 (fully integrated)")
        elif a == "--nu":
            nu = float(args.pop(0))
        elif a == "--every":
            every = float(args.pop(0))
        elif a == "--name":
            name = args.pop(0)
        elif a.startswith("-"):
            sys.exit(f"generate.py: unknown option {a}")
        else:
            outdir = a
    os.makedirs(outdir, exist_ok=True)
    text, params = deck(dx, ny, end, DELTA * end / END, every, ihq, soften, width, elform, nu,
                        length)
    with open(os.path.join(outdir, name + ".k"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, name + ".json"), "w") as f:
        json.dump(params, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
