#!/usr/bin/env python3
"""Writes the decks of tests/regression/run/decks (they are committed; run this after a change).

    python3 make_decks.py [DECKDIR]

block_pull.k     4 x 2 x 2 hex8 steel block, x = 0 face clamped, x = 4 face pulled by a
                 prescribed displacement; states, glstat and nodout on the same interval, so
                 every state has nodout rows at the same time (the VTK read-back test).
block_threads.k  the same load on 16 x 6 x 6 = 576 hex8 (more than one 256-element work
                 item) with a lateral initial velocity (the threads test).
unstable_tssfac.k   block_pull.k with TSSFAC 2.0: the step exceeds the stable limit.
invert_element.k    block_pull.k pushed 8 mm into itself: elements turn inside out.
block_bndout.k   block_pull.k with Poisson's ratio 0, pulled over 60 axial periods, with
                 *DATABASE_BNDOUT, _SPCFORC and _MATSUM (the bndout.csv, spcforc.csv and
                 matsum.csv test) and *DATABASE_SECFORC, an output plyform does not write
                 (read with a warning).
plate_sleout.k   an elastic shell plate thrown at an angle onto a held rigid plate (Coulomb
                 friction 0.3), with *DATABASE_SLEOUT, _RCFORC and _GLSTAT (the sleout.csv
                 test).
bad_*.k          block_pull.k with one error each (the deck-error tests).
"""

import os
import sys


