#!/usr/bin/env python3
"""Square-cup deep drawing of a single aluminium sheet or of a three-layer bonded sandwich.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--layers 1|3] [--n N] [--depth D] [--speed V]
                        [--dt2ms DT] [--elform 2|16] [--plain] [--slave skin|core] [--backup]
                        [--tools-on skins|outer|blank] [--yield j2|barlat|hill] [--name NAME]

The tool set follows the square-cup benchmark of NUMISHEET'93 (punch 70 mm square, blank
150 mm square; the radii and the blank-holder force below): a rigid punch (moving down, its
travel prescribed), a fixed rigid die with an opening and a shoulder radius, and a rigid blank
holder pressed onto the flange by a force. Quarter model (x, y >= 0) with symmetry on the
planes x = 0 and y = 0. Each layer of the blank is its own shell mesh:

- `--layers 1`: one 0.81 mm aluminium sheet.
- `--layers 3`: aluminium 0.25 mm / soft elastic core 1.00 mm / aluminium 0.25 mm, the core's
  mesh coarser than the skins', both interfaces initially bonded by the cohesive law
  (*USER_INTERFACE_FRICTION: C_N 100 MPa/mm, sigma_max 1 MPa, mu 0.2, VDC 10 %), the core the
  master side of each.

The tools touch the blank through *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE (the tool meshes
are the tools' surfaces): a single sheet, or both skins of the sandwich as a part set
(--tools-on outer: the upper skin for the punch and the holder, the lower for the die, as the
paper's deck has them; --tools-on blank: every layer). --n N: elements along the quarter blank's edge (the
core takes 2/3 of it). --depth D: punch travel (mm). --speed V: punch speed (mm/s).
--dt2ms DT: mass scaling to the time step DT (0: none). --elform 16: the blank's shells fully
integrated (no hourglass modes, so no *HOURGLASS on them) instead of Belytschko-Tsay.
--yield barlat|hill: the aluminium with the benchmark's Lankford ratios (R00 0.71, R45 0.58,
R90 0.70) as Barlat 89 (M 8, *MAT_3-PARAMETER_BARLAT) or Hill 1948 (*MAT_HILL_3R), rolled
along x; j2 (the default) is isotropic (*MAT_PIECEWISE_LINEAR_PLASTICITY).
--plain: the deck as a user writes it: every setting the solver leaves to its defaults (no
*HOURGLASS: the viscous default; the shipped deck sets only the stiffness form, IHQ 4, which
`plyform check` asks for on one-point shells under a cohesive interface). --backup: PENOPT 3
and two plain contacts of the core's nodes against the skins (what the decks carried before
issue 29; for comparison only). --slave core: the core is the slave side of both cohesive
contacts (the skins are by default).

Writes OUTDIR/NAME.k and OUTDIR/NAME.json (the numbers check.py needs). Units: mm, t, s, MPa,
N, mJ (N mm).
"""

import os
import sys

# The tool set (geometry, meshes, the tools' cards) is shared with the other forming examples.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from square_cup_tools import (BLANK_HALF, card, die, holder, ids, punch, sheet,  # noqa: E402
                              stroke_curve, tool_cards, write_deck)

HOLDER_FORCE = 19600.0  # N on the whole blank; the quarter model carries a quarter of it
FRICTION = 0.162  # tools against the aluminium

# Aluminium (the benchmark's hardening law: sigma_y = K (EPS0 + eps_p)^N, and its Lankford
# ratios R00, R45, R90, which --yield barlat|hill uses; the rolling direction along x).
AL = {"rho": 2.7e-9, "E": 71000.0, "nu": 0.33, "K": 576.79, "eps0": 0.01658, "n": 0.3593,
      "r00": 0.71, "r45": 0.58, "r90": 0.70}
CORE = {"rho": 1.2e-9, "nu": 0.35}  # a soft polymer core
CORE_E = 1500.0

