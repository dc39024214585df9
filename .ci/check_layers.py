#!/usr/bin/env python3
"""Import structure checks for the workspace (python3, standard library only).

1. Layers of the library crate crates/karkas: every `crate::` path (in `use` lines, grouped
   `use crate::{a::.., b::..}` and written inline in code; comments, doc comments and string
   literals ignored) is mapped from the top-level module of its file to the top-level module
   where the named item lives (root re-exports such as `crate::Point` or `crate::Result` are
   followed to their home module). An import that runs up or sideways in LAYERS fails.
2. File-level import cycles in every crate under crates/*/src: a file that names an item of
   another file of the same crate (`super::x`, `crate::m::x`, `child::x`, inline or in `use`)
   depends on it; re-exports (`pub use`) are followed to the file that defines the item and
   are not dependencies themselves. Every cycle fails.
3. Front ends (the CLI, Python and WASM crates in FRONT_ENDS) name the fit only through what
   crates/karkas/src/fit/mod.rs exports: a path `karkas::fit::m::..` with `m` one of the fit's
   own files or folders (its internals: the method, its measured-data stages, the tolerance
   rounds and repairs) fails, and so does a `pub mod` in fit/mod.rs that would expose them.

Usage: .ci/check_layers.py [--root DIR]    check the workspace (default: the repository)
       .ci/check_layers.py --self-test     check that a synthetic tree with an upward import
                                           and a cycle fails
Exit status 1 when something fails, with one line per offending file:line.
"""

import os
import re
import sys
import tempfile

# Layers of crates/karkas, lowest first. A module may import modules of lower layers only;
# `error` may be imported by every module and imports none. `ONLY` narrows a module further.
LAYERS = [
    ["core"],
    ["solve", "bspline", "geometry"],
    ["spline"],
    ["ll", "dps", "fit", "param", "implicit"],
    ["coons", "section", "measure", "fair"],
    ["loft"],
    ["shape"],
]
ANYWHERE = {"error"}
ONLY = {"bspline": {"core"}}
LIBRARY = "crates/karkas"
# Front ends and the library folders whose internals they may not name (rule 3).
FRONT_ENDS = ["crates/karkas-cli", "crates/karkas-py", "crates/karkas-wasm"]
SEALED = ["fit"]

IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def tokenize(text):
    """Tokens (text, line) of Rust source with comments, strings and chars removed."""
    tokens = []
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif c.isspace():
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            depth, i = 1, i + 2
            while i < n and depth:
                if text.startswith("/*", i):
                    depth, i = depth + 1, i + 2
                elif text.startswith("*/", i):
                    depth, i = depth - 1, i + 2
                else:
                    line += text[i] == "\n"
                    i += 1
        elif re.match(r'b?r#*"', text[i:i + 260]):
            m = re.match(r'b?r(#*)"', text[i:])
            end = text.find('"' + m.group(1), i + m.end())
            end = n if end < 0 else end + 1 + len(m.group(1))
            line += text.count("\n", i, end)
            i = end
        elif c == '"' or text.startswith('b"', i):
            i += 1 if c == '"' else 2
            start = i
            while i < n and text[i] != '"':
                i += 2 if text[i] == "\\" else 1
            line += text.count("\n", start, i)
            i += 1
        elif c == "'" or text.startswith("b'", i):
            j = i + (1 if c == "'" else 2)
            if j < n and text[j] == "\\":
                k = text.find("'", j + 2)
                i = n if k < 0 else k + 1
            elif j + 1 < n and text[j + 1] == "'":
                i = j + 2
            else:  # a lifetime or a label
                i = j
        elif c.isalpha() or c == "_":
            m = IDENT.match(text, i)
            tokens.append((m.group(0), line))
            i = m.end()
        elif text.startswith("::", i):
            tokens.append(("::", line))
            i += 2
        else:
            tokens.append((c, line))
            i += 1
    return tokens


class SourceFile:
    def __init__(self, path, module, children):
        self.path = path
        self.module = module  # module path from the crate root, e.g. ("coons", "surface")
        self.children = children  # names of child modules backed by files
        self.paths = []  # (absolute path tuple, line, inside `pub use`)
        self.reexports = {}  # name -> absolute path tuple


