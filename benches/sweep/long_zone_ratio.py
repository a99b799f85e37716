"""The cohesive reference sweep's long-zone cases against the ratio of the
body's contact modulus at the zone's scale and at the contact's
(BENCHMARKS.md, "Seeds 74 to 85").

Reads the logs of sweeps run with ``LAYERED_CONTACT_REFERENCE_PRINT=1`` and
``LAYERED_CONTACT_REFERENCE_METHOD=cohesive_zone`` (``--nocapture``),
writes the scene of every case flagged ``CohesiveZoneLongAgainstLayer``
that passed at 16 cells into ``OUT``, runs ``examples/zone_scales.rs`` on
them and prints the pull-off errors (as the sweep printed them, at 16
cells) binned by the ratio.

With ``--run``, runs ``layered-contact run`` on every written scene instead
(two at a time, one thread each) and bins the errors the tool prints by the
ratio it prints, measured at the run's own peak contact (the ratio behind
``Caveat::CohesiveZoneStifferThanContact``; BENCHMARKS.md, "The zone stiffer
than the contact"), with the indenter and whether the run carried that
caveat.

Usage: python long_zone_ratio.py [--run] OUT LOG...   (from the repository's
root; builds the example or the tool with cargo)
"""

import concurrent.futures
import os
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


BINS = ((0, 3), (3, 10), (10, 30), (30, 100), (100, float("inf")))
TOOL_ERROR = re.compile(r"^(peak_force|pull_off_force|stiffness): \S+ \(exact \S+, ([+-][\d.]+) %", re.M)
TOOL_RATIO = re.compile(r"the body ([\d.e+-]+) times as stiff")
KIND = re.compile(r'kind = "(sphere|paraboloid|cone|flat_punch)"')


def run_tool(path):
    """(ratio, indenter, flagged, pull-off error in %) of one tool run."""
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    out = subprocess.run(["target/release/layered-contact", "run", str(path), "-o",
                          str(path.with_suffix(""))], capture_output=True, text=True, env=env).stdout
    ratio = TOOL_RATIO.search(out)
    errors = dict(TOOL_ERROR.findall(out))
    kind = KIND.search(path.read_text())
    return (float(ratio.group(1)) if ratio else None, kind.group(1) if kind else "other",
            "far stiffer than the contact" in out,
            float(errors["pull_off_force"]) if "pull_off_force" in errors else None)


def run_all(paths):
    """Runs the tool on `paths` and prints the bins and the flagged cases."""
    subprocess.run(["cargo", "build", "--release", "--quiet"], check=True)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        rows = [(p, *r) for p, r in zip(paths, pool.map(run_tool, paths)) if r[0] is not None]
    print(f"{len(rows)} of {len(paths)} runs printed the ratio")
    print("| ratio | cases | with an exact pull-off | median | largest |")
    print("|---|---|---|---|---|")
    for low, high in BINS:
        sel = [r for r in rows if low <= r[1] < high]
        e = sorted(abs(r[4]) for r in sel if r[4] is not None)
        if e:
            print(f"| {low} to {high} | {len(sel)} | {len(e)} | {e[len(e) // 2]:.2f} % | {e[-1]:.2f} % |")
    print("flagged CohesiveZoneStifferThanContact:")
    for p, ratio, kind, flagged, error in sorted(rows, key=lambda r: r[1]):
        if flagged or ratio >= 30:
            print(f"  {p.name} {kind} ratio {ratio:.1f} flagged {flagged} pull-off {error} %")


def main():
    run = "--run" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--run"]
    out, logs = pathlib.Path(args[0]), args[1:]
    out.mkdir(parents=True, exist_ok=True)
    errors = {}
    for log in logs:
        for scene, _, error in cases(log):
            path = out / f"case{len(errors):03d}.toml"
            path.write_text(scene)
            errors[str(path)] = error
    if run:
        run_all([pathlib.Path(p) for p in errors])
        return
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
    for low, high in BINS:
        sel = [r for r in rows if low <= r[0] < high]
        if sel:
            e = sorted(r[2] for r in sel)
            z = [r[1] for r in sel]
            print(f"| {low} to {high} | {len(sel)} | {100 * e[len(e) // 2]:.1f} % | "
                  f"{100 * e[-1]:.1f} % | {min(z):.2f} to {max(z):.2f} |")


if __name__ == "__main__":
    main()
