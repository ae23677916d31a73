"""The type stubs (massprops/__init__.pyi) parse and name every public function, class and
method of the module, so that editors complete all of them."""
import ast
import inspect
import pathlib

import massprops


def stub_tree():
    path = pathlib.Path(massprops.__file__).with_name("__init__.pyi")
    return ast.parse(path.read_text())


def test_stub_names_every_public_function_and_class():
    tree = stub_tree()
    top = {node.name for node in tree.body
           if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    top |= {t.id for node in tree.body if isinstance(node, ast.AnnAssign)
            for t in [node.target] if isinstance(t, ast.Name)}
    missing = [name for name in massprops.__all__ if name not in top]
    assert not missing


def test_stub_classes_name_every_public_method_and_property():
    classes = {node.name: node for node in stub_tree().body if isinstance(node, ast.ClassDef)}
    missing = []
    for name in massprops.__all__:
        cls = getattr(massprops, name)
        if not inspect.isclass(cls) or issubclass(cls, BaseException) or name == "PrincipalSolver":
            continue
        stubbed = set()
        for node in classes[name].body:
            if isinstance(node, ast.FunctionDef):
                stubbed.add(node.name)
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                stubbed.add(node.target.id)
        for base in classes[name].bases:  # inherited members are stubbed on the base
            if isinstance(base, ast.Name) and base.id in classes:
                stubbed |= {n.name for n in classes[base.id].body
                            if isinstance(n, ast.FunctionDef)}
        for member in vars(cls):
            if not member.startswith("_") and member not in stubbed:
                missing.append(f"{name}.{member}")
    assert not missing
