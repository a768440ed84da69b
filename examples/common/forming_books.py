"""The energy criteria every forming example is held to (examples/square_cup,
examples/deep_drawing): conservation of energy, a positive internal energy, little hourglass
energy, no contact that gives the model energy, and the cohesive interfaces' damping and own
books. Standard library only.
"""

import os
from collections import defaultdict

from histories import rows


def check_books(outdir, interfaces, report, balance=0.01, internal_floor=0.0, books_tol=0.005,
                damping_tol=0.01, books_every=0.01):
    """The energy criteria every forming example is held to, each passed to report(name, ok,
    text); the tolerances are fractions of the final external work, but books_every, a fraction
    of each interface's own work + surface at every output. Returns (glstat rows,
    interface_energy rows by interface)."""
    glstat = rows(os.path.join(outdir, "glstat.csv"))
    books = defaultdict(list)
    for r in rows(os.path.join(outdir, "interface_energy.csv")):
        books[int(r["interface"])].append(r)
    last = glstat[-1]
    ext = last["external_work"]
    worst = max(abs(r["kinetic"] + r["internal"] + r["hourglass"] + r["contact"] -
                    r["external_work"]) for r in glstat)
    report("energy balance", worst <= balance * ext,
           f"largest |total - external work| {worst:.4g} mJ = {100 * worst / ext:.3f} % of the "
           f"external work {ext:.6g} mJ; energy ratio at the end {last['energy_ratio']:.5f}")
    lowest = min(r["internal"] for r in glstat)
    if internal_floor == 0.0:
        report("internal energy", lowest >= 0.0, f"lowest {lowest:.4g} mJ")
    else:
        report("internal energy", last["internal"] > 0.0 and lowest >= -internal_floor * ext,
               f"{last['internal']:.6g} mJ at the end; lowest {lowest:.4g} mJ "
               f"({100 * lowest / ext:+.4f} % of the external work)")
    final_internal = last["internal"]
    share = [r["hourglass"] / r["internal"] for r in glstat
             if r["internal"] >= 0.01 * final_internal and r["internal"] > 0.0]
    report("hourglass", max(share) < 0.05,
           f"{100 * last['hourglass'] / final_internal:.2f} % of the internal energy at the end, "
           f"at most {100 * max(share):.2f} % once the internal energy passed 1 % of its final "
           f"value")
    for iface, hist in sorted(books.items()):
        low = min(r["work"] for r in hist)
        report(f"contact {iface} work", low >= -1e-3 * ext,
               f"lowest {low:.4g} mJ ({100 * low / ext:+.4f} % of the external work), at the end "
               f"{hist[-1]['work']:.6g} mJ")
    for iface in interfaces:
        # The interface's own books at every output, against its own work + surface (once that
        # passed 1 % of its final value): the law's books close on the work the interface did.
        hist = books[iface]
        final = abs(hist[-1]["work"] + hist[-1].get("surface", 0.0))
        worst, worst_t = 0.0, 0.0
        for r in hist:
            done = r["work"] + r.get("surface", 0.0)
            if final == 0.0 or abs(done) < 0.01 * final:
                continue
            booked = r["stored"] + r["damage"] + r["viscous"] + r["friction"] + r["damping"]
            if abs(booked - done) / abs(done) > worst:
                worst, worst_t = abs(booked - done) / abs(done), r["time"]
        report(f"interface {iface} books at every output", worst <= books_every,
               f"worst {100 * worst:.3f} % of its work + surface (t = {worst_t:.4g} s; limit "
               f"{100 * books_every:.0f} %)")
        h = books[iface][-1]
        booked = h["stored"] + h["damage"] + h["viscous"] + h["friction"] + h["damping"]
        # The work the nodes did plus the work the surfaces' own changes did (the layers'
        # thickness followed by the offsets, segment to segment jumps): docs/contact.md.
        worked = h["work"] + h.get("surface", 0.0)
        if damping_tol is not None:
            report(f"interface {iface} damping", h["damping"] <= damping_tol * ext,
                   f"{h['damping']:.4g} mJ = {100 * h['damping'] / ext:.3f} % of the external "
                   f"work")
        report(f"interface {iface} books", abs(booked - worked) <= books_tol * ext,
               f"work {h['work']:.5g} + surface {h.get('surface', 0.0):.4g} mJ, books "
               f"{booked:.5g} mJ (stored {h['stored']:.4g}, "
               f"damage {h['damage']:.4g}, friction {h['friction']:.4g}, damping "
               f"{h['damping']:.4g}, healing {h['healing']:.4g}); difference "
               f"{100 * abs(booked - worked) / ext:.3f} % of the external work")
    return glstat, books
