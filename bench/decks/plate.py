#!/usr/bin/env python3
"""The shell benchmark's plate as a deck (docs/speed.md, docs/parallel.md): an N x N plate of
Belytschko-Tsay shells (ELFORM 2, NIP 5) of steel with J2 plasticity (*MAT_PLASTIC_KINEMATIC),
1 m square and 1 mm thick, clamped along its edges, its centre node driven down at 5 m/s after a
smooth start; with --punch, a rigid dome (a spherical cap of shells) driven down onto it through
*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE instead. Units: mm, s, t, N, MPa.

    python3 plate.py OUTDIR [--n N] [--cycles C] [--punch] [--states K]

--n N        elements along each edge (default 100: 10,000 shells)
--cycles C   about how many cycles the run takes (default 500; the end time follows from the
             plate's stable step)
--punch      the rigid dome punch and its contact instead of the driven centre node
--states K   states written (d3plot), besides the first and last (default 0)

Writes OUTDIR/plate.k. Standard library only.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "common"))
from deck_cards import card, ids  # noqa: E402


def main(argv):
    args = argv[1:]
    opts = {"--n": 100, "--cycles": 500, "--states": 0}
    punch = False
    outdir = None
    i = 0
    while i < len(args):
        a = args[i]
        if a in opts:
            opts[a] = int(args[i + 1])
            i += 2
        elif a == "--punch":
            punch = True
            i += 1
        elif not a.startswith("-") and outdir is None:
            outdir = a
            i += 1
        else:
            sys.exit(f"plate.py: unknown option {a}")
    if outdir is None:
        sys.exit(__doc__)
    n = opts["--n"]
    side, t = 1000.0, 1.0
    h = side / n
    e_mod, nu, rho = 2.1e5, 0.3, 7.85e-9
    # The BT step: the area over the longest side over the plate wave speed, times TSSFAC 0.9.
    c = math.sqrt(e_mod / (rho * (1.0 - nu * nu)))
    dt = 0.9 * h / c
    end = opts["--cycles"] * dt
    lines = ["*KEYWORD\n", "*TITLE\n",
             f"plate benchmark {n} x {n} BT NIP 5 J2{' with a rigid dome punch' if punch else ''}\n",
             "*CONTROL_TERMINATION\n", card(end), "*CONTROL_TIMESTEP\n", card(0.0, 0.9),
             "*DATABASE_GLSTAT\n", card(end / 20.0),
             "*DATABASE_BINARY_D3PLOT\n", card(end / (opts["--states"] + 1)),
             "*DATABASE_NODOUT\n", card(end / 20.0)]
    centre = (n // 2) * (n + 1) + n // 2 + 1
    lines += ["*DATABASE_HISTORY_NODE\n", card(centre, 1)]
    lines += ["*PART\n", "plate\n", card(1, 1, 1), "*SECTION_SHELL\n", card(1, 2, 0.8333, 5),
              card(t, t, t, t), "*MAT_PLASTIC_KINEMATIC\n",
              card(1, rho, e_mod, nu, 250.0, 1000.0, 0.0)]
    if punch:
        lines += ["*PART\n", "dome punch\n", card(2, 2, 2), "*SECTION_SHELL\n", card(2, 2, 0.8333, 2),
                  card(t, t, t, t), "*MAT_RIGID\n", card(2, rho, e_mod, nu),
                  card(1.0, 4, 7)]
    lines.append("*NODE\n")

    def node(nid, x, y, z):
        return f"{nid:8d}{x:16.6f}{y:16.6f}{z:16.6f}\n"

    for j in range(n + 1):
        for i in range(n + 1):
            lines.append(node(j * (n + 1) + i + 1, i * h, j * h, 0.0))
    nodes_plate = (n + 1) * (n + 1)
    dome_nodes = []
    if punch:
        # A spherical cap of radius 200 mm over the centre, 20 x 20 facets over 200 mm, its
        # lowest point 2 mm above the plate.
        r_dome, m, span = 200.0, 20, 200.0
        for j in range(m + 1):
            for i in range(m + 1):
                x = side / 2 - span / 2 + i * span / m
                y = side / 2 - span / 2 + j * span / m
                d2 = (x - side / 2) ** 2 + (y - side / 2) ** 2
                z = 2.0 + r_dome - math.sqrt(r_dome * r_dome - d2)
                nid = nodes_plate + j * (m + 1) + i + 1
                dome_nodes.append(nid)
                lines.append(node(nid, x, y, z))
    lines.append("*ELEMENT_SHELL\n")
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i + 1
            lines.append(f"{j * n + i + 1:8d}{1:8d}{a:8d}{a + 1:8d}{a + n + 2:8d}{a + n + 1:8d}\n")
    if punch:
        m = 20
        for j in range(m):
            for i in range(m):
                a = nodes_plate + j * (m + 1) + i + 1
                lines.append(f"{n * n + j * m + i + 1:8d}{2:8d}{a:8d}{a + m + 1:8d}{a + m + 2:8d}"
                             f"{a + 1:8d}\n")
    edge = [j * (n + 1) + i + 1 for j in range(n + 1) for i in range(n + 1)
            if i in (0, n) or j in (0, n)]
    lines += ["*SET_NODE_LIST\n", card(1)] + ids(edge)
    lines += ["*BOUNDARY_SPC_SET\n", card(1, 0, 1, 1, 1, 1, 1, 1)]
    # 5 m/s after a smooth start over the first fifth of the run.
    v = 5000.0
    lines += ["*DEFINE_CURVE\n", card(1)]
    for k in range(11):
        s = k / 10.0
        time = s * end / 5.0
        lines.append(card(time, -v * (3 * s * s - 2 * s ** 3), width=20))
    lines.append(card(end, -v, width=20))
    if punch:
        lines += ["*BOUNDARY_PRESCRIBED_MOTION_RIGID\n", card(2, 3, 0, 1, 1.0)]
        lines += ["*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n", card(1, 2, 3, 3),
                  card(0.1, 0.1), card()]
    else:
        lines += ["*BOUNDARY_PRESCRIBED_MOTION_NODE\n", card(centre, 3, 0, 1, 1.0)]
    lines.append("*END\n")
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, "plate.k"), "w") as f:
        f.writelines(lines)


if __name__ == "__main__":
    main(sys.argv)