def parse_path(tokens, i):
    """Paths (segment lists, '*' for a glob) starting at token i, and the index after."""
    segments = []
    while i < len(tokens):
        tok = tokens[i][0]
        if tok == "{":
            results, i = [], i + 1
            while i < len(tokens) and tokens[i][0] != "}":
                if tokens[i][0] == ",":
                    i += 1
                    continue
                sub, i = parse_path(tokens, i)
                for s in sub:
                    results.append(segments + ([] if s == ["self"] else s))
            return results, i + 1
        if tok == "*":
            return [segments + ["*"]], i + 1
        if not IDENT.fullmatch(tok):
            break
        segments.append(tok)
        i += 1
        if i + 1 < len(tokens) and tokens[i][0] == "::" and tokens[i + 1][0] != "<":
            i += 1
            continue
        if i < len(tokens) and tokens[i][0] == "as":
            alias = tokens[i + 1][0]
            return [segments + ["as", alias]], i + 2
        break
    return [segments], i


def collect(source, tokens):
    """Fill source.paths and source.reexports from the tokens of one file."""
    scopes = []  # (brace depth where an inline module opened, its name)
    depth = 0
    in_use = None  # None, "use" or "pub use" while inside a use statement
    i = 0
    while i < len(tokens):
        tok, line = tokens[i]
        prev = tokens[i - 1][0] if i else ""
        if tok == "{":
            depth += 1
        elif tok == "}":
            depth -= 1
            while scopes and scopes[-1][0] > depth:
                scopes.pop()
        elif tok == ";":
            in_use = None
        if tok == "mod" and i + 2 < len(tokens) and tokens[i + 2][0] == "{":
            scopes.append((depth + 1, tokens[i + 1][0]))
        if tok == "use" and prev != "::":
            j = i - 1
            while j >= 0 and tokens[j][0] in ("(", ")", "crate", "super", "self", "in"):
                j -= 1
            in_use = "pub use" if j >= 0 and tokens[j][0] == "pub" else "use"
        current = source.module + tuple(name for _, name in scopes)
        starts = tok in ("crate", "super", "self") or (
            not scopes and tok in source.children
        )
        if (
            starts
            and prev != "::"
            and i + 1 < len(tokens)
            and tokens[i + 1][0] == "::"
        ):
            paths, end = parse_path(tokens, i)
            for segs in paths:
                alias = None
                if len(segs) >= 2 and segs[-2] == "as":
                    alias, segs = segs[-1], segs[:-2]
                absolute = absolutize(segs, current)
                if absolute is None:
                    continue
                public = in_use == "pub use"
                source.paths.append((absolute, line, public))
                if public and absolute and absolute[-1] != "*":
                    source.reexports[alias or absolute[-1]] = absolute
            i = max(end, i + 1)
            continue
        i += 1


def absolutize(segs, current):
    base = list(current)
    k = 0
    if segs and segs[0] == "crate":
        base, k = [], 1
    else:
        while k < len(segs) and segs[k] in ("super", "self"):
            if segs[k] == "super":
                if not base:
                    return None
                base.pop()
            k += 1
    return tuple(base + segs[k:])


def load_crate(src_dir):
    """The crate's files by module path, parsed."""
    files = {}
    for root, _, names in os.walk(src_dir):
        for name in names:
            if not name.endswith(".rs"):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, src_dir)[:-3].split(os.sep)
            if rel[-1] == "mod":
                rel = rel[:-1]
            if rel in (["lib"], ["main"]):
                rel = []
            if rel and rel[0] == "bin":
                continue
            files.setdefault(tuple(rel), path)
    sources = {}
    for module, path in files.items():
        children = {m[-1] for m in files if len(m) == len(module) + 1 and m[:-1] == module}
        source = SourceFile(path, module, children)
        with open(path, encoding="utf-8") as f:
            collect(source, tokenize(f.read()))
        sources[module] = source
    return sources


