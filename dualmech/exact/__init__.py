"""Exact evaluation: rational points, trigonometric values, surds and radicals, intervals."""
