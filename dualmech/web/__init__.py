"""The page where students answer and teachers see their class (``dualmech serve``).

A thin ASGI layer (Starlette, served by uvicorn; the ``web`` extra) over the grader: a page
per problem with validation while typing and feedback on submission, a teacher page behind a
token that grades a class's CSV in the background, and a JSON API with an OpenAPI page.  See
:func:`create_app` and :func:`serve`.

Example
-------
>>> from dualmech.web import ProblemInfo
>>> from dualmech.web.preview import preview
>>> preview(ProblemInfo.build("simple_pendulum"), "a*theta'' + g*sin(theta) = 0")["ok"]
True
"""
from importlib import import_module

_HOME = {"app": ("create_app", "served_problems", "WebLimits"), "server": ("serve",),
         "catalog": ("ProblemInfo",), "store": ("Store",)}
_WHERE = {name: module for module, names in _HOME.items() for name in names}

__all__ = ["create_app", "served_problems", "WebLimits", "serve", "ProblemInfo", "Store"]


def __getattr__(name):   # imported when first used: `dualmech --help` never loads starlette
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'dualmech.web' has no attribute {name!r}")
    value = getattr(import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value
