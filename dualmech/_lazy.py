"""Names a package exports, imported from their home module when first used.

Each package's ``__init__`` lists its public names by home module; :func:`exports` gives it the
module-level ``__getattr__`` and ``__dir__`` (PEP 562), so ``import dualmech`` loads nothing
heavy and ``dualmech list`` never imports sympy.

Example
-------
>>> import types
>>> pkg = types.ModuleType("demo")
>>> pkg.__getattr__, pkg.__dir__ = exports("json", {"decoder": ("JSONDecodeError",)}, vars(pkg))
>>> pkg.__getattr__("JSONDecodeError").__name__
'JSONDecodeError'
"""
from __future__ import annotations

from importlib import import_module

__all__ = ["exports"]


def exports(package: str, homes: dict, namespace: dict):
    """``__getattr__`` and ``__dir__`` for ``package`` whose names live in ``homes``.

    ``homes`` maps a module (relative to ``package``) to the names it defines; a name is imported
    from its module on first access and kept in ``namespace`` (the package's globals).
    """
    where = {name: module for module, names in homes.items() for name in names}

    def __getattr__(name):
        module = where.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(import_module(f"{package}.{module}"), name)
        namespace[name] = value
        return value

    def __dir__():
        return sorted(set(namespace) | set(where))

    return __getattr__, __dir__
