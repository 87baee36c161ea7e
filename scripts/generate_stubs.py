"""Writes python/cartan/_cartan.pyi, the type stubs of the compiled module ``cartan._cartan``, from
the built module itself: the pybind11 signature lines of its docstrings (``name(a: float, b:
object = None) -> numpy.ndarray[numpy.float64]``), its classes, static methods, properties and
attributes. Regenerate after changing the bindings (python/src), then commit the stub:

    cmake --build build --target cartan_python
    PYTHONPATH=build/python /usr/bin/python3 scripts/generate_stubs.py

``--check`` writes nothing and fails if the committed stub differs from what the module gives
(python/tests/test_stubs.py runs it in `make test`, beside mypy's stubtest).

Why not mypy's stubgen (Debian's python3-mypy 1.0.1, which stubtest below uses): measured on this
module (2026-11-29), its output is not Python (``def point_shape(self) -> The shape of a point:
...``: a property's docstring read as its type, a SyntaxError at line 38), 20 of its 53
constructors lose their signature (``__init__(self, *args, **kwargs)``: pybind11's overloads and
keyword-only arguments; here 5, the classes with no constructor: the groups and BvpSolution), and its
``numpy.ndarray[numpy.float64]`` annotations are not valid for mypy (ndarray takes two
parameters). This script is those rules and nothing else; stubtest checks its result.

Types: pybind11's names become annotations (``numpy.ndarray[numpy.float64[3, 1]]`` ->
``NDArray[numpy.float64]``, ``object`` -> ``Any``, ``cartan._cartan.X`` -> ``X``); a C++ type
pybind11 could not name (``cartan::...``) is an error: register the class before the function that
uses it, or take and return py::object.
"""
import argparse
import importlib
import inspect
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STUB = ROOT / "python" / "cartan" / "_cartan.pyi"
MODULE = "cartan._cartan"
TYPING_NAMES = ("Any", "Callable", "Dict", "Iterable", "Iterator", "List", "Optional", "Sequence", "Tuple", "Union")
# pybind11's names of Python types (pybind11/pytypes.h handle_type_name) that are not annotations.
RENAMES = {"object": "Any", "handle": "Any", "function": "Callable[..., Any]", "capsule": "Any",
           "args": "Any", "kwargs": "Any", "numpy.ndarray": "NDArray[Any]"}
OPEN, CLOSE = "([{<", ")]}>"


def split_top_level(text, separator=","):
    """``text`` split at each ``separator`` outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote and text[i - 1] != "\\" else quote
        elif c in "'\"":
            quote = c
        elif c in OPEN:
            depth += 1
        elif c in CLOSE:
            depth -= 1
        elif c == separator and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    tail = text[start:].strip()
    return parts + [tail] if tail else parts


def annotation(text):
    """A pybind11 type name as a stub annotation."""
    text = text.strip()
    if text in RENAMES:
        return RENAMES[text]
    if "::" in text:
        raise ValueError(f"{text!r} is a C++ type pybind11 could not name in Python: register its class "
                         "before the function that uses it (python/src), or take/return py::object")
    match = re.fullmatch(r"numpy\.ndarray\[([\w.]+)(?:\[[^\]]*\])?(?:, [^\]]*)?\]", text)
    if match:
        return f"NDArray[{match.group(1)}]"
    match = re.fullmatch(r"([\w.]+)\[(.*)\]", text)
    if match:
        name, inner = match.groups()
        if name == "Callable" and inner.startswith("["):
            arguments, result = split_top_level(inner)
            args = ", ".join(annotation(a) for a in split_top_level(arguments[1:-1]))
            return f"Callable[[{args}], {annotation(result)}]"
        return f"{annotation(name)}[{', '.join(annotation(a) for a in split_top_level(inner))}]"
    return text.removeprefix(MODULE + ".")


def parse_signature(line):
    """``name(params) -> result`` as (name, [param texts], result annotation)."""
    name, _, rest = line.partition("(")
    depth = 1
    for end, c in enumerate(rest):
        depth += (c in OPEN) - (c in CLOSE)
        if depth == 0:
            break
    else:
        raise ValueError(f"not a pybind11 signature: {line!r}")
    params = split_top_level(rest[:end])
    result = rest[end + 1:].strip().removeprefix("->").strip() or "None"
    return name.strip(), params, annotation(result)


def parameter(text, index, method):
    """One parameter of a signature, with its type and any default as ``...``."""
    if text in ("*", "/"):
        return text
    if method and index == 0:
        return "self"
    head, eq, _default = text.partition("=")
    name, _, kind = head.partition(":")
    name = name.strip()
    result = name if not kind.strip() else f"{name}: {annotation(kind)}"
    if name.startswith("*") and not kind.strip():
        result = f"{name}: Any"
    return result + (" = ..." if eq else "")


def docstring(text, indent):
    """``text`` as a stub docstring (empty string if there is none)."""
    text = inspect.cleandoc(text or "").replace("\\", "\\\\").replace('"""', '\\"\\"\\"')
    return f'{indent}"""{text}"""\n' if text else ""


