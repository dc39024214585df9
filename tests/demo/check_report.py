#!/usr/bin/env python3
"""Checks the report of `karkas demo`: every example is there, every file it names exists,
the cylinder row of Kuznetsov and Filatov's table lands in 0.008..0.013 (the paper prints 0.011),
and each statement of the notes on their table and angle sweep holds on the rows.

Usage: python3 tests/demo/check_report.py DEMO_DIR
"""
import json
import pathlib
import sys

EXAMPLES = [
    "ll-contour",
    "ll-aircraft",
    "coons-fig3",
    "coons-fuselage",
    "dps-five-petal",
    "dps-knotted-tube",
    "fit-hydrofoil",
    "fit-hydrofoil-clean",
    "param-cylinder-hyperboloid",
    "param-angle-sweep",
    "param-relay",
    "loft-wing",
]


def kuznetsov_filatov_statements(rows: dict) -> list:
    """Each statement of the notes of param-cylinder-hyperboloid and param-angle-sweep,
    checked against the rows it speaks of."""
    failures = []

    def value(label):
        row = rows.get("004 " + label)
        if row is None:
            failures.append(f"no row 004 {label}")
            return None, None
        return row["karkas"], row.get("paper")

    principal, _ = value("cylinder, lines of curvature")
    hyperboloid, hyperboloid_paper = value("hyperboloid, lines of curvature")
    meridian, meridian_paper = value("hyperboloid, meridian turned 68 deg")
    helix, _ = value("cylinder, helices turned 30 deg")
    if None in (principal, hyperboloid, meridian, helix):
        return failures
    for deg in (30, 45):
        both, paper = value(f"cylinder, both axes turned {deg} deg")
        # "both families turned raise the error as in the paper, though less"
        if both is not None and not principal < both < paper:
            failures.append(f"both axes turned {deg}: {both} not between {principal} and {paper}")
        one, paper = value(f"cylinder, generator turned {deg} deg")
        # "the generator alone: the error barely rises" (under 1.5 times; the paper's
        # figures are not within 30%)
        if one is not None and not (one < 1.5 * principal and one < 0.7 * paper):
            failures.append(f"generator turned {deg}: {one} is not a bare rise from {principal}")
    # "about a third of the paper's 0.03", "about a seventh of 0.078"
    if not 0.25 <= hyperboloid / hyperboloid_paper <= 0.42:
        failures.append(f"hyperboloid {hyperboloid} is not about a third of {hyperboloid_paper}")
    if not 0.1 <= meridian / meridian_paper <= 0.2:
        failures.append(f"turned meridian {meridian} is not about a seventh of {meridian_paper}")
    # "the helix frame beats the lines of curvature on the cylinder"
    if not helix < principal:
        failures.append(f"helix frame {helix} does not beat {principal}")
    # The sweep: "the error ties with 0 deg" at small angles of the meridian; 75 deg of the
    # generator far above the rest.
    sweep = {k[len("004 sweep: "):]: r["karkas"] for k, r in rows.items() if k.startswith("004 sweep: ")}
    generator75 = sweep.get("cylinder, generator turned 75 deg")
    generator60 = sweep.get("cylinder, generator turned 60 deg")
    if generator75 is None or generator60 is None or not generator75 > 10 * generator60:
        failures.append(f"sweep: generator 75 deg {generator75} not far above 60 deg {generator60}")
    for deg in (15, 30):
        tie = sweep.get(f"hyperboloid, meridian turned {deg} deg")
        if tie is None or abs(tie - hyperboloid) > 0.02 * hyperboloid:
            failures.append(f"sweep: meridian turned {deg} deg {tie} does not tie with {hyperboloid}")
    return failures


def main() -> int:
    out = pathlib.Path(sys.argv[1])
    report = json.loads((out / "report.json").read_text())
    failures = []
    ids = [e["id"] for e in report["examples"]]
    missing = [e for e in EXAMPLES if e not in ids]
    if missing:
        failures.append(f"examples missing from report.json: {missing}")
    for e in report["examples"]:
        if not e["rows"]:
            failures.append(f"{e['id']}: no rows")
        for kind in ("pictures", "viewers", "data"):
            for name in e[kind]:
                f = out / name
                if not f.is_file() or f.stat().st_size == 0:
                    failures.append(f"{e['id']}: {name} missing or empty")
    rows = [r for e in report["examples"] for r in e["rows"]]
    cylinder = [r for r in rows if r["example"] == "004 cylinder, lines of curvature"]
    if len(cylinder) != 1:
        failures.append("no single cylinder row")
    elif not 0.008 <= cylinder[0]["karkas"] <= 0.013:
        failures.append(f"cylinder row {cylinder[0]['karkas']} outside 0.008..0.013")
    failures += kuznetsov_filatov_statements(
        {
            r["example"]: r
            for r in rows
            if r["measure"] == "two-sided Hausdorff error, 5 x 9 frame"
            or r["example"].startswith("004 sweep: ")
        }
    )
    for f in failures:
        print("report.json:", f)
    if not failures:
        print(
            f"report.json: {len(ids)} examples, {len(rows)} rows, "
            f"cylinder {cylinder[0]['karkas']:.4f} (paper 0.011), "
            f"{report['runtime_seconds']:.2f} s"
        )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
