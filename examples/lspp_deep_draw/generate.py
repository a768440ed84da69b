#!/usr/bin/env python3
"""A small deep-drawing deck written the way LS-PrePost writes one.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR] [--n N] [--depth D] [--speed V] [--name NAME]

The square cup of examples/square_cup (the NUMISHEET'93 tool set, quarter model: rigid punch
moving down, fixed die, blank holder pressed by a force), here with a deep-drawing steel sheet
in *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037: Hill 1948, normal anisotropy R = 1.8,
Swift hardening as a curve) and every keyword written as LS-PrePost writes it: fixed 10-column
fields, a "$#" line naming the fields above every card, every card of every keyword (the
optional ones at their defaults), *TITLE, the controls an LS-PrePost forming setup carries
(*CONTROL_ACCURACY, _BULK_VISCOSITY, _CONTACT with its six cards, _ENERGY, _HOURGLASS, _OUTPUT,
_SHELL with cards 3 and 4, _TERMINATION, _TIMESTEP with card 2), three FORMING contacts of the
sheet on the tools and a single-surface contact of the sheet on itself, and the output requests
of a forming run: GLSTAT, MATSUM, SPCFORC, SLEOUT, RCFORC, NODOUT, ELOUT with history shells,
D3PLOT and EXTENT_BINARY (the last warned about: plyform writes VTU). Units: mm, t, s, MPa, N.

Writes OUTDIR/NAME.k and OUTDIR/NAME.json (the numbers check.py needs).
"""

import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import square_cup_tools as cup  # noqa: E402  (the square cup's tool set: examples/common)

# Deep-drawing steel (DC04-like): Swift hardening sigma_y = K (EPS0 + eps_p)^N, R = 1.8.
STEEL = {"rho": 7.85e-9, "E": 210000.0, "nu": 0.3, "K": 550.0, "eps0": 0.005, "n": 0.22,
         "R": 1.8}
THICKNESS = 0.8
FRICTION = 0.12
HOLDER_FORCE = 19600.0  # N on the whole blank; a quarter on the quarter model
TOOL = cup.TOOL


def f10(v):
    """One 10-column field as LS-PrePost writes it (blank for None)."""
    if v is None:
        return " " * 10
    if isinstance(v, float):
        s = f"{v:.6g}"
        for digits in (5, 4, 3, 2):
            if len(s) <= 10:
                break
            s = f"{v:.{digits}g}"
        if "e" not in s and "." not in s:
            s += "."
        return s.rjust(10)
    return str(v).rjust(10)


def card(names, values):
    """The "$#" header naming the fields, then the card."""
    head = "$#" + "".join(n.rjust(10) for n in names)[2:]
    return head + "\n" + "".join(f10(v) for v in values) + "\n"


def title_card(text):
    return "$#" + "title".rjust(78) + "\n" + text + "\n"


def curve(lcid, title, points):
    out = ["*DEFINE_CURVE_TITLE\n", title + "\n",
           card(["lcid", "sidr", "sfa", "sfo", "offa", "offo", "dattyp", "lcint"],
                [lcid, 0, 1.0, 1.0, 0.0, 0.0, 0, 0]),
           "$#" + "a1".rjust(18) + "o1".rjust(20) + "\n"]
    out += [f"{x:20.10g}{y:20.10g}\n" for x, y in points]
    return out