# Cohesive interfaces (three-layer blank): omega = sigma_max^2 / C_N = 0.01 mJ/mm^2.
CN, SMAX, MU, VDC = 100.0, 1.0, 0.2, 10.0
ETA, ZETA = 1.0e-9, 120.0  # Lambda = eta v / (omega g_c) ~ 3e-2 at 3 m/s: nearly rate free
HG_QM = 0.03  # stiffness hourglass control (IHQ 4) of the blank's layers (0.1 stiffens the draw by 2 %)
TOOL_VDC = 20.0  # normal damping of the tool contacts, percent of critical
# Constants that --set NAME=VALUE may change (studies of the model's sensitivity).
TUNABLE = ("CN", "SMAX", "MU", "VDC", "ETA", "ZETA", "HG_QM", "TOOL_VDC", "FRICTION",
           "HOLDER_FORCE", "CORE_E")


def deck(layers=3, n=30, depth=30.0, speed=3000.0, dt2ms=0.0, core_n=None, end_time=None):
    hold_start = 0.2e-3  # the holder force rises over this time before the punch moves
    ramp = 1.0e-3
    end = hold_start + depth / speed + 0.5 * ramp
    if layers == 1:
        spec = [(1, "aluminium sheet", 0.81, 0.0, n, "al")]
    else:
        spec = [(1, "lower skin (aluminium)", 0.25, -0.625, n, "al"),
                (2, "core", 1.00, 0.0, core_n or max(2, round(n * 2 / 3)), "core"),
                (3, "upper skin (aluminium)", 0.25, 0.625, n, "al")]
    half = 0.5 * sum(s[2] for s in spec)
    sheets = []
    for part, title, t, z, ne, mat in spec:
        m, rows = sheet(part, 100000 * part + 1, z, ne)
        sheets.append((part, title, t, z, ne, mat, m, rows))
    ns = 2 * max(8, round(n * 0.8))  # tool elements along a quarter contour
    tools = [punch(1100001, half, ns, depth + 5.0), die(1200001, -half, ns, depth),
             holder(1300001, half, ns)]

    k = ["*KEYWORD\n", "*TITLE\n", f"plyform square cup ({layers} layer{'s' if layers > 1 else ''},"
         f" {n} elements along the quarter's edge)\n"]
    k += ["*CONTROL_TERMINATION\n", card(end_time or end)]
    # --backup (for comparison only, see below): PENOPT 3, every contact's
    # penalty from its slave side.
    if BACKUP:
        k += ["*CONTROL_CONTACT\n", card(0.1, 0.0, 0, 0, 3)]
    k += ["*CONTROL_TIMESTEP\n", card(0.0, 0.9, 0, 0.0, -dt2ms if dt2ms > 0 else 0.0)]
    k += ["*DATABASE_BINARY_D3PLOT\n", card(end / 15)]
    out_dt = end / 400
    for name in ("GLSTAT", "RCFORC", "NODOUT"):
        k += [f"*DATABASE_{name}\n", card(out_dt)]
    # History: the blank's edge midpoints (draw-in along x and y) and its corner (diagonal), in
    # every layer, and the centre.
    history = []
    for part, title, t, z, ne, mat, m, rows in sheets:
        history += [rows[0][ne], rows[ne][0], rows[ne][ne], rows[0][0]]
    k += ["*DATABASE_HISTORY_NODE\n"] + ids(history)
    # IHQ 4 (stiffness): the interfaces act on single nodes, which a one-point shell's
    # zero-energy modes must resist at rest; the viscous default cannot (`plyform check` warns).
    if not PLAIN:
        k += ["*HOURGLASS\n", card(1, 4, HG_QM)]
    for part, title, t, z, ne, mat, m, rows in sheets:
        hgid = 0 if ELFORM == 16 or PLAIN else 1
        k += [f"*PART\n{title}\n", card(part, part, 1 if mat == "al" else 2, 0, hgid)]
        k += ["*SECTION_SHELL\n", card(part, ELFORM, 0.8333, 5 if mat == "al" else 3),
              card(*([t] * 4))]
    k += aluminium_cards()
    k += ["*MAT_ELASTIC_TITLE\ncore\n", card(2, CORE["rho"], CORE_E, CORE["nu"])]
    k += tool_cards()
    k += ["*NODE\n"]
    for mesh in [s[6] for s in sheets] + tools:
        for nid, x, y, z in mesh.nodes:
            k.append(f"{nid:8d}{x:16.8f}{y:16.8f}{z:16.8f}\n")
    k += ["*ELEMENT_SHELL\n"]
    for mesh in [s[6] for s in sheets] + tools:
        for i, (a, b, c, d) in enumerate(mesh.elems):
            k.append(card(mesh.first + i, mesh.part, a, b, c, d, width=8))
    # Symmetry planes: x = 0 (u_x, rotations about y and z) and y = 0 (u_y, about x and z).
    on_x0 = [nid for s in sheets for nid, x, y, z in s[6].nodes if x == 0.0]
    on_y0 = [nid for s in sheets for nid, x, y, z in s[6].nodes if y == 0.0]
    k += ["*SET_NODE_LIST_TITLE\nsymmetry plane x = 0\n", card(1)] + ids(on_x0)
    k += ["*SET_NODE_LIST_TITLE\nsymmetry plane y = 0\n", card(2)] + ids(on_y0)
    k += ["*BOUNDARY_SPC_SET\n", card(1, 0, 1, 0, 0, 0, 1, 1)]
    k += ["*BOUNDARY_SPC_SET\n", card(2, 0, 0, 1, 0, 1, 0, 1)]
    k += ["*DEFINE_CURVE_TITLE\npunch travel (down)\n", card(2)]
    k += [f"{t + hold_start:20.10g}{-d:20.10g}\n" for t, d in stroke_curve(end - hold_start, depth, ramp)]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_RIGID\n", card(11, 3, 2, 2, 1.0)]
    k += ["*DEFINE_CURVE_TITLE\nblank-holder force (quarter)\n", card(3)]
    k += [f"{0.0:20.10g}{0.0:20.10g}\n", f"{hold_start:20.10g}{1.0:20.10g}\n",
          f"{end * 2:20.10g}{1.0:20.10g}\n"]
    k += ["*LOAD_RIGID_BODY\n", card(13, 3, 3, -0.25 * HOLDER_FORCE)]
    top, bottom = sheets[-1][0], sheets[0][0]
    # The tools meet the layers that can reach them (TOOLS_ON): with three layers, by default
    # both skins, as a part set.
    tool_set = TOOL_SLAVES[TOOLS_ON] if layers == 3 else None
    upper, lower = ("the upper surface", "the lower surface") if tool_set is None else (
        (f"the {TOOLS_ON}",) * 2)
    contacts = [(1, f"punch on {upper}", top, 11), (2, f"holder on {upper}", top, 13),
                (3, f"die under {lower}", bottom, 12)]
    if tool_set is not None:
        k += ["*SET_PART_LIST_TITLE\nthe layers the tools meet\n", card(5)] + ids(tool_set)
    for cid, title, slave, master in contacts:
        slave, sstyp = (slave, 3) if tool_set is None else (5, 2)
        k += ["*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(cid).rstrip("\n") + title + "\n"]
        k += [card(slave, master, sstyp, 3), card(FRICTION, FRICTION, 0.0, 0.0, TOOL_VDC),
              card(1.0, 1.0)]
    if layers == 3:
        for cid, title, skin in ((4, "upper skin on the core", 3), (5, "lower skin on the core", 1)):
            # --slave core: the core is the slave side of both (a user's other choice).
            slave, master = (2, skin) if SLAVE == "core" else (skin, 2)
            k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(cid).rstrip("\n") + title + "\n"]
            k += [card(slave, master, 3, 3), card(0.0), card(1.0, 1.0)]
            #     MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC MU_LO
            #     MU_HI VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
            uc = [1, CN, SMAX, SMAX, 0.0, 0.0, ETA, ZETA, ZETA, 1.0, 1.0e-3, 0, MU, MU, 0.0, 0.0,
                  0.0, VDC, 1.0e-3, CN]
            k += ["*USER_INTERFACE_FRICTION\n", card(cid, len(uc), 0)]
            k += ids(float(v) if isinstance(v, float) else v for v in uc)
        # The cohesive contacts are one way: skin nodes against core segments, and each keeps
        # the core's nodes out of its skin by its guard pass; with PENOPT blank each takes the
        # stiffer side's penalty (docs/contact.md). Nothing else holds the layers. --backup
        # adds what the deck carried before (PENOPT 3 and a plain, frictionless contact of the
        # core's nodes against each skin, the core's penalty scaled by SFS to about the skin's):
        # no shipped deck needs it (README.md says what the restart tests' n 10 deck needed).
        sfs = 1969.0 / (0.1 * CORE_E / (3 * (1 - 2 * CORE["nu"])) / (BLANK_HALF / n * 2 ** 0.5))
        backup = ((6, "core under the upper skin", 3), (7, "core on the lower skin", 1)) if BACKUP else ()
        for cid, title, master in backup:
            k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(cid).rstrip("\n") + title + "\n"]
            k += [card(2, master, 3, 3), card(0.0, 0.0, 0.0, 0.0, 0.0), card(round(sfs, 1), 1.0)]
    k += ["*END\n"]
    params = {
        "layers": layers, "n": n, "depth": depth, "speed": speed, "end": end,
        "hold_start": hold_start, "ramp": ramp, "holder_force_quarter": 0.25 * HOLDER_FORCE,
        "blank_half": BLANK_HALF, "dt2ms": dt2ms,
        "edge_x": [s[7][0][s[4]] for s in sheets], "edge_y": [s[7][s[4]][0] for s in sheets],
        "corner": [s[7][s[4]][s[4]] for s in sheets],
        "parts": {s[0]: s[1] for s in sheets}, "tool_contacts": [1, 2, 3],
        "interfaces": [4, 5] if layers == 3 else [],
    }
    return "".join(k), params


