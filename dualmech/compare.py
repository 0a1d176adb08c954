"""Decide whether derivations describe the same motion, check printed answers, recover reactions.

The public front door of :mod:`dualmech.verify`: ``compare(problem)`` returns a
:class:`Comparison` (``str()`` is the report a teacher reads); ``compare_models`` judges two
equation sets.  How a verdict is reached is documented in :mod:`dualmech.verify.verdicts`
(judging every derivation at once, naming the faulty one), :mod:`dualmech.verify.sampling`
(exact evaluation at random points) and :mod:`dualmech.exact` (why that is sound).
"""
from dualmech.verify.check import (METHOD_NAMES, Comparison, PairResult, compare, compare_models,
                           compare_reactions, method_name, reaction_pairs, recover_reactions)
from dualmech.verify.explain import Mismatch
from dualmech.verify.sampling import Context

__all__ = ["compare", "compare_models", "compare_reactions", "reaction_pairs",
           "recover_reactions", "Comparison", "PairResult", "Mismatch", "Context",
           "METHOD_NAMES", "method_name"]
