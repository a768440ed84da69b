"""Beam theory of the DCB with the deck's own cohesive law: the reference for the peak load.

    /usr/bin/python3 cohesive_beam.py RUNDIR_OR_JSON [--h H]

One arm is an Euler-Bernoulli beam `EI w'''' = -q(w)`; by symmetry the two arms open by
`u = 2 w`. Over the starter crack (0 < x < a0) the arm is free, beyond it rests on the interface:
`q = B t(u)` with the RCCM law in its rate-independent limit (contact-law.md):
- tension (u > 0): `t = C_N beta^2 u`, `beta = min(beta_history, omega / (C_N u^2))`, so the
  traction rises to sigma_max at `u_c = sigma_max / C_N` and then falls as `sigma_max (u_c/u)^3`;
- compression (u < 0): the contact penalty per area, or the adhesive layer's C_N beta^2 where
  that is stiffer (a bonded node in compression, contact-law.md), `t = max(k_pen, C_N beta^2) u`.
The tip opening delta is raised step by step (the damage is irreversible: each point keeps the
smallest beta it has seen); at each step Newton's method solves the beam by central finite
differences, spacing h, on the bonded length a0 < x < L. The free cantilever in front is exact:
at x = a0 the moment is P a0 and the shear P, and `delta / 2 = w(a0) - a0 w'(a0) + P a0^3 / (3 EI)`.

This is the beam-theory value of the cohesive-zone peak, which LEFM with the root rotation
approaches as the zone shrinks; its discretisation error falls as h^2 (the main() run prints
the peak for h and h/2). numpy only.
"""

import json
import math
import os
import sys

import numpy as np


def traction(u, beta_hist, cn, omega, k_pen):
    """Traction (tension positive), its derivative in u, and the beta it implies."""
    beta = np.minimum(beta_hist, np.where(u > 0, omega / np.maximum(cn * u * u, 1e-300), 1.0))
    beta = np.minimum(beta, 1.0)
    k_comp = np.maximum(k_pen, cn * beta ** 2)
    t = np.where(u > 0, cn * beta ** 2 * u, k_comp * u)
    damaging = (u > 0) & (beta < beta_hist)  # on the softening branch: t = omega^2 / (C_N u^3)
    dt = np.where(u > 0, np.where(damaging, -3.0 * t / np.maximum(u, 1e-300), cn * beta ** 2),
                  k_comp)
    return t, dt, beta


