"""Deciding and explaining: exact linear algebra on sampled values, pair verdicts, blame."""
