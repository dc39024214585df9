"""The documentation of the karkas module: every public callable is documented, numpy style,
with a real signature, and every example in a docstring runs as written.

What is collected comes from introspection, not from a list: the module itself, every name of
`karkas.__all__`, and for every class each public attribute it defines itself (methods, static
methods, properties; inherited ones are checked once, on the class that defines them). A callable
added later is therefore checked without touching this file.

What each docstring must have (numpy style, sections underlined with dashes):

- the module, and every class, function and method: a summary line and an ``Examples`` section
  whose examples run;
- every function and method, and every class that can be constructed from Python: a
  ``Parameters`` section when it takes arguments, a ``Raises`` section when it takes
  arguments (bad arguments raise), and (functions and methods) a ``Returns`` section;
- exceptions: a summary line (they take a message, nothing else);
- properties: a summary line (what they are; the class's examples show them).

Dunder methods (``__call__``, ``__repr__``, ``__len__``, ``__reduce__``, ...) are exempt: Python
shows the slot's generic docstring for them, not ours, so calling conventions are documented in
the class docstring instead. Classes that cannot be constructed from Python (base classes, and
classes only returned by functions) need no Parameters or Raises section.
"""

import doctest
import inspect
import re

import numpy as np
import pytest

import karkas

SECTION = re.compile(r"^\s*(\w+(?: \w+)?)\n\s*-{3,}\s*$", re.MULTILINE)


def sections(doc):
    """The numpy-style section titles of a docstring."""
    return set(SECTION.findall(doc or ""))


def is_exception(obj):
    return inspect.isclass(obj) and issubclass(obj, BaseException)


def constructible(cls):
    """False for a class whose instances only the library makes (no constructor in Python)."""
    try:
        cls()
    except TypeError as e:
        return not ("No constructor defined" in str(e) or "cannot create" in str(e))
    except Exception:  # a constructor that ran and refused the missing arguments
        return True
    return True


def documented():
    """(qualified name, kind, object) for everything public of the module."""
    items = [("karkas", "module", karkas)]
    for name in karkas.__all__:
        if name.startswith("_"):
            continue
        obj = getattr(karkas, name)
        if is_exception(obj):
            items.append((name, "exception", obj))
        elif inspect.isclass(obj):
            items.append((name, "class", obj))
            for attr, raw in vars(obj).items():
                if attr.startswith("_"):
                    continue
                qual = f"{name}.{attr}"
                if isinstance(raw, (property,)) or inspect.isdatadescriptor(raw):
                    items.append((qual, "property", raw))
                elif isinstance(raw, staticmethod) or callable(raw) or inspect.ismethoddescriptor(raw):
                    items.append((qual, "method", getattr(obj, attr)))
        elif callable(obj):
            items.append((name, "function", obj))
    return items


ITEMS = documented()
CALLABLES = [i for i in ITEMS if i[1] in ("function", "method")]
CLASSES = [i for i in ITEMS if i[1] == "class"]
IDS = [i[0] for i in ITEMS]


def takes_arguments(obj):
    params = list(inspect.signature(obj).parameters.values())
    return any(p.name not in ("self", "cls") for p in params)


@pytest.mark.parametrize("name,kind,obj", ITEMS, ids=IDS)
def test_has_a_summary_line(name, kind, obj):
    doc = inspect.getdoc(obj)
    assert doc and doc.strip(), f"{name} has no docstring"
    first = doc.strip().splitlines()[0]
    assert first.strip() and not first.startswith(("Parameters", "Returns")), (
        f"{name}: the docstring must open with a summary line"
    )


@pytest.mark.parametrize("name,kind,obj", CALLABLES + CLASSES, ids=[i[0] for i in CALLABLES + CLASSES])
def test_numpy_sections(name, kind, obj):
    doc = inspect.getdoc(obj)
    found = sections(doc)
    assert "Examples" in found, f"{name}: no Examples section (found {sorted(found)})"
    if kind == "class":
        if not constructible(obj):
            return
        needed = {"Parameters", "Raises"} if takes_arguments(obj) else set()
    else:
        needed = {"Returns"}
        if takes_arguments(obj):
            needed |= {"Parameters", "Raises"}
    missing = needed - found
    assert not missing, f"{name}: missing sections {sorted(missing)} (found {sorted(found)})"
    if "Parameters" in needed:
        # Every argument of the signature is described in Parameters.
        params = doc.split("Parameters", 1)[1]
        params = re.split(r"\n\s*\w+(?: \w+)?\n\s*-{3,}", params[params.index("\n") + 1:], maxsplit=1)[0]
        for p in inspect.signature(obj).parameters:
            if p in ("self", "cls"):
                continue
            assert re.search(rf"(^|[\s,]){re.escape(p)}\b", params), (
                f"{name}: argument {p!r} is not described under Parameters"
            )


def test_module_examples():
    assert "Examples" in sections(karkas.__doc__)


@pytest.mark.parametrize("name,kind,obj", CALLABLES + CLASSES, ids=[i[0] for i in CALLABLES + CLASSES])
def test_real_signature(name, kind, obj):
    if kind == "class" and not constructible(obj):
        return
    sig = inspect.signature(obj)  # raises ValueError when Python has no signature
    params = list(sig.parameters.values())
    kinds = {p.kind for p in params}
    assert not (
        inspect.Parameter.VAR_POSITIONAL in kinds and inspect.Parameter.VAR_KEYWORD in kinds
    ), f"{name}: signature {sig} is not the real one"
    for p in params:
        assert p.default is not Ellipsis, f"{name}: default of {p.name} shows as ... in {sig}"


@pytest.mark.parametrize(
    "name,kind,obj",
    [i for i in ITEMS if i[1] != "property"],
    ids=[i[0] for i in ITEMS if i[1] != "property"],
)
def test_examples_run(name, kind, obj, tmp_path, monkeypatch):
    """The examples of the docstring run with doctest (in an empty temporary folder, with
    numpy as np and karkas in scope) and print what they say."""
    doc = inspect.getdoc(obj) or ""
    monkeypatch.chdir(tmp_path)
    globs = {"np": np, "karkas": karkas}
    parser = doctest.DocTestParser()
    test = parser.get_doctest(doc, globs, name, None, 0)
    if kind in ("exception",) and not test.examples:
        return
    assert test.examples, f"{name}: no doctest examples"
    runner = doctest.DocTestRunner(
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, verbose=False
    )
    out = []
    with np.printoptions(legacy=False):
        runner.run(test, out=out.append)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} examples failed\n" + "".join(out)


def test_everything_is_collected():
    """The collection sees the classes' own methods and properties (a check of this file)."""
    assert "Curve.sample" in IDS and "Curve.domain" in IDS and "LLCurve.interpolate" in IDS
    assert "fit_curve" in IDS and "KarkasError" in IDS