def deck(n=16, depth=15.0, speed=5000.0):
    hold_start = 0.2e-3
    ramp = 1.0e-3
    end = hold_start + depth / speed + 0.5 * ramp
    half = 0.5 * THICKNESS
    sheet, rows = cup.sheet(1, 1, 0.0, n)
    ns = 2 * max(8, round(n * 0.8))
    tools = [cup.punch(1100001, half, ns, depth + 5.0), cup.die(1200001, -half, ns, depth),
             cup.holder(1300001, half, ns)]
    names = {11: "punch", 12: "die", 13: "blank holder"}
    out_dt = end / 200
    k = ["$# LS-DYNA Keyword file created by LS-PrePost(R) (as its layout; written by "
         "examples/lspp_deep_draw/generate.py)\n", "*KEYWORD\n", "*TITLE\n",
         title_card("square cup, DC04 steel 0.8 mm, MAT_037 (LS-PrePost layout)")]
    k += ["*CONTROL_ACCURACY\n",
          card(["osu", "inn", "pidosu", "iacc", "exacc"], [1, 4, 0, 0, 0.0])]
    k += ["*CONTROL_BULK_VISCOSITY\n",
          card(["q1", "q2", "type", "btype", "tstype"], [1.5, 0.06, -2, 0, 0])]
    k += ["*CONTROL_CONTACT\n",
          card(["slsfac", "rwpnal", "islchk", "shlthk", "penopt", "thkchg", "orien", "enmass"],
               [0.1, 0.0, 1, 0, 4, 0, 1, 0]),
          card(["usrstr", "usrfrc", "nsbcs", "interm", "xpene", "ssthk", "ecdt", "tiedprj"],
               [0, 0, 0, 0, 4.0, 0, 0, 0]),
          card(["sfric", "dfric", "edc", "vfc", "th", "th_sf", "pen_sf"],
               [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
          card(["ignore", "frceng", "skiprwg", "outseg", "spotstp", "spotdel", "spothin"],
               [1, 0, 0, 0, 0, 0, 0.0]),
          card(["isym", "nserod", "rwgaps", "rwgdth", "rwksf", "icov", "swradf", "ithoff"],
               [0, 0, 1, 0.0, 1.0, 0, 0.0, 0]),
          card(["shledg", "pstiff", "ithcnt", "tdcnof", "ftall", "unused", "shltrw"],
               [0, 0, 0, 0, 0, None, 0.0])]
    k += ["*CONTROL_ENERGY\n", card(["hgen", "rwen", "slnten", "rylen"], [2, 2, 2, 2])]
    k += ["*CONTROL_HOURGLASS\n", card(["ihq", "qh"], [4, 0.03])]
    k += ["*CONTROL_OUTPUT\n",
          card(["npopt", "neecho", "nrefup", "iaccop", "opifs", "ipnint", "ikedit", "iflush"],
               [0, 0, 0, 0, 0.0, 0, 100, 5000]),
          card(["iprtf", "ierode", "tet10", "msgmax", "ipcurv", "gmdt", "ip1dblt", "eocs"],
               [0, 0, 2, 50, 0, 0.0, 0, 0]),
          card(["tolev", "newleg", "frfreq", "minfo", "solsig", "msgflg", "cdetol"],
               [2, 0, 1, 0, 0, 0, 10.0])]
    k += ["*CONTROL_SHELL\n",
          card(["wrpang", "esort", "irnxx", "istupd", "theory", "bwc", "miter", "proj"],
               [20.0, 1, -1, 1, 2, 2, 1, 0]),
          card(["rotascl", "intgrd", "lamsht", "cstyp6", "thshel"], [1.0, 0, 0, 1, 0]),
          card(["psstupd", "sidt4tu", "cntco", "itsflg", "irquad", "w-mode", "stretch", "icrq"],
               [0, 0, 0, 0, 2, 0.0, 0.0, 0]),
          card(["nfail1", "nfail4", "psnfail", "keepcs", "delfr", "drcpsid", "drcprm", "intperr"],
               [1, 1, 0, 0, 0, 0, 1.0, 0])]
    k += ["*CONTROL_TERMINATION\n",
          card(["endtim", "endcyc", "dtmin", "endeng", "endmas", "nosol"],
               [end, 0, 0.0, 0.0, 1.0e8, 0])]
    k += ["*CONTROL_TIMESTEP\n",
          card(["dtinit", "tssfac", "isdo", "tslimt", "dt2ms", "lctm", "erode", "ms1st"],
               [0.0, 0.9, 0, 0.0, 0.0, 0, 0, 0]),
          card(["dt2msf", "dt2mslc", "imscl", "unused", "unused", "rmscl"],
               [0.0, 0, 0, None, None, 0.0])]
    for name in ("GLSTAT", "MATSUM", "SPCFORC", "SLEOUT", "RCFORC", "NODOUT", "ELOUT"):
        fields = ["dt", "binary", "lcur", "ioopt"]
        values = [out_dt, 1, 0, 1]
        if name == "ELOUT":
            fields += ["option1", "option2", "option3", "option4"]
            values += [0, 0, 0, 0]
        k += [f"*DATABASE_{name}\n", card(fields, values)]
    k += ["*DATABASE_BINARY_D3PLOT\n",
          card(["dt", "lcdt", "beam", "npltc", "psetid"], [end / 15, 0, 0, 0, 0]),
          card(["ioopt"], [0])]
    k += ["*DATABASE_EXTENT_BINARY\n",
          card(["neiph", "neips", "maxint", "strflg", "sigflg", "epsflg", "rltflg", "engflg"],
               [0, 0, 3, 1, 1, 1, 1, 1]),
          card(["cmpflg", "ieverp", "beamip", "dcomp", "shge", "stssz", "n3thdt", "ialemat"],
               [0, 0, 0, 1, 1, 1, 2, 1])]
    # History: the elements at the punch's nose (centre), the die's shoulder and the flange.
    def element_at(x, y):
        i, j = min(n - 1, int(x / cup.BLANK_HALF * n)), min(n - 1, int(y / cup.BLANK_HALF * n))
        return 1 + j * n + i
    history = [element_at(5.0, 5.0), element_at(40.0, 5.0), element_at(60.0, 5.0),
               element_at(40.0, 40.0)]
    k += ["*DATABASE_HISTORY_SHELL\n",
          card([f"id{i}" for i in range(1, 9)], history + [0] * (8 - len(history)))]
    k += ["*DATABASE_HISTORY_NODE\n",
          card([f"id{i}" for i in range(1, 9)],
               [rows[0][n], rows[n][0], rows[n][n], rows[0][0], 0, 0, 0, 0])]
    # The sheet.
    k += ["*PART\n", title_card("sheet DC04"),
          card(["pid", "secid", "mid", "eosid", "hgid", "grav", "adpopt", "tmid"],
               [1, 1, 1, 0, 0, 0, 0, 0])]
    k += ["*SECTION_SHELL_TITLE\n", "sheet\n",
          card(["secid", "elform", "shrf", "nip", "propt", "qr/irid", "icomp", "setyp"],
               [1, 2, 0.8333, 5, 1.0, 0, 0, 1]),
          card(["t1", "t2", "t3", "t4", "nloc", "marea", "idof", "edgset"],
               [THICKNESS] * 4 + [0.0, 0.0, 0.0, 0])]
    k += ["*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC_TITLE\n", "DC04\n",
          card(["mid", "ro", "e", "pr", "sigy", "etan", "r", "hlcid"],
               [1, STEEL["rho"], STEEL["E"], STEEL["nu"], 0.0, 0.0, STEEL["R"], 1]),
          card(["idscale", "ea", "coe", "icfld", "strainlt"], [0, 0.0, 0.0, 0, 0.0])]
    k += curve(1, "DC04 Swift hardening", [
        (2.0 * (i / 40) ** 2, STEEL["K"] * (STEEL["eps0"] + 2.0 * (i / 40) ** 2) ** STEEL["n"])
        for i in range(41)])
    # The tools: rigid shells, one section; the punch and the holder move along z only.
    k += ["*SECTION_SHELL_TITLE\n", "tools\n",
          card(["secid", "elform", "shrf", "nip", "propt", "qr/irid", "icomp", "setyp"],
               [10, 2, 0.8333, 2, 1.0, 0, 0, 1]),
          card(["t1", "t2", "t3", "t4", "nloc", "marea", "idof", "edgset"],
               [1.0] * 4 + [0.0, 0.0, 0.0, 0])]
    for pid, con1 in ((11, 4), (12, 7), (13, 4)):
        k += ["*PART\n", title_card(names[pid]),
              card(["pid", "secid", "mid", "eosid", "hgid", "grav", "adpopt", "tmid"],
                   [pid, 10, pid, 0, 0, 0, 0, 0])]
        k += ["*MAT_RIGID_TITLE\n", names[pid] + "\n",
              card(["mid", "ro", "e", "pr", "n", "couple", "m", "alias"],
                   [pid, TOOL["rho"], TOOL["E"], TOOL["nu"], 0.0, 0.0, 0.0, None]),
              card(["cmo", "con1", "con2"], [1.0, con1, 7]),
              card(["lco or a1", "a2", "a3", "v1", "v2", "v3"], [0.0] * 6)]
    k += ["*NODE\n", "$#   nid               x               y               z      tc      rc\n"]
    for mesh in [sheet] + tools:
        for nid, x, y, z in mesh.nodes:
            k.append(f"{nid:8d}{x:16.8f}{y:16.8f}{z:16.8f}{0:8d}{0:8d}\n")
    k += ["*ELEMENT_SHELL\n",
          "$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n"]
    for mesh in [sheet] + tools:
        for i, (a, b, c, d) in enumerate(mesh.elems):
            k.append("".join(f"{v:8d}" for v in (mesh.first + i, mesh.part, a, b, c, d, 0, 0, 0,
                                                  0)) + "\n")
    on_x0 = [nid for nid, x, y, z in sheet.nodes if x == 0.0]
    on_y0 = [nid for nid, x, y, z in sheet.nodes if y == 0.0]
    for sid, title, members in ((1, "symmetry x = 0", on_x0), (2, "symmetry y = 0", on_y0)):
        k += ["*SET_NODE_LIST_TITLE\n", title + "\n",
              card(["sid", "da1", "da2", "da3", "da4", "solver"], [sid, 0.0, 0.0, 0.0, 0.0, "MECH"])]
        k += ["$#" + "".join(f"nid{i}".rjust(10) for i in range(1, 9))[2:] + "\n"]
        for i in range(0, len(members), 8):
            chunk = members[i:i + 8]
            k.append("".join(f10(v) for v in chunk + [0] * (8 - len(chunk))) + "\n")
    k += ["*BOUNDARY_SPC_SET_ID\n",
          card(["id", "heading"], [1, None]).rstrip() + "symmetry x = 0\n",
          card(["nsid", "cid", "dofx", "dofy", "dofz", "dofrx", "dofry", "dofrz"],
               [1, 0, 1, 0, 0, 0, 1, 1])]
    k += ["*BOUNDARY_SPC_SET_ID\n",
          card(["id", "heading"], [2, None]).rstrip() + "symmetry y = 0\n",
          card(["nsid", "cid", "dofx", "dofy", "dofz", "dofrx", "dofry", "dofrz"],
               [2, 0, 0, 1, 0, 1, 0, 1])]
    stroke = [(t + hold_start, -d) for t, d in cup.stroke_curve(end - hold_start, depth, ramp)]
    k += curve(2, "punch travel (down)", [(0.0, 0.0)] + stroke)
    k += ["*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n",
          card(["id", "heading"], [1, None]).rstrip() + "punch\n",
          card(["pid", "dof", "vad", "lcid", "sf", "vid", "death", "birth"],
               [11, 3, 2, 2, 1.0, 0, 1.0e28, 0.0])]
    k += curve(3, "blank-holder force (quarter)", [(0.0, 0.0), (hold_start, 1.0), (2 * end, 1.0)])
    k += ["*LOAD_RIGID_BODY\n",
          card(["pid", "dof", "lcid", "sf", "cid", "m1", "m2", "m3"],
               [13, 3, 3, -0.25 * HOLDER_FORCE, 0, 0, 0, 0])]
    contact_cards = [
        (["fs", "fd", "dc", "vc", "vdc", "penchk", "bt", "dt"],
         [FRICTION, FRICTION, 0.0, 0.0, 20.0, 0, 0.0, 1.0e20]),
        (["sfs", "sfm", "sst", "mst", "sfst", "sfmt", "fsf", "vsf"],
         [1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]),
        (["soft", "sofscl", "lcidab", "maxpar", "sbopt", "depth", "bsort", "frcfrq"],
         [0, 0.1, 0, 1.025, 2, 2, 0, 1]),
        (["penmax", "thkopt", "shlthk", "snlog", "isym", "i2d3d", "sldthk", "sldstf"],
         [0.0, 0, 0, 0, 0, 0, 0.0, 0.0]),
        (["igap", "ignore", "dprfac", "dtstif", "edgek", "unused", "flangl", "cid_rcf"],
         [1, 0, 0.0, 0.0, 0.0, None, 0.0, 0]),
    ]
    for cid, title, master in ((1, "punch", 11), (2, "die", 12), (3, "blank holder", 13)):
        k += ["*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ID\n",
              "$#     cid" + "title".rjust(70) + "\n", f10(cid) + f"sheet on the {title}\n",
              card(["ssid", "msid", "sstyp", "mstyp", "sboxid", "mboxid", "spr", "mpr"],
                   [1, master, 3, 3, 0, 0, 1, 1])]
        k += [card(names_, values) for names_, values in contact_cards]
    k += ["*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID\n", "$#     cid" + "title".rjust(70) + "\n",
          f10(4) + "sheet on itself\n",
          card(["ssid", "msid", "sstyp", "mstyp", "sboxid", "mboxid", "spr", "mpr"],
               [1, 0, 3, 0, 0, 0, 0, 0])]
    k += [card(*contact_cards[0][0:1], [0.1, 0.1, 0.0, 0.0, 20.0, 0, 0.0, 1.0e20])]
    k += [card(*contact_cards[1])]
    k += ["*END\n"]
    params = {"n": n, "depth": depth, "speed": speed, "end": end, "hold_start": hold_start,
              "holder_force_quarter": 0.25 * HOLDER_FORCE, "blank_half": cup.BLANK_HALF,
              "edge_x": rows[0][n], "edge_y": rows[n][0], "corner": rows[n][n],
              "history_shells": history, "sheet_part": 1, "tool_parts": [11, 12, 13],
              "tool_contacts": [1, 2, 3], "self_contact": 4}
    return "".join(k), params


def main(argv):
    outdir, name, n, depth, speed = ".", "lspp_deep_draw", 16, 15.0, 5000.0
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--n":
            n = int(args.pop(0))
        elif a == "--depth":
            depth = float(args.pop(0))
        elif a == "--speed":
            speed = float(args.pop(0))
        elif a == "--name":
            name = args.pop(0)
        elif a.startswith("-"):
            sys.exit(f"generate.py: unknown option {a}")
        else:
            outdir = a
    os.makedirs(outdir, exist_ok=True)
    text, params = deck(n, depth, speed)
    with open(os.path.join(outdir, name + ".k"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, name + ".json"), "w") as f:
        json.dump(params, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
