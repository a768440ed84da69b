#!/usr/bin/env python3
"""Solid block demo: a soft Mooney-Rivlin rubber cube compressed by 30 % and released.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--elements N]

    OUTDIR         where to write (default: the current directory)
    --elements N   hexahedra along each edge of the cube, even (default 10: 1000 elements)

Writes into OUTDIR:
  solid_block.k    the deck (*MAT_MOONEY-RIVLIN_RUBBER, hex8 ELFORM 1, prescribed top face,
                   rollers at the bottom, mass scaling, glstat / nodout / d3plot requests)
  parameters.json  the numbers plot.py needs (geometry, material, history node ids, ...)

Units: mm, t (tonne), s, MPa (N/mm^2), N, N mm (= mJ).

The top face moves down by uz(t) = -DISP * r(t) and back: r = 3 s^2 - 2 s^3 with s = t / T_LOAD
while loading (zero velocity at both ends), then r = 1 - (3 s^2 - 2 s^3) with
s = (t - T_LOAD) / T_LOAD while releasing. Only uz of the top nodes is prescribed and the bottom
nodes are only held in z (rollers), so both faces slide freely: the block is in uniaxial stress,
the homogeneous state plot.py compares with the closed form of the material law.
"""

import json
import math
import re
import os
import sys

# --- Geometry and mesh -----------------------------------------------------------------------
EDGE = 20.0  # cube edge [mm]: x, y in [-EDGE/2, EDGE/2], z in [0, EDGE]
DEFAULT_ELEMENTS = 10  # per edge (even, so that the faces have a centre node)

# --- Material: the paper's soft rubber (MAT_027) ---------------------------------------------
RHO = 1.1e-9  # density [t/mm^3] = 1100 kg/m^3
NU = 0.49  # Poisson's ratio (near incompressibility, as LS-DYNA recommends for MAT_027)
A10 = 0.08  # Mooney-Rivlin A [MPa]
A01 = 0.02  # Mooney-Rivlin B [MPa]: small-strain shear modulus G = 2 (A + B) = 0.2 MPa

# --- Loading ---------------------------------------------------------------------------------
STRAIN = 0.30  # compression, fraction of the height: top face down by 6 mm
T_LOAD = 0.1  # [s] for the compression, and again for the release
RAMP_POINTS = 101  # points of each smooth ramp in *DEFINE_CURVE

# --- Time step and output --------------------------------------------------------------------
TSSFAC = 0.9
MASS_FACTOR = 4.0  # DT2MS chosen so that the mass of every element grows by this factor:
#                   the step grows by sqrt(MASS_FACTOR) = 2
STATES = 20  # *DATABASE_BINARY_D3PLOT states (plus the initial one)
HISTORY_DT_COUNT = 400  # glstat and nodout lines over the run


def shear_modulus():
    return 2.0 * (A10 + A01)


def bulk_modulus():
    g = shear_modulus()
    return 2.0 * g * (1.0 + NU) / (3.0 * (1.0 - 2.0 * NU))


def physical_element_dt(h):
    """plyform's stable step of an undeformed cube of edge h (ELFORM 1, before TSSFAC):
    L = 1 / sqrt(2 sum |grad N_i|^2) = h / sqrt(3), over the dilatational wave speed."""
    c = math.sqrt((bulk_modulus() + 4.0 * shear_modulus() / 3.0) / RHO)
    return h / math.sqrt(3.0) / c


def smoothstep(s):
    return 3.0 * s * s - 2.0 * s**3


def real(x, digits=4):
    """A real short enough for a 10-character field: 5.9956e-05 -> '5.996e-5'."""
    return re.sub(r"e([+-])0*(\d)", r"e\1\2", f"{x:.{digits}g}")


def fixed(*fields, width=10):
    """A fixed-format card of right-aligned fields."""
    return "".join(f"{f:>{width}}" for f in fields).rstrip()


