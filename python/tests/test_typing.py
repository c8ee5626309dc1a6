"""Typed and documented: the stub __init__.pyi beside the package declares every public name,
each public function and method with the runtime's parameters (names, kinds, defaults) and an
annotation on every parameter and return; every annotation resolves; every public name, method
and property has a docstring."""
import ast
import inspect
import os

import impact

STUB = os.path.join(os.path.dirname(impact.__file__), "__init__.pyi")
# Declared only for type checkers: Table's result attributes (``r.completed``) are set per table.
STUB_ONLY = {("Table", "__getattr__")}


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read(), STUB)


def public_callables():
    """(class name or None, name, object) of every public function, and every public method and
    property (and __init__) a public class defines itself."""
    for name in impact.__all__:
        obj = getattr(impact, name)
        if inspect.isfunction(obj):
            yield None, name, obj
        elif inspect.isclass(obj):
            for attr, value in vars(obj).items():
                if attr == "__init__" or not attr.startswith("_"):
                    if inspect.isfunction(value) or isinstance(value, property):
                        yield name, attr, value


def stub_functions(tree):
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[(None, node.name)] = node
        elif isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    out[(node.name, item.name)] = item
    return out


def stub_parameters(node):
    """[(name, kind, default or inspect.Parameter.empty)] of a stub function."""
    a = node.args
    positional = a.posonlyargs + a.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(a.defaults)) + [
        ast.literal_eval(d) for d in a.defaults]
    out = [(p.arg, inspect.Parameter.POSITIONAL_OR_KEYWORD, d) for p, d in zip(positional,
                                                                               defaults)]
    if a.vararg:
        out.append((a.vararg.arg, inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.empty))
    for p, d in zip(a.kwonlyargs, a.kw_defaults):
        out.append((p.arg, inspect.Parameter.KEYWORD_ONLY,
                    inspect.Parameter.empty if d is None else ast.literal_eval(d)))
    if a.kwarg:
        out.append((a.kwarg.arg, inspect.Parameter.VAR_KEYWORD, inspect.Parameter.empty))
    return out


def test_every_public_name_is_in_the_stub():
    tree = stub_tree()
    declared = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            declared.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            declared.add(node.target.id)
    missing = sorted(set(impact.__all__) - declared)
    assert not missing, f"{STUB}: not declared: {missing}"


def test_stub_signatures_match_the_runtime_and_are_annotated():
    functions = stub_functions(stub_tree())
    problems = []
    for cls, name, obj in public_callables():
        node = functions.get((cls, name))
        where = f"{cls + '.' if cls else ''}{name}"
        if node is None:
            problems.append(f"{where}: not in the stub")
            continue
        if isinstance(obj, property):
            if not any(isinstance(d, ast.Name) and d.id == "property"
                       for d in node.decorator_list) or node.returns is None:
                problems.append(f"{where}: expected an annotated @property")
            continue
        runtime = [(p.name, p.kind, p.default)
                   for p in inspect.signature(obj).parameters.values()]
        if stub_parameters(node) != runtime:
            problems.append(f"{where}: stub {stub_parameters(node)} != runtime {runtime}")
        unannotated = [p.arg for p in node.args.posonlyargs + node.args.args
                       + node.args.kwonlyargs if p.annotation is None and p.arg != "self"]
        unannotated += [p.arg for p in (node.args.vararg, node.args.kwarg)
                        if p is not None and p.annotation is None]
        if unannotated or node.returns is None:
            problems.append(f"{where}: not annotated: {unannotated or 'return'}")
    for cls, name in set(functions) - {(c, n) for c, n, _ in public_callables()} - STUB_ONLY:
        problems.append(f"{cls + '.' if cls else ''}{name}: in the stub, not at run time")
    assert not problems, "\n".join(problems)


def test_every_stub_annotation_resolves():
    """Executing the stub evaluates every annotation (no postponed evaluation): a misspelt type
    or a missing import fails here."""
    namespace = {}
    with open(STUB) as f:
        exec(compile(f.read(), STUB, "exec"), namespace)  # noqa: S102 (our own stub)
    assert issubclass(namespace["RunError"], RuntimeError)


def own_doc(obj):
    """The object's own docstring (inspect.getdoc would inherit ValueError's for InputError)."""
    if inspect.isclass(obj):
        return vars(obj).get("__doc__")
    return obj.__doc__


def test_every_public_name_has_a_docstring():
    undocumented = [name for name in impact.__all__
                    if (inspect.isclass(getattr(impact, name))
                        or inspect.isfunction(getattr(impact, name)))
                    and not own_doc(getattr(impact, name))]
    undocumented += [f"{cls}.{name}" for cls, name, obj in public_callables()
                     if cls and name != "__init__" and not own_doc(obj)]
    assert not undocumented, undocumented
    assert impact.__doc__ and "InputError" in impact.__doc__


def test_the_package_is_marked_typed():
    assert os.path.exists(os.path.join(os.path.dirname(impact.__file__), "py.typed"))