def resolve(sources, absolute, seen=None):
    """The module path of the file that defines the item `absolute` names."""
    seen = seen or set()
    k = len(absolute)
    while k > 0 and absolute[:k] not in sources:
        k -= 1
    module = absolute[:k]
    if k < len(absolute) and module in sources:
        target = sources[module].reexports.get(absolute[k])
        if target is not None and target not in seen:
            seen.add(target)
            return resolve(sources, target + absolute[k + 1:], seen)
    return module


def layer_of(module):
    for index, names in enumerate(LAYERS):
        if module in names:
            return index
    return None


def check_layers(src_dir, rel):
    problems = []
    sources = load_crate(src_dir)
    for module, source in sorted(sources.items()):
        if not module:
            continue  # the crate root only declares modules and re-exports
        top = module[0]
        for absolute, line, _ in source.paths:
            target = resolve(sources, absolute)
            if not target or target[0] == top:
                continue
            dest = target[0]
            where = f"{rel(source.path)}:{line}"
            if top in ANYWHERE:
                problems.append(f"{where}: {top} -> {dest} ({top} imports no module)")
            elif dest in ANYWHERE:
                continue
            elif layer_of(top) is None or layer_of(dest) is None:
                unknown = top if layer_of(top) is None else dest
                problems.append(f"{where}: {top} -> {dest} ({unknown} is in no layer)")
            elif top in ONLY and dest not in ONLY[top]:
                allowed = ", ".join(sorted(ONLY[top]))
                problems.append(f"{where}: {top} -> {dest} ({top} imports {allowed} only)")
            elif layer_of(dest) >= layer_of(top):
                kind = "sideways" if layer_of(dest) == layer_of(top) else "up"
                problems.append(f"{where}: {top} -> {dest} (runs {kind})")
    return list(dict.fromkeys(problems))


def check_cycles(src_dir, rel):
    sources = load_crate(src_dir)
    edges = {m: {} for m in sources}
    for module, source in sources.items():
        for absolute, line, public in source.paths:
            if public:
                continue
            target = resolve(sources, absolute)
            if target != module and target in sources:
                edges[module].setdefault(target, line)
    problems = []
    for component in strongly_connected(edges):
        if len(component) < 2:
            continue
        members = set(component)
        lines = [
            f"{rel(sources[a].path)}:{edges[a][b]}: -> {rel(sources[b].path)}"
            for a in sorted(members)
            for b in sorted(edges[a])
            if b in members
        ]
        names = ", ".join(rel(sources[m].path) for m in sorted(members))
        problems.append(f"file-level import cycle among {names}:\n    " + "\n    ".join(lines))
    return problems


