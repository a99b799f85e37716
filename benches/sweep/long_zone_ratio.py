"""The cohesive reference sweep's long-zone cases against the ratio of the
body's contact modulus at the zone's scale and at the contact's
(BENCHMARKS.md, "Seeds 74 to 85").

Reads the logs of sweeps run with ``LAYERED_CONTACT_REFERENCE_PRINT=1`` and
``LAYERED_CONTACT_REFERENCE_METHOD=cohesive_zone`` (``--nocapture``),
writes the scene of every case flagged ``CohesiveZoneLongAgainstLayer``
that passed at 16 cells into ``OUT``, runs ``examples/zone_scales.rs`` on
them and prints the pull-off errors (as the sweep printed them, at 16
cells) binned by the ratio.

Usage: python long_zone_ratio.py OUT LOG...   (from the repository's root;
builds the example with cargo)
"""

import pathlib
import re
import subprocess
import sys

QUANTITY = re.compile(r"(peak_force|pull_off_force|peak_contact_radius|stiffness) (\S+)")


def cases(log):
    """(scene text, caveats line, pull-off error) of each flagged case."""
    lines = pathlib.Path(log).read_text().split("\n")
    caveats, errors, rerun, i = None, {}, False, 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("caveats:"):
            caveats = line
        elif line.startswith("at 32 cells"):
            rerun = True
        elif (m := QUANTITY.match(line)) and not rerun:
            errors.setdefault(m.group(1), float(m.group(2)))
        elif line.startswith("case:"):
            # The sweep prints a case's scene after its numbers.
            j = i + 1
            while j < len(lines) and not lines[j].startswith("adhesion_method"):
                j += 1
            scene = "\n".join(lines[i + 1 : j + 1]) + "\n"
            if caveats and "LongAgainstLayer" in caveats and not rerun:
                yield scene, caveats, errors.get("pull_off_force")
            caveats, errors, rerun, i = None, {}, False, j
        i += 1


def main():
    out, logs = pathlib.Path(sys.argv[1]), sys.argv[2:]
    out.mkdir(parents=True, exist_ok=True)
    errors = {}
    for log in logs:
        for scene, _, error in cases(log):
            path = out / f"case{len(errors):03d}.toml"
            path.write_text(scene)
            errors[str(path)] = error
    table = subprocess.run(
        ["cargo", "run", "--release", "--quiet", "--example", "zone_scales", "--", *errors],
        capture_output=True, text=True, check=True,
    ).stdout
    rows = []
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] in errors and len(cells) == 5 and cells[4] and errors[cells[0]] is not None:
            rows.append((float(cells[4]), float(cells[1]), errors[cells[0]]))
    print(f"{len(rows)} of {len(errors)} flagged cases with an exact peak contact")
    print("| E*(zone) / E*(contact) | cases | pull-off error: median | largest | zone / h |")
    print("|---|---|---|---|---|")
    for low, high in ((0, 3), (3, 10), (10, 30), (30, 100), (100, float("inf"))):
        sel = [r for r in rows if low <= r[0] < high]
        if sel:
            e = sorted(r[2] for r in sel)
            z = [r[1] for r in sel]
            print(f"| {low} to {high} | {len(sel)} | {100 * e[len(e) // 2]:.1f} % | "
                  f"{100 * e[-1]:.1f} % | {min(z):.2f} to {max(z):.2f} |")


if __name__ == "__main__":
    main()
