#!/usr/bin/env python3
"""Counts the public constructors and fitting entry points of the library crates (karkas,
karkas-io) and how many carry a runnable example (a ``` block in their doc comment, which
`cargo test --doc` runs).

A constructor is a `pub fn` of an inherent `impl` block that takes no `self` and returns the
type (`Self`, `Result<Self, _>`, `Option<Self>`); a fitting entry point is a free `pub fn` named
`fit*`, `fair*`, `loft*` or `interpolate*`. Items in private modules are counted too (the count
is of source items, a slight over-count of the public API).

Usage: tests/docs/count_examples.py [--list] [--min-share F]
(--min-share: fail when fewer than this share carry an example).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
CRATES = [REPO / "crates" / "karkas" / "src", REPO / "crates" / "karkas-io" / "src"]
ENTRY = re.compile(r"^(fit|fair|loft|interpolate)")


def items(path: Path):
    lines = path.read_text(encoding="utf-8").split("\n")
    depth = 0
    impl_stack: list[tuple[int, bool]] = []  # (depth at which the impl opened, inherent)
    docs: list[str] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if stripped.startswith("#[cfg(test)]"):
            break  # test modules sit at the end of the file
        if stripped.startswith("///"):
            docs.append(stripped)
        elif stripped.startswith("#[") or not stripped:
            pass
        else:
            m = re.match(r"^(pub(\(crate\))? )?(const )?fn (\w+)", stripped)
            if stripped.startswith("impl") and not re.search(r"\bfor\b", stripped.split("{")[0]):
                impl_stack.append((depth, True))
            elif stripped.startswith("impl"):
                impl_stack.append((depth, False))
            if m and stripped.startswith("pub fn") or (m and stripped.startswith("pub const fn")):
                sig = stripped
                j = i
                while "{" not in sig and ";" not in sig and j + 1 < len(lines):
                    j += 1
                    sig += " " + lines[j].strip()
                name = m.group(4)
                params = sig[sig.find("("):]
                ret = sig.split("->", 1)[1].split("{")[0] if "->" in sig else ""
                has_example = any("```" in d for d in docs)
                in_inherent = bool(impl_stack) and impl_stack[-1][1]
                takes_self = re.search(r"\(\s*&?\s*(mut\s+)?self\b", params) is not None
                if in_inherent and not takes_self and re.search(r"\bSelf\b", ret):
                    yield ("constructor", name, i + 1, has_example)
                elif not impl_stack and ENTRY.match(name):
                    yield ("entry point", name, i + 1, has_example)
            docs = []
        depth += line.count("{") - line.count("}")
        while impl_stack and depth <= impl_stack[-1][0]:
            impl_stack.pop()
        i += 1


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--list", action="store_true", help="list the items without an example")
    ap.add_argument("--min-share", type=float, default=0.0)
    args = ap.parse_args()
    found = []
    for root in CRATES:
        for path in sorted(root.rglob("*.rs")):
            for kind, name, line, ok in items(path):
                found.append((kind, name, path.relative_to(REPO), line, ok))
    for kind in ("constructor", "entry point"):
        sel = [f for f in found if f[0] == kind]
        with_ex = sum(f[4] for f in sel)
        print(f"{kind}s: {len(sel)}, with a runnable example {with_ex}, without {len(sel) - with_ex}")
    if args.list:
        for kind, name, path, line, ok in found:
            if not ok:
                print(f"  no example: {kind} {name} ({path}:{line})")
    share = sum(f[4] for f in found) / max(1, len(found))
    print(f"share with an example: {share:.2f}")
    return 0 if share >= args.min_share else 1


if __name__ == "__main__":
    sys.exit(main())
