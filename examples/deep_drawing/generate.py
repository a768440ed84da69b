#!/usr/bin/env python3
"""Hot deep drawing of the paper's three-layer sandwich: steel 0.25 / woven carbon-PA6 1.00 /
steel 0.25 mm, each layer its own shell mesh, bonded by the cohesive law, heated above the
matrix's melt and drawn in colder tools with the temperatures computed (the paper's
section 5.3, figs. 11-14).

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--n N] [--core-n N] [--depth D] [--full]
                        [--interface two-way|one-way|tiebreak] [--skin-elform 16|2]
                        [--shell-bulk-viscosity]
                        [--set NAME=VALUE] [--end T] [--name NAME]

The tools are the square cup's (examples/square_cup: punch 70 mm square, die opening
74.47 mm, shoulder and nose radii 8 mm, blank holder over the flange; the tool meshes come
from that generator), the blank 150 mm square. Quarter model with symmetry on x = 0 and
y = 0, or with --full the whole blank and tools (mirrored meshes, no symmetry conditions).

- Skins: a low-carbon deep-drawing steel as `*MAT_ELASTIC_PLASTIC_THERMAL` (004): E, SIGY
  and ETAN tabulated from 20 to 400 C; Belytschko-Tsay shells with stiffness hourglass
  control (IHQ 4), NIP 5.
- Core: the woven carbon/PA6 ply of examples/materials/cf_pa6_woven_ply.k
  (`*MAT_REINFORCED_THERMOPLASTIC`, fibres along x and y), fully integrated shells
  (ELFORM 16: the molten ply carries almost nothing in shear, and a one-point shell's
  hourglass control would carry more than the ply), NIP 3, its mesh coarser than the skins'.
- Interfaces: each skin the slave of a one-way contact against the core with
  `*USER_INTERFACE_FRICTION` (the RCCM law), temperature dependent between T_LO and T_HI
  (the matrix's solidification and melt): weak adhesion and fast re-healing in the melt,
  strong adhesion and no healing when solid. --interface chooses how the layers are
  coupled (README: the paper's outlook):
    one-way  (default) the cohesive contacts alone (the paper's model); each keeps the
             core's nodes out of its skin too (its guard pass, docs/contact.md);
    two-way  the cohesive contacts plus a plain contact of the core's nodes against each
             skin (what this deck needed before the guard);
    tiebreak LS-DYNA's built-in *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK (OPTION 2,
             both ways) instead of the cohesive law.
- Heat: *CONTROL_SOLUTION 2; the blank starts at T_BLANK, the tools (rigid, not
  conducting: reservoirs) stay at T_TOOL; every contact carries heat (_THERMAL), the tools'
  with the gap conductance H_TOOL, the interfaces' with H_INTERFACE; friction heat (FRCENG 1)
  and the skins' plastic work (FWORK 0.9) heat the blank. The punch runs at SPEED, 100 times
  the press's 30 mm/s, and the thermal speed-up factor TSF = 100 gives the temperatures of the
  real, slower draw at each stroke (docs/thermal.md).

Writes OUTDIR/NAME.k and OUTDIR/NAME.json (the numbers check.py and plot.py need). Units: mm,
t, s, MPa, N, mJ, C.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import square_cup_tools as cup  # noqa: E402  (the square cup's tool set: examples/common)

card, ids, Mesh = cup.card, cup.ids, cup.Mesh
PLY_FILE = os.path.join(HERE, "..", "materials", "cf_pa6_woven_ply.k")
PLY_MID = 249

BLANK_HALF = cup.BLANK_HALF
HOLDER_FORCE = 20000.0  # N on the whole blank (the quarter model carries a quarter)
FRICTION = 0.15  # tools against the steel skins (hot, unlubricated: 0.1-0.2)
SPEED = 3000.0  # punch speed, mm/s (the press: 30 mm/s; TSF below)
TSF = 100.0  # thermal speed-up factor: SPEED / the press's speed

# Steel skins, *MAT_004 table (a DC04-like deep-drawing steel; handbook values):
STEEL_T = (20.0, 100.0, 200.0, 300.0, 400.0)
STEEL_E = (210000.0, 205000.0, 198000.0, 190000.0, 181000.0)
STEEL_ALPHA = (1.2e-5, 1.25e-5, 1.3e-5, 1.35e-5, 1.4e-5)
STEEL_SIGY = (180.0, 172.0, 163.0, 152.0, 138.0)
STEEL_ETAN = (800.0, 780.0, 750.0, 700.0, 640.0)
STEEL = {"rho": 7.85e-9, "nu": 0.3, "c": 4.6e8, "k": 50.0}  # c: mm^2/(s^2 K); k: N/(s K)
PLY_THERMAL = {"c": 1.2e9, "k": 2.0}  # carbon/PA6 ply: c 1200 J/(kg K), k about 2 W/(m K)

# Temperatures (C) and heat transfer coefficients (t/(s^3 K) = 1000 W/(m^2 K)).
T_BLANK, T_TOOL = 260.0, 80.0
H_TOOL = 3.0  # the tools' contact conductance, closed gap (3000 W/(m^2 K))
H_INTERFACE = 10.0  # a bonded interface: the matrix wets both sides
LMAX = 0.1  # gap (mm) beyond which no heat crosses a contact
LMIN_INTERFACE = 0.01  # gap (mm) up to which an interface counts as closed (a tied tiebreak node)

# The interface law (*USER_INTERFACE_FRICTION, docs/contact-law.md), between T_LO (the matrix
# solid) and T_HI (molten): sigma_max and zeta (re-healing) and mu at each end.
CN = 10.0  # MPa/mm: g_c = sigma_max / C_N (0.05 mm in the melt), omega = sigma_max^2 / C_N
CT = 10.0  # MPa/mm: the adhesive shear stiffness (mixed-mode damage)
SMAX_LO, SMAX_HI = 2.0, 0.5  # MPa
T_LO, T_HI = 200.0, 230.0
ZETA_LO, ZETA_HI = 0.0, 120.0  # 1/(MPa s): no healing in the solid, fast in the melt
MU_LO, MU_HI = 0.3, 0.2
ETA = 1.0e-9  # nearly rate free at these speeds
VDC = 10.0
TOOL_VDC = 20.0
HG_QM = 0.03  # the skins' stiffness hourglass control (IHQ 4) with --skin-elform 2
SKIN_ELFORM = 16  # the skins' shells: 16 fully integrated (default) or 2 Belytschko-Tsay
# --shell-bulk-viscosity: *CONTROL_BULK_VISCOSITY TYPE -2 (LS-DYNA's defaults Q1 1.5, Q2 0.06),
# the bulk viscosity in the shells' membrane too (docs/materials.md), its work booked.
SHELL_BULK = False
TUNABLE = ("HOLDER_FORCE", "FRICTION", "T_BLANK", "T_TOOL", "H_TOOL", "H_INTERFACE", "CN", "CT",
           "SMAX_LO", "SMAX_HI", "T_LO", "T_HI", "ZETA_LO", "ZETA_HI", "MU_LO", "MU_HI", "VDC",
           "HG_QM", "SPEED", "TSF")


def mirror_full(mesh):
    """The whole mesh from its quarter (x, y >= 0): four copies mirrored about x = 0 and y = 0,
    nodes on the planes shared, each copy's element orientation kept (a mirrored copy's
    node order is reversed so that its normals still point the same way). The first copy is
    the quarter itself with its ids unchanged."""
    full = Mesh(mesh.part, mesh.first)
    at = {}
    idmap = {}
    for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        local = {}
        for nid, x, y, z in mesh.nodes:
            key = (round(sx * x, 7), round(sy * y, 7), round(z, 7))
            if key not in at:
                at[key] = full.node(sx * x if x else 0.0, sy * y if y else 0.0, z)
            local[nid] = at[key]
        idmap[(sx, sy)] = local
        for a, b, c, d in mesh.elems:
            q = (local[a], local[b], local[c], local[d])
            full.elems.append(q if sx * sy > 0 else (q[0], q[3], q[2], q[1]))
    return full, idmap


def steel_cards():
    n = len(STEEL_T)
    pad = [""] * (8 - n)
    k = ["*MAT_ELASTIC_PLASTIC_THERMAL_TITLE\nsteel skins (DC04-like), 20-400 C\n",
         card(1, STEEL["rho"])]
    for row in (STEEL_T, STEEL_E, [STEEL["nu"]] * n, STEEL_ALPHA, STEEL_SIGY, STEEL_ETAN):
        k.append(card(*[float(v) for v in row], *pad))
    return k


def ply_cards():
    """The woven ply's keywords from the shipped material file (one source for its values)."""
    text = open(PLY_FILE).read()
    body = [line + "\n" for line in text.splitlines()
            if line.strip() and line.strip().upper() not in ("*KEYWORD", "*END")]
    return body


