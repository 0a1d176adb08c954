"""Studies of the numbers: work-precision, the stability atlas, regimes, singularities,
Floquet and Mathieu charts, chaotic horizons, fidelity ladders."""
