#!/usr/bin/env python3
"""Counts the public constructors and fitting entry points of the library crates (karkas,
karkas-io) and how many carry a runnable example (a ``` block in their doc comment, which
`cargo test --doc` runs).

A constructor is a `pub fn` of an inherent `impl` block that takes no `self` and returns the
type, named `Self` or by its name (`Self`, `Result<Self, _>`, `Option<Foo>`, `Result<Foo>`); a fitting entry point is a free `pub fn` named
`fit*`, `fair*`, `loft*` or `interpolate*`.

Only items a user of the crate can name are counted, judged the way the compiler does: a
module is reachable when every `mod` on its path from the crate root is `pub mod`; a type or
free function is reachable when it is a bare `pub` item of a reachable module, or when a bare
`pub use` (plain, braced, renamed with `as`, or a glob) in a reachable module names it, followed
through chains of such re-exports (a `pub use` in a private module counts only when a reachable
module re-exports it in turn). A constructor is reachable when its type is. This cannot be gamed
by hiding: a constructor or entry point declared `pub` whose type or module is NOT reachable is
reported as an error ("unreachable pub") and fails the run, so every `pub` constructor either
carries an example or is narrowed to `pub(crate)`, which the compiler then holds to (a crate
that used it would no longer build). The check of the compiler's own judgement is the doctests
themselves: an example that names an unreachable item does not compile.

Usage: tests/docs/count_examples.py [--list] [--min-share F]
(--min-share: fail when fewer than this share of the reachable items carry an example; CI
passes 1.0, so a new public constructor without an example fails).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
CRATES = [REPO / "crates" / "karkas" / "src", REPO / "crates" / "karkas-io" / "src"]
ENTRY = re.compile(r"^(fit|fair|loft|interpolate)")

Mod = tuple  # a module path, e.g. ("coons", "blending")


def module_of(root: Path, path: Path) -> Mod:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] in ("lib", "mod"):
        parts = parts[:-1]
    return tuple(parts)


def code_lines(path: Path) -> list[str]:
    """The file's lines with every `#[cfg(test)]` item blanked (line numbers kept)."""
    lines = path.read_text(encoding="utf-8").split("\n")
    out = list(lines)
    i = 0
    while i < len(lines):
        if lines[i].strip().startswith("#[cfg(test)]"):
            depth, opened = 0, False
            j = i
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                opened = opened or "{" in lines[j]
                out[j] = ""
                if (opened and depth <= 0) or (not opened and lines[j].rstrip().endswith(";")):
                    break
                j += 1
            i = j
        i += 1
    return out


def strip_generics(text: str) -> str:
    out, depth = [], 0
    for ch in text:
        if ch == "<":
            depth += 1
        elif ch == ">" and depth:
            depth -= 1
        elif not depth:
            out.append(ch)
    return "".join(out)


def expand_use(tree: str) -> list[tuple[list[str], str]]:
    """`a::{b, c::{d as e}}` -> [(["a", "b"], "b"), (["a", "c", "d"], "e")]; globs give "*"."""
    tree = tree.strip()
    brace = tree.find("{")
    if brace < 0:
        m = re.match(r"^([\w:*]+)(\s+as\s+(\w+))?$", tree)
        if not m:
            return []
        segs = [s for s in m.group(1).split("::") if s]
        return [(segs, m.group(3) or segs[-1])]
    prefix = [s for s in tree[:brace].split("::") if s]
    inner = tree[brace + 1 : tree.rfind("}")]
    parts, depth, cur = [], 0, ""
    for ch in inner:
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        cur += ch
    parts.append(cur)
    out = []
    for p in parts:
        if p.strip():
            for segs, name in expand_use(p):
                if segs == ["self"]:
                    out.append((prefix, prefix[-1]))
                else:
                    out.append((prefix + segs, name))
    return out


