#!/usr/bin/env python3
"""Probe tack test of the paper (section 2.1, fig. 3-4): writes the decks and opening paths.

Standard library only; runs with any Python 3.

    python3 generate.py [OUTDIR]        (default: the current directory)

Writes into OUTDIR:
  probe.k            the law: *PARAMETER values and *USER_INTERFACE_FRICTION, with ETA
                     referenced as &ETA (not runnable alone: &ETA is defined by the eta decks)
  eta_<tag>.k        one small deck per eta value: defines R ETA, then *INCLUDE probe.k
  path_v<tag>.csv    one opening path per rate: gap = rate * t from 0 (bonded) to G_END
  cases.csv          the (eta, rate) cases to run: deck, path, output file, Lambda
  parameters.json    the numbers plot.py needs (area, sigma_max, C_N, ...)

Units: mm, s, MPa (N/mm^2), N, N mm (= mJ).
"""

import csv
import json
import math
import os
import sys

# --- Physical data ---------------------------------------------------------------------------
LAYER_H = 0.1  # soft acrylic layer thickness [mm] (paper, section 2.1)
SIGMA_MAX = 0.3  # peak separation stress [MPa] (paper, sections 2.1 and 4)
CN = 30.0  # cohesive normal stiffness C_N [MPa/mm]: g_c = SIGMA_MAX/CN = 0.01 mm = 10 % of LAYER_H
PROBE_D = 10.0  # flat probe diameter [mm]; force = traction * area
BETA0 = 1.0  # initially bonded, intact
BOND_TOL = 1.0e-6  # [mm]: the first path gap (0) is within it, so the point starts bonded
BETA_MIN = 1.0e-3  # cut-off: beta below it counts as fully debonded
TEMPERATURE = 20.0  # [deg C]; sigma_max is taken temperature independent here

GC = SIGMA_MAX / CN  # opening at the quasi-static peak [mm]
OMEGA = SIGMA_MAX**2 / CN  # adhesion energy per area [N/mm = MPa mm]
AREA = math.pi * PROBE_D**2 / 4.0  # [mm^2]

# --- Cases -----------------------------------------------------------------------------------
# Lambda = eta * v / (omega * g_c) is the one number that controls the shape of the curve.
# omega * g_c = 3e-5 MPa mm^2, so eta = Lambda * 3e-5 / v.
REF_RATE = 1.0e-2  # [mm/s] = 10 um/s: the rate of the eta series
REF_ETA = 3.0e-3  # [MPa mm s]: the eta of the rate series (Lambda = 1 at REF_RATE)
ETAS = [3.0e-5, 3.0e-4, 3.0e-3, 3.0e-2]  # Lambda = 0.01, 0.1, 1, 10 at REF_RATE
RATES = [1.0e-3, 3.0e-3, 1.0e-2, 3.0e-2, 1.0e-1]  # [mm/s]: Lambda = 0.1, 0.3, 1, 3, 10 at REF_ETA
# (eta 3e-4, 10 um/s) and (eta 3e-3, 1 um/s) share Lambda = 0.1: plot.py checks they coincide.

# --- Path resolution -------------------------------------------------------------------------
STEPS_PER_GC = 250  # >= 200 steps per g_c for smooth curves
G_END_OVER_GC = 50.0  # beta < BETA_MIN needs g > sqrt(1/BETA_MIN) g_c = 31.6 g_c (quasi-static)
G_END = G_END_OVER_GC * GC


def tag(x):
    """A file-name tag for a number: 3e-05 -> '3e-05', 0.01 -> '1e-02'."""
    return f"{x:.0e}"


def fixed(*fields):
    """A fixed-format card of 10-character right-aligned fields."""
    return "".join(f"{f:>10}" for f in fields).rstrip()