def signatures(function):
    """[(signature line, doc)] of a pybind11 function: one per overload."""
    lines = (function.__doc__ or "").split("\n")
    if len(lines) > 1 and lines[1].strip() == "Overloaded function.":
        entries, current = [], None
        for line in lines[2:]:
            match = re.match(r"^\d+\. (.*)$", line)
            if match:
                current = [match.group(1), []]
                entries.append(current)
            elif current is not None:
                current[1].append(line)
        return [(sig, "\n".join(doc)) for sig, doc in entries]
    return [(lines[0], "\n".join(lines[1:]))]


def function_stub(name, function, indent, kind):
    """``def`` lines for a module function (kind None), a static or an instance method."""
    overloads = signatures(function)
    out = []
    for line, doc in overloads:
        sig_name, params, result = parse_signature(line)
        if sig_name != name:
            raise ValueError(f"{name}: docstring signature names {sig_name!r}")
        decorators = (["@overload"] if len(overloads) > 1 else []) + (["@staticmethod"] if kind == "static" else [])
        out += [f"{indent}{d}\n" for d in decorators]
        args = ", ".join(parameter(p, i, kind == "method") for i, p in enumerate(params))
        body = docstring(doc, indent + "    ")
        out.append(f"{indent}def {name}({args}) -> {result}:" + ("\n" + body if body else " ...\n"))
    return "".join(out)


def value_type(value):
    """The annotation of a plain attribute's value."""
    if isinstance(value, (tuple, list)):
        inner = {value_type(v) for v in value}
        item = inner.pop() if len(inner) == 1 else "Any"
        return f"tuple[{item}, ...]" if isinstance(value, tuple) else f"list[{item}]"
    if isinstance(value, dict):
        return "dict[str, Any]"
    kind = type(value)
    return kind.__name__ if kind.__module__ == "builtins" else annotation(f"{kind.__module__}.{kind.__qualname__}")


def property_stub(name, prop, indent):
    """A property: read-only as @property, read-write as an annotated attribute."""
    _name, _params, result = parse_signature("fget" + (prop.fget.__doc__ or "").split("\n")[0])
    if prop.fset is not None:
        return f"{indent}{name}: {result}\n"
    body = docstring(prop.__doc__, indent + "    ")
    return f"{indent}@property\n{indent}def {name}(self) -> {result}:" + ("\n" + body if body else " ...\n")


def class_stub(cls, indent=""):
    """A class with its methods, properties, attributes and nested classes."""
    inner = indent + "    "
    body = [docstring(cls.__doc__, inner)]
    if not hasattr(cls.__dict__.get("__init__"), "__func__"):  # a slot: any arguments, raises TypeError
        body.append(f"{inner}def __init__(self, *args: Any, **kwargs: Any) -> None:\n"
                    f'{inner}    """No constructor: raises TypeError."""\n')
    for name, member in cls.__dict__.items():
        if name in ("__doc__", "__module__", "__dict__", "__weakref__") or name.startswith("_pybind11"):
            continue
        if isinstance(member, staticmethod):
            body.append(function_stub(name, member.__func__, inner, "static"))
        elif isinstance(member, property):
            body.append(property_stub(name, member, inner))
        elif isinstance(member, type) and member.__qualname__ == f"{cls.__qualname__}.{name}":
            body.append(class_stub(member, inner))
        elif isinstance(member, type):  # another class as an attribute (a model's group)
            body.append(f"{inner}{name}: type[{annotation(f'{member.__module__}.{member.__qualname__}')}]\n")
        elif hasattr(member, "__func__"):  # pybind11's instancemethod
            body.append(function_stub(name, member.__func__, inner, "method"))
        elif not name.startswith("__"):
            body.append(f"{inner}{name}: {value_type(member)}\n")
    # The metaclass is pybind11's pybind11_type, a subclass of type that the stubs cannot name:
    # declared as type, which stubtest accepts as a metaclass and is true of pybind11_type.
    return f"{indent}class {cls.__name__}(metaclass=type):\n{''.join(body)}"


def generate(module):
    """The text of the stub of ``module``."""
    parts = []
    for name, member in module.__dict__.items():
        if name.startswith("__") and name != "__version__":
            continue
        if isinstance(member, type):
            parts.append(class_stub(member))
        elif callable(member):
            parts.append(function_stub(name, member, "", None))
        else:
            parts.append(f"{name}: {value_type(member)}\n")
    body = "\n".join(parts)
    used = [n for n in TYPING_NAMES if re.search(rf"\b{n}\b", body)] + ["overload"] * ("@overload" in body)
    header = [f'"""Type stubs of {MODULE}, generated from the built module by scripts/generate_stubs.py:',
              'do not edit; regenerate after changing the bindings (python/src)."""',
              "import numpy", "from numpy.typing import NDArray"]
    if used:
        header.append(f"from typing import {', '.join(used)}")
    return "\n".join(header) + "\n\n" + body


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--output", type=Path, default=STUB, help=f"the stub file (default {STUB})")
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 if the stub file is stale")
    args = parser.parse_args(argv)
    text = generate(importlib.import_module(MODULE))
    if args.check:
        current = args.output.read_text(encoding="utf-8") if args.output.exists() else ""
        if current != text:
            print(f"{args.output} is not the stub of the built {MODULE}: regenerate it with "
                  "`PYTHONPATH=build/python /usr/bin/python3 scripts/generate_stubs.py` and commit it", file=sys.stderr)
            return 1
        return 0
    args.output.write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
