#!/usr/bin/env python3
"""Fundamental model of the cohesive interface (the paper's section 5.1, figs. 5-7).

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--variant full|partial] [--temperature T] [--name NAME]

Two flat shell plates, 1 mm thick, whose surfaces touch at t = 0. The lower plate (12 x 12 mm,
6 x 6 elements) is the master side and held in all degrees of freedom; the upper plate
(10 x 10 mm, 4 x 4 elements, a mesh that does not match the lower one) is the slave side and
moves by prescribed displacement: normal to the plates by the curve of the variant, and
tangentially at a constant 10 mm/s throughout. The law of *USER_INTERFACE_FRICTION acts
between them (*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID, as in the paper).

  full     pressed, pulled apart beyond full separation, pressed again (re-healing, beta from
           0 back up), pulled apart again (the second peak reflects the healed beta)
  partial  pressed, pulled to 2 g_c only, and brought back near contact: partial damage,
           final beta = omega / (C_N g_max^2) = 0.25

Writes OUTDIR/NAME.k (default NAME: fundamental or fundamental_partial) and OUTDIR/NAME.json
(the numbers plot.py needs). Units: mm, t, s, MPa, N, mJ (N mm).
"""

import json
import os
import sys

# --- Plates ----------------------------------------------------------------------------------
THICKNESS = 1.0  # both plates [mm]
E, NU, RHO = 2.0e5, 0.3, 7.85e-9  # steel [MPa], [-], [t/mm^3]
LOWER = (0.0, 12.0, 6)  # x and y from, to, elements
UPPER = (1.0, 11.0, 4)

# --- Interface law (*USER_INTERFACE_FRICTION, constants UC1..UC20 of docs/contact-law.md) ----
CN = 100.0  # cohesive stiffness C_N [MPa/mm]
SMAX_LO, SMAX_HI = 1.0, 0.5  # sigma_max at and below T_LO, at and above T_HI [MPa]
T_LO, T_HI = 100.0, 200.0  # transition [deg C]
ETA = 1.0e-9  # viscosity of the adhesion evolution [MPa mm s]: Lambda = eta v / (omega g_c) ~ 1e-3
ZETA = 120.0  # re-healing rate [1/(MPa s)]
MU = 0.2  # Coulomb coefficient
BETA_MIN = 1.0e-3

# --- Motion ----------------------------------------------------------------------------------
V_T = 10.0  # tangential velocity of the upper plate [mm/s]
PRESS = -2.5e-4  # normal displacement while pressed [mm]: about 0.9 MPa with the SOFT = 0 penalty
PULL = 0.5  # beyond full separation: the law's cut-off beta < BETA_MIN is reached at
#            g_c / sqrt(BETA_MIN) = 0.32 mm
G_C = SMAX_LO / CN  # opening at the peak (below T_LO)
PARTIAL = 2.0 * G_C  # g_max of the partial variant
CURVES = {
    # time [s], normal displacement of the upper plate [mm]
    # The pulls open slowly (16.7 mm/s) through the peak and the softening branch up to 5 g_c,
    # then fast to PULL.
    "full": [(0.0, 0.0), (0.002, PRESS), (0.004, PRESS), (0.007, 5 * G_C), (0.009, PULL),
             (0.011, PRESS), (0.015, PRESS), (0.018, 5 * G_C), (0.0195, PULL), (0.020, PULL)],
    "partial": [(0.0, 0.0), (0.002, PRESS), (0.004, PRESS), (0.0052, PARTIAL),
                (0.006, 0.1 * G_C), (0.008, 0.1 * G_C)],
}
OUTPUT_DT = 2.0e-6  # glstat, rcforc, nodout, cohesive.csv [s]: 0.003 g_c of opening


def card(*fields, width=10):
    out = []
    for f in fields:
        if isinstance(f, float):
            s = f"{f:.4g}" if abs(f) < 1e5 else f"{f:.3e}"
            out.append(s.rjust(width))
        else:
            out.append(str(f).rjust(width))
    return "".join(out) + "\n"


def grid(first_node, x0, x1, n, z):
    h = (x1 - x0) / n
    nodes = []
    for j in range(n + 1):
        for i in range(n + 1):
            nodes.append((first_node + j * (n + 1) + i, x0 + i * h, x0 + j * h, z))
    elems = []
    for j in range(n):
        for i in range(n):
            a = first_node + j * (n + 1) + i
            elems.append((a, a + 1, a + n + 2, a + n + 1))
    return nodes, elems


