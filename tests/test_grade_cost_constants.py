"""The cost model evaluates constant arithmetic before it estimates (multiples and exponents
written as powers, sums or products of numbers), so such answers are refused at once, by the
library call as by the command."""
import time

import pytest

from dualmech import grade
from dualmech.grade.cost import TooCostly, check
from dualmech.grade.parser import parse


@pytest.mark.parametrize("answer, culprit", [
    ("cos(10^20*theta + phi) = 0", "cos(10^20*theta + phi)"),
    ("sin((500 + 500)*theta) = 0", "sin((500 + 500)*theta)"),
    ("sin(10^(10^6)*theta) = 0", "sin(10^(10^6)*theta)"),
    ("sin(theta*(1/10)^(-30)) = 0", "sin(theta*(1/10)^(-30))"),
    ("cos(theta)^(10^3) = 0", "cos(theta)^(10^3)"),
    ("sin(2^2^2^2^2*theta) = 0", None),
])
def test_a_multiple_written_as_constant_arithmetic_is_costed_as_its_value(answer, culprit):
    start = time.perf_counter()
    with pytest.raises(TooCostly) as err:
        check(parse(answer)[0].lhs)
    assert time.perf_counter() - start < 1.0
    if culprit is not None:
        assert f"`{culprit}`" in str(err.value)


@pytest.mark.parametrize("answer", ["sin(2^3*theta) = 0", "sin((-2)^3*theta) = 0",
                                    "cos((1 + 1)*theta) = 0", "sin(0^2*theta + phi) = 0",
                                    "sin(theta*(1/2)^(-2)) = 0"])
def test_small_constant_multiples_are_graded(answer):
    check(parse(answer)[0].lhs)     # 8, -8, 2, 0 and 4 times an angle: within the limits


def test_the_library_call_refuses_a_huge_power_multiple_at_once():
    start = time.perf_counter()
    result = grade("toy_car", "R*theta'' + cos(10^20*theta + phi) = 0")
    assert time.perf_counter() - start < 5.0
    assert result.status == "invalid" and "too costly" in str(result)
    assert "`cos(10^20*theta + phi)`" in str(result)


def test_a_right_answer_with_a_constant_factor_written_as_arithmetic_is_still_right():
    # (2^2 - 3)^5 = 1: the toy car's theta equation (Lagrange), times one
    answer = ("R*theta'' + R*phi'^2*sin(theta)*cos(theta) "
              "+ g*cos(phi)*sin(theta)*(2^2 - 3)^5 = 0")
    assert grade("toy_car", answer).right
