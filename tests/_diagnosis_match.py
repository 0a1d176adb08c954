"""Whether a diagnosis statement names a quantity and a term: what the teacher-mistake corpora
(tests/test_teacher_mistakes.py, tests/test_teacher_mutants_4.py) assert of each mutant."""
import sympy as sp


def same(a, b) -> bool:
    """Equal expressions (both given), decided by expanding and simplifying the difference."""
    return a is not None and b is not None and sp.simplify(sp.expand(a - b)) == 0


def names(statement, subject: str, term) -> bool:
    """Whether ``statement`` is about ``subject`` and shows ``term`` (either sign) as one of
    its sides or as the whole change it proposes; ``term=None`` asks for the subject only."""
    if subject not in statement.subject and subject not in statement.text():
        return False
    if term is None:
        return True
    sides = [x for _, have, right in statement.terms for x in (have, right) if x is not None]
    change = sum(((right or 0) - (have or 0) for _, have, right in statement.terms),
                 sp.Integer(0))
    return any(same(x, term) or same(x, -term) for x in sides + [change])