def write_base_deck(path):
    # UC1..UC19 (product.md table); blank fields take the law's default.
    uc = [""] * 19
    uc[0] = "1"  # MODEL      RCCM with re-healing
    uc[1] = "&CN"  # CN
    uc[2] = "&SMAX"  # SMAX_LO    (SMAX_HI blank: same value, no temperature dependence)
    uc[6] = "&ETA"  # ETA        defined by the eta_<tag>.k deck that includes this file
    uc[7] = "0.0"  # ZETA_LO    no re-healing (the probe only opens)
    uc[9] = "&BETA0"  # BETA0
    uc[10] = "&BTOL"  # BOND_TOL
    uc[11] = "0"  # FRIC       Coulomb (MU = 0: no slip in this test anyway)
    uc[18] = "&BMIN"  # BETA_MIN
    lines = [
        "*KEYWORD",
        "*TITLE",
        "Probe tack test: one initially bonded point opened at constant rate",
        "$ Units: mm, s, MPa, N. Included by eta_<tag>.k, which defines R ETA first.",
        f"$ Flat probe diameter {PROBE_D:g} mm (area {AREA:.4f} mm^2), acrylic layer {LAYER_H:g} mm.",
        f"$ g_c = SMAX/CN = {GC:g} mm, omega = SMAX^2/CN = {OMEGA:g} N/mm.",
        "*PARAMETER",
        "$ name   |  value  | name    |  value  | name    |  value  | name    |  value",
        fixed("R CN", f"{CN:g}", "R SMAX", f"{SIGMA_MAX:g}", "R BETA0", f"{BETA0:g}", "R BTOL",
              f"{BOND_TOL:.1e}"),
        fixed("R BMIN", f"{BETA_MIN:.1e}"),
        "*USER_INTERFACE_FRICTION",
        "$    NOSID       NOC      NOCI",
        fixed("1", str(len(uc)), "0"),
        "$    MODEL        CN   SMAX_LO   SMAX_HI      T_LO      T_HI       ETA   ZETA_LO",
        fixed(*uc[0:8]),
        "$  ZETA_HI     BETA0  BOND_TOL      FRIC     MU_LO     MU_HI   VISC_LO   VISC_HI",
        fixed(*uc[8:16]),
        "$   FILM_H       VDC  BETA_MIN",
        fixed(*uc[16:19]),
        "*END",
    ]
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines) + "\n")


def write_eta_deck(path, eta):
    lines = [
        "*KEYWORD",
        "*TITLE",
        f"Probe tack test, eta = {eta:g} MPa mm s",
        "*PARAMETER",
        fixed("R ETA", f"{eta:.3e}"),
        "*INCLUDE",
        "probe.k",
        "*END",
    ]
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines) + "\n")


def write_path(path, rate):
    n = int(round(G_END_OVER_GC * STEPS_PER_GC))
    dg = G_END / n
    with open(path, "w", encoding="ascii", newline="") as f:
        f.write(f"# probe opening at {rate:g} mm/s, {STEPS_PER_GC} steps per g_c = {GC:g} mm\n")
        f.write("time,gap,slip_x,slip_y,temperature\n")
        for i in range(n + 1):
            g = i * dg
            f.write(f"{g / rate:.12g},{g:.12g},0,0,{TEMPERATURE:g}\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    write_base_deck(os.path.join(out, "probe.k"))

    etas = sorted(set(ETAS + [REF_ETA]))
    rates = sorted(set(RATES + [REF_RATE]))
    for eta in etas:
        write_eta_deck(os.path.join(out, f"eta_{tag(eta)}.k"), eta)
    for v in rates:
        write_path(os.path.join(out, f"path_v{tag(v)}.csv"), v)

    cases = []
    for eta in ETAS:  # series 1: eta at the reference rate
        cases.append((eta, REF_RATE))
    for v in RATES:  # series 2: rate at the reference eta
        if (REF_ETA, v) not in cases:
            cases.append((REF_ETA, v))
    with open(os.path.join(out, "cases.csv"), "w", encoding="ascii", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "eta", "rate", "lambda", "deck", "path", "output"])
        for eta, v in cases:
            name = f"eta{tag(eta)}_v{tag(v)}"
            lam = eta * v / (OMEGA * GC)
            w.writerow([name, f"{eta:g}", f"{v:g}", f"{lam:.6g}", f"eta_{tag(eta)}.k",
                        f"path_v{tag(v)}.csv", f"{name}.csv"])

    params = {
        "units": {"length": "mm", "time": "s", "stress": "MPa", "force": "N", "energy": "N mm"},
        "layer_thickness": LAYER_H,
        "sigma_max": SIGMA_MAX,
        "cn": CN,
        "g_c": GC,
        "omega": OMEGA,
        "probe_diameter": PROBE_D,
        "area": AREA,
        "beta_min": BETA_MIN,
        "ref_rate": REF_RATE,
        "ref_eta": REF_ETA,
        "etas": ETAS,
        "rates": RATES,
        "steps_per_gc": STEPS_PER_GC,
        "g_end": G_END,
    }
    with open(os.path.join(out, "parameters.json"), "w", encoding="ascii") as f:
        json.dump(params, f, indent=2)
        f.write("\n")
    print(f"generate.py: {len(etas)} eta decks, {len(rates)} paths, {len(cases)} cases in {out}")


if __name__ == "__main__":
    main()