def block_deck(nx, ny, nz, title, end_time=1.0e-5, interval=1.0e-6, tssfac="0.9",
               pull="0.01", initial_velocity=None, pr="0.3", bndout=False):
    lx, ly, lz = float(nx), float(ny), float(nz)  # 1 mm cubes

    def nid(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)

    history = [nid(nx, 0, 0), nid(nx, ny, 0), nid(nx, ny, nz), nid(nx // 2, ny // 2, nz // 2)]
    clamped = [nid(0, j, k) for k in range(nz + 1) for j in range(ny + 1)]
    pulled = [nid(nx, j, k) for k in range(nz + 1) for j in range(ny + 1)]

    def cards(ids):
        return ["".join(f"{i:10d}" for i in ids[p:p + 8]) for p in range(0, len(ids), 8)]

    lines = [
        "*KEYWORD",
        "*TITLE",
        title,
        f"$ Units: mm, t, s, MPa, N. {lx:g} x {ly:g} x {lz:g} mm steel block of {nx} x {ny} x {nz}",
        "$ hex8; states, glstat and nodout on one interval (coinciding times).",
        "$ Written by tests/regression/run/make_decks.py.",
        "*CONTROL_TERMINATION",
        "$   ENDTIM    ENDCYC     DTMIN",
        f"{end_time:10.3e}         0       0.0",
        "*CONTROL_TIMESTEP",
        "$   DTINIT    TSSFAC",
        f"       0.0{tssfac:>10}",
        "*DATABASE_BINARY_D3PLOT",
        f"{interval:10.3e}",
        "*DATABASE_GLSTAT",
        f"{interval:10.3e}",
        "*DATABASE_NODOUT",
        f"{interval:10.3e}",
        "*DATABASE_HISTORY_NODE",
        "".join(f"{h:10d}" for h in history),
        "*PART",
        "steel block",
        "$      PID     SECID       MID     EOSID      HGID",
        "         1         1         1         0         0",
        "*SECTION_SOLID",
        "$    SECID    ELFORM",
        "         1         1",
        "*MAT_ELASTIC",
        "$      MID        RO         E        PR",
        f"         1   7.85e-9  210000.0{pr:>10}",
        "*DEFINE_CURVE",
        "$     LCID",
        "         1",
        f"{0.0:20.6e}{0.0:20.6e}",
        f"{end_time:20.6e}{float(pull):20.6e}",
        "*SET_NODE_LIST",
        "         1",
        *cards(clamped),
        "*SET_NODE_LIST",
        "         2",
        *cards(pulled),
        "*BOUNDARY_SPC_SET",
        "$     NSID       CID      DOFX      DOFY      DOFZ",
        "         1         0         1         1         1",
        "*BOUNDARY_PRESCRIBED_MOTION_SET",
        "$     NSID       DOF       VAD      LCID        SF",
        "         2         1         2         1       1.0",
    ]
    if bndout:
        lines += ["*DATABASE_BNDOUT", f"{interval:10.3e}", "*DATABASE_SPCFORC",
                  f"{interval:10.3e}", "*DATABASE_MATSUM", f"{interval:10.3e}",
                  "*DATABASE_SECFORC", f"{interval:10.3e}"]
    if initial_velocity is not None:
        lines += ["*INITIAL_VELOCITY_GENERATION",
                  "$       ID      STYP     OMEGA        VX        VY        VZ",
                  "         1         2       0.0" + initial_velocity]
    lines.append("*NODE")
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                lines.append(f"{nid(i, j, k):8d}{float(i):16.8g}{float(j):16.8g}{float(k):16.8g}")
    lines.append("*ELEMENT_SOLID")
    e = 1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                lines.append(f"{e:8d}{1:8d}" + "".join(f"{q:8d}" for q in c))
                e += 1
    lines.append("*END")
    return "\n".join(lines) + "\n"


def sleout_deck():
    n = 4  # elements along each side of the 8 mm plate; the rigid plate is 12 mm
    lines = ["*KEYWORD", "*TITLE", "Plate thrown onto a rigid plate, sleout.csv",
             "$ Units: mm, t, s, MPa, N. Written by tests/regression/run/make_decks.py.",
             "*CONTROL_TERMINATION", "4.0e-4", "*DATABASE_GLSTAT", "2.0e-5",
             "*DATABASE_RCFORC", "2.0e-5", "*DATABASE_SLEOUT", "2.0e-5",
             # Stiffness hourglass control: the one-point shells of a plate that lands at an
             # angle ring their hourglass modes (13 % of the largest internal energy with the
             # viscous default, a run whose results are not to be trusted).
             "*PART", "plate", "1,1,1,0,1", "*HOURGLASS", "1,4,0.1",
             "*PART", "rigid plate", "2,2,2",
             "*SECTION_SHELL", "1,2,0.8333,3", "0.5,0.5,0.5,0.5",
             "*SECTION_SHELL", "2,2,0.8333,2", "1.0,1.0,1.0,1.0",
             "*MAT_ELASTIC", "1,7.85e-9,210000.0,0.3",
             "*MAT_RIGID", "2,7.85e-9,210000.0,0.3", "1.0,7,7",
             "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE", "1,2,3,3", "0.3,0.3,0.0,0.0,20.0", "1.0,1.0",
             "*INITIAL_VELOCITY_GENERATION", "1,2,0.0,2000.0,0.0,-3000.0", "*NODE"]
    for j in range(n + 1):
        for i in range(n + 1):
            lines.append(f"{1 + i + (n + 1) * j},{2.0 * i},{2.0 * j},1.0")
    for j in range(2):
        for i in range(2):
            lines.append(f"{101 + i + 2 * j},{-2.0 + 12.0 * i},{-2.0 + 12.0 * j},0.0")
    lines.append("*ELEMENT_SHELL")
    for j in range(n):
        for i in range(n):
            a = 1 + i + (n + 1) * j
            lines.append(f"{1 + i + n * j},1,{a},{a + 1},{a + n + 2},{a + n + 1}")
    lines += ["100,2,101,102,104,103", "*END"]
    return "\n".join(lines) + "\n"


def replace_once(text, old, new):
    assert text.count(old) == 1, old
    return text.replace(old, new)


def main(argv):
    out = argv[0] if argv else os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
    os.makedirs(out, exist_ok=True)
    base = block_deck(4, 2, 2, "Steel block pulled by prescribed displacement")
    decks = {
        "block_pull.k": base,
        "block_threads.k": block_deck(16, 6, 6, "Steel block pulled, with lateral initial "
                                      "velocity", end_time=2.0e-5, interval=1.0e-6,
                                      initial_velocity="       0.0     500.0     200.0"),
        "unstable_tssfac.k": block_deck(4, 2, 2, "Steel block with TSSFAC 2.0 (unstable)",
                                        end_time=1.0e-4, tssfac="2.0"),
        "invert_element.k": block_deck(4, 2, 2, "Steel block pushed 8 mm into itself",
                                       pull="-8.0"),
        "block_bndout.k": block_deck(4, 2, 2, "Steel block (Poisson 0) pulled slowly, bndout.csv",
                                     end_time=2.0e-4, interval=2.0e-5, pr="0.0", bndout=True),
        "plate_sleout.k": sleout_deck(),
        # One error each; the line numbers named by the tests are those of these edits.
        "bad_unknown_keyword.k": replace_once(base, "*SECTION_SOLID\n", "*SECTION_SOLIDD\n"),
        "bad_number.k": replace_once(base, "   7.85e-9  210000.0", "   7.85e-9  210x00.0"),
        "bad_missing_card.k": replace_once(
            base, "*MAT_ELASTIC\n$      MID        RO         E        PR\n"
            "         1   7.85e-9  210000.0       0.3\n", "*MAT_ELASTIC\n"),
        "bad_undefined_id.k": replace_once(base, "         1         1         1         0         0",
                                           "         1         1         7         0         0"),
        "bad_out_of_range.k": replace_once(base, "210000.0       0.3", "210000.0       0.7"),
        "bad_repeated_node.k": replace_once(
            base, "       2       1       2       3       8       7      17      18      23      22",
            "       2       1       2       3       8       7      17      18      23      17"),
    }
    for name, text in decks.items():
        with open(os.path.join(out, name), "w", encoding="ascii") as f:
            f.write(text)
    print(f"make_decks.py: {len(decks)} decks -> {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
