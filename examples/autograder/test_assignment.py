"""An autograder for a small assignment on Sample Problem 18.4, with kinetics.check.

Each question is one test: the student's answer (a string in their submission) is checked
against the scene, and a wrong answer fails with the checker's words — the named slip and
the correct form — as the message a student reads. Run it with plain pytest:

    KINETICS_SUBMISSION=submissions/slipped.py pytest examples/autograder

(`KINETICS_SUBMISSION` names the student's file; `submission.py` beside this file by
default). README.md says how it plugs into Otter-Grader and nbgrader.
"""

import importlib.util
import os
import pathlib

import pytest

import kinetics

HERE = pathlib.Path(__file__).resolve().parent
SCENE = HERE.parent / "scenes" / "sp18_4_shaft_reactions.scene"


def submission():
    """The student's answers: a module of strings, one per question."""
    path = pathlib.Path(os.environ.get("KINETICS_SUBMISSION", HERE / "submission.py"))
    if not path.is_absolute():
        path = HERE / path
    spec = importlib.util.spec_from_file_location("submission", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# Question, the name of the student's answer, what it must state.
QUESTIONS = [
    ("q1", "alpha", "the angular acceleration alpha in symbols"),
    ("q2", "D_y", "the reaction D_y at bearing D in symbols"),
    ("q3", "C_z", "the reaction C_z at bearing C in symbols"),
    ("q4", "H_x", "the component H_x of the angular momentum about O"),
]


@pytest.mark.parametrize("question, name, asked", QUESTIONS, ids=[q[0] for q in QUESTIONS])
def test_question(question, name, asked):
    answer = getattr(submission(), question, None)
    if answer is None:
        pytest.fail(f"{question}: no answer given ({asked})")
    verdict = kinetics.check(f"{name} = {answer}", scene=SCENE)
    assert verdict.holds, verdict.message()
