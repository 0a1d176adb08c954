"""The source's printed answers, checked against the derivations (see
:mod:`dualmech.verify.published`)."""
from dualmech.verify.published import PublishedVerdict, check_published, closest_equation

__all__ = ["PublishedVerdict", "check_published", "closest_equation"]
