#!/usr/bin/env python3
"""Checks the report of `karkas demo`: every example is there, every file it names exists,
and the cylinder row of Kuznetsov and Filatov's table lands in 0.008..0.013 (the paper prints 0.011).

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
]


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
