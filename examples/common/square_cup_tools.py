"""The NUMISHEET'93 square-cup tool set and the deck-writing helpers the forming examples share
(examples/square_cup, examples/deep_drawing, examples/lspp_deep_draw): the quarter model's rigid
punch, die (with its opening and shoulder radius) and blank holder as shell meshes of their
surfaces, a blank's sheet mesh, the punch's stroke curve, the tools' cards, and fixed-width
cards. Standard library only; runs with any Python 3. Units: mm, t, s, MPa, N.
"""

import json
import math
import os

from deck_cards import card, ids  # noqa: F401  (the generators take them from here too)

# Tools (mm).
PUNCH_HALF, PUNCH_CORNER, PUNCH_NOSE = 35.0, 10.0, 8.0
DIE_HALF, DIE_CORNER, DIE_SHOULDER = 37.235, 12.235, 8.0  # opening 74.47 mm square
TOOL_EXTENT = 85.0  # die and holder flats reach x, y = 85 mm (the blank's edge is at 75 mm)
BLANK_HALF = 75.0
TOOL = {"rho": 7.85e-9, "E": 210000.0, "nu": 0.3}  # the rigid tools' steel (contact stiffness)


def contour(half, corner, n):
    """Quarter of a rounded square (half-width, corner radius) from (half, 0) to (0, half):
    n + 1 points evenly spaced in arc length, with their outward normals."""
    straight = half - corner
    arc = 0.5 * math.pi * corner
    total = 2 * straight + arc
    pts = []
    for k in range(n + 1):
        s = total * k / n
        if s <= straight:
            p, nrm = (half, s), (1.0, 0.0)
        elif s <= straight + arc:
            a = (s - straight) / corner if corner > 0 else 0.0
            nrm = (math.cos(a), math.sin(a))
            p = (straight + corner * nrm[0], straight + corner * nrm[1])
        else:
            p, nrm = (max(0.0, straight - (s - straight - arc)), half), (0.0, 1.0)
        pts.append((p, nrm))
    return pts


class Mesh:
    """Shell nodes and quadrilaterals of one part, numbered from a first id."""

    def __init__(self, part, first):
        self.part, self.first = part, first
        self.nodes, self.elems = [], []

    def node(self, x, y, z):
        self.nodes.append((self.first + len(self.nodes), x, y, z))
        return self.nodes[-1][0]

    def grid(self, rows):
        """rows[i][j] node ids; a quad between each pair of rows and columns."""
        for i in range(len(rows) - 1):
            for j in range(len(rows[i]) - 1):
                self.elems.append((rows[i][j], rows[i][j + 1], rows[i + 1][j + 1], rows[i + 1][j]))


def sheet(part, first, z, n):
    m = Mesh(part, first)
    rows = [[m.node(BLANK_HALF * i / n, BLANK_HALF * j / n, z) for i in range(n + 1)]
            for j in range(n + 1)]
    m.grid(rows)
    return m, rows


def o_grid_flat(m, half, corner, ns, nr, z):
    """The flat quarter inside a rounded-square contour: an inner square block of ns/2 x ns/2
    elements and nr rings out to the contour. Returns the contour's node ids."""
    half_inner = 0.5 * half
    h = ns // 2
    inner = [[m.node(half_inner * i / h, half_inner * j / h, z) for i in range(h + 1)]
             for j in range(h + 1)]
    m.grid(inner)
    # Boundary of the inner block from (q, 0) up to (q, q) and across to (0, q), as the contour.
    ring0 = [inner[j][h] for j in range(h + 1)] + [inner[h][i] for i in range(h - 1, -1, -1)]
    base = [(half_inner, half_inner * j / h) for j in range(h + 1)]
    base += [(half_inner * i / h, half_inner) for i in range(h - 1, -1, -1)]
    outer = contour(half, corner, ns)
    rings = [ring0]
    for r in range(1, nr + 1):
        f = r / nr
        rings.append([m.node(b[0] + f * (p[0] - b[0]), b[1] + f * (p[1] - b[1]), z)
                      for b, (p, _) in zip(base, outer)])
    m.grid(rings)
    return rings[-1]


