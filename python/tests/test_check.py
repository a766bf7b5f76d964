"""kinetics.check: verdicts, named slips, the correct side as text and SymPy."""

import pytest
import sympy

import kinetics
from conftest import scene

SP18_4 = scene("sp18_4_shaft_reactions.scene")


def test_the_sign_slip_is_named():
    v = kinetics.check("D_y = -3*M/(16*c) + 1/4*m*c*w^2", scene=SP18_4)
    assert v.holds is False and not v
    assert v.slip == "cross-product-reversed"
    assert "Ω × H" in v.explanation
    assert v.correct.text == "-3*M/(16*c) - 1/4*m*c*w^2"
    correct = v.correct.to_sympy()
    M, c, m, w = sorted(correct.free_symbols, key=lambda s: s.name)[0:4]
    assert sympy.simplify(correct - kinetics.solve(SP18_4).results["D_y"].to_sympy()) == 0
    page = v._repr_html_()
    assert "differs" in page and "cross-product-reversed" in page
    # MathML, read without MathJax; the explanation a sentence.
    assert "<math displaystyle" in page and "$$" not in page and "<p>The cross product" in page
    assert v._repr_latex_().startswith(r"$$\begin{aligned}&\text{differs")


def test_a_right_claim_holds():
    v = kinetics.check("D_y = -3*M/(16*c) - 1/4*m*c*w^2", scene=SP18_4)
    assert v.holds is True and v
    assert v.slip is None


def test_general_body_with_principal_axes():
    v = kinetics.check("T = 1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2)", principal=True, fixed_point=True)
    assert v.holds is True
    wrong = kinetics.check("H_x = I_x w_x - I_xy w_y - I_xz w_z", principal=True)
    # With principal axes the products of inertia are zero, but I_xy is not a name there.
    assert wrong.holds in (False, None) or wrong.slip is not None


def test_an_unreadable_claim_is_a_scene_error():
    with pytest.raises(kinetics.SceneError) as caught:
        kinetics.check("D_y = = 3", scene=SP18_4)
    assert caught.value.column >= 1


def test_the_scene_says_its_own_context():
    with pytest.raises(ValueError, match="a scene says all of that itself"):
        kinetics.check("T = 0", scene=SP18_4, principal=True)


def test_a_vector_sides_components_are_x_y_z():
    # SP 18.3: the rod turns about A (the origin O) in the xy-plane; H_O has no z-component.
    v = kinetics.check("H_O = 1/3*m*L^2*w*j", scene=scene("sp18_3_rotating_rod.scene"))
    assert v.holds is False
    assert v.correct.to_sympy().shape == (3, 1)
    assert v.correct.text.startswith("(") and v.correct.text.endswith(", 0)")


def test_a_symbolic_claim_missing_a_small_term_differs():
    # The w_2 term is 0.2 % of T: a claim in names is exact, not within a tolerance.
    disk = ("given m = 4 kg\ngiven r = 250 mm\ngiven w1 = 300 rpm\ngiven w2 = 2 rad/s\n"
            "body disk(r) mass m along z\nvbar = 0\nomega = w2*i + w1*k\nfind T\n")
    v = kinetics.check("T = 1/4*m*r^2*w1^2", scene=disk)
    assert v.holds is False and "1/8*m*r^2*w_2^2" in v.explanation


def test_a_claim_in_numbers_says_how_far_it_is():
    v = kinetics.check("D_z = 36.75", scene=SP18_4)
    assert v.holds is False
    assert v.numbers == ["36.75 N has the wrong sign: the exact value is -36.75 N"]
    assert "the exact value is -36.75 N" in v.message() and "wrong sign" in v._repr_html_()
    # 156.2 is 0.58 % from 155.3: shown with the figures that tell it from 0.5 %.
    near = kinetics.check("C_z = -156.2", scene=SP18_4)
    assert near.holds is False and "the tolerance is 0.5 %" in near.numbers[0]


def test_a_derivation_is_followed_line_by_line():
    # The slip (H x Omega for Omega x H) is made in the moment equation; the last line is
    # right from it, so it follows and is not counted a second slip.
    work = kinetics.check_derivation(
        "alpha = 3*M/(2*m*c^2)\n"
        "# about z: D_y L = Hdot_z\n"
        "D_y*L = -1/8*m*L*c*alpha + 1/4*m*L*c*w^2\n"
        "D_y = -3*M/(16*c) + 1/4*m*c*w^2\n",
        scene=SP18_4)
    assert [(line.number, line.verdict) for line in work.lines] == [
        (1, "holds"), (3, "differs"), (4, "follows")]
    assert work.first_slip == (3, "cross-product-reversed")
    assert work.lines[2].follows_from == [3]
    assert work.holds is False and not work
    assert "follows" in work._repr_html_() and "| 4 |" in work._repr_markdown_()
    right = kinetics.check_derivation(["T = 1/2 (I_x w_x^2 + I_y w_y^2 + I_z w_z^2)"],
                                      principal=True, fixed_point=True)
    assert right.holds is True
    with pytest.raises(ValueError, match="no line to check"):
        kinetics.check_derivation("# only a comment\n")
