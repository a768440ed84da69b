"""LS-DYNA keyword cards in fixed 10-character fields, as the examples' generators write them.
Standard library only.
"""


def card(*fields, width=10):
    """One card: each field right-aligned in `width` characters, a real in the shortest of %g's
    forms that fits (1.23457e-05 is 11 characters: 1.2346e-05)."""
    out = []
    for f in fields:
        if isinstance(f, float):
            s = f"{f:.6g}"
            for digits in (5, 4, 3, 2):
                if len(s) <= width:
                    break
                s = f"{f:.{digits}g}"
            out.append(s.rjust(width))
        else:
            out.append(str(f).rjust(width))
    return "".join(out) + "\n"


def ids(values):
    """A list of ids as cards of eight."""
    values = list(values)
    return [card(*values[i:i + 8]) for i in range(0, len(values), 8)]