def strongly_connected(edges):
    """Tarjan's strongly connected components (iterative)."""
    index, low, on_stack, stack, result = {}, {}, set(), [], []
    counter = 0
    for root in sorted(edges):
        if root in index:
            continue
        work = [(root, iter(sorted(edges[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, it = work[-1]
            advanced = False
            for nxt in it:
                if nxt not in index:
                    index[nxt] = low[nxt] = counter
                    counter += 1
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(edges[nxt]))))
                    advanced = True
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                result.append(component)
    return result


def check_sealed(root, rel):
    """Rule 3: front ends name no internal module of a SEALED library folder."""
    library = os.path.join(root, LIBRARY, "src")
    sources = load_crate(library)
    problems = []
    internals = {}
    for folder in SEALED:
        source = sources.get((folder,))
        if source is None:
            continue
        internals[folder] = source.children
        with open(source.path, encoding="utf-8") as f:
            tokens = tokenize(f.read())
        for k in range(len(tokens) - 2):
            if tokens[k][0] == "pub" and tokens[k + 1][0] == "mod":
                problems.append(
                    f"{rel(source.path)}:{tokens[k][1]}: pub mod {tokens[k + 2][0]} "
                    f"(the internals of {folder} stay private; export items instead)"
                )
    for crate in FRONT_ENDS:
        for path, tokens in rust_sources(os.path.join(root, crate, "src")):
            for k, (tok, line) in enumerate(tokens):
                if tok != "karkas" or (k and tokens[k - 1][0] == "::"):
                    continue
                for segs in parse_path(tokens, k)[0]:
                    if len(segs) >= 3 and segs[1] in internals and segs[2] in internals[segs[1]]:
                        problems.append(
                            f"{rel(path)}:{line}: karkas::{segs[1]}::{segs[2]} "
                            f"(front ends use what {segs[1]}/mod.rs exports only)"
                        )
    return list(dict.fromkeys(problems))


def run(root):
    def rel(path):
        return os.path.relpath(path, root)

    problems = []
    library = os.path.join(root, LIBRARY, "src")
    if os.path.isdir(library):
        problems += check_layers(library, rel)
        problems += check_sealed(root, rel)
    crates = os.path.join(root, "crates")
    for name in sorted(os.listdir(crates)):
        src = os.path.join(crates, name, "src")
        if os.path.isdir(src):
            problems += check_cycles(src, rel)
    return problems


def self_test():
    files = {
        "crates/karkas/src/lib.rs": "pub mod core;\npub mod ll;\nmod error;\n"
        "pub use crate::core::Point;\npub use error::Result;\n",
        "crates/karkas/src/error.rs": "pub type Result<T> = std::result::Result<T, ()>;\n",
        "crates/karkas/src/core/mod.rs": "mod grid;\nmod point;\npub use point::Point;\n",
        # Upward inside a group of a `use` line (error is fine from anywhere).
        "crates/karkas/src/core/grid.rs": "use crate::{error::Result, ll::{curve::g}};\n",
        # Upward: core names ll inline, behind a comment and a string that must not count.
        "crates/karkas/src/core/point.rs": "// crate::ll::x in a comment\n"
        "pub struct Point;\nfn f() { let _ = \"crate::ll\"; crate::ll::curve::g(); }\n",
        "crates/karkas/src/ll/mod.rs": "pub mod curve;\nmod surface;\n",
        # Allowed: ll -> core (through the root re-export) and ll -> error.
        "crates/karkas/src/ll/curve.rs": "use crate::{Point, Result};\n"
        "use super::surface::h;\npub fn g() {}\n",
        "crates/karkas/src/ll/surface.rs": "pub fn h() { super::curve::g() }\n",
        # Rule 3: a front end naming a fit internal, and one exposed by `pub mod`.
        "crates/karkas/src/fit/mod.rs": "mod penalty;\npub mod rounds;\npub use penalty::fit;\n",
        "crates/karkas/src/fit/penalty.rs": "pub fn fit() {}\n",
        "crates/karkas/src/fit/rounds.rs": "pub fn round() {}\n",
        "crates/karkas-cli/src/main.rs": "use karkas::fit::{fit, penalty::Settings};\n"
        "fn main() { karkas::fit::fit(); }\n",
    }
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            full = os.path.join(root, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as f:
                f.write(text)
        problems = run(root)
    report = "\n".join(problems)
    expected_up = "crates/karkas/src/core/point.rs:3: core -> ll (runs up)"
    assert expected_up in report, report
    assert "file-level import cycle" in report and "ll/surface.rs" in report, report
    assert "crates/karkas/src/core/grid.rs:1: core -> ll (runs up)" in report, report
    assert "crates/karkas-cli/src/main.rs:1: karkas::fit::penalty" in report, report
    assert "crates/karkas/src/fit/mod.rs:2: pub mod rounds" in report, report
    assert len(problems) == 5, report
    print(
        "check_layers self-test: the synthetic upward import, cycle and front end naming a fit "
        "internal fail, as they must"
    )


def root_argument(argv):
    """The tree to check: `--root DIR`, else the repository holding this script."""
    if "--root" in argv:
        return argv[argv.index("--root") + 1]
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def rust_sources(src):
    """(path, tokens) of every .rs file below the folder `src`, folders and files in name
    order."""
    for folder, _, names in sorted(os.walk(src)):
        for name in sorted(names):
            if name.endswith(".rs"):
                path = os.path.join(folder, name)
                with open(path, encoding="utf-8") as f:
                    yield path, tokenize(f.read())


def main(argv):
    if "--self-test" in argv:
        self_test()
        return 0
    root = os.path.normpath(root_argument(argv))
    problems = run(root)
    for p in problems:
        print(p)
    if problems:
        print(f"check_layers: {len(problems)} problem(s)")
        return 1
    print(
        "check_layers: imports run down the layers, no file-level cycle, front ends use the "
        "fit's exports only"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
