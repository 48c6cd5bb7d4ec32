"""Every public name of the fspm module explains itself: classes, functions, methods and
properties have a docstring beyond pybind11's generated signature, and fields named with a unit
(length_m, angle_deg, lifetime_years, turn_rad) say that unit."""
import inspect
import re

import fspm

# Suffix of a field name -> pattern its docstring must contain.
UNITS = {
    "_m": re.compile(r"\bm\b|metre", re.IGNORECASE),
    "_deg": re.compile(r"degree", re.IGNORECASE),
    "_years": re.compile(r"year", re.IGNORECASE),
    "_rad": re.compile(r"\brad\b|radian", re.IGNORECASE),
}


def _public(names):
    return sorted(n for n in names if not n.startswith("_"))


def _signature_line(line, name):
    """pybind11 writes `name(arg: type, ...) -> type` (numbered for overloads) before the text."""
    line = re.sub(r"^\d+\. ", "", line.strip())
    return line.startswith(name + "(") and line.endswith(")") or re.match(
        re.escape(name) + r"\(.*\) -> .+$", line
    ) is not None


def _explained(doc, name):
    """True when `doc` has text besides pybind11's signatures; for an overloaded function every
    overload needs some."""
    if not doc or not doc.strip():
        return False
    sections, current = [], None
    for line in doc.splitlines():
        if line.strip() == "Overloaded function.":
            continue
        if _signature_line(line, name):
            current = []
            sections.append(current)
        elif line.strip():
            if current is None:
                current = []
                sections.append(current)
            current.append(line)
    overloaded = "Overloaded function." in doc
    if overloaded:
        sections = sections[1:]  # the first signature is the generic (*args, **kwargs) one
    return bool(sections) and all(sections)


def _members():
    """(qualified name, kind, object) of every public name and of every public member of a
    public class."""
    out = []
    for name in _public(dir(fspm)):
        obj = getattr(fspm, name)
        if inspect.ismodule(obj):
            continue
        if inspect.isclass(obj):
            out.append((name, "class", obj))
            for member in _public(vars(obj)):
                raw = vars(obj)[member]
                if isinstance(raw, property):
                    out.append((f"{name}.{member}", "property", raw))
                elif callable(getattr(obj, member)):
                    out.append((f"{name}.{member}", "method", getattr(obj, member)))
        elif callable(obj):
            out.append((name, "function", obj))
    return out


def test_the_walk_sees_the_families():
    names = {qualified for qualified, _, _ in _members()}
    for expected in ("GrowthParams", "GrowthParams.alpha", "Tree.from_arrays", "grow_tree",
                     "LineTree.radii", "MannWhitneyResult.u", "Error", "read_results"):
        assert expected in names


def test_every_public_name_has_a_docstring():
    missing = []
    for qualified, kind, obj in _members():
        doc = obj.__doc__ if kind != "class" else vars(obj).get("__doc__")
        if not _explained(doc, qualified.rsplit(".", 1)[-1]):
            missing.append(f"{kind} {qualified}")
    assert not missing, f"{len(missing)} public names without a docstring:\n" + "\n".join(missing)


def test_fields_with_a_unit_in_their_name_state_it():
    wrong = []
    for qualified, kind, obj in _members():
        if kind != "property":
            continue
        field = qualified.rsplit(".", 1)[-1]
        for suffix, pattern in UNITS.items():
            if field.endswith(suffix) and not pattern.search(obj.__doc__ or ""):
                wrong.append(f"{qualified}: {obj.__doc__!r} does not name the unit of {suffix}")
    assert not wrong, "\n".join(wrong)


def test_the_checks_themselves():
    # A bare pybind11 signature is not a docstring; a signature followed by text is.
    assert not _explained("f(x: int) -> int\n", "f")
    assert not _explained("", "f")
    assert _explained("f(x: int) -> int\n\nDoubles x.\n", "f")
    assert _explained("A tree graph.", "Tree")
    overloads = ("g(*args, **kwargs)\nOverloaded function.\n\n1. g(a: str) -> None\n\nFrom a file."
                 "\n\n2. g(a: int) -> None\n")
    assert not _explained(overloads, "g")  # the second overload says nothing
    assert _explained(overloads + "\nFrom a number.\n", "g")
    assert UNITS["_m"].search("Tip radius (m, > 0)") and not UNITS["_m"].search("metamers")