def deck(variant, temperature):
    lower_nodes, lower_elems = grid(1, *LOWER, 0.0)
    upper_nodes, upper_elems = grid(1001, *UPPER, THICKNESS)
    curve = CURVES[variant]
    end = curve[-1][0]
    k = ["*KEYWORD\n", "*TITLE\n", f"plyform fundamental model ({variant}, T = {temperature})\n"]
    k += ["*CONTROL_TERMINATION\n", card(end)]
    k += ["*CONTROL_TIMESTEP\n", card(0.0, 0.9)]
    k += ["*DATABASE_BINARY_D3PLOT\n", card(end / 20)]
    for name in ("GLSTAT", "RCFORC", "NODOUT"):
        k += [f"*DATABASE_{name}\n", card(OUTPUT_DT)]
    centre = 1001 + 2 * 5 + 2  # middle node of the upper plate
    k += ["*DATABASE_HISTORY_NODE\n", card(centre, 1001)]
    k += ["*PART\nlower plate (master)\n", card(1, 1, 1)]
    k += ["*PART\nupper plate (slave)\n", card(2, 1, 1)]
    k += ["*SECTION_SHELL\n", card(1, 2, 0.8333, 2), card(THICKNESS, THICKNESS, THICKNESS, THICKNESS)]
    k += ["*MAT_ELASTIC\n", card(1, RHO, E, NU)]
    k += ["*NODE\n"]
    for n, x, y, z in lower_nodes + upper_nodes:
        k.append(f"{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}\n")
    k += ["*ELEMENT_SHELL\n"]
    for e, q in enumerate(lower_elems, start=1):
        k.append(card(e, 1, *q, width=8))
    for e, q in enumerate(upper_elems, start=101):
        k.append(card(e, 2, *q, width=8))
    k += ["*SET_NODE_LIST_TITLE\nlower plate\n", card(1)]
    ids = [n for n, *_ in lower_nodes]
    k += [card(*ids[i:i + 8]) for i in range(0, len(ids), 8)]
    k += ["*SET_NODE_LIST_TITLE\nupper plate\n", card(2)]
    ids = [n for n, *_ in upper_nodes]
    k += [card(*ids[i:i + 8]) for i in range(0, len(ids), 8)]
    k += ["*BOUNDARY_SPC_SET\n", card(1, 0, 1, 1, 1, 1, 1, 1)]
    k += ["*BOUNDARY_SPC_SET\n", card(2, 0, 0, 1, 0, 1, 1, 1)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_SET\n", card(2, 3, 2, 1, 1.0)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_SET\n", card(2, 1, 0, 2, 1.0)]
    k += ["*DEFINE_CURVE_TITLE\nnormal displacement of the upper plate\n", card(1)]
    k += [f"{t:20.8g}{d:20.8g}\n" for t, d in curve]
    k += ["*DEFINE_CURVE_TITLE\ntangential velocity\n", card(2)]
    k += [f"{0.0:20.8g}{V_T:20.8g}\n", f"{end:20.8g}{V_T:20.8g}\n"]
    k += ["*INITIAL_TEMPERATURE_SET\n", card(2, float(temperature))]
    k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(1) + "".rjust(0)]
    k[-1] = card(1).rstrip("\n") + "lower-upper cohesive interface\n"
    k += [card(2, 1, 3, 3), card(0.0), card(1.0, 1.0)]
    uc = [1, CN, SMAX_LO, SMAX_HI, T_LO, T_HI, ETA, ZETA, ZETA, 1.0, 0.0, 0, MU, MU, 0.0, 0.0,
          0.0, 0.0, BETA_MIN, 0.0]
    k += ["*USER_INTERFACE_FRICTION\n", card(1, len(uc), 0)]
    uc = [float(v) if isinstance(v, float) else v for v in uc]
    k += [card(*uc[i:i + 8]) for i in range(0, len(uc), 8)]
    k += ["*END\n"]
    params = {
        "variant": variant, "temperature": temperature, "cn": CN, "smax_lo": SMAX_LO,
        "smax_hi": SMAX_HI, "t_lo": T_LO, "t_hi": T_HI, "eta": ETA, "zeta": ZETA, "mu": MU,
        "beta_min": BETA_MIN, "v_t": V_T, "curve": curve, "slave_area": (UPPER[1] - UPPER[0]) ** 2,
        "history_node": centre, "g_max_partial": PARTIAL, "interface": 1,
    }
    return "".join(k), params


def main(argv):
    outdir, variant, temperature, name = ".", "full", 20.0, None
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--variant":
            variant = args.pop(0)
        elif a == "--temperature":
            temperature = float(args.pop(0))
        elif a == "--name":
            name = args.pop(0)
        elif a.startswith("-"):
            sys.exit(f"generate.py: unknown option {a}")
        else:
            outdir = a
    if variant not in CURVES:
        sys.exit(f"generate.py: --variant must be one of {sorted(CURVES)}")
    name = name or ("fundamental" if variant == "full" else "fundamental_partial")
    os.makedirs(outdir, exist_ok=True)
    text, params = deck(variant, temperature)
    with open(os.path.join(outdir, name + ".k"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, name + ".json"), "w") as f:
        json.dump(params, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