def node_id(i, j, k, n):
    """Node (i, j, k), each 0..n along x, y, z, numbered from 1, x fastest."""
    return 1 + i + (n + 1) * (j + (n + 1) * k)


def node_list_cards(ids):
    return [fixed(*ids[p:p + 8]) for p in range(0, len(ids), 8)]


def write_deck(path, n):
    h = EDGE / n
    half = EDGE / 2.0
    dt_phys = physical_element_dt(h)
    dt2ms = math.sqrt(MASS_FACTOR) * dt_phys
    end_time = 2.0 * T_LOAD
    disp = STRAIN * EDGE
    c = n // 2

    nodes = []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                nodes.append((node_id(i, j, k, n), -half + i * h, -half + j * h, k * h))
    elements = []
    eid = 1
    for k in range(n):
        for j in range(n):
            for i in range(n):
                b = [node_id(i, j, k, n), node_id(i + 1, j, k, n), node_id(i + 1, j + 1, k, n),
                     node_id(i, j + 1, k, n)]
                t = [node_id(i, j, k + 1, n), node_id(i + 1, j, k + 1, n),
                     node_id(i + 1, j + 1, k + 1, n), node_id(i, j + 1, k + 1, n)]
                elements.append((eid, b + t))
                eid += 1
    bottom = [node_id(i, j, 0, n) for j in range(n + 1) for i in range(n + 1)]
    top = [node_id(i, j, n, n) for j in range(n + 1) for i in range(n + 1)]
    history = {
        "top_centre": node_id(c, c, n, n),
        "side_x": node_id(n, c, c, n),  # centre of the +x face (mid-height)
        "side_y": node_id(c, n, c, n),  # centre of the +y face (mid-height)
        "top_corner": node_id(n, n, n, n),
    }
    bottom_centre = node_id(c, c, 0, n)
    bottom_x = node_id(n, c, 0, n)  # on the x axis: held in y, no rotation about z

    lines = [
        "*KEYWORD",
        "*TITLE",
        f"Solid block: Mooney-Rivlin rubber cube {EDGE:g} mm, {n}^3 hex8, "
        f"{100 * STRAIN:g} % compression and release",
        "$ Units: mm, t, s, MPa, N. Written by examples/solid_block/generate.py.",
        "*CONTROL_TERMINATION",
        "$   ENDTIM    ENDCYC     DTMIN",
        fixed(f"{end_time:g}", "0", "0.0"),
        "*CONTROL_TIMESTEP",
        f"$ DT2MS: element mass x {MASS_FACTOR:g} (physical stable step of an element "
        f"{dt_phys:.4e} s)",
        "$   DTINIT    TSSFAC      ISDO    TSLIMT     DT2MS",
        fixed("0.0", f"{TSSFAC:g}", "0", "0.0", real(-dt2ms)),
        "*DATABASE_BINARY_D3PLOT",
        "$       DT",
        fixed(real(end_time / STATES, 6)),
        "*DATABASE_GLSTAT",
        fixed(real(end_time / HISTORY_DT_COUNT, 6)),
        "*DATABASE_NODOUT",
        fixed(real(end_time / HISTORY_DT_COUNT, 6)),
        "*DATABASE_HISTORY_NODE",
        fixed(*history.values()),
        "*PART",
        "rubber block",
        "$      PID     SECID       MID     EOSID      HGID",
        fixed("1", "1", "1", "0", "0"),
        "*SECTION_SOLID",
        "$    SECID    ELFORM",
        fixed("1", "1"),
        "*MAT_MOONEY-RIVLIN_RUBBER",
        f"$ G = 2 (A + B) = {shear_modulus():g} MPa, K = {bulk_modulus():.4g} MPa",
        "$      MID        RO        PR         A         B",
        fixed("1", real(RHO), f"{NU:g}", f"{A10:g}", f"{A01:g}"),
        "*DEFINE_CURVE_TITLE",
        "top face displacement / DISP: smooth ramp down (3s^2 - 2s^3) and back",
        "$     LCID      SIDR       SFA       SFO",
        fixed("1", "0", "1.0", "1.0"),
    ]
    for p in range(RAMP_POINTS):
        s = p / (RAMP_POINTS - 1)
        lines.append(fixed(f"{s * T_LOAD:.8e}", f"{smoothstep(s):.8e}", width=20))
    for p in range(1, RAMP_POINTS):
        s = p / (RAMP_POINTS - 1)
        lines.append(fixed(f"{T_LOAD + s * T_LOAD:.8e}", f"{1.0 - smoothstep(s):.8e}", width=20))
    lines += ["*SET_NODE_LIST_TITLE", "bottom face", fixed("1")]
    lines += node_list_cards(bottom)
    lines += ["*SET_NODE_LIST_TITLE", "top face", fixed("2")]
    lines += node_list_cards(top)
    lines += [
        "*BOUNDARY_SPC_SET",
        "$ Bottom on rollers: z held, x and y free.",
        "$     NSID       CID      DOFX      DOFY      DOFZ",
        fixed("1", "0", "0", "0", "1"),
        "*BOUNDARY_SPC_NODE",
        "$ Rigid-body motion in the plane: bottom centre held in x and y, the bottom node on",
        "$ the +x axis held in y (no rotation about z). Both are consistent with the uniform",
        "$ lateral expansion of uniaxial stress.",
        "$      NID       CID      DOFX      DOFY      DOFZ",
        fixed(str(bottom_centre), "0", "1", "1", "1"),
        fixed(str(bottom_x), "0", "0", "1", "1"),
        "*BOUNDARY_PRESCRIBED_MOTION_SET",
        f"$ Top face: uz = -{disp:g} mm x curve 1 (VAD 2: displacement); x and y free.",
        "$     NSID       DOF       VAD      LCID        SF",
        fixed("2", "3", "2", "1", f"{-disp:g}"),
        "*NODE",
    ]
    for nid, x, y, z in nodes:
        lines.append(f"{nid:8d}{x:16.8g}{y:16.8g}{z:16.8g}")
    lines.append("*ELEMENT_SOLID")
    for e, conn in elements:
        lines.append(f"{e:8d}{1:8d}" + "".join(f"{q:8d}" for q in conn))
    lines.append("*END")
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines) + "\n")

    return {
        "deck": os.path.basename(path),
        "edge": EDGE,
        "elements_per_edge": n,
        "elements": n**3,
        "nodes": (n + 1) ** 3,
        "rho": RHO,
        "nu": NU,
        "A": A10,
        "B": A01,
        "shear_modulus": shear_modulus(),
        "bulk_modulus": bulk_modulus(),
        "strain": STRAIN,
        "displacement": disp,
        "t_load": T_LOAD,
        "end_time": end_time,
        "tssfac": TSSFAC,
        "mass_factor": MASS_FACTOR,
        "dt2ms": dt2ms,
        "dt_physical": TSSFAC * dt_phys,
        "history": history,
    }


def main(argv):
    outdir = "."
    n = DEFAULT_ELEMENTS
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--elements":
            if not args:
                raise SystemExit("generate.py: --elements needs a number")
            n = int(args.pop(0))
        elif a.startswith("-"):
            raise SystemExit(f"generate.py: unknown option {a}\n{__doc__}")
        else:
            outdir = a
    if n < 2 or n % 2:
        raise SystemExit(f"generate.py: --elements must be even and at least 2, not {n}")
    os.makedirs(outdir, exist_ok=True)
    prm = write_deck(os.path.join(outdir, "solid_block.k"), n)
    with open(os.path.join(outdir, "parameters.json"), "w", encoding="ascii") as f:
        json.dump(prm, f, indent=2)
        f.write("\n")
    print(f"generate.py: {prm['elements']} hex8 ({n} per edge), {prm['nodes']} nodes -> "
          f"{os.path.join(outdir, 'solid_block.k')}")


if __name__ == "__main__":
    main(sys.argv[1:])
