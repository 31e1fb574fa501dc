# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The type stubs shipped with the package against the compiled module:
the same parameters (names, order, defaults, keyword-only) for every
function and method, docstrings that document parameters and errors, and
mypy refusing a misspelt option."""

import ast
import inspect
import os
import textwrap

import pytest

import ssmd
from ssmd import _ssmd

STUB = os.path.join(os.path.dirname(ssmd.__file__), "_ssmd.pyi")


def parameters(function):
    """(name, default or None, keyword-only) of an ast function, without self."""
    a = function.args
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    result = [(p.arg, None if d is None else ast.literal_eval(d), False) for p, d in zip(positional, defaults)]
    result += [(p.arg, None if d is None else ast.literal_eval(d), True)
               for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return [p for p in result if p[0] != "self"]


def runtime_parameters(obj):
    """The parameters of a pybind11 function, from the signature pybind11
    writes at the head of its docstring."""
    head = obj.__doc__.lstrip().splitlines()[0]
    return parameters(ast.parse("def " + head + ": pass").body[0])


def stub_functions():
    """{qualified name: [ast function, ...]} (several for overloads)."""
    tree = ast.parse(open(STUB).read())
    functions = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    functions.setdefault(node.name + "." + item.name, []).append(item)
    return functions


def is_property(node):
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def runtime_object(name):
    obj = _ssmd
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


def test_stub_signatures_are_the_module_signatures():
    functions = stub_functions()
    checked = 0
    for name, nodes in functions.items():
        if is_property(nodes[0]):
            assert isinstance(inspect.getattr_static(_ssmd.Deformation, name.split(".")[1]), property), name
            continue
        runtime = runtime_parameters(runtime_object(name))
        if len(nodes) == 1:
            assert parameters(nodes[0]) == runtime, name
        else:
            # Overloads: each names parameters of the module in its order;
            # all of them together name every parameter.
            names = [p[0] for p in runtime]
            for node in nodes:
                own = [p[0] for p in parameters(node)]
                assert own == [n for n in names if n in own], (name, own)
            assert {p[0] for node in nodes for p in parameters(node)} == set(names), name
        checked += 1
    assert checked == 14
    public = {n for n in dir(_ssmd) if not n.startswith("_") and callable(getattr(_ssmd, n))
              and not isinstance(getattr(_ssmd, n), type)}
    assert public <= set(functions), public - set(functions)
    methods = {"Deformation." + n for n, v in vars(_ssmd.Deformation).items()
               if not n.startswith("_") and not isinstance(v, property)}
    assert methods <= set(functions), methods - set(functions)


def documented_functions():
    yield ssmd.Deformation.__init__
    for name in ("set_targets", "translate", "rotate", "deform", "refine", "save_basis", "load_basis"):
        yield getattr(ssmd.Deformation, name)
    for name in ("manifold_harmonics", "from_file", "to_file", "read_selection", "read_handle_transformation",
                 "mesh_arrays", "progress_bar"):
        yield getattr(ssmd, name)


@pytest.mark.parametrize("function", list(documented_functions()), ids=lambda f: f.__qualname__)
def test_docstrings_document_parameters_and_errors(function):
    doc = inspect.getdoc(function)
    assert "Parameters\n----------" in doc and "Raises\n------" in doc, function
    signature = runtime_parameters(function) if "(" in doc.lstrip().splitlines()[0] \
        else [(p, None, False) for p in inspect.signature(function).parameters]
    for name, _, _ in signature:
        if name.startswith("**"):
            continue
        assert "\n" + name.lstrip("*") + " :" in doc or "\n**" + name in doc, (function, name)


def run_mypy(tmp_path, code):
    api = pytest.importorskip("mypy.api")
    (tmp_path / "snippet.py").write_text(textwrap.dedent(code))
    cache = os.environ.get("MYPY_CACHE_DIR", str(tmp_path / "cache"))
    here = os.path.dirname(os.path.abspath(__file__))
    out, err, status = api.run(["--config-file", os.path.join(here, "mypy.ini"), "--cache-dir", cache,
                                "--no-error-summary", str(tmp_path / "snippet.py")])
    return status, out + err


def test_mypy_accepts_the_documented_calls_and_refuses_a_misspelt_option(tmp_path):
    status, out = run_mypy(tmp_path, """
        import numpy as np
        import ssmd
        V, F = ssmd.from_file("tube.off")
        d = ssmd.Deformation(V, F, handles=[0, 1], fixed=np.arange(3), policy="soft", basis="exact",
                             progress=ssmd.progress_bar())
        d.rotate([1.0, 0.0, 0.0, 0.0], center=[0, 0, 0])
        W: np.ndarray = d.deform(iterations=5)
        refined: bool = d.refine(50, tolerance=0.0)
        energies = d.refine_report["energies"]
        values, basis = ssmd.manifold_harmonics(V, F, 10)
        values, basis, mass = ssmd.manifold_harmonics(V, F, 10, mass=True)
        values, basis = ssmd.manifold_harmonics((V, F), m=10)
        ssmd.to_file("out.ply", W, F)
    """)
    assert status == 0, out
    status, out = run_mypy(tmp_path, """
        import ssmd
        V, F = ssmd.from_file("tube.off")
        d = ssmd.Deformation(V, F, handles=[0], policy="exakt")
    """)
    assert status == 1 and "policy" in out and "Literal" in out, out
