"""The course notes the catalogue comes from, named by course rather than by file.

A problem's ``source`` reads ``"<file>: <where in it>"`` with the archive's hashed file name
(``001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 1``); a handout names the course and
the problem instead (``MIT 2.003J, Spring 2011: quiz 1``).  Sources that do not start with a
known file are returned unchanged.  Every place a person reads a source uses
:func:`source_name`; JSON carries the name as ``source`` and the file, for programs, as
``source_file`` (:func:`source_fields`).

Example
-------
>>> source_name("001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 1")
'MIT 2.003J Dynamics and Control I, Spring 2011: quiz 1'
>>> source_name("by hand")
'by hand'
>>> source_file("001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 1"), source_file("by hand")
('001_9d08622cf8d659c2.txt', None)
"""
from __future__ import annotations

import re

__all__ = ["COURSES", "source_name", "source_file", "source_fields", "course_of"]

#: a file name that opens a source: ``notes.pdf: Example 3`` (no spaces, an extension)
_FILE = re.compile(r"[\w.-]+\.[A-Za-z0-9]{1,5}")

#: file -> (course, prefixes of the "where" part that repeat the course and are dropped)
COURSES: dict[str, tuple[str, tuple[str, ...]]] = {
    "000_203248afac9714e6.txt": ("Lecture notes, Lagrange's method", ()),
    "001_9d08622cf8d659c2.txt": ("MIT 2.003J Dynamics and Control I, Spring 2011",
                                 ("2.003J spring 2011, ",)),
    "002_df41972c66c4514e.txt": ("Cambridge 3C5 Dynamics, Lagrangian mechanics", ()),
    "003_d6818267b4d96a20.txt": ("Rigid-body dynamics, lecture 18", ("lecture 18, ",)),
    "004_f75aa9bb64d0737a.txt": ("Exam \"Dynamics and Stability\", worked solutions", ()),
}


def course_of(source: str) -> tuple[str, str]:
    """``(course, where)`` of a problem's ``source``; ``("", source)`` when the file is not
    one of :data:`COURSES`."""
    file, sep, where = source.partition(": ")
    if file not in COURSES:
        return "", source
    course, repeats = COURSES[file]
    where = where.strip() if sep else ""
    for prefix in repeats:
        if where.lower().startswith(prefix.lower()):
            where = where[len(prefix):]
    return course, where


def source_name(source: str) -> str:
    """``source`` with the archive's file name replaced by the course's name."""
    course, where = course_of(source)
    if not course:
        return source
    return f"{course}: {where}" if where else course


def source_file(source: str) -> str | None:
    """The file a problem's ``source`` names first (``000_203248afac9714e6.txt``), or
    ``None`` when it opens with no file name (``"textbook: Landau & Lifshitz"``)."""
    file, sep, _ = source.partition(": ")
    return file if file in COURSES or (sep and _FILE.fullmatch(file)) else None


def source_fields(source: str) -> dict:
    """``{"source": <named by course>, "source_file": <file or None>}``: the two JSON fields."""
    return {"source": source_name(source), "source_file": source_file(source)}
