"""The package's folders show the pipeline and its arrows point one way (DESIGN.md, "Layout"):
cli -> web -> grade, report -> numeric -> verify -> exact -> model.  A module imports only from
its own stage or the stages below it; the one exception is the Jupyter display hook
(``_repr_html_``), which a model object may have and which imports the presentation only when a
notebook shows the object.  At most eight modules stay at the package root."""
import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "dualmech"
ORDER = {"model": 0, "exact": 1, "verify": 2, "numeric": 3, "grade": 4, "report": 4, "web": 5,
         "cli": 6}


def _stage(module: str):
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[0] == "dualmech" and parts[1] in ORDER else None


def _upward_imports():
    """``(module, imported, enclosing function or None)`` of every import that points up."""
    out = []
    for path in sorted(PACKAGE.rglob("*.py")):
        module = ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        module = module.removesuffix(".__init__")
        here = _stage(module)
        if here is None:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        parents = {child: node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)}
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            else:
                continue
            for name in names:
                there = _stage(name)
                if there is not None and ORDER[there] > ORDER[here]:
                    up = parents.get(node)
                    while up is not None and not isinstance(up, (ast.FunctionDef,
                                                                 ast.AsyncFunctionDef)):
                        up = parents.get(up)
                    out.append((module, name, up.name if up is not None else None))
    return out


def test_no_module_imports_from_a_later_stage_except_the_jupyter_display_hook():
    found = _upward_imports()
    assert [f for f in found if f[2] != "_repr_html_"] == [], found


def test_the_check_finds_an_upward_import():
    # the scan is not vacuous: the display hooks it allows are upward imports it does see
    assert {(m, f) for m, _, f in _upward_imports()} >= {("dualmech.model.problem",
                                                           "_repr_html_")}


def test_at_most_eight_modules_at_the_root():
    root = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert len(root) <= 8, root