class Crate:
    def __init__(self, root: Path):
        self.root = root
        self.files = {module_of(root, p): p for p in sorted(root.rglob("*.rs"))}
        self.pub_mod: dict[Mod, bool] = {(): True}
        self.defs: dict[Mod, set[str]] = {}  # bare-pub types and free functions per module
        self.uses: list[tuple[Mod, str, Mod, str]] = []  # (module, alias) -> (module, name)
        for mod, path in self.files.items():
            self.scan(mod, code_lines(path))

    def scan(self, mod: Mod, lines: list[str]) -> None:
        text = "\n".join(lines)
        for m in re.finditer(r"^\s*(pub(\([\w:]+\))?\s+)?mod\s+(\w+)\s*;", text, re.M):
            self.pub_mod[mod + (m.group(3),)] = bool(m.group(1)) and not m.group(2)
        defs = self.defs.setdefault(mod, set())
        for m in re.finditer(r"^pub\s+(struct|enum|trait|type|fn|const fn|union)\s+(\w+)", text, re.M):
            defs.add(m.group(2))
        for m in re.finditer(r"^\s*pub\s+use\s+([^;]+);", text, re.M):
            for segs, alias in expand_use(m.group(1)):
                target = self.resolve(mod, segs[:-1])
                if target is not None:
                    self.uses.append((mod, alias, target, segs[-1]))

    def resolve(self, mod: Mod, segs: list[str]) -> Mod | None:
        if not segs:
            return mod
        if segs[0] == "crate":
            base, rest = (), segs[1:]
        elif segs[0] == "self":
            base, rest = mod, segs[1:]
        elif segs[0] == "super":
            base, rest = mod[:-1], segs[1:]
            while rest and rest[0] == "super":
                base, rest = base[:-1], rest[1:]
        elif mod + (segs[0],) in self.pub_mod:
            base, rest = mod, segs
        else:
            return None  # another crate
        return base + tuple(rest)

    def reachable_module(self, mod: Mod) -> bool:
        return all(self.pub_mod.get(mod[: i + 1], False) for i in range(len(mod)))

    def reachable(self) -> set[tuple[Mod, str]]:
        names: set[tuple[Mod, str]] = set()
        for mod, defs in self.defs.items():
            if self.reachable_module(mod):
                names |= {(mod, d) for d in defs}
        for mod, alias, _, _ in self.uses:
            if self.reachable_module(mod):
                names.add((mod, alias))
        changed = True
        while changed:
            changed = False
            for mod, alias, target, name in self.uses:
                if (mod, alias) not in names and not (alias == "*" and self.reachable_module(mod)):
                    continue
                if name == "*":
                    new = {(target, d) for d in self.defs.get(target, ())}
                    new |= {(m, a) for m, a, _, _ in self.uses if m == target}
                else:
                    new = {(target, name)}
                if not new <= names:
                    names |= new
                    changed = True
        return names

    def home_of(self, mod: Mod, type_name: str) -> Mod | None:
        """The module that defines `type_name`, seen from an impl block in `mod`."""
        homes = [m for m, d in self.defs.items() if type_name in d]
        for m in [mod] + [mod[:i] for i in range(len(mod) - 1, -1, -1)]:
            near = [h for h in homes if h[: len(m)] == m]
            if len(near) == 1 or m == mod and mod in near:
                return near[0] if len(near) == 1 else mod
        return homes[0] if len(homes) == 1 else None


def items(crate: Crate, mod: Mod, lines: list[str]):
    """(kind, name, type name or None, line, has example, declared pub) for each candidate."""
    depth = 0
    impl_stack: list[tuple[int, str | None]] = []  # (depth at which it opened, inherent type)
    docs: list[str] = []
    for i, line in enumerate(lines):
        stripped = line.strip()
        if stripped.startswith("///"):
            docs.append(stripped)
        elif stripped.startswith("#[") or not stripped:
            pass
        else:
            if stripped.startswith("impl"):
                head = strip_generics(stripped.split("{")[0])
                m = re.match(r"^impl\s+([\w:]+)", head)
                inherent = m and not re.search(r"\bfor\b", head)
                impl_stack.append((depth, m.group(1).split("::")[-1] if inherent else None))
            m = re.match(r"^pub(\([\w:]+\))?\s+(const\s+)?fn\s+(\w+)", stripped)
            if m:
                sig, j = stripped, i
                while "{" not in sig and ";" not in sig and j + 1 < len(lines):
                    j += 1
                    sig += " " + lines[j].strip()
                name = m.group(3)
                params = sig[sig.find("(") :]
                ret = sig.split("->", 1)[1].split("{")[0] if "->" in sig else ""
                has_example = any("```" in d for d in docs)
                is_pub = m.group(1) is None
                owner = impl_stack[-1][1] if impl_stack else None
                takes_self = re.search(r"\(\s*&?\s*(mut\s+)?self\b", params) is not None
                returns_own = re.search(rf"\b(Self|{owner})\b", ret) if owner else None
                if owner and not takes_self and returns_own:
                    yield ("constructor", name, owner, i + 1, has_example, is_pub)
                elif not impl_stack and ENTRY.match(name):
                    yield ("entry point", name, None, i + 1, has_example, is_pub)
            docs = []
        depth += line.count("{") - line.count("}")
        while impl_stack and depth <= impl_stack[-1][0]:
            impl_stack.pop()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--list", action="store_true", help="list the items without an example")
    ap.add_argument("--min-share", type=float, default=0.0)
    args = ap.parse_args()
    found, unreachable = [], []
    for root in CRATES:
        crate = Crate(root)
        names = crate.reachable()
        for mod, path in crate.files.items():
            for kind, name, owner, line, ok, is_pub in items(crate, mod, code_lines(path)):
                if not is_pub:
                    continue
                if owner:
                    home = crate.home_of(mod, owner)
                    label = f"{owner}::{name}"
                    seen = home is not None and (home, owner) in names
                else:
                    label = name
                    seen = (mod, name) in names
                where = f"{path.relative_to(REPO)}:{line}"
                if seen:
                    found.append((kind, label, where, ok))
                else:
                    unreachable.append((kind, label, where))
    for kind in ("constructor", "entry point"):
        sel = [f for f in found if f[0] == kind]
        with_ex = sum(f[3] for f in sel)
        print(f"{kind}s: {len(sel)}, with a runnable example {with_ex}, without {len(sel) - with_ex}")
    if args.list:
        for kind, label, where, ok in found:
            if not ok:
                print(f"  no example: {kind} {label} ({where})")
    for kind, label, where in unreachable:
        print(f"  unreachable pub (make it pub(crate) or export its type): {kind} {label} ({where})")
    share = sum(f[3] for f in found) / max(1, len(found))
    print(f"share with an example: {share:.2f}")
    return 0 if share >= args.min_share and not unreachable else 1


if __name__ == "__main__":
    sys.exit(main())
