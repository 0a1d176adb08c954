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
from dualmech._lazy import exports

_HOME = {"app": ("create_app", "served_problems", "WebLimits"), "server": ("serve",),
         "catalog": ("ProblemInfo",), "store": ("Store",)}

__all__ = ["create_app", "served_problems", "WebLimits", "serve", "ProblemInfo", "Store"]

__getattr__, __dir__ = exports(__name__, _HOME, globals())   # imported when first used
