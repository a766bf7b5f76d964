"""kinetics.solve: results checked against hand derivations, forms against SymPy."""

import json
import math

import pytest
import sympy

import kinetics
from conftest import scene

SP18_4 = scene("sp18_4_shaft_reactions.scene")


def test_sp18_4_reaction_at_d_by_hand():
    s = kinetics.solve(SP18_4)
    d_y = s.results["D_y"]
    # ΣM_z about C: D_y L = -m c (α/8 + ω²/4) L  with α = 3M/(2 m c²) (by hand, notes §18.4).
    m, c, M, w = 0.3, 0.1, 6.0, 125.7
    alpha = 3 * M / (2 * m * c**2)
    by_hand = -m * c * alpha / 8 - m * c * w**2 / 4
    assert d_y.value == pytest.approx(by_hand, rel=1e-12)
    assert f"{d_y.value:.4g}" == "-129.8"
    assert d_y.unit == "N"
    assert s.results["alpha"].value == pytest.approx(alpha, rel=1e-12)


def test_to_sympy_is_the_exact_form_with_assumptions():
    s = kinetics.solve(SP18_4)
    d_y = s.results["D_y"].to_sympy()
    M, c, m, w = (s.symbols[n] for n in ("M", "c", "m", "w"))
    assert sympy.simplify(d_y - (-3 * M / (16 * c) - m * c * w**2 / 4)) == 0
    # Masses and lengths are positive; a couple and a rate may be negative.
    assert m.is_positive and c.is_positive
    assert M == sympy.Symbol("M") and w == sympy.Symbol("w")
    # So the hand form may be written with SymPy's own symbols, m and c positive.
    m_, c_ = sympy.symbols("m c", positive=True)
    M_, w_ = sympy.symbols("M w")
    assert sympy.simplify(d_y - (-3 * M_ / (16 * c_) - m_ * c_ * w_**2 / 4)) == 0
    # The exact form evaluates to the page's number.
    values = {M: 6, c: sympy.Rational(1, 10), m: sympy.Rational(3, 10), w: sympy.Rational(1257, 10)}
    assert float(d_y.subs(values)) == pytest.approx(s.results["D_y"].value, rel=1e-12)


def test_text_path_and_pathlike_are_one_scene():
    import pathlib

    text = pathlib.Path(SP18_4).read_text()
    by_text = kinetics.solve(text).results["C_z"].value
    by_path = kinetics.solve(pathlib.Path(SP18_4)).results["C_z"].value
    assert by_text == by_path


def test_pages_in_every_format():
    s = kinetics.solve(SP18_4)
    assert "<math" in s._repr_html_()
    assert s._repr_html_().startswith('<div class="kinetics-page">')
    assert "<!DOCTYPE html>" in s.to_html()
    assert r"\begin{align*}" in s.to_latex()
    assert s.to_latex(standalone=True).startswith(r"\documentclass")
    page = json.loads(s.to_json())
    assert [r["name"] for r in page["results"]] == list(s.results)
    assert s._repr_latex_().startswith("$$") and r"D_y &= " in s._repr_latex_()
    assert "**Given:**" in s._repr_markdown_()
    with pytest.raises(ValueError, match="standalone goes with the LaTeX format"):
        s._solved.render("html", standalone=True)


def test_steps_are_the_pages_steps():
    s = kinetics.solve(SP18_4)
    page = json.loads(s.to_json())
    assert [st.title for st in s.steps] == page["plan"]
    last = s.steps[-1]
    assert last.title.startswith("equations of motion")
    assert "M = 2/3*m*c^2*alpha" in [r.text for r in last.relations]


def test_result_reprs():
    r = kinetics.solve(SP18_4).results["alpha"]
    assert str(r) == "alpha = 3*M/(2*m*c^2) = 3000 rad/s²"
    assert r._repr_html_().startswith('<div class="kinetics-page">')
    assert '<math display="block">' in r._repr_html_()
    assert r._repr_latex_() == r"$$\alpha = \frac{3 M}{2 m c^2} = 3000\,\mathrm{rad/s^2}$$"