def interface_law_cards(cid):
    #     MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC MU_LO
    #     MU_HI VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
    uc = [1, CN, SMAX_LO, SMAX_HI, T_LO, T_HI, ETA, ZETA_LO, ZETA_HI, 1.0, 1.0e-3, 0, MU_LO,
          MU_HI, 0.0, 0.0, 0.0, VDC, 1.0e-3, CT]
    return ["*USER_INTERFACE_FRICTION\n", card(cid, len(uc), 0)] + ids(
        float(v) if isinstance(v, float) else v for v in uc)


def thermal_card(h, lmin=0.0):
    # K FRAD H0 LMIN LMAX FTOSA BC_FLG ALGO: h where the gap is closed (up to LMIN; a bonded
    # cohesive node always), nothing beyond LMIN (K = 0: no gas conduction), friction heat half
    # to each side.
    return card(0.0, 0.0, h, lmin, LMAX, 0.5, 0, 0)


def deck(n=40, core_n=None, depth=25.0, full=False, interface="one-way", end_time=None):
    hold_start, ramp = 0.2e-3, 1.0e-3
    end = hold_start + depth / SPEED + 0.5 * ramp
    core_n = core_n or max(2, round(n * 2 / 3))
    spec = [(1, "lower skin (steel)", 0.25, -0.625, n, 1),
            (2, "core (woven carbon/PA6)", 1.00, 0.0, core_n, PLY_MID),
            (3, "upper skin (steel)", 0.25, 0.625, n, 1)]
    sheets = []
    for part, title, t, z, ne, mid in spec:
        m, rows = cup.sheet(part, 100000 * part + 1, z, ne)
        sheets.append({"part": part, "title": title, "t": t, "z": z, "n": ne, "mid": mid,
                       "mesh": m, "rows": rows})
    ns = 2 * max(8, round(n * 0.8))
    tools = [cup.punch(1100001, 0.75, ns, depth + 5.0), cup.die(1200001, -0.75, ns, depth),
             cup.holder(1300001, 0.75, ns)]
    if full:
        for s in sheets:
            s["mesh"], _ = mirror_full(s["mesh"])
        tools = [mirror_full(t)[0] for t in tools]
    quarter = 0.25 if not full else 1.0

    k = ["*KEYWORD\n", "*TITLE\n",
         f"plyform hot deep drawing, steel / woven carbon-PA6 / steel, {interface} interfaces\n"]
    k += ["*CONTROL_TERMINATION\n", card(end_time or end)]
    # FRCENG 1: friction heats. PENOPT blank: the cohesive interfaces take the stiffer side's
    # penalty (docs/contact.md), the tools' contacts LS-DYNA's default.
    k += ["*CONTROL_CONTACT\n", card(0.1, 0.0, 0, 0, 0), card(0), card(0.0), card(0, 1)]
    k += ["*CONTROL_TIMESTEP\n", card(0.0, 0.9)]
    if SHELL_BULK:
        k += ["*CONTROL_BULK_VISCOSITY\n", card(1.5, 0.06, -2)]
    k += ["*CONTROL_SOLUTION\n", card(2)]
    #     ATYPE PTYPE SOLVER CGTOL GPT EQHEAT FWORK; card 2: TSF in columns 71-80
    k += ["*CONTROL_THERMAL_SOLVER\n", card(1, 0, 11, 0.0, 8, 1.0, 0.9),
          card(0, 0, 0.0, 0.0, 0.0, 0.0, 0.0, TSF)]
    # Backward Euler (no Crank-Nicolson ringing where a hot sheet meets a cold tool), a variable
    # step aiming at 2 degrees per step, up to 100 mechanical steps.
    k += ["*CONTROL_THERMAL_TIMESTEP\n", card(1, 1.0, 1.0e-7, 0.0, 0.0, 2.0)]
    k += ["*DATABASE_BINARY_D3PLOT\n", card(end / 20)]
    out_dt = end / 300
    for name in ("GLSTAT", "RCFORC", "NODOUT", "TPRINT"):
        k += [f"*DATABASE_{name}\n", card(out_dt)]
    # Histories: the upper skin's nodes along the diagonal and along the x axis (interface
    # history, temperatures), the core's corner and edge midpoints and the skins' (draw-in,
    # layer slip).
    up = sheets[2]["rows"]
    history = [up[i][i] for i in range(n + 1)] + [up[0][i] for i in range(1, n + 1)]
    for s in sheets:
        r, ne = s["rows"], s["n"]
        history += [r[0][ne], r[ne][0], r[ne][ne]]
    k += ["*DATABASE_HISTORY_NODE\n"] + ids(dict.fromkeys(history))
    k += ["*HOURGLASS\n", card(1, 4, HG_QM)]
    for s in sheets:
        skin = s["mid"] == 1
        elform = SKIN_ELFORM if skin else 16
        hgid = 1 if elform == 2 else 0  # the fully integrated shell has no hourglass modes
        k += [f"*PART\n{s['title']}\n",
              card(s["part"], s["part"], s["mid"], 0, hgid, 0, 0, 1 if skin else 2)]
        k += ["*SECTION_SHELL\n", card(s["part"], elform, 0.8333, 5 if skin else 3),
              card(*([s["t"]] * 4))]
    k += steel_cards() + ply_cards()
    k += ["*MAT_THERMAL_ISOTROPIC_TITLE\nsteel\n", card(1, 0.0), card(STEEL["c"], STEEL["k"])]
    k += ["*MAT_THERMAL_ISOTROPIC_TITLE\ncarbon/PA6 ply\n", card(2, 0.0),
          card(PLY_THERMAL["c"], PLY_THERMAL["k"])]
    k += cup.tool_cards()
    k += ["*NODE\n"]
    meshes = [s["mesh"] for s in sheets] + tools
    for mesh in meshes:
        for nid, x, y, z in mesh.nodes:
            k.append(f"{nid:8d}{x:16.8f}{y:16.8f}{z:16.8f}\n")
    k += ["*ELEMENT_SHELL\n"]
    for mesh in meshes:
        for i, (a, b, c, d) in enumerate(mesh.elems):
            k.append(card(mesh.first + i, mesh.part, a, b, c, d, width=8))
    blank_nodes = [nid for s in sheets for nid, *_ in s["mesh"].nodes]
    tool_nodes = [nid for t in tools for nid, *_ in t.nodes]
    k += ["*SET_NODE_LIST_TITLE\nthe blank\n", card(3)] + ids(blank_nodes)
    k += ["*SET_NODE_LIST_TITLE\nthe tools\n", card(4)] + ids(tool_nodes)
    k += ["*INITIAL_TEMPERATURE_SET\n", card(3, T_BLANK), card(4, T_TOOL)]
    if not full:
        on_x0 = [nid for s in sheets for nid, x, y, z in s["mesh"].nodes if x == 0.0]
        on_y0 = [nid for s in sheets for nid, x, y, z in s["mesh"].nodes if y == 0.0]
        k += ["*SET_NODE_LIST_TITLE\nsymmetry plane x = 0\n", card(1)] + ids(on_x0)
        k += ["*SET_NODE_LIST_TITLE\nsymmetry plane y = 0\n", card(2)] + ids(on_y0)
        k += ["*BOUNDARY_SPC_SET\n", card(1, 0, 1, 0, 0, 0, 1, 1)]
        k += ["*BOUNDARY_SPC_SET\n", card(2, 0, 0, 1, 0, 1, 0, 1)]
    k += ["*DEFINE_CURVE_TITLE\npunch travel (down)\n", card(2)]
    k += [f"{t + hold_start:20.10g}{-d:20.10g}\n"
          for t, d in cup.stroke_curve(end - hold_start, depth, ramp)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_RIGID\n", card(11, 3, 2, 2, 1.0)]
    k += ["*DEFINE_CURVE_TITLE\nblank-holder force\n", card(3)]
    k += [f"{0.0:20.10g}{0.0:20.10g}\n", f"{hold_start:20.10g}{1.0:20.10g}\n",
          f"{end * 2:20.10g}{1.0:20.10g}\n"]
    k += ["*LOAD_RIGID_BODY\n", card(13, 3, 3, -quarter * HOLDER_FORCE)]
    # The tools meet the blank's layers that can reach them (--tools-on, TOOL_SLAVES).
    tool_set = TOOL_SLAVES[TOOLS_ON]
    upper, lower = (("the upper skin", "the lower skin") if tool_set is None
                    else (f"the {TOOLS_ON}",) * 2)
    contacts = [(1, f"punch on {upper}", 3, 11), (2, f"holder on {upper}", 3, 13),
                (3, f"die under {lower}", 1, 12)]
    if tool_set is not None:
        k += ["*SET_PART_LIST_TITLE\nthe layers the tools meet\n", card(5)] + ids(tool_set)
    for cid, title, slave, master in contacts:
        k += ["*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_THERMAL_ID\n",
              card(cid).rstrip("\n") + title + "\n"]
        slave, sstyp = (slave, 3) if tool_set is None else (5, 2)
        k += [card(slave, master, sstyp, 3), card(FRICTION, FRICTION, 0.0, 0.0, TOOL_VDC),
              card(1.0, 1.0), thermal_card(H_TOOL)]
    interfaces = [(4, "upper skin on the core", 3), (5, "lower skin on the core", 1)]
    if interface == "tiebreak":
        # Tied where the layers touch at t = 0, failing on (p / NFLS)^2 + (tau / SFLS)^2 >= 1
        # at the melt's strength; after failure penalty contact with Coulomb friction.
        for cid, title, slave in interfaces:
            k += ["*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK_THERMAL_ID\n",
                  card(cid).rstrip("\n") + title + "\n"]
            k += [card(slave, 2, 3, 3), card(MU_HI, MU_HI, 0.0, 0.0, VDC), card(1.0, 1.0),
                  card(2, SMAX_HI, SMAX_HI), thermal_card(H_INTERFACE, LMIN_INTERFACE)]
    else:
        for cid, title, slave in interfaces:
            k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_THERMAL_ID\n",
                  card(cid).rstrip("\n") + title + "\n"]
            k += [card(slave, 2, 3, 3), card(0.0), card(1.0, 1.0),
                  thermal_card(H_INTERFACE, LMIN_INTERFACE)]
            k += interface_law_cards(cid)
    if interface == "two-way":
        # The core's nodes against each skin, frictionless (the cohesive contact carries the
        # friction); PENOPT 1 takes the smaller side's penalty, the ply's, which counts its
        # fibres' stiffness and is about the skins'.
        for cid, title, master in ((6, "core under the upper skin", 3),
                                   (7, "core on the lower skin", 1)):
            k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n",
                  card(cid).rstrip("\n") + title + "\n"]
            k += [card(2, master, 3, 3), card(0.0, 0.0, 0.0, 0.0, 0.0), card(1.0, 1.0)]
    k += ["*END\n"]

    def node_xy(s, i, j):
        return s["rows"][j][i]

    params = {
        "n": n, "core_n": core_n, "depth": depth, "speed": SPEED, "end": end_time or end,
        "stroke_end": end, "hold_start": hold_start, "ramp": ramp, "full": full,
        "model_fraction": quarter, "interface": interface, "blank_half": BLANK_HALF,
        "holder_force_model": quarter * HOLDER_FORCE, "t_blank": T_BLANK, "t_tool": T_TOOL,
        "t_lo": T_LO, "t_hi": T_HI, "smax_lo": SMAX_LO, "smax_hi": SMAX_HI,
        "diagonal": [up[i][i] for i in range(n + 1)],
        "axis": [up[0][i] for i in range(n + 1)],
        "edge_x": [node_xy(s, s["n"], 0) for s in sheets],
        "edge_y": [node_xy(s, 0, s["n"]) for s in sheets],
        "corner": [node_xy(s, s["n"], s["n"]) for s in sheets],
        "parts": {s["part"]: s["title"] for s in sheets}, "tool_contacts": [1, 2, 3],
        "interfaces": [4, 5], "skins": [1, 3], "core": 2,
    }
    return "".join(k), params