def punch(first, z0, ns, height):
    """Punch face at z0 (touching the blank from above), its nose radius and wall above."""
    m = Mesh(11, first)
    inset = contour(PUNCH_HALF - PUNCH_NOSE, PUNCH_CORNER - PUNCH_NOSE, ns)
    rings = [o_grid_flat(m, PUNCH_HALF - PUNCH_NOSE, PUNCH_CORNER - PUNCH_NOSE, ns, ns // 4, z0)]
    nn = max(4, ns // 4)
    for j in range(1, nn + 1):
        phi = 0.5 * math.pi * j / nn
        r, dz = PUNCH_NOSE * math.sin(phi), PUNCH_NOSE * (1 - math.cos(phi))
        rings.append([m.node(p[0] + r * q[0], p[1] + r * q[1], z0 + dz) for p, q in inset])
    nw = max(2, round(height / 5.0))
    for j in range(1, nw + 1):
        rings.append([m.node(p[0] + PUNCH_NOSE * q[0], p[1] + PUNCH_NOSE * q[1],
                             z0 + PUNCH_NOSE + height * j / nw) for p, q in inset])
    m.grid(rings)
    return m


def flat_frame(m, half, corner, ns, nr, z, reverse=False):
    """The flat between a rounded-square contour and the square x, y = TOOL_EXTENT."""
    inner = contour(half, corner, ns)
    h = ns // 2
    box = [(TOOL_EXTENT, TOOL_EXTENT * j / h) for j in range(h + 1)]
    box += [(TOOL_EXTENT * i / h, TOOL_EXTENT) for i in range(h - 1, -1, -1)]
    rings = []
    for r in range(nr + 1):
        f = r / nr
        rings.append([m.node(p[0] + f * (b[0] - p[0]), p[1] + f * (b[1] - p[1]), z)
                      for (p, _), b in zip(inner, box)])
    m.grid(rings[::-1] if reverse else rings)
    return rings[0]


def die(first, z0, ns, depth):
    """Die face at z0 (touching the blank from below), its shoulder and its wall below."""
    m = Mesh(12, first)
    out = contour(DIE_HALF + DIE_SHOULDER, DIE_CORNER + DIE_SHOULDER, ns)
    edge = flat_frame(m, DIE_HALF + DIE_SHOULDER, DIE_CORNER + DIE_SHOULDER, ns, ns // 4, z0,
                      reverse=True)
    rings = [edge]
    nn = max(4, ns // 4)
    for j in range(1, nn + 1):
        phi = 0.5 * math.pi * j / nn
        r, dz = DIE_SHOULDER * math.sin(phi), DIE_SHOULDER * (1 - math.cos(phi))
        rings.append([m.node(p[0] - r * q[0], p[1] - r * q[1], z0 - dz) for p, q in out])
    wall = depth + 5.0
    nw = max(2, round(wall / 5.0))
    for j in range(1, nw + 1):
        rings.append([m.node(p[0] - DIE_SHOULDER * q[0], p[1] - DIE_SHOULDER * q[1],
                             z0 - DIE_SHOULDER - wall * j / nw) for p, q in out])
    m.grid(rings)
    return m


def holder(first, z0, ns):
    """Blank holder face at z0 over the flange: inside it stops 1 mm beyond the die's shoulder."""
    m = Mesh(13, first)
    flat_frame(m, DIE_HALF + DIE_SHOULDER + 1.0, DIE_CORNER + DIE_SHOULDER + 1.0, ns, ns // 4, z0)
    return m


def stroke_curve(end, depth, ramp):
    """Punch displacement (down): the speed rises as a half cosine over `ramp`, then stays."""
    v = depth / (end - 0.5 * ramp)
    pts = []
    for k in range(21):
        t = ramp * k / 20
        pts.append((t, v * (0.5 * t - 0.5 * ramp / math.pi * math.sin(math.pi * t / ramp))))
    pts.append((end, depth))
    return pts


def tool_cards():
    """The rigid tools' parts, materials and section (the meshes are the tools' surfaces): the
    die (12) held, the punch (11) and the blank holder (13) free along z only."""
    k = []
    for pid, title, con1 in ((11, "punch", 4), (12, "die", 7), (13, "blank holder", 4)):
        k += [f"*PART\n{title}\n", card(pid, 10, pid)]
        k += [f"*MAT_RIGID_TITLE\n{title}\n", card(pid, TOOL["rho"], TOOL["E"], TOOL["nu"]),
              card(1.0, con1, 7)]
    return k + ["*SECTION_SHELL\n", card(10, 2, 0.8333, 2), card(*([1.0] * 4))]


def write_deck(outdir, name, text, params):
    """OUTDIR/NAME.k (the deck) and OUTDIR/NAME.json (the numbers the checks need)."""
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, name + ".k"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, name + ".json"), "w") as f:
        json.dump(params, f, indent=1)