def aluminium_cards():
    """The aluminium's material: J2 with the hardening curve (*MAT_024), or with --yield the
    benchmark's anisotropy, Barlat 89 with M 8 (*MAT_036) or Hill 1948 (*MAT_122), both with the
    Swift law (HR 2) of the same curve and the rolling direction along x (AOPT 2)."""
    swift = (AL["K"], AL["n"])
    axes = [card(2.0), card(0.0, 0.0, 0.0, 1.0, 0.0, 0.0), card(0.0, 0.0, 0.0, 0.0, 0.0, 1.0)]
    if YIELD == "barlat":
        return (["*MAT_3-PARAMETER_BARLAT_TITLE\naluminium (NUMISHEET'93, Barlat 89)\n",
                 card(1, AL["rho"], AL["E"], AL["nu"], 2.0, *swift, 0.0),
                 card(8.0, AL["r00"], AL["r45"], AL["r90"], 0, AL["eps0"], 0.0, 0.0)] + axes[:2]
                + [card(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)])
    if YIELD == "hill":
        return (["*MAT_HILL_3R_TITLE\naluminium (NUMISHEET'93, Hill 1948)\n",
                 card(1, AL["rho"], AL["E"], AL["nu"], 2.0, *swift),
                 card(AL["r00"], AL["r45"], AL["r90"], 0, AL["eps0"])] + axes)
    k = ["*MAT_PIECEWISE_LINEAR_PLASTICITY_TITLE\naluminium (NUMISHEET'93 hardening)\n",
         card(1, AL["rho"], AL["E"], AL["nu"], 0.0, 0.0, 0.0), card(0.0, 0.0, 1, 0),
         card(*([0.0] * 8)), card(*([0.0] * 8))]
    k += ["*DEFINE_CURVE_TITLE\naluminium yield stress against plastic strain\n", card(1)]
    for i in range(41):
        ep = 2.0 * (i / 40) ** 2
        k.append(f"{ep:20.10g}{AL['K'] * (AL['eps0'] + ep) ** AL['n']:20.10g}\n")
    return k


