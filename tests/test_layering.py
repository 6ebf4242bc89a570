"""The package's layering, read from its source: lower stages never import higher ones.

The pipeline's order (``docs/architecture.md``): the base modules, then
``geometry`` < ``model`` < ``measure`` < ``solve`` < ``pipeline`` <
``stream`` < ``live`` < ``lab`` < ``cli``.  Every import of the package's own modules,
at module level or inside a function, is checked against it; module-level
imports form no cycle; no private name (``_x``) and no private module is
imported from another sub-package.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "ballscan"
LAYERS = ("geometry", "model", "measure", "solve", "pipeline", "stream", "live", "lab", "cli")
TOP = {"__main__": len(LAYERS)}  # ``python -m ballscan`` is the command itself
FRONT_DOOR = "ballscan"  # the package's __init__ re-exports the public API of every stage (lazily)


def _module_name(path: Path) -> str:
    parts = path.relative_to(SRC.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _layer(module: str) -> int:
    """The layer of ``ballscan.x...``: -1 for the base modules (errors, compiled helpers)."""
    parts = module.split(".")
    if len(parts) < 2:
        return -1
    if parts[1] in LAYERS:
        return LAYERS.index(parts[1])
    return TOP.get(parts[1], -1)


def _imports(path: Path):
    """``(target module, imported names, line, at module level)`` for each import of the package's own modules."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    tree = ast.parse(path.read_text(), str(path))
    top = {id(n) for n in tree.body}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("ballscan"):
                continue
            for alias in node.names:
                sub = f"{target}.{alias.name}"
                is_module = (SRC.parent / sub.replace(".", "/")).with_suffix(".py").exists() or (SRC.parent / sub.replace(".", "/")).is_dir()
                yield (sub if is_module else target), alias.name, node.lineno, id(node) in top
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("ballscan"):
                    yield alias.name, alias.name.rpartition(".")[2], node.lineno, id(node) in top


MODULES = sorted(SRC.rglob("*.py"))


def _subpackage(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] in LAYERS) else ""


def test_the_package_has_its_stages():
    assert {p.name for p in SRC.iterdir() if (p / "__init__.py").exists()} == set(LAYERS)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(SRC)))
def test_no_import_of_a_higher_stage(path):
    here = _module_name(path)
    if here == FRONT_DOOR:
        return
    wrong = sorted({f"line {line}: {target}" for target, _, line, _ in _imports(path) if _layer(target) > _layer(here)})
    assert not wrong, f"{here} ({LAYERS[_layer(here)] if _layer(here) >= 0 else 'base'}) imports a higher stage: {wrong}"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(SRC)))
def test_no_private_import_across_subpackages(path):
    here = _module_name(path)
    wrong = []
    for target, imported, line, _ in _imports(path):
        if _subpackage(target) == _subpackage(here) or not _subpackage(target):
            continue
        private_module = any(part.startswith("_") and part != "__init__" for part in target.split(".")[1:])
        if imported.startswith("_") or private_module:
            wrong.append(f"line {line}: {imported} from {target}")
    assert not wrong, f"{here} imports private names of another sub-package: {wrong}"


def test_no_import_cycle():
    graph: dict[str, set[str]] = {}
    for path in MODULES:
        here = _module_name(path)
        graph[here] = {t for t, _, _, top in _imports(path) if top and t != here and not here.startswith(t + ".")}
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> None:
        state[m] = 1
        stack.append(m)
        for t in sorted(graph.get(m, ())):
            if state.get(t) == 1:
                raise AssertionError("import cycle: " + " -> ".join(stack[stack.index(t):] + [t]))
            if t in graph and not state.get(t):
                visit(t)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if not state.get(m):
            visit(m)


def test_the_checks_see_a_violation(tmp_path):
    """The rules fire: a base-layer module importing the CLI, a private name across sub-packages."""
    fake = tmp_path / "ballscan"
    (fake / "geometry").mkdir(parents=True)
    (fake / "solve").mkdir()
    for d in (fake, fake / "geometry", fake / "solve"):
        (d / "__init__.py").write_text("")
    (fake / "geometry" / "camera.py").write_text("from ..solve.fit import _helper\nfrom ..solve import fit\n")
    (fake / "solve" / "fit.py").write_text("def _helper():\n    pass\n")
    global SRC
    old = SRC
    SRC = fake
    try:
        cam = fake / "geometry" / "camera.py"
        found = list(_imports(cam))
        assert ("ballscan.solve.fit", "_helper", 1, True) in found
        assert any(_layer(t) > _layer("ballscan.geometry.camera") for t, *_ in found)
        with pytest.raises(AssertionError, match="private"):
            test_no_private_import_across_subpackages(cam)
        with pytest.raises(AssertionError, match="higher stage"):
            test_no_import_of_a_higher_stage(cam)
    finally:
        SRC = old