# The layers each tool's contact takes as its slave side: "outer" (the punch and the holder the
# upper skin, the die the lower: the paper's deck), or a part set of the "skins" (the default)
# or of the "blank" (every layer), as a forming contact is given the blank's parts. Where the
# layers slip, the lower skin's edge strip comes out beyond the core's and the upper skin's
# edges under the holder; only a contact that takes it keeps it under the holder's face.
TOOL_SLAVES = {"outer": None, "skins": (1, 3), "blank": (1, 2, 3)}
TOOLS_ON = "skins"


def main(argv):
    ap = argparse.ArgumentParser(prog="generate.py", description=__doc__.splitlines()[0])
    ap.add_argument("outdir", nargs="?", default=".")
    ap.add_argument("--n", type=int, default=40, help="skin elements along the quarter's edge")
    ap.add_argument("--core-n", type=int, default=None, help="core elements (default 2/3 n)")
    ap.add_argument("--depth", type=float, default=25.0, help="punch travel (mm)")
    ap.add_argument("--full", action="store_true", help="the whole blank and tools")
    ap.add_argument("--interface", choices=("two-way", "one-way", "tiebreak"), default="one-way")
    ap.add_argument("--skin-elform", type=int, choices=(2, 16), default=SKIN_ELFORM)
    ap.add_argument("--end", type=float, default=None, help="end time (default: the stroke's)")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help=f"one of {', '.join(TUNABLE)}")
    ap.add_argument("--shell-bulk-viscosity", action="store_true",
                    help="*CONTROL_BULK_VISCOSITY TYPE -2: bulk viscosity in the shells too")
    ap.add_argument("--tools-on", choices=sorted(TOOL_SLAVES), default=TOOLS_ON,
                    help="the layers the tools' contacts take (see TOOL_SLAVES)")
    ap.add_argument("--name", default=None)
    a = ap.parse_args(argv)
    globals()["TOOLS_ON"] = a.tools_on
    for item in a.set:
        key, _, value = item.partition("=")
        if key not in TUNABLE or not value:
            ap.error(f"--set takes NAME=VALUE with NAME one of {', '.join(TUNABLE)}")
        globals()[key] = float(value)
    globals()["SKIN_ELFORM"] = a.skin_elform
    globals()["SHELL_BULK"] = a.shell_bulk_viscosity
    if a.n < 4 or a.n % 2:
        ap.error("--n is an even number of at least 4")
    outdir, name, n, core_n, depth, full, interface, end_time = (
        a.outdir, a.name, a.n, a.core_n, a.depth, a.full, a.interface, a.end)
    cup.write_deck(outdir, name or "deep_drawing", *deck(n, core_n, depth, full, interface,
                                                       end_time))


if __name__ == "__main__":
    main(sys.argv[1:])
