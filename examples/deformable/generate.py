#!/usr/bin/env python3
"""Deformable test model of the paper (figs. 8-10): a soft Mooney-Rivlin block bonded to a plate
by the cohesive interface law, loaded by a rigid cylindrical tool that slides across its top.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--dx DX] [--dz0 DZ0] [--name NAME]

    --dx DX     element size along the block's length and width (default 1 mm)
    --dz0 DZ0   height of the element layer at the bonded face (default 0.5 mm); the layers
                grow by GROWTH towards the top (the mesh is finer at the contact surface)

Writes OUTDIR/NAME.k (the deck) and OUTDIR/NAME.json (the numbers check.py and plot.py need).
Units: mm, t (tonne), s, MPa (N/mm^2), N, mJ (N mm).

The block (LENGTH x WIDTH x HEIGHT, hexahedra ELFORM 1 with stiffness hourglass control) lies on
a rigid plate (*MAT_RIGID shells, held); its bottom faces are the slave side of
*CONTACT_ONE_WAY_SURFACE_TO_SURFACE with the cohesive law of *USER_INTERFACE_FRICTION, bonded at
t = 0 by BOND_TOL. A rigid cylinder (faceted *MAT_RIGID shells, axis along y) is pressed DEPTH
into the top near the block's rear end, slid along x with Coulomb friction MU_TOOL (its
rotations held: it slides, it does not roll) and held near the front end. Its friction
drags the top of the block forward: the material under the tool presses the interface, and the
tool's drag tips the block forward about the pressed zone, so the interface behind the tool is
pulled open and separates, the peel front following the tool.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from deck_cards import card, ids  # noqa: E402

# --- Geometry ----------------------------------------------------------------------------------
LENGTH, WIDTH, HEIGHT = 48.0, 10.0, 10.0  # block: x in [0, L], y in [0, W], z in [0, H]
GROWTH = 1.3  # ratio of successive element layers from the bonded face up ...
MAX_LAYER = 3.0  # ... up to this many times the first layer's height
PLATE_MARGIN = 5.0  # the plate reaches this far beyond the block on every side
RADIUS = 6.0  # tool radius
FACETS = 72  # facets around the tool (5 degrees each)

# --- Block: the paper's soft rubber (*MAT_MOONEY-RIVLIN_RUBBER) ------------------------------
RHO = 1.1e-9  # [t/mm^3], 1100 kg/m^3
NU = 0.49  # the paper's Poisson's ratio
A10 = 0.2  # Mooney-Rivlin A [MPa]; the paper: "elastic constants of 0.2 MPa"
A01 = 0.2  # Mooney-Rivlin B [MPa]: small-strain shear modulus G = 2 (A + B) = 0.8 MPa
ELFORM = 2  # selective reduced hexahedra (F-bar): no hourglass modes to control. With one
#            point (ELFORM 1, IHQ 4) the tool's and the interface's nodal forces put 12-15 % of
#            the internal energy into hourglass control.

# --- Interface: cohesive law (contact-law.md) -------------------------------------------------
SMAX = 0.3  # sigma_max [MPa], the paper's value
CN = 10.0  # C_N [MPa/mm]: g_c = sigma_max / C_N = 0.03 mm, omega = sigma_max^2 / C_N = 9 J/m^2
ETA = 1.0e-7  # adhesion viscosity [MPa mm s]: Lambda = eta v / (omega g_c) <~ 0.04
MU_INTERFACE = 1.0  # Coulomb friction of the interface where it is pressed
BOND_TOL = 1.0e-3  # [mm] every bottom node touches the plate at t = 0: all bonded, beta = 1
SFS = 10.0  # slave penalty scale of both contacts: the block's SOFT = 0 penalty (0.1 K A / V)
#             would let the tool sink about 0.7 mm into it under 2 MPa

# --- Tool motion ---------------------------------------------------------------------------------
X_START = 8.0  # tool axis at t = 0 (x); it ends at X_START + TRAVEL
TRAVEL = 24.0
CLEARANCE = 0.5  # the tool's lowest line starts this far above the block
DEPTH = 2.5  # indentation of the block's top
MU_TOOL = 0.8  # tool-block Coulomb friction (rubber on steel)
T_PRESS, T_MOVE, T_HOLD = 0.02, 0.12, 0.01  # [s]: pressed in, slid across, held
TOOL_VDC = 10.0  # normal damping of the tool contact [% of critical]

# --- Time step and output -------------------------------------------------------------------
TSSFAC = 0.9
DT_TARGET = 5.0e-6  # DT2MS (negative: mass only on the elements whose step is below it)
STATES = 30  # VTU states over the run (the pressure field along the interface)
HISTORY_DT = 1.0e-4  # glstat, rcforc, matsum interval [s]
POINT_DT = 1.0e-5  # nodout / cohesive.csv interval of the two points [s]: the tension passes
#                    through its peak within a few 1e-4 s
POINT_X = (14.0, 22.0)  # the two interface points of the histories (fig. 10)


def shear_modulus():
    return 2.0 * (A10 + A01)


def bulk_modulus():
    g = shear_modulus()
    return 2.0 * g * (1.0 + NU) / (3.0 * (1.0 - 2.0 * NU))


def layers(dz0):
    """Element layer tops from the bonded face up: dz0, dz0 GROWTH, dz0 GROWTH^2, ... while a
    layer stays below MAX_LAYER * dz0, then equal layers no taller than that up to HEIGHT (the
    tool indents the top by 2.5 mm: its elements must not be coarse either)."""
    zs, dz = [0.0], dz0
    while zs[-1] + dz <= HEIGHT and dz <= MAX_LAYER * dz0:
        zs.append(zs[-1] + dz)
        dz *= GROWTH
    while True:  # the equal layers no thinner than the last graded one
        rest = HEIGHT - zs[-1]
        n = max(1, math.ceil(rest / (MAX_LAYER * dz0) - 1e-9))
        if len(zs) < 3 or rest / n >= zs[-1] - zs[-2]:
            break
        zs.pop()
    return zs + [zs[-1] + rest * (i + 1) / n for i in range(n)]


def smoothstep(s):
    s = min(max(s, 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


def element_dt(a, b, c):
    """plyform's stable step of an undeformed a x b x c brick (before TSSFAC):
    L = 1 / sqrt(2 sum |grad N_I|^2) = 1 / sqrt(1/a^2 + 1/b^2 + 1/c^2) over the dilatational
    wave speed."""
    speed = math.sqrt((bulk_modulus() + 4.0 * shear_modulus() / 3.0) / RHO)
    return 1.0 / math.sqrt(a ** -2 + b ** -2 + c ** -2) / speed


def deck(dx, dz0):
    nx, ny = round(LENGTH / dx), round(WIDTH / dx)
    zs = layers(dz0)
    nz = len(zs) - 1
    xs = [LENGTH * i / nx for i in range(nx + 1)]
    ys = [WIDTH * j / ny for j in range(ny + 1)]

    def nid(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)

    nodes = [(nid(i, j, k), xs[i], ys[j], zs[k]) for k in range(nz + 1) for j in range(ny + 1)
             for i in range(nx + 1)]
    elems = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                elems.append((len(elems) + 1, nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                              nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                              nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)))
    # Bottom faces, outward (-z): N1..N4 clockwise seen from above. Top faces outward (+z).
    bottom = [(nid(i, j, 0), nid(i, j + 1, 0), nid(i + 1, j + 1, 0), nid(i + 1, j, 0))
              for j in range(ny) for i in range(nx)]
    top = [(nid(i, j, nz), nid(i + 1, j, nz), nid(i + 1, j + 1, nz), nid(i, j + 1, nz))
           for j in range(ny) for i in range(nx)]

    # Plate: rigid shells at z = 0, one element per 2.5 mm, beyond the block on every side.
    plate_first = 100001
    px = [-PLATE_MARGIN + (LENGTH + 2 * PLATE_MARGIN) * i / 20 for i in range(21)]
    py = [-PLATE_MARGIN + (WIDTH + 2 * PLATE_MARGIN) * j / 8 for j in range(9)]
    plate_nodes = [(plate_first + i + 21 * j, px[i], py[j], 0.0) for j in range(9)
                   for i in range(21)]
    plate_elems = [(plate_first + i + 20 * j, plate_first + i + 21 * j,
                    plate_first + i + 1 + 21 * j, plate_first + i + 1 + 21 * (j + 1),
                    plate_first + i + 21 * (j + 1)) for j in range(8) for i in range(20)]

    # Tool: a closed faceted cylinder about an axis along y, 2 mm longer than the block is wide
    # on each side, its lowest line CLEARANCE above the block (a facet's midpoint lowest).
    tool_first = 200001
    zc = HEIGHT + CLEARANCE + RADIUS
    ty = [-2.0, WIDTH / 2, WIDTH + 2.0]
    tool_nodes = []
    for j, y in enumerate(ty):
        for m in range(FACETS):
            a = 2 * math.pi * (m + 0.5) / FACETS  # a node at angle a from -z, about +y
            r = RADIUS / math.cos(math.pi / FACETS)  # facets' midpoints on the radius
            tool_nodes.append((tool_first + j * FACETS + m, X_START + r * math.sin(a), y,
                               zc - r * math.cos(a)))
    tool_elems = [(tool_first + j * FACETS + m, tool_first + j * FACETS + m,
                   tool_first + j * FACETS + (m + 1) % FACETS,
                   tool_first + (j + 1) * FACETS + (m + 1) % FACETS,
                   tool_first + (j + 1) * FACETS + m)
                  for j in range(len(ty) - 1) for m in range(FACETS)]

    # Tool motion: down by CLEARANCE + DEPTH, across by TRAVEL, then held; each leg a smooth
    # ramp (zero velocity at both ends).
    t1, t2 = T_PRESS, T_PRESS + T_MOVE
    end = t2 + T_HOLD
    down = CLEARANCE + DEPTH
    curve_z, curve_x = [], []
    for k in range(41):
        t = t1 * k / 40
        curve_z.append((t, -down * smoothstep(t / t1)))
    curve_z.append((end, -down))
    curve_x.append((0.0, 0.0))
    for k in range(81):
        t = t1 + T_MOVE * k / 80
        curve_x.append((t, TRAVEL * smoothstep((t - t1) / T_MOVE)))
    curve_x.append((end, TRAVEL))

    # Mass scaling: the step of the finest layer raised to DT_TARGET.
    dt_fine = TSSFAC * element_dt(dx, dx, zs[1] - zs[0])
    dt2ms = max(DT_TARGET, dt_fine)

    mid = ny // 2
    line = [nid(i, mid, 0) for i in range(nx + 1)]  # the interface along the centre line
    points = [nid(round(x / dx), mid, 0) for x in POINT_X]
    top_line = [nid(i, mid, nz) for i in range(nx + 1)]

    k = ["*KEYWORD\n", "*TITLE\n",
         f"plyform deformable test model (dx {dx:g}, dz0 {dz0:g}): rubber block, "
         "cohesive interface, sliding cylinder\n",
         "$ Units: mm, t, s, MPa, N. Written by examples/deformable/generate.py.\n"]
    k += ["*CONTROL_TERMINATION\n", card(end)]
    # PENOPT 3: each contact's penalty is the slave side's (the block's, scaled by SFS); the
    # rigid sides' would be hundreds of times stiffer and only set the step.
    k += ["*CONTROL_CONTACT\n", card(0.1, 0.0, 0, 0, 3)]
    k += [f"$ DT2MS: the finest layer's step {dt_fine:.3e} s raised to {dt2ms:.3e} s\n"]
    k += ["*CONTROL_TIMESTEP\n", card(0.0, TSSFAC, 0, 0.0, -dt2ms)]
    k += ["*DATABASE_BINARY_D3PLOT\n", card(end / STATES)]
    for name in ("GLSTAT", "RCFORC", "MATSUM"):
        k += [f"*DATABASE_{name}\n", card(HISTORY_DT)]
    k += ["*DATABASE_NODOUT\n", card(POINT_DT)]
    k += ["*DATABASE_HISTORY_NODE\n"] + ids(points)
    k += ["*PART\nrubber block\n", card(1, 1, 1)]
    k += ["*SECTION_SOLID\n", card(1, ELFORM)]
    k += [f"$ G = 2 (A + B) = {shear_modulus():g} MPa, K = {bulk_modulus():.4g} MPa\n"]
    k += ["*MAT_MOONEY-RIVLIN_RUBBER\n", card(1, RHO, NU, A10, A01)]
    k += ["*PART\nplate (rigid, held)\n", card(2, 2, 2)]
    k += ["*SECTION_SHELL\n", card(2, 2, 0.8333, 2), card(*([1.0] * 4))]
    k += ["*MAT_RIGID\n", card(2, 7.85e-9, 210000.0, 0.3), card(1.0, 7, 7)]
    k += ["*PART\ncylindrical tool (rigid)\n", card(3, 2, 3)]
    # Rotations and y held: it moves in x and z only, by the prescribed motions below.
    k += ["*MAT_RIGID\n", card(3, 7.85e-9, 210000.0, 0.3), card(1.0, 2, 7)]
    k += ["*NODE\n"]
    for n, x, y, z in nodes + plate_nodes + tool_nodes:
        k.append(f"{n:8d}{x:16.8f}{y:16.8f}{z:16.8f}\n")
    k += ["*ELEMENT_SOLID\n"]
    for e, *conn in elems:
        k.append(card(e, 1, *conn, width=8))
    k += ["*ELEMENT_SHELL\n"]
    for e, *conn in plate_elems:
        k.append(card(e, 2, *conn, width=8))
    for e, *conn in tool_elems:
        k.append(card(e, 3, *conn, width=8))
    k += ["*SET_SEGMENT_TITLE\nbonded face of the block\n", card(1)]
    k += [card(*s) for s in bottom]
    k += ["*SET_SEGMENT_TITLE\ntop face of the block\n", card(2)]
    k += [card(*s) for s in top]
    k += ["*DEFINE_CURVE_TITLE\ntool z displacement\n", card(1)]
    k += [f"{t:20.10g}{v:20.10g}\n" for t, v in curve_z]
    k += ["*DEFINE_CURVE_TITLE\ntool x displacement\n", card(2)]
    k += [f"{t:20.10g}{v:20.10g}\n" for t, v in curve_x]
    k += ["*BOUNDARY_PRESCRIBED_MOTION_RIGID\n", card(3, 3, 2, 1, 1.0), card(3, 1, 2, 2, 1.0)]
    # The cohesive interface: block bottom (slave) on the plate (master).
    k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(1).rstrip("\n") + "bonded interface\n"]
    k += [card(1, 2, 0, 3), card(0.0), card(SFS, 1.0)]
    #      MODEL CN SMAX_LO SMAX_HI T_LO T_HI ETA ZETA_LO ZETA_HI BETA0 BOND_TOL FRIC MU_LO MU_HI
    #      VISC_LO VISC_HI FILM_H VDC BETA_MIN CT
    uc = [1, CN, SMAX, SMAX, 0.0, 0.0, ETA, 0.0, 0.0, 1.0, BOND_TOL, 0, MU_INTERFACE,
          MU_INTERFACE, 0.0, 0.0, 0.0, 0.0, 1.0e-3, 0.0]
    k += ["*USER_INTERFACE_FRICTION\n", card(1, len(uc), 0)]
    k += ids(float(v) if isinstance(v, float) else v for v in uc)
    # The tool on the block's top: penalty and Coulomb friction.
    k += ["*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n", card(2).rstrip("\n") + "tool on block\n"]
    k += [card(2, 3, 0, 3), card(MU_TOOL, MU_TOOL, 0.0, 0.0, TOOL_VDC), card(SFS, 1.0)]
    k += ["*END\n"]
    params = {
        "length": LENGTH, "width": WIDTH, "height": HEIGHT, "dx": dx, "dz0": dz0,
        "layers": zs, "elements": len(elems), "nodes": len(nodes), "rho": RHO, "nu": NU,
        "A": A10, "B": A01, "shear_modulus": shear_modulus(), "bulk_modulus": bulk_modulus(),
        "sigma_max": SMAX, "cn": CN, "eta": ETA, "mu_interface": MU_INTERFACE,
        "mu_tool": MU_TOOL, "radius": RADIUS, "x_start": X_START, "travel": TRAVEL,
        "clearance": CLEARANCE, "depth": DEPTH, "t_press": T_PRESS, "t_move": T_MOVE,
        "t_hold": T_HOLD, "point_dt": POINT_DT, "elform": ELFORM, "end": end, "dt2ms": dt2ms,
        "dt_fine": dt_fine,
        "history_dt": HISTORY_DT, "interface": 1, "tool_contact": 2, "tool_part": 3,
        "line_nodes": line, "line_x": xs, "top_line_nodes": top_line,
        "points": {f"x{x:g}": n for x, n in zip(POINT_X, points)},
        "point_x": {f"x{x:g}": xs[round(x / dx)] for x in POINT_X},
    }
    return "".join(k), params


def main(argv):
    outdir, dx, dz0, name = ".", 1.0, 0.5, "deformable"
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--dx":
            dx = float(args.pop(0))
        elif a == "--dz0":
            dz0 = float(args.pop(0))
        elif a == "--name":
            name = args.pop(0)
        elif a.startswith("-"):
            sys.exit(f"generate.py: unknown option {a}\n{__doc__}")
        else:
            outdir = a
    for x in POINT_X:
        if abs(x / dx - round(x / dx)) > 1e-9:
            sys.exit(f"generate.py: --dx {dx} puts no node at the history point x = {x}")
    os.makedirs(outdir, exist_ok=True)
    text, params = deck(dx, dz0)
    with open(os.path.join(outdir, name + ".k"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, name + ".json"), "w") as f:
        json.dump(params, f, indent=1)
    print(f"generate.py: {params['elements']} hexahedra ({len(params['layers']) - 1} layers, "
          f"dx {dx:g}, dz0 {dz0:g}) -> {os.path.join(outdir, name + '.k')}")


if __name__ == "__main__":
    main(sys.argv[1:])
