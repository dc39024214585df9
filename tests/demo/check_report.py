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
    checked against the rows it speaks of, and the rows against the SciPy rebuild of
    kf_rebuild.py."""
    failures = []

    def value(label):
        row = rows.get("004 " + label)
        if row is None:
            failures.append(f"no row 004 {label}")
            return None, None
        return row["karkas"], row.get("paper")

    def near(x, paper):
        return abs(x - paper) <= 0.3 * paper

    natural = ", natural ends"
    table = {}
    for label in [
        "cylinder, lines of curvature",
        "cylinder, both axes turned 30 deg",
        "cylinder, both axes turned 45 deg",
        "cylinder, generator turned 30 deg",
        "cylinder, generator turned 45 deg",
        "hyperboloid, lines of curvature",
        "hyperboloid, meridian turned 68 deg",
        "cylinder, helices turned 30 deg",
    ]:
        for ends in ("", natural):
            table[label + ends] = value(label + ends)
    if failures:
        return failures
    k = {label: v for label, (v, _) in table.items()}
    paper = {label: p for label, (_, p) in table.items()}
    cyl, hyp = "cylinder, lines of curvature", "hyperboloid, lines of curvature"
    # "Reproduced within 30%: the cylinder ... with not-a-knot ends and the hyperboloid ...
    # with natural ends; no one end condition gives both."
    if not near(k[cyl], paper[cyl]):
        failures.append(f"cylinder {k[cyl]} not within 30% of {paper[cyl]}")
    if not near(k[hyp + natural], paper[hyp]):
        failures.append(f"hyperboloid, natural ends {k[hyp + natural]} not within 30% of {paper[hyp]}")
    if near(k[cyl + natural], paper[cyl]) or near(k[hyp], paper[hyp]):
        failures.append(f"one end condition gives both: {k[cyl + natural]}, {k[hyp]}")
    # "Not reproduced: the eightfold rise with the generator alone turned": under 1.5 times
    # with either end condition (the paper: 7.8 and 8.2).
    for deg in (30, 45):
        for ends in ("", natural):
            one = k[f"cylinder, generator turned {deg} deg" + ends]
            if not one < 1.5 * k[cyl + ends] or near(one, paper[f"cylinder, generator turned {deg} deg"]):
                failures.append(f"generator turned {deg}{ends}: {one} is not a bare rise from {k[cyl + ends]}")
    # "both families turned and the turned meridian rise less than the paper's" (and above the
    # lines of curvature: "the paper's frames along the lines of curvature beat its turned
    # frames under both end conditions").
    for label, base in [
        ("cylinder, both axes turned 30 deg", cyl),
        ("cylinder, both axes turned 45 deg", cyl),
        ("cylinder, generator turned 30 deg", cyl),
        ("cylinder, generator turned 45 deg", cyl),
        ("hyperboloid, meridian turned 68 deg", hyp),
    ]:
        for ends in ("", natural):
            if not k[base + ends] < k[label + ends]:
                failures.append(f"{label}{ends}: {k[label + ends]} does not exceed {k[base + ends]}")
            if not k[label + ends] / k[base + ends] < paper[label] / paper[base]:
                failures.append(f"{label}{ends}: rises as much as the paper's")
    # "the helix frame beats the lines of curvature on the cylinder under both"
    for ends in ("", natural):
        if not k["cylinder, helices turned 30 deg" + ends] < k[cyl + ends]:
            failures.append(f"helix frame{ends} does not beat the lines of curvature")
    # The sweep: "the error ties with 0 deg" at small angles of the meridian; 75 deg of the
    # generator eight times the 60 deg frame's.
    sweep = {k[len("004 sweep: "):]: r["karkas"] for k, r in rows.items() if k.startswith("004 sweep: ")}
    generator75 = sweep.get("cylinder, generator turned 75 deg")
    generator60 = sweep.get("cylinder, generator turned 60 deg")
    if generator75 is None or generator60 is None or not 6 * generator60 < generator75 < 10 * generator60:
        failures.append(f"sweep: generator 75 deg {generator75} not about eight times 60 deg {generator60}")
    for deg in (15, 30):
        tie = sweep.get(f"hyperboloid, meridian turned {deg} deg")
        if tie is None or abs(tie - k[hyp]) > 0.02 * k[hyp]:
            failures.append(f"sweep: meridian turned {deg} deg {tie} does not tie with {k[hyp]}")
    # Every rebuilt frame: karkas's two-sided error is at least the rebuild's forward distance
    # (same samples) and at most 3% above it.
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    from kf_rebuild import rebuild

    for label, scipy in rebuild().items():
        ours = sweep.get(label[len("sweep: "):]) if label.startswith("sweep: ") else k.get(label)
        if ours is None or not scipy * (1 - 1e-6) <= ours <= 1.03 * scipy:
            failures.append(f"{label}: karkas {ours} against the SciPy rebuild's {scipy}")
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
    # Chashnikov's figures 1 and 2 (coons-fig3): the pictures, and the blending functions'
    # extreme values against the Hermite cubics' closed form (1 at the node; 4/27, the peak of
    # s (1 - s)^2 at s = 1/3).
    fig3 = next((e for e in report["examples"] if e["id"] == "coons-fig3"), None)
    for name in ("coons-blending-fig1.svg", "coons-blending-fig2.svg"):
        if fig3 is None or name not in fig3["pictures"]:
            failures.append(f"coons-fig3: picture {name} missing")
    for label, expected, tolerance in [
        ("001 fig. 1: blending function H_2i, i = 2", 1.0, 1e-12),
        ("001 fig. 2: blending function H_2i+1, i = 2", 4 / 27, 1e-4),
    ]:
        found = [r["karkas"] for r in rows if r["example"] == label]
        if len(found) != 1 or abs(found[0] - expected) > tolerance:
            failures.append(f"{label}: {found} is not {expected}")
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