def peak_load(p, k_pen, h=0.05, steps=60):
    """Peak tip load of the beam model, and the opening where it occurs.

    p: the dcb.json dictionary of generate.py (E, width, thickness, a0, length, cn, sigma_max).
    Up to the peak every point of the interface opens monotonically, so beta depends on the
    current opening alone and the steps in delta may be coarse; the peak is the vertex of the
    parabola through the three largest loads.
    """
    from scipy.linalg import solve_banded

    # Plane strain across the width (the decks hold y at every node): E / (1 - nu^2).
    e = p["E"] / (1.0 - p.get("nu", 0.0) ** 2)
    b, th, a0, length = p["width"], p["thickness"], p["a0"], p["length"]
    cn, smax = p["cn"], p["sigma_max"]
    omega = smax ** 2 / cn
    ei = e * b * th ** 3 / 12.0
    n = int(round((length - a0) / h))
    h = (length - a0) / n
    m = n + 1  # unknowns w_0..w_n (x = a0 + j h) and the load P
    # EI w'''' by central differences; the ghost points come from the end conditions: at x = a0
    # EI w'' = P a0 and EI w''' = P, at x = L w'' = w''' = 0:
    #   w_{-1} = 2 w_0 - w_1 + h^2 a0 P / EI,
    #   w_{-2} = 4 w_0 - 4 w_1 + w_2 + (2 h^2 a0 - 2 h^3) P / EI,
    #   w_{n+1} = 2 w_n - w_{n-1},  w_{n+2} = 4 w_n - 4 w_{n-1} + w_{n-2}.
    ghost = {
        -1: ({0: 2.0, 1: -1.0}, h ** 2 * a0 / ei),
        -2: ({0: 4.0, 1: -4.0, 2: 1.0}, (2.0 * h ** 2 * a0 - 2.0 * h ** 3) / ei),
        n + 1: ({n: 2.0, n - 1: -1.0}, 0.0),
        n + 2: ({n: 4.0, n - 1: -4.0, n - 2: 1.0}, 0.0),
    }
    c = ei / h ** 4
    band = np.zeros((5, m))  # scipy's banded storage: band[2 + i - j, j] = A[i, j]
    p_col = np.zeros(m)  # the load's column
    for i in range(m):
        for off, wgt in ((-2, 1.0), (-1, -4.0), (0, 6.0), (1, -4.0), (2, 1.0)):
            j = i + off
            if 0 <= j < m:
                band[2 + i - j, j] += c * wgt
            else:
                coeffs, p_coeff = ghost[j]
                for jj, cc in coeffs.items():
                    band[2 + i - jj, jj] += c * wgt * cc
                p_col[i] += c * wgt * p_coeff

    def operator(w, load):
        r = band[2] * w
        for k in (1, 2):  # the super- and sub-diagonals
            r[:-k] += band[2 - k, k:] * w[k:]
            r[k:] += band[2 + k, :-k] * w[:-k]
        return r + p_col * load

    def residual(w, load, beta_hist):
        t, dt, _ = traction(2.0 * w, beta_hist, cn, omega, k_pen)
        return operator(w, load) + b * t, dt  # EI w'''' + B t(2 w) = 0 at each node

    def solve(target, w, load, beta_hist):
        # Newton with w_0 (half the opening at the crack tip, which grows monotonically) held
        # at the target; a backtracking line search carries it over the law's kink at u_c.
        w = w.copy()
        w[0] = target
        r, dt = residual(w, load, beta_hist)
        for _ in range(60):
            jac = band.copy()
            jac[2] += 2.0 * b * dt
            # The bordered system: J dw + p_col dP = -r with dw_0 = 0; eliminate the load.
            y1 = solve_banded((2, 2), jac, -r)
            y2 = solve_banded((2, 2), jac, p_col)
            d_load = y1[0] / y2[0]
            dw = y1 - y2 * d_load
            norm0 = np.linalg.norm(r)
            step = 1.0
            for _ in range(20):
                w_try, load_try = w + step * dw, load + step * d_load
                r_try, dt_try = residual(w_try, load_try, beta_hist)
                if np.linalg.norm(r_try) < norm0 or step < 1e-3:
                    break
                step *= 0.5
            w, load, r, dt = w_try, load_try, r_try, dt_try
            if np.max(np.abs(step * dw)) < 1e-10 * np.max(np.abs(w)):
                return w, load, np.minimum(beta_hist, traction(2.0 * w, beta_hist, cn, omega,
                                                               k_pen)[2])
        return None

    def advance(w0_from, w0_to, w, load, beta_hist, depth=0):
        # Where Newton cycles (a node crossing the law's peak within the step), the step is
        # split, each part starting from the last converged state and its damage.
        out = solve(w0_to, w, load, beta_hist)
        if out is not None:
            return out
        if depth == 8:
            raise RuntimeError(f"cohesive_beam: Newton did not converge at w_0 {w0_to:.4g}")
        mid = 0.5 * (w0_from + w0_to)
        w, load, beta_hist = advance(w0_from, mid, w, load, beta_hist, depth + 1)
        return advance(mid, w0_to, w, load, beta_hist, depth + 1)

    lam = (2.0 * cn * b / (4.0 * ei)) ** 0.25
    la = lam * a0
    compliance = 2.0 * a0 ** 3 / (3.0 * ei) * (1 + 3 / la + 3 / la ** 2 + 1.5 / la ** 3)
    p_lefm = b * math.sqrt(omega * e * th ** 3 / 12.0) / (a0 + 1.0 / lam)
    # Steps in the crack-tip opening, up to a few times the opening of the law's peak.
    u_c = smax / cn
    dw0 = 4.0 * 0.5 * u_c / steps
    w, load = np.zeros(m), 0.0
    beta_hist = np.ones(m)
    history = []
    for k in range(1, 32 * steps):
        w, load, beta_hist = advance((k - 1) * dw0, k * dw0, w, load, beta_hist)
        slope = (w[1] - (2.0 * w[0] - w[1] + h * h * a0 * load / ei)) / (2.0 * h)
        delta = 2.0 * (w[0] - a0 * slope + load * a0 ** 3 / (3.0 * ei))
        history.append((delta, load))
        if load < 0.95 * max(p for _, p in history):  # well past the peak
            break
    else:
        raise RuntimeError("cohesive_beam: no peak within 16 times the law's peak opening")
    i = max(range(1, len(history) - 1), key=lambda j: history[j][1])
    (d0, p0), (d1, p1), (d2, p2) = history[i - 1:i + 2]
    # The vertex of the parabola through the last three loads (uniform steps in w_0).
    s = 0.5 * (p0 - p2) / (p0 - 2.0 * p1 + p2)
    return {"peak": p1 - 0.25 * (p0 - p2) * s, "opening": d1 + 0.5 * s * (d2 - d0),
            "lefm": p_lefm, "lambda": lam, "compliance": compliance}


def main(argv):
    if not argv:
        sys.exit(__doc__)
    path = argv[0]
    if os.path.isdir(path):
        path = os.path.join(path, "dcb.json")
    with open(path) as f:
        p = json.load(f)
    h = float(argv[argv.index("--h") + 1]) if "--h" in argv else 0.05
    k_pen = p.get("penalty", p["cn"])
    for hh in (h, 0.5 * h):
        r = peak_load(p, k_pen, hh)
        print(f"h {hh:.4g} mm: peak {r['peak']:.5g} N at opening {r['opening']:.4g} mm "
              f"(LEFM with the root rotation {r['lefm']:.5g} N, {100 * (r['peak'] / r['lefm'] - 1):+.2f} %)")


if __name__ == "__main__":
    main(sys.argv[1:])
