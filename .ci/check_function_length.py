#!/usr/bin/env python3
"""Function length check for the workspace (python3, standard library only).

Every `fn` with a body in crates/*/src (test modules included) spans at most MAX_LINES lines,
counted from the line of its `fn` keyword to the line of its closing brace (doc comments and
attributes above it not counted). Comments, strings and chars are skipped by the tokenizer of
check_layers.py, so a brace inside them does not count.

Usage: .ci/check_function_length.py [--root DIR]  check the workspace (default: the repository)
       .ci/check_function_length.py --self-test   check that a synthetic long function fails
                                                  and a short one with tricky braces passes
Exit status 1 when a function is too long, with one line per function: file:line, name, lines.
"""

import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_layers import IDENT, root_argument, rust_sources  # noqa: E402

MAX_LINES = 80


def function_spans(tokens):
    """(name, first line, last line) of every function with a body, nested ones included."""
    spans = []
    for i, (tok, line) in enumerate(tokens):
        if tok != "fn" or i + 1 >= len(tokens) or not IDENT.fullmatch(tokens[i + 1][0]):
            continue
        j, depth = i + 2, 0
        # The body is the first `{` outside the signature's brackets; a `;` first means none.
        while j < len(tokens):
            t = tokens[j][0]
            if t in "([":
                depth += 1
            elif t in ")]":
                depth -= 1
            elif depth == 0 and t in "{;":
                break
            j += 1
        if j >= len(tokens) or tokens[j][0] == ";":
            continue
        braces = 0
        for k in range(j, len(tokens)):
            t = tokens[k][0]
            braces += (t == "{") - (t == "}")
            if braces == 0:
                spans.append((tokens[i + 1][0], line, tokens[k][1]))
                break
    return spans


def check(root):
    failures = []
    crates = os.path.join(root, "crates")
    for crate in sorted(os.listdir(crates)):
        for path, tokens in rust_sources(os.path.join(crates, crate, "src")):
            for fn, first, last in function_spans(tokens):
                if last - first + 1 > MAX_LINES:
                    rel = os.path.relpath(path, root)
                    failures.append(f"{rel}:{first}: fn {fn} spans {last - first + 1} lines")
    return failures


def self_test():
    long_body = "".join(f"    let x{k} = {k};\n" for k in range(MAX_LINES - 1))
    tricky = (
        "/// A doc comment does not count, nor a } in a comment.\n"
        "#[inline]\n"
        "fn short<'a>(s: &'a str, f: fn(u8) -> u8) -> char {\n"
        "    let _ = \"} { }\"; // }\n"
        "    let _ = r#\"}\"#;\n"
        "    '}'\n"
        "}\n"
        "trait T { fn declared(&self); fn defaulted(&self) {} }\n"
    )
    cases = [
        (tricky + "fn fits() {\n" + long_body[: -len("    let x78 = 78;\n")] + "}\n", 0),
        ("fn too_long() {\n" + long_body + "}\n", 1),
        ("impl A {\n    fn outer() {\n        fn inner() {\n" + long_body + "        }\n    }\n}\n", 2),
    ]
    for text, expected in cases:
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "crates", "a", "src"))
            with open(os.path.join(root, "crates", "a", "src", "lib.rs"), "w") as f:
                f.write(text)
            got = check(root)
            if len(got) != expected:
                sys.exit(f"check_function_length self-test: expected {expected} failures, got {got}")
    print("check_function_length self-test: a function over the limit fails, braces in strings, "
          "comments and chars do not count")


def main(argv):
    if "--self-test" in argv:
        self_test()
        return 0
    failures = check(os.path.abspath(root_argument(argv)))
    for line in failures:
        print(line)
    if failures:
        print(f"{len(failures)} function(s) over {MAX_LINES} lines", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