def test_vector_and_tensor_results():
    # A uniform sphere spinning about z with its centre at rest: H_G = (2/5) m r² ω k.
    s = kinetics.solve(
        "given m = 5 kg\ngiven r = 0.1 m\ngiven w = 2 rad/s\n"
        "body sphere(r) mass m\nvbar = 0\nomega = w*k\nfind H_G, I_G, T\n")
    h = s.results["H_G"]
    assert h.value == pytest.approx((0.0, 0.0, 2 / 5 * 5 * 0.01 * 2))
    assert h.to_sympy().shape == (3, 1)
    inertia = s.results["I_G"]
    assert inertia.value[0][0] == pytest.approx(2 / 5 * 5 * 0.01)
    assert inertia.to_sympy().shape == (3, 3)
    assert s.results["T"].value == pytest.approx(0.5 * 2 / 5 * 5 * 0.01 * 4)


def test_us_units():
    s = kinetics.solve(SP18_4, units="us")
    # 1 lbf = 4.4482216152605 N.
    assert s.results["D_y"].unit == "lb"
    assert s.results["D_y"].value == pytest.approx(-129.753675 / 4.4482216152605, rel=1e-6)


def test_scene_error_carries_place_and_hint():
    with pytest.raises(kinetics.SceneError) as caught:
        kinetics.solve("given m = 3 kg\nbody rod(L) mass m\nomega = w*k\nfind T\n")
    error = caught.value
    assert isinstance(error, ValueError)
    assert error.line >= 1 and error.column >= 1
    assert error.message in str(error)
    assert f"{error.line} |" in str(error)


def test_a_missing_file_is_a_file_error():
    with pytest.raises(FileNotFoundError):
        kinetics.solve("no/such/problem.scene")


def test_bad_arguments_say_why():
    with pytest.raises(ValueError, match="units"):
        kinetics.solve(SP18_4, units="imperial")
    with pytest.raises(TypeError):
        kinetics.solve(42)
    assert math.isfinite(kinetics.solve(SP18_4).results["C_y"].value)


def test_symbols_are_the_scenes_as_the_page_spells_them():
    s = kinetics.solve(SP18_4)
    # L is a given no result holds; it is among the scene's symbols all the same.
    assert {"m", "c", "M", "L", "w", "alpha", "D_y"} <= set(s.symbols)
    assert s.symbols["L"].is_positive
    disk = kinetics.solve("given m = 4 kg\ngiven r = 250 mm\ngiven w1 = 300 rpm\n"
                          "body disk(r) mass m along z\nvbar = 0\nomega = w1*k\nfind T\n")
    w_1 = disk.symbols["w_1"]
    m, r = disk.symbols["m"], disk.symbols["r"]
    assert sympy.simplify(disk.results["T"].to_sympy() - m * r**2 * w_1**2 / 4) == 0


def test_markdown_with_its_figure(tmp_path):
    s = kinetics.solve(SP18_4)
    figure = tmp_path / "sp18_4.svg"
    page = s.to_markdown(figure=str(figure))
    assert "![The figure of the problem](sp18_4.svg)" in page
    assert figure.read_text().startswith("<svg")
    assert "to_markdown(figure=" in s.to_markdown()


def test_units_in_any_case_and_a_missing_path():
    assert kinetics.solve(SP18_4, units="SI").results["D_y"].unit == "N"
    with pytest.raises(FileNotFoundError):
        kinetics.solve("examples/scenes/sp18_4_shaft_reactions")


def test_hostile_input_is_refused_with_its_reason():
    with pytest.raises(kinetics.SceneError, match="nested more than 200 levels"):
        kinetics.check("T = " + "(" * 5000 + "m" + ")" * 5000)
    with pytest.raises(kinetics.SceneError, match="more than the limit"):
        kinetics.solve("# a comment\n" * 100000 + "find T\n")
    with pytest.raises(kinetics.SceneError):
        kinetics.solve("\n\n")
    with pytest.raises(ValueError):
        kinetics.check("T = 1", rtol=float("nan"))


def test_a_result_that_is_a_number_says_it_once():
    # SP 18.3's pin: A_z = 0 (no load along z); said as its value with its unit.
    s = kinetics.solve(scene("sp18_3_rotating_rod.scene"))
    a_z = s.results["A_z"]
    assert a_z.value == 0 and str(a_z) == "A_z = 0 N"
    assert a_z._repr_latex_() == r"$$A_z = 0\,\mathrm{N}$$"