# The aluminium's yield function: "j2" (*MAT_024), "barlat" (*MAT_036) or "hill" (*MAT_122).
YIELD = "j2"

# The blank's shell formulation: 2 (Belytschko-Tsay, stiffness hourglass control) or 16 (fully
# integrated, no hourglass control).
ELFORM = 2
# --plain: no setting beyond the defaults (see the module's docstring).
PLAIN = False
BACKUP = False
# Which side of the cohesive contacts is the slave: "skin" (each skin against the core) or "core".
SLAVE = "skin"
# The layers each tool's contact takes as its slave side (three layers): "outer" (the punch
# and the holder the upper skin, the die the lower: the paper's deck), or a part set of the
# "skins" (the default) or of the "blank" (every layer), as a forming contact is given the
# blank's parts. Where the layers slip, the lower skin's edge strip comes out beyond the
# core's and the upper skin's edges under the holder: only a contact that takes it keeps it
# under the holder's face (with "outer" it rose through it, README.md).
TOOL_SLAVES = {"outer": None, "skins": (1, 3), "blank": (1, 2, 3)}
TOOLS_ON = "skins"


def main(argv):
    outdir, name, layers, n, depth, speed, dt2ms, core_n = ".", None, 3, 30, 30.0, 3000.0, 0.0, None
    end_time = None
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--layers":
            layers = int(args.pop(0))
        elif a == "--n":
            n = int(args.pop(0))
        elif a == "--depth":
            depth = float(args.pop(0))
        elif a == "--speed":
            speed = float(args.pop(0))
        elif a == "--core-n":
            core_n = int(args.pop(0))
        elif a == "--dt2ms":
            dt2ms = float(args.pop(0))
        elif a == "--end":
            end_time = float(args.pop(0))
        elif a == "--set":
            key, value = args.pop(0).split("=")
            if key not in TUNABLE:
                sys.exit(f"generate.py: --set takes one of {', '.join(TUNABLE)}")
            globals()[key] = float(value)
        elif a == "--elform":
            globals()["ELFORM"] = int(args.pop(0))
        elif a == "--yield":
            globals()["YIELD"] = args.pop(0)
        elif a == "--plain":
            globals()["PLAIN"] = True
        elif a == "--slave":
            globals()["SLAVE"] = args.pop(0)
        elif a == "--backup":
            globals()["BACKUP"] = True
        elif a == "--tools-on":
            globals()["TOOLS_ON"] = args.pop(0)
        elif a == "--name":
            name = args.pop(0)
        elif a.startswith("-"):
            sys.exit(f"generate.py: unknown option {a}")
        else:
            outdir = a
    if layers not in (1, 3):
        sys.exit("generate.py: --layers is 1 or 3")
    if TOOLS_ON not in TOOL_SLAVES:
        sys.exit(f"generate.py: --tools-on is one of {', '.join(TOOL_SLAVES)}")
    if SLAVE not in ("skin", "core"):
        sys.exit("generate.py: --slave is skin or core")
    if YIELD not in ("j2", "barlat", "hill"):
        sys.exit("generate.py: --yield is j2, barlat or hill")
    if ELFORM not in (2, 16):
        sys.exit("generate.py: --elform is 2 or 16")
    name = name or f"square_cup_{layers}"
    write_deck(outdir, name, *deck(layers, n, depth, speed, dt2ms, core_n, end_time))


if __name__ == "__main__":
    main(sys.argv[1:])
